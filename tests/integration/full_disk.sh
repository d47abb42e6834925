#!/usr/bin/env bash
# A disk that fills mid-campaign (issue 31.9): the campaign directory on a small tmpfs. The
# coordinator stops with the I/O exit code (4) and says so; the database passes SQLite's
# integrity check; no temporary file is left behind; no job is charged a retry for it (a
# worker's write that failed for want of room is disk_full, free, and stops the claims). Given room again, the same command
# finishes the campaign: every job done once, results bit-identical to a campaign that never
# lacked room. Needs root (mount); skipped (exit 77) without it.
source "$(dirname "$0")/lib.sh"
DISK=$WORK/disk
mkdir -p "$DISK"
mount -t tmpfs -o size=1500k tmpfs "$DISK" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs (not root?)"; exit 77; }
trap 'while mountpoint -q "$DISK"; do umount "$DISK" 2>/dev/null || umount -l "$DISK"; done; rm -rf "$WORK"' EXIT
cat > "$WORK/sweep.json" <<'J'
{"name": "full-disk",
 "base": {"N": 300, "W": 12, "E_sp": 100},
 "run": {"t_max": 200, "target_rel_err": 1e-9, "min_window": 20, "checkpoint_interval": 2},
 "sweep": {"product": [{"lambda": [0.1, "inf"]}, {"w": [3, 4, 5, 6]}]}}
J
# One flow on file systems too small for its files: it ends with exit 0 or 4 (never a signal:
# HDF5's clean-up at exit crashed after a failed write) and leaves no file under its own name
# that cannot be read (a checkpoint whose flush failed was committed before 2026-12-04). Given
# room, the same flow resumed gives the result of a run that never lacked room, bit for bit (a
# checkpoint whose dataset's data failed to reach the disk at H5Dclose was committed with zeros
# in its velocity profile before 2026-12-07; integration.full_disk caught it once in CI).
echo '{"N": 300, "W": 12, "E_sp": 100, "w": 4, "zeta": 0.3, "mu": 0, "run": {"t_max": 200, "target_rel_err": 1e-9, "min_window": 20, "checkpoint_interval": 2}}' > "$WORK/one.json"
"$BIN" simulate "$WORK/one.json" -o "$WORK/one_roomy" --progress quiet > /dev/null 2>&1 || fail "the flow failed with room"
reference=$(result_data "$WORK/one_roomy/result.h5")
SMALL=$WORK/small
mkdir -p "$SMALL"
for size in 40k 80k 100k 120k 140k 150k 160k 170k 180k 250k; do
  mount -t tmpfs -o size=$size tmpfs "$SMALL"
  set +e; "$BIN" simulate "$WORK/one.json" -o "$SMALL/o" --progress quiet > /dev/null 2> "$WORK/small.err"; rc=$?; set -e
  for f in "$SMALL"/o/checkpoint.h5 "$SMALL"/o/result.h5; do
    [ ! -f "$f" ] || h5dump -H "$f" > /dev/null 2>&1 || { umount "$SMALL"; fail "$size: $(basename "$f") committed but unreadable (exit $rc)"; }
  done
  [ "$rc" -eq 0 ] || [ "$rc" -eq 4 ] || { umount "$SMALL"; fail "$size: simulate ended with $rc, expected 0 or 4: $(tail -1 "$WORK/small.err")"; }
  mount -o remount,size=64M "$SMALL"
  "$BIN" simulate "$WORK/one.json" -o "$SMALL/o" --resume --progress quiet > /dev/null 2> "$WORK/small_resume.err" ||
    { umount "$SMALL"; fail "$size: resuming with room failed: $(tail -1 "$WORK/small_resume.err")"; }
  [ "$(result_data "$SMALL/o/result.h5")" = "$reference" ] ||
    { umount "$SMALL"; fail "$size (exit $rc: $(tail -c 200 "$WORK/small.err")): resumed with room, the result differs from the run that never lacked room"; }
  umount "$SMALL"
