#!/bin/bash
# The quickstart campaign (paper Fig. 2, 14 jobs) with two binaries one after the other: wall
# time, engine time and its transient, steps, the fitted exponents, and how far apart the 14 Q
# are (combined standard errors). For an engine change that alters the order of sums: Q must
# agree within errors. Usage: bench/quickstart_compare.sh OLD_BINARY NEW_BINARY [WORKDIR]
set -eu
OLD=$1 NEW=$2 WORK=${3:-$(mktemp -d)}
mkdir -p "$WORK"
here=$(cd "$(dirname "$0")/.." && pwd)
for tag in old new; do
  bin=$OLD; [ $tag = new ] && bin=$NEW
  rm -rf "$WORK/$tag"
  s=$(date +%s.%N)
  "$bin" run "$here/sweeps/quickstart.json" --dir "$WORK/$tag" --workers 2 --progress quiet > "$WORK/$tag.log" 2>&1
  e=$(date +%s.%N)
  db=$WORK/$tag/campaign.sqlite
  echo "$tag: wall $(awk -v a="$s" -v b="$e" 'BEGIN{printf "%.1f", b-a}') s; engine $(sqlite3 "$db" "SELECT printf('%.1f', sum(wall_seconds)) FROM results") s;" \
       "transient $(sqlite3 "$db" "SELECT printf('%.1f', sum(window_start / dt * 1600 / particle_steps_per_second)) FROM results") s;" \
       "steps $(sqlite3 "$db" "SELECT printf('%.3g', sum(steps)) FROM results"); statuses $(sqlite3 "$db" "SELECT group_concat(DISTINCT status) FROM results")"
  sqlite3 "$db" "SELECT printf('  beta %.3f +- %.3f', beta, beta_err) FROM beverloo_fit_results ORDER BY beta DESC"
done
sqlite3 "$WORK/new/campaign.sqlite" "ATTACH '$WORK/old/campaign.sqlite' AS o;
  SELECT printf('Q new against old: max |z| %.2f, chi^2 %.1f for %d points', max(abs(z)), sum(z * z), count(*))
  FROM (SELECT (n.Q - p.Q) / sqrt(n.Q_err * n.Q_err + p.Q_err * p.Q_err) AS z FROM runs n JOIN o.runs p ON n.w = p.w AND n.mu = p.mu)"
