#!/usr/bin/env bash
# The two README commands share one build: the launcher builds the program in build/, tests/run adds the
# tests to the same folder, and when both start at once the second build waits for the first; tests/run
# --sanitize keeps its own folder. Runs the real launcher and tests/run of SOURCE_DIR on a copy, with
# stand-ins for cmake and ctest that record which folder and target each build used, and when.
#   shared_build_test.sh SOURCE_DIR
set -eu
source_dir=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
root=$tmp/clone
mkdir -p "$root/.ci" "$root/tests" "$tmp/bin"
cp "$source_dir/physltl-studio" "$root/"
cp "$source_dir/tests/run" "$root/tests/"
cp "$source_dir/.ci/build.sh" "$source_dir/.ci/debian-packages" "$root/.ci/"
for dir in build build-sanitize; do
  mkdir -p "$root/$dir"
  touch "$root/$dir/.packages-ok"  # newer than the package list: no dpkg query
done
log=$tmp/log
cat >"$tmp/bin/cmake" <<'STUB'
#!/usr/bin/env bash
if [ "$1" = "-S" ]; then  # cmake -S SOURCE -B DIR -G Ninja OPTIONS...
  dir=$4
  shift 6
  echo "configure $dir" >>"$STUB_LOG"
  touch "$dir/build.ninja"
  for option in "$@"; do
    option=${option#-D}
    echo "${option%%=*}:STRING=${option#*=}" >>"$dir/CMakeCache.txt"
  done
elif [ "$1" = "--build" ]; then  # cmake --build DIR --target TARGET -- -jN
  echo "start $2 $4 $(date +%s.%N)" >>"$STUB_LOG"
  sleep 1
  printf '#!/bin/sh\necho "program ran: $*"\n' >"$2/physltl-studio"
  chmod +x "$2/physltl-studio"
  echo "end $2 $4 $(date +%s.%N)" >>"$STUB_LOG"
fi
STUB
printf '#!/bin/sh\necho "ctest in $PWD" >>"$STUB_LOG"\n' >"$tmp/bin/ctest"
chmod +x "$tmp/bin/cmake" "$tmp/bin/ctest"
export PATH="$tmp/bin:$PATH" STUB_LOG=$log

fail() { echo "FAILED: $*" >&2; echo "--- log:" >&2; cat "$log" >&2; exit 1; }

"$root/physltl-studio" --version >"$tmp/launcher.out" 2>"$tmp/launcher.err" &
launcher=$!
"$root/tests/run" >"$tmp/tests.out" 2>"$tmp/tests.err" &
tests=$!
wait "$launcher" || fail "the launcher exited with $?"
wait "$tests" || fail "tests/run exited with $?"

grep -q "program ran: --version" "$tmp/launcher.out" || fail "the launcher did not run build/physltl-studio"
[ "$(grep -c '^start' "$log")" = 2 ] || fail "expected two builds"
grep -q "^start $root/build physltl-studio " "$log" || fail "the launcher did not build only physltl-studio in build/"
grep -q "^start $root/build all " "$log" || fail "tests/run did not build everything in build/"
grep -q "^ctest in $root/build$" "$log" || fail "tests/run did not run ctest in build/"
[ "$(grep -c '^configure' "$log")" = 1 ] || fail "build/ was configured more than once"
# The builds took turns: the second started after the first ended.
awk '$1 == "start" { start[n++] = $4 } $1 == "end" { end[m++] = $4 }
     END { exit !(n == 2 && m == 2 && (start[1] >= end[0] || start[0] >= end[1])) }' "$log" ||
  fail "the two builds overlapped"

: >"$log"
"$root/tests/run" --sanitize >/dev/null 2>&1 || fail "tests/run --sanitize exited with $?"
grep -q "^start $root/build-sanitize all " "$log" || fail "tests/run --sanitize did not build in build-sanitize/"
echo "ok: one serialised build in build/, the sanitizer's in build-sanitize/"