done
echo "ok  one flow on file systems of 40k .. 250k: exit 0 or 4, no unreadable file committed, resumed with room bit-identical"

results() { sqlite3 "$1/campaign.sqlite" "SELECT job_key, status, printf('%!.17g|%!.17g', Q, Q_err), steps FROM results ORDER BY job_key"; }
"$BIN" run "$WORK/sweep.json" --dir "$WORK/clean" --workers 2 --progress quiet 2> /dev/null
clean=$(results "$WORK/clean")

set +e; "$BIN" run "$WORK/sweep.json" --dir "$DISK/c" --workers 2 --progress log 2> "$WORK/full.log"; rc=$?; set -e
[ "$rc" -eq 4 ] || { tail "$WORK/full.log"; fail "a full disk: exit $rc, expected 4 (I/O)"; }
grep -q "disk is full" "$WORK/full.log" || fail "the coordinator did not say the disk is full: $(tail -2 "$WORK/full.log")"
done_before=$(sqlite3 "$DISK/c/campaign.sqlite" "SELECT count(*) FROM jobs WHERE state = 'done'")
[ "$done_before" -lt 8 ] || fail "the disk never filled (all 8 jobs done): make the tmpfs smaller"
wait_workers() { for _ in $(seq 100); do pgrep -f "worker $DISK" > /dev/null || return 0; sleep 0.1; done; }
wait_workers  # a worker outlives its coordinator until its own write fails or it ends
[ "$(sqlite3 "$DISK/c/campaign.sqlite" "PRAGMA integrity_check")" = ok ] || fail "the database is damaged"
# no worker crashed on the way out (HDF5's clean-up at exit after a failed write: cli/main.cpp)
crashed=$(sqlite3 "$DISK/c/campaign.sqlite" "SELECT count(*) FROM attempts WHERE message LIKE '%killed by signal%'")
[ "$crashed" -eq 0 ] || fail "$crashed worker(s) died of a signal on the full disk"
# a write that failed for want of room is disk_full, not io: no job paid from its retry budget
charged=$(sqlite3 "$DISK/c/campaign.sqlite" "SELECT count(*) FROM jobs WHERE retries_used > 0")
[ "$charged" -eq 0 ] || fail "$charged job(s) charged a retry for the full disk: $(sqlite3 "$DISK/c/campaign.sqlite" "SELECT failure_class, message FROM attempts WHERE failure_class IS NOT NULL LIMIT 3")"
left=$(find "$DISK" -name '*.tmp*' | head -3)
[ -z "$left" ] || fail "temporary files left on the full disk: $left"
echo "ok  disk full with $done_before of 8 jobs done: exit 4, the database intact, no temporary file left"

mount -o remount,size=64M "$DISK"
"$BIN" run "$WORK/sweep.json" --dir "$DISK/c" --workers 2 --progress quiet 2> "$WORK/after.log" || { tail "$WORK/after.log"; fail "the campaign did not finish once there was room"; }
after=$(results "$DISK/c")
[ "$after" = "$clean" ] || { diff <(echo "$clean") <(echo "$after") >&2 || true
  sqlite3 "$DISK/c/campaign.sqlite" "SELECT job_key, state, failure_class, message FROM attempts ORDER BY id" >&2
  fail "results differ from the campaign that never lacked room (above: < without, > after the full disk)"; }
[ "$(sqlite3 "$DISK/c/campaign.sqlite" "SELECT count(*) FROM attempts WHERE state = 'succeeded'")" -eq 8 ] || fail "a job succeeded twice"
[ "$(sqlite3 "$DISK/c/campaign.sqlite" "SELECT count(*) FROM jobs WHERE state <> 'done'")" -eq 0 ] || fail "jobs not done"
left=$(find "$DISK" -name '*.tmp*' | head -3)
[ -z "$left" ] || fail "temporary files left: $left"
echo "ok  given room, the same command finished the campaign: every job once, results bit-identical"
