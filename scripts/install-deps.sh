#!/usr/bin/env bash
# Installs every Debian package beverloo needs to build, test and report.
# Idempotent: packages already present are skipped; safe to run as root on a fresh machine.
set -euo pipefail

PACKAGES=(
  g++ cmake ninja-build pkg-config        # toolchain
  libeigen3-dev                           # small fixed-size vectors
  nlohmann-json3-dev                      # job and sweep files
  libhdf5-dev hdf5-tools                  # results, checkpoints, trajectories; h5dump for users
  libgsl-dev                              # nonlinear fits (reports)
  libsqlite3-dev sqlite3                  # campaign store
  libcli11-dev                            # command line
  libgtest-dev googletest                 # tests
  libmuparser-dev                         # derived parameters and filters in sweep files
  libssl-dev                              # SHA-256 job keys (OpenSSL libcrypto)
  bc procps                               # tests: timing arithmetic, pgrep/pkill
  gnuplot-nox                             # figures
  python3-h5py python3-numpy              # tests read result files the way users do (h5py)
  chromium                                # tests open the report in a real headless browser
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# Node.js + npm run the JSON Schema test (ajv). This machine image ships Node.js with its own
# npm (NodeSource), which conflicts with Debian's npm package: install Debian's only if absent.
command -v node > /dev/null || missing+=(nodejs)
command -v npm > /dev/null || missing+=(npm)

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
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
