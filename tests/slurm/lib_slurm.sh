# Helpers for the tests against the real one-node Slurm (scripts/slurm-ci.sh start must have run).
source "$(dirname "$0")/../integration/lib.sh"
results() {  # every result, to the last bit, in key order
  sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g|%!.17g', Q, Q_err, rho_n), exits_total, steps
                               FROM results ORDER BY job_key"
}
q() { sqlite3 "$1/campaign.sqlite" "$2"; }
# waits until the predicate command succeeds, at most $1 seconds
wait_until() {
  local limit=$1; shift
  local t0=$SECONDS
  until "$@"; do
    [ $((SECONDS - t0)) -lt "$limit" ] || return 1
    sleep 0.2
  done
}
task_state() {  # task_state ARRAY_TASK -> PENDING / RUNNING / ... (empty if unknown)
  squeue --noheader --array --states=all --jobs="${1%_*}" --format='%i %T' 2>/dev/null | awk -v t="$1" '$1 == t {print $2}'
}
