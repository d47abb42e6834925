#!/usr/bin/env python3
"""The hostile corpus (tests/data/hostile/cases.txt): bad job, sweep and data files, damaged and
foreign campaigns. For each case: the exit code, the first line of the message, no hang (a time
limit), and where it must hold, nothing created, the campaign's database and files unchanged, or
a damaged campaign repaired by the next run with nothing wrong ingested.
Usage: BIN=path/to/beverloo hostile_corpus.py [CASE ...]"""
import os
import shutil
import sqlite3
import stat
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "hostile")
BIN = os.environ["BIN"]
TIME_LIMIT = 60  # seconds: a case that takes longer hangs

REFERENCE_SWEEP = """{"name": "hostile_reference", "base": {"N": 100, "W": 12, "zeta": 0.3, "mu": 0},
 "run": {"t_max": 8, "min_window": 2, "min_transient": 1, "rate_bin": 0.1, "checkpoint_interval": 2},
 "sweep": {"w": [3, 4]}}
"""


def run(args, timeout=TIME_LIMIT):
    return subprocess.run([BIN] + args, capture_output=True, text=True, errors="replace", timeout=timeout)


def db_dump(path):
    """The database's content as text, read without changing the file (immutable URI)."""
    try:
        con = sqlite3.connect(f"file:{path}?immutable=1", uri=True)
        text = "\n".join(con.iterdump())
        con.close()
        return text
    except sqlite3.Error as e:
        return f"(unreadable: {e})"


STRICT = {"foreign_db", "newer_db", "corrupt_db", "db_dir", "db_fifo", "text_db"}


def snapshot(camp, strict=True):
    """Every file's name, size and bytes' hash below camp (the lock's presence only), and the
    database's dump."""
    import hashlib
    listing = []
    for root, dirs, files in os.walk(camp):
        for name in sorted(dirs + files):
            p = os.path.join(root, name)
            st = os.lstat(p)
            if not strict and root == camp and name in ("campaign.sqlite-wal", "campaign.sqlite-shm"):
                continue  # a reader of our own WAL database may leave SQLite's WAL index; the dump is compared
            if name == "coordinator.lock" and root == camp:
                listing.append((name, "lock", ""))  # its text names the last holder: not the campaign's data
            elif stat.S_ISREG(st.st_mode):
                with open(p, "rb") as f:
                    listing.append((os.path.relpath(p, camp), st.st_size, hashlib.sha256(f.read()).hexdigest()))
            else:
                listing.append((os.path.relpath(p, camp), stat.S_IFMT(st.st_mode), ""))
    db = os.path.join(camp, "campaign.sqlite")
    return sorted(listing), (db_dump(db) if os.path.isfile(db) else "(no database)")


# --- preparations: inputs that cannot be files in the repository, and damage to campaigns -----

def job_result_dir(camp, w):
    con = sqlite3.connect(os.path.join(camp, "campaign.sqlite"))
    key, d = con.execute("SELECT key, dir FROM jobs WHERE w = ?", (w,)).fetchone()
    con.close()
    return key, os.path.join(camp, d)


def reopen_attempt(camp, w):
    """The job at w as a coordinator that died after its worker's success would leave it: the
    attempt running, no result ingested. Its outcome.json (success, token, digests) stays."""
    key, d = job_result_dir(camp, w)
    con = sqlite3.connect(os.path.join(camp, "campaign.sqlite"))
    aid = con.execute("SELECT max(id) FROM attempts WHERE job_key = ?", (key,)).fetchone()[0]
    con.execute("UPDATE attempts SET state = 'running', ended_at = NULL, exit_status = NULL WHERE id = ?", (aid,))
    con.execute("UPDATE jobs SET state = 'running' WHERE key = ?", (key,))
    con.execute("DELETE FROM velocity_profiles WHERE job_key = ?", (key,))
    con.execute("DELETE FROM results WHERE job_key = ?", (key,))
    con.commit()
    con.close()
    return d


def remove_database(camp):
    """Takes the campaign's database (and SQLite's files) away; returns its path."""
    db = os.path.join(camp, "campaign.sqlite")
    for ext in ("", "-wal", "-shm"):
        if os.path.exists(db + ext):
            os.remove(db + ext)
    return db


