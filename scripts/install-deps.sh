#!/usr/bin/env bash
# Installs the Debian packages beverloo needs. Usage: scripts/install-deps.sh [main|all]
#   main: what building beverloo and running a campaign with its report needs (the main job)
#   all (default): also what the test suite needs (GoogleTest, Python with h5py, a headless
#        browser, Node.js for the JSON Schema test, the shell tools the tests use)
# Idempotent: packages already present are skipped; safe to run as root on a fresh machine.
set -euo pipefail
MODE=${1:-all}
case "$MODE" in main|all) ;; *) echo "install-deps: unknown mode '$MODE' (main or all)" >&2; exit 2 ;; esac

PACKAGES=(
  g++ cmake ninja-build pkg-config        # toolchain
  libeigen3-dev                           # small fixed-size vectors
  nlohmann-json3-dev                      # job and sweep files
  libhdf5-dev                             # results, checkpoints, trajectories
  libgsl-dev                              # nonlinear fits (reports)
  libsqlite3-dev                          # campaign store
  libcli11-dev                            # command line
  libmuparser-dev                         # derived parameters and filters in sweep files
  libssl-dev                              # SHA-256 job keys (OpenSSL libcrypto)
  gnuplot-nox                             # figures
)
if [ "$MODE" = all ]; then
  PACKAGES+=(
    hdf5-tools sqlite3                    # h5dump and the sqlite3 shell (tests and users)
    libgtest-dev googletest               # tests
    bc procps                             # tests: timing arithmetic, pgrep/pkill
    python3-h5py python3-numpy            # tests read result files the way users do (h5py)
    chromium                              # tests open the report in a real headless browser
  )
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# Node.js + npm run the JSON Schema test (ajv). This machine image ships Node.js with its own
# npm (NodeSource), which conflicts with Debian's npm package: install Debian's only if absent.
if [ "$MODE" = all ]; then
  command -v node > /dev/null || missing+=(nodejs)
  command -v npm > /dev/null || missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present ($MODE)"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# apt's own output goes to a log; the terminal gets one line per step (and the log's end if a step fails)
LOG=${BEVERLOO_INSTALL_LOG:-$(cd "$(dirname "$0")/.." && pwd)/build/install-deps.log}
mkdir -p "$(dirname "$LOG")"
: > "$LOG"
step() {
  local what=$1; shift
  printf 'install-deps: %s ... ' "$what"
  if "$@" >> "$LOG" 2>&1; then
    echo ok
  else
    echo "FAILED (apt's output: $LOG)"
    tail -n 20 "$LOG" >&2
    exit 1
  fi
}
export DEBIAN_FRONTEND=noninteractive
step "updating the package lists" $SUDO apt-get update
step "installing ${#missing[@]} packages (${missing[*]})" $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
echo "install-deps: done (apt's output: $LOG)"
