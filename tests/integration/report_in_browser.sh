#!/usr/bin/env bash
# The report as a reader sees it: a small real campaign (both dissipation limits, w = 4..6),
# its report opened in Debian's headless Chromium (playwright-core, tests/browser/check_report.mjs)
# at a phone and a desktop width: every figure decodes, every link answers, no console error,
# nothing wider than the phone. Every SVG parses and every PNG decodes (tests/browser/check_files.py).
# The screenshots are kept in $ARTEFACT_DIR (default build/test-artefacts/).
source "$(dirname "$0")/lib.sh"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
ARTEFACT_DIR=${ARTEFACT_DIR:-$ROOT/build/test-artefacts}
NODE_DIR=${BEVERLOO_BROWSER_NODE_DIR:-$ROOT/build/browser-node}
[ -x /usr/bin/chromium ] || fail "Debian's chromium is not installed (scripts/install-deps.sh installs it)"
mkdir -p "$ARTEFACT_DIR" "$NODE_DIR"
cp "$ROOT/tests/browser/package.json" "$ROOT/tests/browser/check_report.mjs" "$NODE_DIR/"
if [ ! -d "$NODE_DIR/node_modules/playwright-core" ]; then
  (cd "$NODE_DIR" && npm install --no-audit --no-fund --silent > /dev/null) || fail "npm install playwright-core failed"
fi
cat > "$WORK/sweep.json" <<'JSON'
{"name": "browser_check",
 "base": {"dimension": 2, "N": 300, "W": 16},
 "run": {"t_max": 60, "min_window": 15, "min_transient": 5, "target_rel_err": 0.05},
 "sweep": {"product": [{"lambda": [0, "inf"]}, {"w": [4, 5, 6]}]}}
JSON
"$BIN" run "$WORK/sweep.json" --dir "$WORK/c" --workers 2 --progress quiet > "$WORK/run.log" 2>&1 || { cat "$WORK/run.log"; fail "the campaign failed"; }
[ -f "$WORK/c/report/index.html" ] || fail "no report/index.html"
python3 "$ROOT/tests/browser/check_files.py" "$WORK/c/report" || fail "a figure file is not valid"
node "$NODE_DIR/check_report.mjs" "$WORK/c/report" "$ARTEFACT_DIR" || fail "the report does not render cleanly in Chromium"
cp "$WORK/c/report/index.html" "$ARTEFACT_DIR/report-index.html"
echo "ok  report checked in Chromium; screenshots in $ARTEFACT_DIR"
