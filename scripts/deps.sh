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

# Like mink_need, but only warns when the packages cannot be installed: for what adds to the build
# or the tests without being required (without node and npm the tool is built without the page of
# `mink view`; without Chromium the viewer test reports itself skipped).
mink_want() {
  mink_need "$@" || echo "mink: warning: could not install $*; going on without" >&2
}

# Pairs of a command and the Debian package that provides it: mink_want the packages of the
# commands that are missing. A command found elsewhere is kept (NodeSource's nodejs, for one,
# bundles npm and conflicts with Debian's npm package).
mink_want_commands() {
  local packages=()
  while [ $# -ge 2 ]; do
    command -v "$1" >/dev/null 2>&1 || packages+=("$2")
    shift 2
  done
  [ ${#packages[@]} -eq 0 ] || mink_want "${packages[@]}"
}

# What building the library, the tool and the tests needs.
MINK_BUILD_PACKAGES=(g++ clang cmake ninja-build libeigen3-dev libsimdjson-dev libcli11-dev libgtest-dev
  libcgal-dev libgmp-dev libmpfr-dev)
# What the page of `mink view` needs at build time (three.js from npm), and what its test opens it
# in (tests/viewer): command, package pairs for mink_want_commands.
MINK_VIEWER_COMMANDS=(node nodejs npm npm)
MINK_BROWSER_COMMANDS=(chromium chromium)
# What the benchmarks add: the peers.
MINK_BENCH_PACKAGES=(libbenchmark-dev libccd-dev libfcl-dev libbullet-dev libqhull-dev python3)

# The compiler of scripts/test and scripts/demo (build/release): Clang, unless CXX names another.
# Clang 14 compiles mink's template-heavy query files and tests two to three times faster than
# GCC 12 (a query file for every pair of shapes at -O3: 130 s against 243 s; the static-type
# property tests at -O0: 29 s against 86 s), which keeps CI within its time. GCC still builds a
# user's program against the installed package in the tests (tests/package), and scripts/bench
# builds with the default compiler, as the peers' packages are.
mink_cxx() { echo "${CXX:-clang++}"; }

# Number of parallel build jobs.
mink_jobs() { nproc 2>/dev/null || echo 2; }
