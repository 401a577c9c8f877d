#!/usr/bin/env bash
# A private single-node Slurm cluster for the campaign test: its own munge socket, config, spool and log
# folders and ports, named by DIR; it stops exactly the daemons it started (by their pid files).
#   slurm_cluster.sh start DIR   prints the SLURM_CONF to export, once the node is idle
#   slurm_cluster.sh stop DIR
# Needs root (slurmd runs jobs as their user), Debian's slurm-wlm and munge, and no systemd.
# The short folder stays after stop, with the daemons' logs, until the next start replaces it.
set -eu
action=$1
tag=$(realpath -ms "$2" | cksum | cut -d' ' -f1)
host=$(hostname -s)
# Unix sockets' paths may be at most 108 bytes (munge's, and slurmd's per job step): the cluster lives in a
# short folder named from DIR, which links to it.
dir=/tmp/physltl-slurm-$tag
munge_dir=$dir/munge

stop() {
  local pidfile pid
  for pidfile in "$dir"/run/slurmd.pid "$dir"/run/slurmctld.pid "$munge_dir"/munged.pid; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$pidfile"
  done
}

if [ "$action" = stop ]; then stop; exit 0; fi
[ "$action" = start ] || { echo "usage: $0 start|stop DIR" >&2; exit 2; }

stop
rm -rf "$dir"
mkdir -p "$dir"/etc "$dir"/spool/ctld "$dir"/spool/d "$dir"/log "$dir"/run "$munge_dir" "$(dirname "$2")"
rm -rf "$2" && ln -s "$dir" "$2"
chown munge:munge "$munge_dir"
chmod 0755 "$munge_dir"
# The key Debian's munge package made at install; munged runs as its own user, never as root.
runuser -u munge -- munged --socket="$munge_dir/munge.socket" --pid-file="$munge_dir/munged.pid" \
  --log-file="$munge_dir/munged.log" --seed-file="$munge_dir/munged.seed" --key-file=/etc/munge/munge.key

# Ports other than Slurm's defaults (6817, 6818), chosen from this cluster's folder so that two test trees
# on one machine do not meet.
offset=$(( tag % 1000 * 2 ))
cat >"$dir/etc/slurm.conf" <<CONF
ClusterName=physltltest
SlurmctldHost=$host
SlurmctldPort=$((16000 + offset))
SlurmdPort=$((16001 + offset))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_dir/munge.socket
StateSaveLocation=$dir/spool/ctld
SlurmdSpoolDir=$dir/spool/d
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=campaign Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/etc/slurm.conf"
slurmctld
slurmd
for _ in $(seq 100); do
  if [ "$(sinfo -h -o %t 2>/dev/null)" = idle ]; then echo "$SLURM_CONF"; exit 0; fi
  sleep 0.2
done
echo "the node did not become idle; sinfo says: $(sinfo 2>&1)" >&2
tail -n 5 "$dir"/log/*.log >&2 || true
exit 1
