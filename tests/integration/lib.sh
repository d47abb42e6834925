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
# Kill loops back off when the machine is too slow for their delays: a round in which no
# checkpoint or result was written (everything was killed before its first checkpoint, as on a
# loaded machine where a coordinator takes longer to start than the delay) doubles the next
# round's delay, up to 64 times; a round that wrote one resets it. On a quiet machine every round
# progresses and the delays are what the test chose. Usage: kill_round_begin before starting the
# coordinator, sleep_backed_off MS for each sleep, kill_round_end DIR after it is killed.
stalled_rounds=0
kill_round_begin() { touch "$WORK/kill_round.marker"; }
kill_round_end() {
  if [ -n "$(find "$1" -newer "$WORK/kill_round.marker" \( -name checkpoint.h5 -o -name result.h5 \) -print -quit 2> /dev/null)" ]; then
    stalled_rounds=0
  elif [ "$stalled_rounds" -lt 6 ]; then
    stalled_rounds=$((stalled_rounds + 1))
  fi
}
sleep_backed_off() {
  local ms=$(($1 << stalled_rounds))
  sleep "$((ms / 1000)).$(printf '%03d' $((ms % 1000)))"
}
# Runs `beverloo run SWEEP --dir DIR --workers 2` until it finishes, SIGKILLing the coordinator
# after a random delay of BASE_MS .. BASE_MS + DELAY_MS ms (usage: run_with_kills SWEEP DIR
# DELAY_MS [BASE_MS, default 300]) each round and, every other round on average,
# one of its workers first; the delay backs off while rounds make no progress (above). Sets
# `rounds` and `kills`; fails after 200 rounds. Uses $RANDOM (seed it first) and appends the
# coordinators' stderr to $WORK/chaos.log.
run_with_kills() {
  local sweep=$1 dir=$2 delay_ms=$3 base_ms=${4:-300} coord pid rc
  rounds=0 kills=0
  while :; do
    rounds=$((rounds + 1))
    [ "$rounds" -le 200 ] || fail "$dir: no completion after 200 rounds"
    kill_round_begin
    "$BIN" run "$sweep" --dir "$dir" --workers 2 --progress quiet 2>> "$WORK/chaos.log" &
    coord=$!
    sleep_backed_off $((RANDOM % delay_ms + base_ms))
    if [ $((RANDOM % 2)) -eq 0 ]; then
      pid=$(pgrep -f "worker $dir" | head -n 1 || true)
      [ -n "$pid" ] && kill -9 "$pid" 2>/dev/null || true
    fi
    if kill -9 "$coord" 2>/dev/null; then kills=$((kills + 1)); fi
    set +e; { wait "$coord"; } 2>/dev/null; rc=$?; set -e
    [ "$rc" -eq 0 ] && break
    kill_round_end "$dir"
  done
  pkill -9 -f "worker $dir" 2>/dev/null || true
}
# `beverloo run BAD.json` must exit 2 with a message naming FIELD and create no campaign in
# $WORK/bad. Usage: refused_without_writing BAD.json FIELD WHAT (WHAT: for the failure message).
refused_without_writing() {
  local bad=$1 field=$2 what=$3 rc
  set +e; "$BIN" run "$bad" --dir "$WORK/bad" --progress quiet 2> "$WORK/err"; rc=$?; set -e
  [ "$rc" -eq 2 ] || fail "$what: exit $rc, expected 2"
  grep -q "$field" "$WORK/err" || fail "$what: message does not name $field: $(cat "$WORK/err")"
  [ ! -e "$WORK/bad/campaign.sqlite" ] || fail "$what: a campaign was created"
}
