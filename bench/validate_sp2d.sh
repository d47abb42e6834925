#!/usr/bin/env bash
# Physics validation (issue 2, item 8), run by hand or via `ctest -L validation`:
# 2D SP, E_sp = 100, N = 1600, theta_w = 90 deg, w in {4,5,6,7,8,10}, four dissipation settings.
# Prints Q(w) with errors and a quick least-squares Beverloo fit per setting. The real fitter
# (GSL, weighted, with parameter errors) belongs to the reports; this is a first look.
# Usage: bench/validate_sp2d.sh [OUT_DIR] [WORKERS]     (about 15-40 min on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${BIN:-./build/cli/beverloo}
OUT=${1:-out/validate_sp2d}
WORKERS=${2:-$(nproc)}
mkdir -p "$OUT/jobs"
declare -A ZETA=( [friction_mu_10sqrt10]=0 [friction_mu_sqrt10]=0 [drag_zeta_1oversqrt10]=0.31622776601683794 [drag_zeta_sqrt10]=3.1622776601683795 )
declare -A MU=( [friction_mu_10sqrt10]=31.622776601683793 [friction_mu_sqrt10]=3.1622776601683795 [drag_zeta_1oversqrt10]=0 [drag_zeta_sqrt10]=0 )
for setting in "${!ZETA[@]}"; do
  for w in 4 5 6 7 8 10; do
    cat > "$OUT/jobs/${setting}_w$w.json" <<JOB
{"dimension": 2, "N": 1600, "w": $w, "E_sp": 100, "theta_w_deg": 90,
 "zeta": ${ZETA[$setting]}, "mu": ${MU[$setting]},
 "run": {"t_max": 3000, "target_rel_err": 0.02, "checkpoint_interval": 200}}
JOB
  done
done
ls "$OUT"/jobs/*.json | xargs -P "$WORKERS" -I{} sh -c \
  'n=$(basename {} .json); [ -f '"$OUT"'/runs/$n/summary.json ] || '"$BIN"' simulate {} -o '"$OUT"'/runs/$n --overwrite --progress quiet --json > '"$OUT"'/runs_$n.json 2> '"$OUT"'/runs_$n.log || echo "FAILED $n"'
/usr/bin/python3 - "$OUT" <<'PY'
import glob, json, math, os, sys
import numpy as np
out = sys.argv[1]
rows = {}
for f in sorted(glob.glob(f"{out}/runs/*/summary.json")):
    name = os.path.basename(os.path.dirname(f))
    setting, w = name.rsplit("_w", 1)
    s = json.load(open(f))
    rows.setdefault(setting, []).append((float(w), s))

def fit(ws, q, dq):
    """Weighted least squares of log Q = log C + beta log(w - k), k scanned below min(w)."""
    best = None
    for k in np.linspace(-2.0, min(ws) - 0.05, 400):
        x = np.log(ws - k); y = np.log(q); sw = (q / dq) ** 2
        A = np.vstack([np.ones_like(x), x]).T
        W = np.diag(sw)
        cov = np.linalg.inv(A.T @ W @ A)
        p = cov @ A.T @ W @ y
        chi2 = float(np.sum(sw * (y - A @ p) ** 2))
        if best is None or chi2 < best[0]:
            best = (chi2, k, math.exp(p[0]), p[1], math.sqrt(cov[1, 1]))
    return best

print(f"2D SP, E_sp = 100, N = 1600, theta_w = 90 deg (beverloo {out})")
for setting in sorted(rows):
    data = sorted(rows[setting])
    print(f"\n{setting}")
    print("   w        Q      Q_err   status      window        exits   |F_drag|/|F_fric|  wall s")
    for w, s in data:
        ratio = s['force_ratio'] if s['force_ratio'] is not None else float('inf')
        print(f"  {w:4.1f}  {s['Q']:8.4f}  {s['Q_err']:7.4f}   {s['status']:10s}  {s['window_start']:5.0f}-{s['window_end']:5.0f}  {s['exits_in_window']:6d}   {ratio:10.4g}   {s['wall_seconds']:7.1f}")
    flowing = [(w, s) for w, s in data if s["Q"] > 0 and s["Q_err"] > 0]
    if len(flowing) >= 4:
        ws = np.array([w for w, _ in flowing]); q = np.array([s["Q"] for _, s in flowing]); dq = np.array([s["Q_err"] for _, s in flowing])
        chi2, k, C, beta, dbeta = fit(ws, q, dq)
        print(f"  fit Q = C (w - k)^beta: beta = {beta:.3f} +- {dbeta:.3f} (at best k), k = {k:.2f}, C = {C:.4f}, chi2/dof = {chi2 / (len(ws) - 3):.2f}")
    else:
        print("  too few flowing points to fit")
PY
