#!/usr/bin/env bash
# Every bad sweep file: exit 2, the message names the file, the JSON path, value and rule, and a campaign
# database in the target directory is left byte for byte as it was.
source "$(dirname "$0")/lib.sh"
DATA="$(dirname "$0")/../data/bad_sweeps"
cat > "$WORK/good.json" <<'J'
{"name": "good", "base": {"N": 50, "W": 12, "zeta": 0.3, "mu": 0}, "sweep": {"w": [3, 4]}}
J
"$BIN" campaign create "$WORK/good.json" --dir "$WORK/c" > /dev/null
before=$(sqlite3 "$WORK/c/campaign.sqlite" .dump | sha256sum)
files_before=$(cd "$WORK/c" && find . -type f | sort | sha256sum)
n=0
while IFS='|' read -r name verdict expect; do
  name=$(echo "$name" | xargs); expect=$(echo "$expect" | sed 's/^ *//; s/ *$//')
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  for cmd in "sweep check" "run"; do
    set +e
    if [ "$cmd" = "run" ]; then
      "$BIN" run "$DATA/$name.json" --dir "$WORK/c" --progress quiet > /dev/null 2> "$WORK/err"
    else
      "$BIN" sweep check "$DATA/$name.json" > /dev/null 2> "$WORK/err"
    fi
    rc=$?
    set -e
    [ "$rc" -eq 2 ] || fail "$name ($cmd): exit $rc, expected 2: $(cat "$WORK/err")"
    grep -qF -- "$expect" "$WORK/err" || fail "$name ($cmd): expected '$expect', got: $(cat "$WORK/err")"
    grep -qF -- "$DATA/$name.json: " "$WORK/err" || fail "$name ($cmd): the message does not name the file: $(cat "$WORK/err")"
  done
  n=$((n + 1))
done < "$DATA/expected_errors.txt"
[ "$n" -ge 20 ] || fail "only $n bad sweep files"
after=$(sqlite3 "$WORK/c/campaign.sqlite" .dump | sha256sum)
[ "$before" = "$after" ] || fail "a bad sweep changed the campaign database"
files_after=$(cd "$WORK/c" && find . -type f | sort | sha256sum)
[ "$files_before" = "$files_after" ] || fail "a bad sweep changed the campaign directory"
echo "ok  $n bad sweep files: exit 2 with path, value and rule; database untouched"
