#!/bin/bash
# Are two beverloo binaries' results identical? Runs one short job per model (SP 2D, SP 2D in
# two force blocks (N = 1600, friction; and drag only), SP 3D,
# smooth DP, rough DP, smooth DP with the authors' corrected set through the orifice, rough DP
# with that set, friction only and a thick floor, rough DP with that set and drag only, and the
# authors' SP options with the lanes rule) with each binary and
# compares result.h5 (h5dump at 17 digits: every dataset and attribute, /parameters by the
# attributes both files have, since a newer binary writes every parameter row there; the timing attributes
# wall_seconds and particle_steps_per_second aside, and the engine_version and dt_limiting_term labels) and summary.json
# (timing fields aside). A field that only the new binary writes is named and left out.
# Usage: bench/result_identity.sh OLD_BINARY NEW_BINARY [WORKDIR]
# For refactorings that must change nothing (issue 14.6); exit 0 if all are identical.
set -euo pipefail
OLD=$1 NEW=$2 WORK=${3:-$(mktemp -d)}
mkdir -p "$WORK"
declare -A JOBS=(
  [sp2d]='{"dimension": 2, "N": 300, "W": 16, "w": 5, "zeta": 0.5, "mu": 0, "seed": 3, "run": {"t_max": 30, "min_window": 10, "min_transient": 5}}'
  [sp2d_blocks]='{"dimension": 2, "N": 1600, "W": 40, "w": 6, "zeta": 0, "mu": 31.6227766, "seed": 3, "run": {"t_max": 12, "min_window": 4, "min_transient": 3, "rate_bin": 0.5}}'
  [sp2d_blocks_drag]='{"dimension": 2, "N": 1600, "W": 40, "w": 6, "zeta": 0.316227766, "mu": 0, "seed": 3, "run": {"t_max": 10, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [sp3d]='{"dimension": 3, "N": 600, "W": 9, "w": 4, "zeta": 0, "mu": 10, "seed": 3, "run": {"t_max": 15, "min_window": 5, "min_transient": 3, "rate_bin": 0.5}}'
  [dp_smooth]='{"model": "dp_smooth", "N": 40, "W": 10, "w": 4, "zeta": 0.5, "mu": 0, "seed": 3, "run": {"t_max": 8, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [dp_rough]='{"model": "dp_rough", "N": 40, "W": 10, "w": 4, "zeta": 0, "mu": 2, "seed": 3, "run": {"t_max": 8, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [dp_smooth_authors]='{"model": "dp_smooth", "N": 120, "W": 14, "w": 4, "zeta": 0, "mu": 0, "drag_rate": 1.95959, "dp": {"K_l": 88.29, "K_l_large": 123.62, "K_a": 3055.8, "K_a_large": 1559.1, "K_b": 0.02626, "wall_width": 1, "E_c": 231.48, "E_c_vertex": 115.74, "contact_width": 0.2}, "E_w": 11.574, "reinjection": {"rule": "lanes", "drop_depth_diameters": 2.5}, "seed": 3, "run": {"t_max": 8, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [dp_rough_authors_thick]='{"model": "dp_rough", "N": 120, "W": 14, "w": 4, "zeta": 0, "mu": 8.5052, "mu_n": 0, "dp": {"K_l": 88.29, "K_l_large": 123.62, "K_a": 3055.8, "K_a_large": 1559.1, "K_b": 2.626, "wall_width": 1, "wall_thickness": 1, "E_c": 115.74}, "E_w": 11.574, "reinjection": {"rule": "lanes", "drop_depth_diameters": 2.5}, "seed": 3, "run": {"t_max": 8, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [dp_rough_authors_drag]='{"model": "dp_rough", "N": 120, "W": 14, "w": 4, "zeta": 0, "mu": 0, "drag_rate": 1.95959, "dp": {"K_l": 88.29, "K_l_large": 123.62, "K_a": 3055.8, "K_a_large": 1559.1, "K_b": 2.626, "wall_width": 1, "wall_thickness": 1, "E_c": 115.74}, "E_w": 11.574, "reinjection": {"rule": "lanes", "drop_depth_diameters": 2.5}, "seed": 3, "run": {"t_max": 8, "min_window": 4, "min_transient": 2, "rate_bin": 0.5}}'
  [sp2d_authors]='{"dimension": 2, "N": 300, "W": 16, "w": 5, "zeta": 0, "mu": 8.5, "mu_n": 0, "E_sp": 138.889, "sp_contact_law": "force", "seed": 3, "reinjection": {"rule": "lanes", "drop_depth_diameters": 2.5}, "run": {"t_max": 30, "min_window": 10, "min_transient": 5}}'
)
status=0
for name in "${!JOBS[@]}"; do
  echo "${JOBS[$name]}" > "$WORK/$name.json"
  for side in old new; do
    bin=$OLD; [ $side = new ] && bin=$NEW
    rm -rf "$WORK/$name.$side"
    "$bin" simulate "$WORK/$name.json" -o "$WORK/$name.$side" --progress quiet > /dev/null
  done
  if python3 - "$WORK/$name.old" "$WORK/$name.new" <<'PY'
import json, re, subprocess, sys
def dump(d):
    # every dataset and attribute at full precision, the timing attributes cut out
    text = subprocess.run(["h5dump", "-m", "%.17g", d + "/result.h5"], check=True, capture_output=True, text=True).stdout
    text = re.sub(r'ATTRIBUTE "(wall_seconds|particle_steps_per_second)" \{.*?\n\s*\}\n', "", text, flags=re.S)
    # the version label may differ (a new version that must still give the same numbers)
    # and the dt's label (a label: 0.5.0 named the contact where the friction set dt)
    for label in ("engine_version", "dt_limiting_term"):
        text = re.sub(r'(ATTRIBUTE "' + label + r'" \{.*?STRSIZE )\d+(;.*?DATA \{\s*\(0\): )"[^"]*"', r'\1*\2"*"', text, flags=re.S)
    # /parameters is compared on its own (params below): a newer file may carry more attributes
    text = re.sub(r'\n   GROUP "parameters" \{.*?\n   \}\n', "\n", text, flags=re.S)
    return text.replace(d, "DIR")
def params(d):
    text = subprocess.run(["h5dump", "-m", "%.17g", "-g", "/parameters", d + "/result.h5"], check=True,
                          capture_output=True, text=True).stdout
    return dict(re.findall(r'\n   ATTRIBUTE "([^"]+)" \{(.*?)\n   \}', text, flags=re.S))
def params_agree(a, b):
    # every attribute both files have is equal (the job, the seed, dt, ...); one only a newer
    # binary writes (a parameter row it writes since) is not a different result
    pa, pb = params(a), params(b)
    return "job_json" in pa and all(pa[k] == pb[k] for k in pa.keys() & pb.keys())
def summary(d):
    s = json.load(open(d + "/summary.json"))
    for k in ("wall_seconds", "particle_steps_per_second", "engine_version", "dt_limiting_term"):
        s.pop(k, None)
    return s
def attribute_names(text):
    return set(re.findall(r'ATTRIBUTE "([^"]+)" \{', text))
def without_attributes(text, names):
    for n in names:
        # the attribute's block ends at the brace under its own indentation
        text = re.sub(r'\n([ ]*)ATTRIBUTE "' + re.escape(n) + r'" \{.*?\n\1\}(?=\n)', "", text, flags=re.S)
    return text
a, b = sys.argv[1:3]
# a result field that only the newer binary writes (force_ratio_err since 0.6.3's second
# build, say) is not a different result: it is left out of both sides and named
da, db = dump(a), dump(b)
sa, sb = summary(a), summary(b)
only_new = (attribute_names(db) - attribute_names(da)) | (sb.keys() - sa.keys())
da, db = without_attributes(da, only_new), without_attributes(db, only_new)
for k in only_new:
    sb.pop(k, None)
if only_new:
    print("  (only in the new file, not compared: " + ", ".join(sorted(only_new)) + ")")
same = da == db and sa == sb and params_agree(a, b)
sys.exit(0 if same else 1)
PY
  then
    echo "identical  $name"
  else
    echo "DIFFERENT  $name (h5dump -m %.17g of $WORK/$name.{old,new}/result.h5)"
    status=1
  fi
done
exit $status
