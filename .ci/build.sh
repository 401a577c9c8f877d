# Shared by ./physltl-studio and tests/run: install missing Debian packages, then configure and build.
# Source it, then call `physltl_build BUILD_DIR TARGET [cmake options...]` (TARGET: one target, or all).
# The launcher and tests/run share one build folder, build/: the launcher builds the program, tests/run adds
# the test programs to the same tree, so nothing is compiled twice.

physltl_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

physltl_missing_packages() {
  local wanted
  wanted=$(grep -v -e '^#' -e '^$' "$physltl_root/.ci/debian-packages")
  # shellcheck disable=SC2086
  dpkg-query -W -f='${Package} ${db:Status-Status}\n' $wanted 2>/dev/null | awk '$2=="installed"{print $1}' \
    | sort >"${TMPDIR:-/tmp}/physltl-installed.$$"
  echo "$wanted" | sort | comm -23 - "${TMPDIR:-/tmp}/physltl-installed.$$"
  rm -f "${TMPDIR:-/tmp}/physltl-installed.$$"
}

physltl_ensure_packages() {
  local stamp="$1/.packages-ok" list="$physltl_root/.ci/debian-packages"
  # The package check costs ~50 ms; skip it while the list is unchanged since the last good check.
  if [ -f "$stamp" ] && [ "$stamp" -nt "$list" ]; then return 0; fi
  local missing
  missing=$(physltl_missing_packages | tr '\n' ' ')
  if [ -n "${missing// /}" ]; then
    if [ "$(id -u)" -ne 0 ]; then
      echo "physltl-studio needs these Debian packages: $missing" >&2
      echo "Install them with:  sudo apt-get install -y $missing" >&2
      return 2
    fi
    echo "Installing Debian packages: $missing" >&2
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing) >&2 || {
      echo "apt-get failed; install by hand: apt-get install -y $missing" >&2
      return 2
    }
  fi
  mkdir -p "$1" && touch "$stamp"
}

# Whether the build folder's cache already holds every -DNAME=VALUE option given.
physltl_configured_with() {
  local dir="$1" option name value
  shift
  [ -f "$dir/build.ninja" ] && [ -f "$dir/CMakeCache.txt" ] || return 1
  for option in "$@"; do
    case "$option" in
      -D*=*) name=${option#-D}; value=${name#*=}; name=${name%%=*}; name=${name%%:*}
             grep -qx -- "$name:[A-Z]*=$value" "$dir/CMakeCache.txt" || return 1 ;;
    esac
  done
}

physltl_build() {
  local dir="$1" target="$2" lock status
  shift 2
  physltl_ensure_packages "$dir" || return $?
  # One build at a time in a folder: a launcher and a tests/run started together take turns. The lock is
  # the kernel's (flock), so it goes with the process however that ends.
  exec {lock}>"$dir/.build-lock"
  if ! flock -n "$lock"; then
    echo "waiting for another build in $dir to finish" >&2
    flock "$lock"
  fi
  if ! physltl_configured_with "$dir" "$@"; then
    cmake -S "$physltl_root" -B "$dir" -G Ninja "$@" >&2 || { exec {lock}>&-; return 2; }
  fi
  # Ninja prints nothing useful on a no-op build; keep stdout for the program's own output.
  cmake --build "$dir" --target "$target" -- -j"$(nproc)" >"$dir/.last-build.log" 2>&1
  status=$?
  exec {lock}>&-
  if [ "$status" -ne 0 ]; then
    cat "$dir/.last-build.log" >&2
    return 2
  fi
}

# The options of the shared build/ folder: the same for the launcher and tests/run, so neither reconfigures
# what the other made.
physltl_shared_build_options=(-DPHYSLTL_BUILD_TESTS=ON)
# PHYSLTL_WERROR=1 (CI sets it): warnings are errors, for the launcher and tests/run alike, so that neither
# reconfigures the tree the other made.
if [ "${PHYSLTL_WERROR:-}" = 1 ]; then physltl_shared_build_options+=(-DPHYSLTL_WERROR=ON); fi
