# Shared helpers for the integration tests (sourced).
set -euo pipefail
BIN=${BIN:?BIN must point to the beverloo binary}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/beverloo-test.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# The physics result of a run, to the last bit, without run statistics (wall time, list builds, resumes).
result_data() {
  local f=$1
  for g in /parameters /result /exits /rate /profile /clog_events; do
    h5dump -m %.17g -g "$g" "$f" | tail -n +2  # 17 digits: every bit of a double
  done
}
