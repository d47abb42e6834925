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
def splice(path, marker, block_file):
    """Replaces the text between <!-- MARKER:begin ... --> and <!-- MARKER:end --> in path."""
    text = open(path).read()
    block = open(block_file).read()
    pat = re.compile(r"(<!-- " + marker + r":begin[^>]*-->\n).*?(<!-- " + marker + r":end -->)", re.S)
    if not pat.search(text):
        sys.exit(path + ": " + marker + ":begin/end markers not found")
    text = pat.sub(lambda m: m.group(1) + block + m.group(2), text)
    open(path + ".tmp", "w").write(text); os.replace(path + ".tmp", path)
splice("docs/job-file.md", "parameters", sys.argv[2])
splice("docs/database.md", "results", sys.argv[3])
PY
rm -f /tmp/beverloo-defs.$$ /tmp/beverloo-md.$$ /tmp/beverloo-results.$$
echo "regenerated schema/sweep.schema.json \$defs, docs/job-file.md parameter block, docs/database.md result fields"
