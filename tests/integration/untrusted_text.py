#!/usr/bin/env python3
"""Untrusted text never becomes a command, and every output sink keeps it as data (issue 31).

A corpus of hostile strings (gnuplot, shell and macro payloads, quotes, pipes, commas, HTML,
terminal control sequences, NUL, bidirectional overrides, bytes that are not UTF-8) is planted
in every user string that reaches an output: series, geometry, source and run names of
imported exits, a sweep's name, and the campaign's own directory path. Then `experiment
import`, `fit`, `report`, `sweep check`, `sweep expand`, `campaign create` and `campaign
status` run, and:
- no payload ran: no canary file exists anywhere, and every figure was rendered;
- each gnuplot script holds every user string inside a single-quoted literal on one line;
- beverloo_fits.csv, crossover_fits.csv and paper_claims.csv read back with Python's csv module (RFC 4180) to the
  header's column count, and each series name comes back exactly as it was written;
- each Markdown table row has exactly its columns (no unescaped pipe), on one line;
- index.html has no markup from a name (every < of a name arrives as &lt;);
- what reaches the terminal (stdout and stderr of every command) holds no control character
  (C0 but tab and line feed, DEL, C1, bidirectional controls).
Usage: BIN=path/to/beverloo untrusted_text.py"""
import csv
import glob
import math
import os
import random
import re
import subprocess
import sys
import tempfile

BIN = os.environ["BIN"]
CANARY = "CANARY_RAN"

# Each payload tries another way out of the literal it is put in. {C} is a canary path.
PAYLOADS = [
    's"; system("touch {C}1"); print "',          # gnuplot, double-quoted strings
    "s'; system('touch {C}2'); print '",          # gnuplot, single-quoted strings
    "`touch {C}3`",                                 # gnuplot backquote substitution
    "@x sprintf('%s', system('touch {C}4'))",      # gnuplot macros
    "a|b,c\"d",                                    # CSV and Markdown
    "$(touch {C}5) ; touch {C}6 #",                 # a shell
    "<script>alert(1)</script> &amp;",            # HTML
    "end in backslash \\",                          # gnuplot line continuation
    "esc \x1b]0;title\x07\x1b[31mred\x1b[0m bel\x07 cr\rX del\x7f c1\u009b bidi\u202egnp.exe",  # a terminal
]
LINE_BREAK = "a\n! touch {C}7\nb"  # a header value cannot hold a line break: used where a name can (a sweep's)


def canary_base(work):
    return os.path.join(work, CANARY)


def fill(text, work):
    return text.replace("{C}", canary_base(work))


def run(args, cwd, ok=True):
    p = subprocess.run([BIN] + args, cwd=cwd, capture_output=True, timeout=300)
    if ok and p.returncode != 0:
        sys.exit(f"FAIL: beverloo {' '.join(args)} exited {p.returncode}: {p.stderr.decode(errors='replace')}")
    return p


BAD_TERMINAL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f\u0080-\u009f\u202a-\u202e\u2066-\u2069]")


def check_terminal(what, p, failures):
    for stream, data in (("stdout", p.stdout), ("stderr", p.stderr)):
        text = data.decode("utf-8", errors="strict") if is_utf8(data) else None
        if text is None:
            failures.append(f"{what}: {stream} is not UTF-8")
        elif BAD_TERMINAL.search(text):
            failures.append(f"{what}: {stream} holds a control character: {BAD_TERMINAL.search(text).group()!r}")


def is_utf8(data):
    try:
        data.decode("utf-8")
        return True
    except UnicodeDecodeError:
        return False


def exits_file(path, series, geometry, source, run_names, seed):
    """A draining-hopper data file (docs/experiments.md) of runs at four widths, each run's exits
    from dN/dt = -c0 sqrt(N) with c0 growing as (w - 1)^1.5, jittered (a seeded generator)."""
    rng = random.Random(seed)
    sigma, n0 = 3.15e-4, 300
    with open(path, "w", encoding="utf-8", newline="") as f:
        f.write("# beverloo-exits 1\n")
        f.write(f"# series: {series}\n# provenance: simulated\n# source: {source}\n# geometry: {geometry}\n")
        f.write(f"# sigma_avg_m: {sigma}\n# g_eff_m_s2: 0.639\nrun,w_m,t_s\n")
        for name, w in zip(run_names, (3.0, 4.0, 5.0, 6.0)):
            c0 = 2.0 * (w - 1.0) ** 1.5
            t = 0.0
            for k in range(n0):
                t += rng.expovariate(c0 * math.sqrt(n0 - k))
                f.write(f"{name},{w * sigma:.6g},{t:.6f}\n")


