#!/usr/bin/env python3
"""The outputs of kvd on a bundled scene against their recorded digests
(tests/outputs/digests.txt): the --json output of info, build, order,
simulate and diff, with their keys in order, their values and the types of
their values, timings left out; and the --trace file of simulate and the
certificate of certify, byte for byte; and every exit status.

usage: check_outputs.py KVD SOURCE_DIR WORK_DIR [--update] SCENE...

A SCENE is a path under SOURCE_DIR (data/boxes.json). The commands run in
SOURCE_DIR, so that the paths they print are the same on every machine.
The outputs are kept in WORK_DIR to be looked at. --update records this
binary's digests instead of checking them, for a change meant to alter an
output (the scenes CTest checks: tests/CMakeLists.txt, tests outputs_*):
  tests/outputs/check_outputs.py build/kvd . /tmp/outputs --update data/*.json data/stiff/*.json
"""
import hashlib
import json
import os
import subprocess
import sys

TIMINGS = {"seconds", "seconds_exact", "seconds_inexact", "construction_ms", "update_ms",
           "tree_update_share", "certificate_update_share", "memory"}
DIGESTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "digests.txt")


def commands(scene, events):
    """(name, arguments, file it writes or None, whether stdout is JSON)."""
    n = str(events)
    return [
        ("info", ["info", scene, "--json"], None, True),
        ("build", ["build", scene, "--json"], None, True),
        ("bsp", ["build", scene, "--bsp", "--json"], None, True),
        ("order", ["order", scene, "--view", "30,-40,25", "--cull", "--json"], None, True),
        ("simulate", ["simulate", scene, "--events", n, "--json", "--trace", "{out}"], "trace", True),
        ("simulate-double", ["simulate", scene, "--events", n, "--kernel", "double", "--json", "--trace", "{out}"],
         "trace", True),
        ("diff", ["diff", scene, "--kernel", "double", "--events", n, "--json"], None, True),
        ("certify", ["certify", scene, "--events", n, "--out", "{out}"], "cert", False),
    ]


def without_timings(v):
    if isinstance(v, dict):
        return {k: without_timings(x) for k, x in v.items() if k not in TIMINGS}
    if isinstance(v, list):
        return [without_timings(x) for x in v]
    return v


def digest(text):
    return hashlib.sha256(text).hexdigest()


def run(kvd, src, work, scene):
    """{key: digest} for the scene: 'SCENE NAME status', 'SCENE NAME stdout', 'SCENE NAME file'."""
    events = 200 if os.path.basename(scene) == "collisions.json" else 10  # its four motion changes
    base = os.path.join(work, scene[: -len(".json")].replace("/", "_"))
    found = {}
    for name, args, writes, is_json in commands(scene, events):
        out = f"{base}.{name}.{writes}" if writes else None
        args = [a.replace("{out}", out) if out else a for a in args]
        done = subprocess.run([kvd] + args, cwd=src, capture_output=True)
        key = f"{scene} {name}"
        found[key + " status"] = str(done.returncode)
        with open(f"{base}.{name}.stdout", "wb") as f:
            f.write(done.stdout)
        if is_json and done.returncode in (0, 1):
            # json.loads keeps the keys' order and tells 1 from 1.0, and so does dumps.
            canonical = json.dumps(without_timings(json.loads(done.stdout)), ensure_ascii=False)
            found[key + " stdout"] = digest(canonical.encode())
        if out and os.path.exists(out):
            with open(out, "rb") as f:
                found[key + " file"] = digest(f.read())
    return found


def read_digests():
    if not os.path.exists(DIGESTS):
        return {}
    with open(DIGESTS) as f:
        return dict(line.rstrip("\n").rsplit("  ", 1) for line in f if line.strip())


def main():
    args = [a for a in sys.argv[1:] if a != "--update"]
    update = len(args) < len(sys.argv) - 1
    if len(args) < 4:
        sys.exit(__doc__)
    kvd, src, work, scenes = os.path.abspath(args[0]), args[1], args[2], args[3:]
    os.makedirs(work, exist_ok=True)
    recorded = read_digests()
    changed = 0
    for scene in scenes:
        found = run(kvd, src, work, scene)
        expected = {k: v for k, v in recorded.items() if k.startswith(scene + " ")}
        if update:
            for k in expected:
                del recorded[k]
            recorded.update(found)
            print(f"{scene}: {len(found)} digests recorded")
            continue
        wrong = sorted(k for k in expected.keys() | found.keys() if expected.get(k) != found.get(k))
        for k in wrong:
            print(f"FAIL: {k}: recorded {expected.get(k, 'nothing')}, now {found.get(k, 'nothing')}")
        print(f"{scene}: {len(found) - len(wrong)} of {len(found)} outputs as recorded")
        changed += len(wrong)
    if update:
        with open(DIGESTS, "w") as f:
            f.writelines(f"{k}  {v}\n" for k, v in sorted(recorded.items()))
    elif changed:
        sys.exit(f"{changed} outputs changed (they are in {work})")


if __name__ == "__main__":
    main()
