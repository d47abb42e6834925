#!/usr/bin/env bash
# The JSON Schema (schema/sweep.schema.json, checked by ajv) and beverloo agree: every shipped
# sweep is valid for both; every bad file that the schema rejects, beverloo rejects; the files
# marked "semantic" pass the schema and only beverloo's own checks catch them.
source "$(dirname "$0")/lib.sh"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
NODE_DIR=${BEVERLOO_NODE_DIR:-$ROOT/build/schema-node}
mkdir -p "$NODE_DIR"
cp "$ROOT/tests/schema/package.json" "$ROOT/tests/schema/validate.mjs" "$NODE_DIR/"
if [ ! -d "$NODE_DIR/node_modules/ajv" ]; then
  (cd "$NODE_DIR" && npm install --no-audit --no-fund --silent > /dev/null) || fail "npm install ajv failed"
fi
node "$NODE_DIR/validate.mjs" "$ROOT/schema/sweep.schema.json" "$ROOT"/sweeps/*.json "$ROOT"/tests/data/bad_sweeps/*.json > "$WORK/ajv"
for f in "$ROOT"/sweeps/*.json; do
  grep -q "^$f valid" "$WORK/ajv" || fail "ajv rejects shipped $(basename "$f"): $(grep "^$f" "$WORK/ajv")"
  "$BIN" sweep check "$f" > /dev/null || fail "beverloo rejects shipped $(basename "$f")"
done
while IFS='|' read -r name verdict expect; do
  name=$(echo "$name" | xargs); verdict=$(echo "$verdict" | xargs)
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  f="$ROOT/tests/data/bad_sweeps/$name.json"
  if [ "$verdict" = invalid ]; then
    grep -q "^$f invalid" "$WORK/ajv" || fail "$name: the schema accepts a file it should reject"
  else
    grep -q "^$f valid" "$WORK/ajv" || fail "$name: marked semantic but the schema rejects it: $(grep "^$f" "$WORK/ajv")"
  fi
  if "$BIN" sweep check "$f" > /dev/null 2>&1; then fail "$name: beverloo accepts a bad file"; fi
done < "$ROOT/tests/data/bad_sweeps/expected_errors.txt"
echo "ok  ajv and beverloo agree on $(ls "$ROOT"/sweeps/*.json | wc -l) shipped and $(ls "$ROOT"/tests/data/bad_sweeps/*.json | wc -l) bad sweep files"