def main():
    failures = []
    work = tempfile.mkdtemp(prefix="beverloo-untrusted-")
    # the campaign's directory itself is hostile: a quote, a shell substitution, a space
    camp = os.path.join(work, "camp 'q\" $(touch " + CANARY + "8) `touch " + CANARY + "9`")
    payloads = [fill(p, work) for p in PAYLOADS]
    terminal_outputs = []

    # --- imported exits: series, geometry, source and run names ---------------------------------
    for i in range(0, len(payloads), 3):
        group = payloads[i:i + 3]
        series = f"S{i} " + group[0]
        geometry = group[1 % len(group)]
        run_names = [re.sub(r"[,\r\n]", "_", p).strip() or "r" for p in (group * 2)[:4]]  # a row's field has no comma
        run_names = [f"{n} {k}" for k, n in enumerate(run_names)]
        path = os.path.join(work, f"exits{i}.csv")
        exits_file(path, series, geometry, group[-1], run_names, seed=i)
        p = run(["experiment", "import", path, "--dir", camp, "--fit-skip", "20", "--block-exits", "10"], work)
        terminal_outputs.append(("experiment import", p))
    p = run(["fit", camp], work)
    terminal_outputs.append(("fit", p))
    p = run(["report", camp], work)
    terminal_outputs.append(("report", p))

    # --- a sweep's name (a JSON string may hold anything) --------------------------------------
    sweep = os.path.join(work, "hostile.json")
    name = fill(LINE_BREAK, work) + payloads[-1] + "\u0000nul \udcff".encode("utf-8", "surrogateescape").decode(
        "utf-8", "replace")
    with open(sweep, "w", encoding="utf-8") as f:
        import json
        json.dump({"name": name, "base": {"N": 100, "W": 12, "zeta": 0.3, "mu": 0},
                   "run": {"t_max": 4, "min_window": 1, "min_transient": 1, "rate_bin": 0.1}, "sweep": {"w": [3, 4]}}, f)
    for args in (["sweep", "check", sweep], ["sweep", "expand", sweep], ["sweep", "expand", sweep, "--format", "csv"],
                 ["campaign", "create", sweep, "--dir", camp + "-sweep"], ["campaign", "status", "--dir", camp + "-sweep"]):
        terminal_outputs.append((" ".join(args[:2]), run(args, work)))
    # an error message that repeats what the user wrote
    bad = os.path.join(work, "bad \x1b[2J $(touch " + CANARY + "10).json")  # a relative canary: cwd is work
    with open(bad, "w") as f:
        f.write('{"' + payloads[-1] + '": 1}')
    terminal_outputs.append(("sweep check (refused)", run(["sweep", "check", bad], work, ok=False)))

    for what, p in terminal_outputs:
        check_terminal(what, p, failures)

    # --- nothing ran ----------------------------------------------------------------------------
    ran = [f for f in glob.glob(os.path.join(work, "**", CANARY + "*"), recursive=True)] + glob.glob(CANARY + "*")
    if ran:
        failures.append(f"a payload ran: {ran}")

    report = os.path.join(camp, "report")
    for fig in ("drain_Q_vs_w", "drain_collapse", "drain_curves"):
        for ext in ("svg", "png"):
            if not os.path.isfile(os.path.join(report, f"{fig}.{ext}")):
                failures.append(f"the figure {fig}.{ext} was not rendered")

    # --- gnuplot: every title a single-quoted literal on its own line ---------------------------
    for gp in glob.glob(os.path.join(report, "*.gp")):
        text = open(gp, encoding="utf-8").read()
        for line in text.split("\n"):
            if line.startswith("#"):
                continue
            # outside single-quoted literals ('' is a quote inside one), no double quote and no backquote
            outside = re.sub(r"'(?:[^']|'')*'", "''", line)
            if '"' in outside or "`" in outside or "@" in outside or outside.lstrip().startswith("!"):
                failures.append(f"{os.path.basename(gp)}: text outside a literal: {line[:120]!r}")
            if BAD_TERMINAL.search(line):
                failures.append(f"{os.path.basename(gp)}: a control character in {line[:120]!r}")

    # --- CSV: RFC 4180 round trip ---------------------------------------------------------------
    for table in ("beverloo_fits.csv", "crossover_fits.csv", "paper_claims.csv"):
        with open(os.path.join(report, table), encoding="utf-8", newline="") as f:
            rows = list(csv.reader(f))
        width = len(rows[0])
        for r in rows[1:]:
            if len(r) != width:
                failures.append(f"{table}: a row of {len(r)} fields, the header has {width}: {r[:2]}")
        if table == "beverloo_fits.csv":
            labels = [r[0] for r in rows[1:]]
            for i in range(0, len(payloads), 3):
                series = f"S{i} " + payloads[i]
                if not any(l.startswith(series + " (") for l in labels):
                    failures.append(f"{table}: the series {series!r} does not read back: {labels}")

    # --- Markdown: one row a line, no unescaped pipe ---------------------------------------------
    for table in ("beverloo_fits.md", "crossover_fits.md", "paper_claims.md"):
        lines = open(os.path.join(report, table), encoding="utf-8").read().rstrip("\n").split("\n")
        columns = len(re.findall(r"(?<!\\)\|", lines[0]))
        for line in lines:
            if len(re.findall(r"(?<!\\)\|", line)) != columns or not line.startswith("|"):
                failures.append(f"{table}: a row that is not {columns - 1} cells: {line[:120]!r}")

    # --- HTML: names are text, not markup --------------------------------------------------------
    html = open(os.path.join(report, "index.html"), encoding="utf-8").read()
    if "<script>" in html:
        failures.append("index.html: a name became markup (<script>)")
    if "&lt;script&gt;" not in html:
        failures.append("index.html does not show the series with the <script> name")

    for f in failures:
        print("FAIL " + f)
    if failures:
        print(f"kept {work}")
        sys.exit(1)
    import shutil
    if not os.environ.get("KEEP_WORK"):
        shutil.rmtree(work)
    print(f"ok  {len(PAYLOADS)} hostile strings through import, fit, report, sweep and campaign commands: "
          "no payload ran; gnuplot, CSV, Markdown, HTML and terminal output hold them as data")


if __name__ == "__main__":
    main()
