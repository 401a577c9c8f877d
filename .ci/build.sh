# Shared by ./physltl-studio and tests/run: install missing Debian packages, then configure and build.
# Source it, then call `physltl_build BUILD_DIR [cmake options...]`.

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

physltl_build() {
  local dir="$1"
  shift
  physltl_ensure_packages "$dir" || return $?
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S "$physltl_root" -B "$dir" -G Ninja "$@" >&2 || return 2
  elif [ $# -gt 0 ]; then
    cmake "$dir" "$@" >/dev/null || return 2
  fi
  # Ninja prints nothing useful on a no-op build; keep stdout for the program's own output.
  cmake --build "$dir" -- -j"$(nproc)" >"$dir/.last-build.log" 2>&1 || {
    cat "$dir/.last-build.log" >&2
    return 2
  }
}
