#!/usr/bin/env bash
# beverloo query reads, and refuses every write, ATTACH and writing pragma, leaving the file as it was.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/s.json" <<'J'
{"name": "q", "base": {"N": 50, "W": 12, "zeta": 0.3, "mu": 0}, "sweep": {"w": [3, 4, 5]}}
J
"$BIN" campaign create "$WORK/s.json" --dir "$WORK/c" > /dev/null
before=$(sha256sum < "$WORK/c/campaign.sqlite")
out=$("$BIN" query "$WORK/c" "SELECT w, state FROM runs WHERE w > 3 ORDER BY w" --format csv)
[ "$out" = "$(printf 'w,state\n4,pending\n5,pending')" ] || fail "unexpected query output: $out"
"$BIN" query "$WORK/c" "SELECT count(*) AS n FROM jobs" --format json | grep -q '"n": 3' || fail "json format"
for sql in "INSERT INTO campaigns (name, sweep_json, sweep_sha256) VALUES ('x', '{}', 'y')" \
           "UPDATE jobs SET state = 'done'" "DELETE FROM jobs" "DROP TABLE results" "CREATE TABLE t (x)" \
           "ATTACH DATABASE '$WORK/other.sqlite' AS o" "PRAGMA user_version = 7" "PRAGMA journal_mode = DELETE" \
           "SELECT 1; DELETE FROM jobs" "VACUUM" "CREATE TEMP TABLE t (x)"; do
  set +e; "$BIN" query "$WORK/c" "$sql" > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
  [ "$rc" -ne 0 ] || fail "query accepted: $sql"
  [ ! -s "$WORK/out" ] || fail "query printed results before refusing: $sql"
  echo "ok  refused ($rc): $sql -- $(head -c 100 "$WORK/err")"
done
[ ! -e "$WORK/other.sqlite" ] || fail "ATTACH created a file"
after=$(sha256sum < "$WORK/c/campaign.sqlite")
[ "$before" = "$after" ] || fail "the database file changed"
"$BIN" query "$WORK/c" "PRAGMA user_version" > /dev/null || fail "reading a pragma must work"
echo "ok  query is read-only"
