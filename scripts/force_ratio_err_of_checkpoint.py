#!/usr/bin/env python3
"""force_ratio_err of a finished job from its final checkpoint, for runs by an engine before
the field (2026-12-07): the same estimate as engine/protocol/observables.cpp, from the
checkpoint's /observables/block_scalars (per 5 t0 block: samples, density, sum |F_drag|,
sum |F_friction|) over the blocks of the result's window.

The final checkpoint must be the run's last step (beverloo writes one as the run ends; the
script checks its step against summary.json's). Needs h5dump (hdf5-tools), no h5py.

Usage: scripts/force_ratio_err_of_checkpoint.py JOB_DIR [JOB_DIR ...]
Prints: job_dir force_ratio force_ratio_err blocks (the blocks of the window)
"""
import json
import math
import re
import subprocess
import sys

BLOCK_LENGTH = 5.0  # observables.block_length, t0 (the default; checked against the job below)


def dataset(path, name):
    text = subprocess.run(["h5dump", "-m", "%.17g", "-d", name, path], check=True, capture_output=True,
                          text=True).stdout
    data = text[text.index("DATA {") + len("DATA {"):]
    data = re.sub(r"\(\d+(,\d+)*\):", " ", data[: data.index("}")])
    return [float(x) for x in data.replace(",", " ").split()]


def attribute(path, name):
    text = subprocess.run(["h5dump", "-m", "%.17g", "-a", name, path], check=True, capture_output=True,
                          text=True).stdout
    return float(re.search(r"\(0\): ([-0-9.e+]+)", text).group(1))


def blocking_standard_error(x, min_blocks=16):
    # FlowRateEstimator::blocking_standard_error: the largest over the pairwise levels that
    # keep at least min_blocks blocks (the first level always)
    best, first = 0.0, True
    while len(x) >= max(2, min_blocks) or first:
        n = len(x)
        if n < 2:
            break
        mean = sum(x) / n
        var = sum((v - mean) ** 2 for v in x)
        best = max(best, math.sqrt(var / (n * (n - 1))))
        first = False
        x = [0.5 * (x[2 * k] + x[2 * k + 1]) for k in range(n // 2)]
    return best


def force_ratio_err(job_dir, summary):
    for name in ("spec.json", "job.json"):  # a campaign's job directory, or simulate's
        try:
            spec = json.load(open(job_dir + "/" + name))
            break
        except FileNotFoundError:
            spec = {}
    job = spec.get("job", spec)
    block_length = job.get("observables", {}).get("block_length", BLOCK_LENGTH)
    checkpoint = job_dir + "/checkpoint.h5"
    step = attribute(checkpoint, "/step")
    if int(step) != int(summary["steps"]):
        raise SystemExit(f"{job_dir}: the checkpoint is at step {int(step)}, the run ended at {summary['steps']}")
    sc = dataset(checkpoint, "/observables/block_scalars")
    first = math.ceil(summary["window_start"] / block_length - 1e-9)
    blocks = [sc[4 * b: 4 * b + 4] for b in range(first, len(sc) // 4) if sc[4 * b] != 0]
    samples = sum(b[0] for b in blocks)
    drag = sum(b[2] for b in blocks) / samples
    fric = sum(b[3] for b in blocks) / samples
    if not fric > 0:
        return math.inf, math.nan, len(blocks)
    ratio = drag / fric
    u = [(b[2] / b[0] - ratio * b[3] / b[0]) / fric for b in blocks]
    return ratio, (blocking_standard_error(u) if len(u) >= 2 else math.nan), len(blocks)


for job_dir in sys.argv[1:]:
    summary = json.load(open(job_dir + "/summary.json"))
    ratio, err, n = force_ratio_err(job_dir, summary)
    if abs(ratio - summary["force_ratio"]) > 1e-12 * abs(ratio):
        raise SystemExit(f"{job_dir}: ratio {ratio} from the blocks, {summary['force_ratio']} in summary.json")
    print(job_dir, f"{ratio:.10g}", f"{err:.6g}", n)
