#!/usr/bin/env bash
# Threads change no result: a job large enough for force blocks (N >= 1000) run by `simulate`
# with --threads 1 and 2 (and killed with 2, resumed with 1) gives the same result to the last
# bit; a campaign run with --threads 2 passes the count to its workers (spec.json) and stores
# the same Q as one run with 1; more threads than CPUs is refused before anything is written.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/job.json" <<'JOB'
{"dimension": 2, "N": 1200, "W": 30, "w": 5, "E_sp": 100, "zeta": 0.3, "mu": 1.0,
 "run": {"t_max": 25, "target_rel_err": 1e-9, "min_window": 5, "min_transient": 5, "rate_bin": 0.5, "checkpoint_interval": 2}}
JOB
# simulate JOB on 1 and 2 threads into DIR1 and DIR2; the results must be the same bits
same_on_one_and_two_threads() {
  local job=$1 one=$2 two=$3 what=$4
  "$BIN" simulate "$job" -o "$one" --threads 1 --progress quiet > /dev/null
  "$BIN" simulate "$job" -o "$two" --threads 2 --progress quiet > /dev/null
  diff <(result_data "$one/result.h5") <(result_data "$two/result.h5") > "$WORK/diff" \
    || { head -20 "$WORK/diff"; fail "$what: --threads 2 gives another result than --threads 1"; }
  echo "ok  $what simulate --threads 1 and 2: bit-identical result"
}
same_on_one_and_two_threads "$WORK/job.json" "$WORK/t1" "$WORK/t2" "SP"

# a DP job (engine 0.5.0: its force field in fixed chunks): the same bits on 1 and 2 threads
cat > "$WORK/dp.json" <<'JOB'
{"model": "dp_smooth", "N": 200, "W": 20, "w": 5, "zeta": 0, "mu": 8.5052, "mu_n": 0, "seed": 5,
 "dp": {"K_l": 88.29, "K_l_large": 123.62, "K_a": 3055.8, "K_a_large": 1559.1, "K_b": 0.02626, "wall_width": 1,
        "wall_thickness": 1, "E_c": 231.48, "E_c_vertex": 115.74, "contact_width": 0.2},
 "E_w": 11.574, "reinjection": {"rule": "lanes", "drop_depth_diameters": 2.5},
 "run": {"t_max": 3, "target_rel_err": 1e-9, "min_window": 1, "min_transient": 1, "rate_bin": 0.1}}
JOB
same_on_one_and_two_threads "$WORK/dp.json" "$WORK/dp1" "$WORK/dp2" "DP"

# interrupted with two threads, resumed with one
"$BIN" simulate "$WORK/job.json" -o "$WORK/mixed" --threads 2 --progress quiet > /dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do [ -f "$WORK/mixed/checkpoint.h5" ] && break; sleep 0.05; done
kill -TERM "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
"$BIN" simulate "$WORK/job.json" -o "$WORK/mixed" --resume --threads 1 --progress quiet > /dev/null
resumed=$(h5dump -a /run/resumed_times "$WORK/mixed/result.h5" | grep -o '(0): [0-9]*' | grep -o '[0-9]*$')
[ "$resumed" -ge 1 ] || fail "the run with 2 threads finished before it could be stopped; make the job longer"
diff <(result_data "$WORK/t1/result.h5") <(result_data "$WORK/mixed/result.h5") > /dev/null \
  || fail "a run stopped with 2 threads and resumed with 1 differs"
echo "ok  stopped with 2 threads, resumed with 1: bit-identical result"

# a campaign: the workers get the threads, the results are the same
cat > "$WORK/sweep.json" <<'SWEEP'
{"name": "threads", "base": {"dimension": 2, "N": 1200, "W": 30, "E_sp": 100, "zeta": 0.3, "mu": 1.0},
 "run": {"t_max": 15, "target_rel_err": 1e-9, "min_window": 5, "min_transient": 5, "rate_bin": 0.5},
 "sweep": {"w": [5]}}
SWEEP
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c1" --workers 1 --threads 1 --progress quiet > /dev/null 2>&1
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c2" --workers 1 --threads 2 --progress quiet > /dev/null 2>&1
grep -q '"threads": 2' "$WORK"/c2/jobs/*/spec.json || fail "the workers' spec.json does not carry --threads 2"
q1=$(sqlite3 "$WORK/c1/campaign.sqlite" "SELECT printf('%.17g', Q) FROM results")
q2=$(sqlite3 "$WORK/c2/campaign.sqlite" "SELECT printf('%.17g', Q) FROM results")
[ -n "$q1" ] && [ "$q1" = "$q2" ] || fail "campaign Q with 1 thread ($q1) and 2 threads ($q2) differ"
echo "ok  run --threads 2: spec.json carries it, Q identical ($q1)"

# more threads than CPUs: refused, nothing created
cpus=$(nproc)
set +e
msg=$("$BIN" run "$WORK/sweep.json" --dir "$WORK/c3" --threads $((cpus + 1)) 2>&1); rc=$?
set -e
[ "$rc" -eq 2 ] || fail "--threads beyond the CPUs: exit $rc, expected 2"
echo "$msg" | grep -q "exceed" || fail "--threads beyond the CPUs: no reason given ($msg)"
[ ! -e "$WORK/c3" ] || fail "--threads beyond the CPUs created the campaign directory"
echo "ok  --threads $((cpus + 1)) on $cpus CPUs: exit 2, nothing written"
