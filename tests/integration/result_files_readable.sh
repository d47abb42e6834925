#!/usr/bin/env bash
# result.h5 opens with h5dump and h5py with the documented layout; the trajectory is H5MD 1.1.
source "$(dirname "$0")/lib.sh"
cat > "$WORK/job.json" <<'JOB'
{"dimension": 3, "N": 500, "W": 9, "w": 4, "E_sp": 100, "zeta": 0, "mu": 10,
 "run": {"t_max": 30, "min_window": 10, "min_transient": 5, "rate_bin": 0.5, "trajectory_every_steps": 2000}}
JOB
"$BIN" simulate "$WORK/job.json" -o "$WORK/run" --progress quiet --json > "$WORK/summary.out"
h5dump -H "$WORK/run/result.h5" > /dev/null || fail "h5dump cannot read result.h5"
/usr/bin/python3 - "$WORK/run" <<'PY'
import json, sys, h5py, numpy as np
d = sys.argv[1]
with h5py.File(f"{d}/result.h5", "r") as f:
    assert f.attrs["format"] == b"beverloo-result" or f.attrs["format"] == "beverloo-result"
    r = f["result"].attrs
    for key in ["Q", "Q_err", "window_start", "window_end", "rho_n", "Q_prime", "mean_F_drag", "mean_F_friction"]:
        assert key in r, key
    assert r["Q"] > 0 and np.isfinite(r["Q_err"])
    t = f["exits/time"][:]
    assert np.all(np.diff(t) >= 0) and len(t) == r["exits_total"]
    assert f["profile/h"].shape == f["profile/v_g"].shape
    job = json.loads(f["parameters"].attrs["job_json"])
    assert job["dimension"] == 3 and job["w"] == 4
summary = json.load(open(f"{d}/summary.json"))
assert summary["status"] in ("converged", "time_limit")
with h5py.File(f"{d}/trajectory.h5", "r") as t:
    assert list(t["h5md"].attrs["version"]) == [1, 1]
    pos = t["particles/all/position"]
    assert pos["value"].shape[1:] == (500, 3), pos["value"].shape
    assert pos["step"].shape[0] == pos["value"].shape[0] == pos["time"].shape[0] >= 2
    assert t["particles/all/species"].shape == (500,)
    assert list(t["particles/all/box"].attrs["dimension"]) == [3]
print("ok  result.h5, summary.json and trajectory.h5 read with h5py")
PY
