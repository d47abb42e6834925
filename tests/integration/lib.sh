# Shared helpers for the integration tests (sourced).
set -euo pipefail
BIN=${BIN:?BIN must point to the beverloo binary}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/beverloo-test.XXXXXX")
trap '[ -n "${KEEP_WORK:-}" ] && echo "kept $WORK" >&2 || rm -rf "$WORK"' EXIT  # KEEP_WORK=1: keep it for debugging
fail() { echo "FAIL: $*" >&2; exit 1; }
# The physics result of a run, to the last bit, without run statistics (wall time, list builds, resumes).
result_data() {
  local f=$1
  for g in /parameters /result /exits /rate /profile /clog_events; do
    h5dump -m %.17g -g "$g" "$f" | tail -n +2  # 17 digits: every bit of a double
  done
}
