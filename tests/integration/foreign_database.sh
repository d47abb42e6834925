#!/usr/bin/env bash
# A campaign.sqlite that belongs to another application is refused by every command that
# opens a campaign, and leaves with the bytes it came with (no WAL switch, no migration).
source "$(dirname "$0")/lib.sh"
mkdir -p "$WORK/d"
python3 -c "
import sqlite3, sys
c = sqlite3.connect(sys.argv[1]); c.execute('CREATE TABLE t (x)'); c.execute('INSERT INTO t VALUES (1)'); c.commit(); c.close()
" "$WORK/d/campaign.sqlite"
before=$(sha256sum < "$WORK/d/campaign.sqlite")
cat > "$WORK/s.json" <<'J'
{"name": "f", "base": {"N": 50, "W": 12, "zeta": 0.3, "mu": 0}, "sweep": {"w": [3, 4]}}
J
for cmd in "campaign status --dir $WORK/d" "query $WORK/d SELECT_1_AS_one" "fit $WORK/d" "report $WORK/d" \
           "run $WORK/s.json --dir $WORK/d --workers 1" "campaign create $WORK/s.json --dir $WORK/d" \
           "campaign cancel --dir $WORK/d" "campaign retry --dir $WORK/d"; do
  read -r -a args <<< "$cmd"
  for k in "${!args[@]}"; do  # the query's SQL is one argument
    if [[ ${args[$k]} == SELECT_* ]]; then args[$k]=${args[$k]//_/ }; fi
  done
  set +e; "$BIN" "${args[@]}" > "$WORK/out" 2> "$WORK/err"; rc=$?; set -e
  [ "$rc" -ne 0 ] || fail "$cmd accepted another application's database"
  grep -qi "another application\|not a beverloo campaign" "$WORK/err" || fail "$cmd: $(cat "$WORK/err")"
  [ "$before" = "$(sha256sum < "$WORK/d/campaign.sqlite")" ] || fail "$cmd changed the foreign database"
  echo "ok  $cmd refused ($rc): $(head -c 90 "$WORK/err")"
done
[ ! -e "$WORK/d/campaign.sqlite-wal" ] && [ ! -d "$WORK/d/jobs" ] || fail "files were added beside the foreign database"
echo "ok  another application's database is left as it was"
