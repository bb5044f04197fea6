# Shared by scripts/demo, scripts/test and scripts/bench: install the Debian 12 packages that are
# missing, and only those. Source it, then call `mink_need pkg...`.

mink_need() {
  local missing=()
  local pkg
  for pkg in "$@"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "mink: installing missing packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "mink: run as root or install: ${missing[*]}" >&2; return 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  # Refresh the package lists only when a first attempt cannot find a package.
  $sudo apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null 2>&1 ||
    { $sudo apt-get update -qq && $sudo apt-get install -y --no-install-recommends "${missing[@]}"; }
}

# What building the library, the tool and the tests needs.
MINK_BUILD_PACKAGES=(g++ cmake ninja-build libeigen3-dev libsimdjson-dev libcli11-dev libgtest-dev
  libcgal-dev libgmp-dev libmpfr-dev)
# What the benchmarks add: the peers.
MINK_BENCH_PACKAGES=(libbenchmark-dev libccd-dev libfcl-dev libbullet-dev libqhull-dev python3)

# Number of parallel build jobs.
mink_jobs() { nproc 2>/dev/null || echo 2; }
