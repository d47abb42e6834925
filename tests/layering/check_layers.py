#!/usr/bin/env python3
"""The layer rule (docs/architecture.md): includes point one way,
cli -> reports -> orchestrator -> engine -> core. A file may include project headers of its own
layer or of a lower one; anything else (up, or into a layer that is not below) fails, with the
file, the line and the include. Usage: check_layers.py [REPO_ROOT]"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
# (path prefix, layer name, rank); the first matching prefix wins
LAYERS = [
    ("core/", "core", 0),
    ("engine/", "engine", 1),
    ("cli/", "cli", 4),
    ("orchestrator/", "orchestrator", 2),
    ("reports/", "reports", 3),
    ("bench/", "tools", 5),
]
# "..." and <...>: a project header named with angle brackets counts too (only paths under the
# project's top folders are project headers; other angle includes are the system's)
INCLUDE = re.compile(r'^\s*#\s*include\s+(?:"([^"]+)"|<([^>]+)>)')
TOPS = ("core", "engine", "orchestrator", "reports", "cli", "bench")


def layer_of(rel):
    for prefix, name, rank in LAYERS:
        if rel.startswith(prefix):
            return name, rank
    return None


def resolve(rel_file, target):
    if target.split("/")[0] in TOPS:
        return os.path.normpath(target)
    return os.path.relpath(os.path.normpath(os.path.join(ROOT, os.path.dirname(rel_file), target)), ROOT)


def main():
    bad, checked = [], 0
    for top in TOPS:
        for d, _, files in os.walk(os.path.join(ROOT, top)):
            for f in files:
                if not f.endswith((".h", ".cpp")):
                    continue
                rel = os.path.relpath(os.path.join(d, f), ROOT)
                src = layer_of(rel)
                with open(os.path.join(d, f), encoding="utf-8") as fh:
                    for n, line in enumerate(fh, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        if m.group(2) and m.group(2).split("/")[0] not in TOPS:
                            continue  # a system header
                        target = resolve(rel, m.group(1) or m.group(2))
                        dst = layer_of(target)
                        if dst is None:  # generated files, system headers in quotes
                            continue
                        checked += 1
                        if dst[1] > src[1]:
                            bad.append(f"{rel}:{n}: {src[0]} includes {target} ({dst[0]}): points up")
    for b in bad:
        print("FAIL " + b)
    if bad:
        print(f"{len(bad)} of {checked} project includes break the layer rule "
              "(cli -> reports -> orchestrator -> engine -> core)")
        return 1
    print(f"ok  {checked} project includes follow cli -> reports -> orchestrator -> engine -> core")
    return 0


if __name__ == "__main__":
    sys.exit(main())
