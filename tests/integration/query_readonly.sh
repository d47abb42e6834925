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
# introspection pragmas, also as table-valued functions, are reads
"$BIN" query "$WORK/c" "PRAGMA table_info(jobs)" --format csv | grep -q '^0,key,' || fail "PRAGMA table_info(jobs)"
"$BIN" query "$WORK/c" "SELECT name FROM pragma_table_info('runs') WHERE name = 'Q'" --format csv | grep -qx 'Q' \
  || fail "pragma_table_info('runs')"
set +e; "$BIN" query "$WORK/c" "UPDATE sqlite_master SET type = 'x'" > /dev/null 2>&1; rc=$?; set -e
[ "$rc" -ne 0 ] || fail "a write of sqlite_master was accepted"
# a query without end stops at its time limit, and one with too many rows is refused; nothing printed
endless="WITH RECURSIVE c(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM c) SELECT count(*) FROM c"
set +e; timeout 60 "$BIN" query "$WORK/c" "$endless" --max-seconds 1 > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] || fail "an endless recursive CTE: exit $rc, expected 2 ($(cat "$WORK/err"))"
[ ! -s "$WORK/out" ] && grep -q "max-seconds" "$WORK/err" || fail "the time limit is not named"
set +e; "$BIN" query "$WORK/c" "WITH RECURSIVE c(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM c) SELECT x FROM c" \
  --max-rows 100 > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
[ "$rc" -eq 2 ] && [ ! -s "$WORK/out" ] && grep -q "max-rows" "$WORK/err" || fail "endless rows: exit $rc"
# JSON output of values JSON cannot hold as such: a denormal, bytes that are not UTF-8, a blob
"$BIN" query "$WORK/c" "SELECT 4.9e-324 AS d, CAST(x'ff41' AS TEXT) AS t, x'00ff' AS b" --format json > "$WORK/j" \
  || fail "json output of a denormal / non-UTF-8 text"
python3 -c "import json,sys; r=json.load(open(sys.argv[1]))[0]; assert r['d'] > 0 and r['b'] == \"x'00ff'\", r" "$WORK/j" \
  || fail "json output is not valid JSON with the values: $(cat "$WORK/j")"
# a campaign in a directory its reader cannot write (as another user: root writes anywhere)
if [ "$(id -u)" = 0 ] && id nobody > /dev/null 2>&1 && command -v su > /dev/null; then
  cp "$BIN" "$WORK/bin" && chmod a+rx "$WORK" "$WORK/bin" && chmod -R a+rX "$WORK/c" && chmod a-w "$WORK/c"
  su nobody -s /bin/sh -c "'$WORK/bin' query '$WORK/c' 'SELECT count(*) AS n FROM jobs' --format csv" > "$WORK/ro" 2>&1 \
    || fail "query in a read-only campaign directory: $(cat "$WORK/ro")"
  grep -qx 3 "$WORK/ro" || fail "query in a read-only directory printed: $(cat "$WORK/ro")"
  su nobody -s /bin/sh -c "'$WORK/bin' campaign status --dir '$WORK/c'" > "$WORK/ro" 2>&1 \
    || fail "campaign status in a read-only campaign directory: $(cat "$WORK/ro")"
  chmod u+w "$WORK/c"
  echo "ok  a read-only campaign directory can be queried"
fi
echo "ok  query is read-only"
