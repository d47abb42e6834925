#!/bin/sh
# Rewrites the generated copies of the parameter table after a row of engine/parameters.cpp
# changed: the $defs of schema/sweep.schema.json and the block of docs/job-file.md between its
# parameters:begin / parameters:end markers; and the result-field table of docs/database.md
# (engine/protocol/result_fields.cpp) between its results:begin / results:end markers.
# Usage: scripts/regen-params.sh [BEVERLOO]   (default: build/cli/beverloo)
# tests/orchestrator/test_parameters.cpp fails until both match the table.
set -eu
cd "$(dirname "$0")/.."
bin=${1:-build/cli/beverloo}
"$bin" params --format schema-defs > /tmp/beverloo-defs.$$
"$bin" params --format markdown > /tmp/beverloo-md.$$
"$bin" params --results --format markdown > /tmp/beverloo-results.$$
python3 - /tmp/beverloo-defs.$$ /tmp/beverloo-md.$$ /tmp/beverloo-results.$$ <<'PY'
import json, re, sys
defs = json.load(open(sys.argv[1]))
schema_path = "schema/sweep.schema.json"
schema = json.load(open(schema_path))
schema.setdefault("$defs", {}).update(defs)
tmp = schema_path + ".tmp"
with open(tmp, "w") as f:
    json.dump(schema, f, indent=2)
    f.write("\n")
import os; os.replace(tmp, schema_path)
md_path = "docs/job-file.md"
md = open(md_path).read()
block = open(sys.argv[2]).read()
pat = re.compile(r"(<!-- parameters:begin[^>]*-->\n).*?(<!-- parameters:end -->)", re.S)
if not pat.search(md):
    sys.exit(md_path + ": parameters:begin/end markers not found")
md = pat.sub(lambda m: m.group(1) + block + m.group(2), md)
open(md_path + ".tmp", "w").write(md); os.replace(md_path + ".tmp", md_path)
db_path = "docs/database.md"
db = open(db_path).read()
block = open(sys.argv[3]).read()
pat = re.compile(r"(<!-- results:begin[^>]*-->\n).*?(<!-- results:end -->)", re.S)
if not pat.search(db):
    sys.exit(db_path + ": results:begin/end markers not found")
db = pat.sub(lambda m: m.group(1) + block + m.group(2), db)
open(db_path + ".tmp", "w").write(db); os.replace(db_path + ".tmp", db_path)
PY
rm -f /tmp/beverloo-defs.$$ /tmp/beverloo-md.$$ /tmp/beverloo-results.$$
echo "regenerated schema/sweep.schema.json \$defs, docs/job-file.md parameter block, docs/database.md result fields"