def prep(kind, work, case, camp):
    """Returns the input path {IN} for the case (or None)."""
    path = os.path.join(work, case + ".input")
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "dir":
        os.mkdir(path)
    elif kind == "big":
        with open(path, "w") as f:
            f.write('{"w": 6, "zeta": 0.3, "mu": 0, "pad": "' + "x" * (50 << 20) + '"}')
    elif kind == "deep_array":
        with open(path, "w") as f:
            f.write("[" * 100000 + "]" * 100000)
    elif kind == "deep_object":
        with open(path, "w") as f:
            f.write('{"a": ' * 5000 + "1" + "}" * 5000)
    elif kind == "symloop":
        os.symlink(path + ".b", path)
        os.symlink(path, path + ".b")
    elif kind == "longname":
        path = os.path.join(work, "x" * 300 + ".json")
    elif kind == "job_ok_copy":
        shutil.copy(os.path.join(DATA, "inputs", "job_ok.json"), path)
    elif kind == "csv_no_provenance_copy":
        shutil.copy(os.path.join(DATA, "inputs", "csv_no_provenance.csv"), path)
    elif kind == "sweep_1e12":
        import json
        axes = [{"w": [3 + i * 0.001 for i in range(1000)]}, {"zeta": [0.1 + i * 0.001 for i in range(1000)]},
                {"mu": [0.1 + i * 0.001 for i in range(1000)]}, {"E_sp": [100 + i for i in range(1000)]}]
        with open(path, "w") as f:
            json.dump({"name": "huge", "base": {"N": 50, "W": 12}, "sweep": {"product": axes}}, f)
    elif kind == "sweep_deep_union":
        with open(path, "w") as f:
            f.write('{"name": "u", "base": {"N": 50, "W": 12, "zeta": 0.3, "mu": 0}, "sweep": '
                    + '{"union": [' * 200 + '{"w": [3]}' + "]}" * 200 + "}")
    elif kind == "foreign_db":
        db = remove_database(camp)
        con = sqlite3.connect(db)
        con.execute("CREATE TABLE notes (t TEXT)")
        con.execute("INSERT INTO notes VALUES ('someone else''s')")
        con.commit()
        con.close()
    elif kind == "text_db":
        db = remove_database(camp)
        with open(db, "w") as f:
            f.write("these are my notes, not a database\n" * 10)
    elif kind == "newer_db":
        con = sqlite3.connect(os.path.join(camp, "campaign.sqlite"))
        con.execute("PRAGMA user_version = 99")
        con.commit()
        con.close()
    elif kind == "corrupt_db":
        db = os.path.join(camp, "campaign.sqlite")
        with open(db, "r+b") as f:
            f.seek(4096)
            f.write(os.urandom(8192))
    elif kind == "db_dir":
        db = remove_database(camp)
        os.mkdir(db)
    elif kind == "db_fifo":
        db = remove_database(camp)
        os.mkfifo(db)
    elif kind.startswith("checkpoint_"):
        # a job stopped part-way whose checkpoint is damaged: no outcome, no result, and a
        # checkpoint.h5 that is garbage or another file; the next run sets it aside and reruns
        d = reopen_attempt(camp, 4)
        result = os.path.join(d, "result.h5")
        if kind == "checkpoint_is_a_result":
            shutil.copy(result, os.path.join(d, "checkpoint.h5"))
        for name in ("outcome.json", "summary.json", "result.h5"):
            if os.path.exists(os.path.join(d, name)):
                os.remove(os.path.join(d, name))
        if kind == "checkpoint_garbage":
            with open(os.path.join(d, "checkpoint.h5"), "wb") as f:
                f.write(b"\x89HDF\r\n\x1a\n" + os.urandom(4000))
    elif kind.startswith("outcome_") or kind == "job_dir_file":
        d = reopen_attempt(camp, 4)
        if kind == "outcome_summary_missing":
            os.remove(os.path.join(d, "summary.json"))
        elif kind == "outcome_summary_edited":
            import json
            p = os.path.join(d, "summary.json")
            s = json.load(open(p))
            s["rho_n"] = s["rho_n"] + 1.0  # Q, its error, steps and seed as before: only the digest tells
            json.dump(s, open(p, "w"), indent=2)
        elif kind == "outcome_result_truncated":
            p = os.path.join(d, "result.h5")
            os.truncate(p, os.path.getsize(p) // 2)
        elif kind == "outcome_result_q_nan":
            subprocess.run(["/usr/bin/python3", "-c", f"""  # Debian's python3-h5py
import h5py
with h5py.File({os.path.join(d, 'result.h5')!r}, 'r+') as f:
    f['result'].attrs['Q'] = float('nan')
"""], check=True)
        elif kind == "outcome_garbage":
            with open(os.path.join(d, "outcome.json"), "w") as f:
                f.write('{"token": ')
        elif kind == "job_dir_file":
            shutil.rmtree(d)
            with open(d, "w") as f:
                f.write("not a directory\n")
    elif kind:
        raise SystemExit(f"unknown preparation {kind}")
    return path


def input_of(case):
    for ext in (".json", ".csv"):
        p = os.path.join(DATA, "inputs", case + ext)
        if os.path.exists(p):
            return p
    return None


def reference_campaign(work):
    sweep = os.path.join(work, "reference.json")
    with open(sweep, "w") as f:
        f.write(REFERENCE_SWEEP)
    camp = os.path.join(work, "reference")
    r = run(["run", sweep, "--dir", camp, "--workers", "2", "--progress", "quiet"], timeout=300)
    if r.returncode != 0:
        raise SystemExit("the reference campaign failed:\n" + r.stdout + r.stderr)
    con = sqlite3.connect(f"file:{os.path.join(camp, 'campaign.sqlite')}?immutable=1", uri=True)
    q = dict(con.execute("SELECT w, Q FROM runs"))
    con.close()
    return sweep, camp, q


def main():
    only = set(sys.argv[1:])
    cases = []
    with open(os.path.join(DATA, "cases.txt")) as f:
        for line in f:
            if not line.strip() or line.startswith("#"):
                continue
            fields = [x.strip() for x in line.rstrip("\n").split("|")]
            fields += [""] * (6 - len(fields))
            cases.append(fields[:6])
    if only:
        cases = [c for c in cases if c[0] in only]
    work = tempfile.mkdtemp(prefix="beverloo-hostile-")
    failures = []
    try:
        sweep, reference, ref_q = reference_campaign(work)
        for name, command, exit_code, message, checks, preparation in cases:
            case_dir = os.path.join(work, name)
            os.mkdir(case_dir)
            camp = os.path.join(case_dir, "campaign")
            shutil.copytree(reference, camp, symlinks=True)
            new, out = os.path.join(case_dir, "new"), os.path.join(case_dir, "out")
            path = prep(preparation, case_dir, name, camp) if preparation else input_of(name)
            if path and path.startswith(os.path.join(DATA, "inputs")):
                # a copy beside the case: whatever the command writes next to its input stays out of the repository
                shutil.copy(path, case_dir)
                path = os.path.join(case_dir, os.path.basename(path))
            strict = preparation in STRICT  # not ours: not even SQLite's files may appear
            before = snapshot(camp, strict)
            subst = {"{IN}": path or "", "{CAMP}": camp, "{SWEEP}": sweep, "{NEW}": new, "{OUT}": out}
            args = []
            for a in command.split(" "):
                for k, v in subst.items():
                    a = a.replace(k, v)
                args.append(a.replace("~", " ") if args and args[0] == "query" and len(args) == 2 else a)
            try:
                r = run(args)
            except subprocess.TimeoutExpired:
                failures.append(f"{name}: no answer within {TIME_LIMIT} s (a hang)")
                continue
            first = (r.stderr.strip().splitlines() or [""])[0]
            problems = []
            if r.returncode != int(exit_code):
                problems.append(f"exit {r.returncode}, expected {exit_code}")
            expected = message.replace("{IN}", os.path.basename(path or ""))
            if expected != "-" and expected not in first:
                problems.append(f"first line lacks \"{expected}\"")
            if r.returncode < 0 or "terminate called" in r.stderr or "internal error" in r.stderr:
                problems.append("crashed or reported an internal error")
            for check in filter(None, checks.split(",")):
                if check == "created":
                    for p in (new, out):
                        if os.path.lexists(p):
                            problems.append(f"created {os.path.basename(p)}")
                elif check == "unchanged":
                    after = snapshot(camp, strict)
                    if after != before:
                        changed = sorted(set(before[0]) ^ set(after[0]))
                        what = ", ".join(sorted({c[0] for c in changed})) or "the database's content"
                        problems.append(f"changed the campaign ({what})")
                elif check == "completes":
                    con = sqlite3.connect(f"file:{os.path.join(camp, 'campaign.sqlite')}?immutable=1", uri=True)
                    states = [s for (s,) in con.execute("SELECT state FROM jobs")]
                    q = dict(con.execute("SELECT w, Q FROM runs"))
                    con.close()
                    if states != ["done"] * len(states):
                        problems.append(f"job states after the run: {states}")
                    if q != ref_q:
                        problems.append(f"ingested Q {q}, the engine's are {ref_q}")
                    again = run(["run", sweep, "--dir", camp, "--progress", "quiet"])
                    if again.returncode != 0:
                        problems.append(f"a second run exits {again.returncode}: {again.stderr.strip()[:200]}")
                elif check != "none":
                    problems.append(f"unknown check {check}")
            status = "FAIL" if problems else "ok  "
            print(f"{status} {name}: exit {r.returncode}: {first[:150]}" + ("  <- " + "; ".join(problems) if problems else ""))
            if problems:
                failures.append(f"{name}: " + "; ".join(problems))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{len(cases) - len(failures)} of {len(cases)} hostile cases behave as expected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
