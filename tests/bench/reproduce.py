#!/usr/bin/env python3
"""CTest bench_reproduces: every committed non-timing number under data/bench/
comes out the same in a fresh run, and the pages copy the committed tables.

Usage: reproduce.py KVD SOURCE_DIR WORK_DIR

Re-runs the small cases (the whole accuracy suite, its segment scenes
included, the thesis suite at 25 triangles, the update suite at 100
triangles, the cost suite at 25, the aeg
suite at 100 segments (and its rotating scenes, the long one at 30), the
aeg-cost suite at 100, 200 and 400 segments (and 25, 50 and 100 rotating), and kvd_bench_next_root as
committed when it is built beside kvd), compares each fresh CSV row with the
committed row of the same key, number by number, compares the sections of
Markdown tables that hold no timing (accuracy.md's Segment scenes, which
README.md shows) with the fresh ones as text, and runs splice.py --check.
Timing quantities differ from run to run and machine to machine and are
skipped: names ending in _ms or starting with ms_, seconds, the tree and
certificate shares of the update time, and anything named for memory (rss),
a ratio, a speed-up or a fitted exponent; microseconds (_us). Standard library only.
"""
import csv
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "data" / "bench"))
from splice import section  # noqa: E402

TIMING = re.compile(r"(_ms$|^ms_|_us$|seconds|^tree_share$|^certificate_share$|rss|ratio|speedup|exponent)")


def rows(path, key):
    with open(path, newline="", encoding="utf-8") as f:
        return {tuple(r[k] for k in key): r for r in csv.DictReader(f)}


def compare(name, committed, fresh, key, long_form=False):
    """Differences between fresh rows and the committed rows of the same key.
    long_form: one number per row (the thesis's figure,...,quantity,value)."""
    old, new = rows(committed, key), rows(fresh, key)
    problems = []
    for k, r in new.items():
        if long_form and TIMING.search(r["quantity"]):
            continue
        if k not in old:
            problems.append(f"{name}: {k} is not in the committed file")
            continue
        for column, value in r.items():
            if not long_form and TIMING.search(column):
                continue
            if old[k].get(column) != value:
                problems.append(f"{name}: {k} {column}: committed {old[k].get(column)!r}, fresh {value!r}")
    return problems


def untimed_section(name, committed, fresh, heading):
    """A difference when the section `heading` of the fresh Markdown file is
    not the committed one, line for line (splice.py's notion of a section)."""
    old, new = section(committed, heading), section(fresh, heading)
    if old == new:
        return []
    changed = [f"committed {a!r}, fresh {b!r}" for a, b in zip(old.splitlines(), new.splitlines()) if a != b]
    if len(old.splitlines()) != len(new.splitlines()):
        changed.append(f"{len(old.splitlines())} lines committed, {len(new.splitlines())} fresh")
    return [f"{name} '{heading}': {c}" for c in changed]


def run(args):
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def main():
    kvd, src, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    bench = src / "data" / "bench"
    data = str(src / "data")
    problems = []
    run([kvd, "bench", "accuracy", "--data", data, "--out", str(work / "accuracy")])
    problems += compare("accuracy.csv", bench / "accuracy.csv", work / "accuracy" / "accuracy.csv", ["scene", "kernel"])
    problems += compare("accuracy-segments.csv", bench / "accuracy-segments.csv",
                        work / "accuracy" / "accuracy-segments.csv", ["scene", "kernel"])
    problems += untimed_section("accuracy.md", bench / "accuracy.md", work / "accuracy" / "accuracy.md", "Segment scenes")
    run([kvd, "bench", "thesis", "--sizes", "25", "--events", "1000", "--data", data, "--out", str(work / "thesis")])
    problems += compare("thesis.csv", bench / "thesis.csv", work / "thesis" / "thesis.csv",
                        ["figure", "family", "size", "kernel", "quantity"], long_form=True)
    run([kvd, "bench", "update", "--sizes", "100", "--out", str(work / "update")])
    problems += compare("update.csv", bench / "update.csv", work / "update" / "update.csv", ["triangles", "configuration"])
    run([kvd, "bench", "cost", "--sizes", "25", "--repeats", "1", "--out", str(work / "cost")])
    problems += compare("cost.csv", bench / "cost.csv", work / "cost" / "cost.csv", ["triangles"])
    # The rebuilds are timing only (the local and subtree updates are checked
    # against each other); the long segments' rebuild takes a second a batch.
    run([kvd, "bench", "aeg", "--sizes", "100", "--kinetic-sizes", "100", "--kinetic-quadratic-up-to", "100",
         "--rotating-long", "30", "--rebuild-up-to", "0", "--repeats", "1", "--out", str(work / "aeg")])
    problems += compare("aeg.csv", bench / "aeg.csv", work / "aeg" / "aeg.csv", ["part", "family", "crossings", "n", "m"])
    run([kvd, "bench", "aeg-cost", "--sizes", "100,200,400", "--flip-sizes", "25,50,100", "--out",
         str(work / "aeg-cost")])
    problems += compare("aeg-cost.csv", bench / "aeg-cost.csv", work / "aeg-cost" / "aeg-cost.csv",
                        ["family", "run", "n", "m"])
    next_root = pathlib.Path(kvd).parent / "kvd_bench_next_root"
    if next_root.exists():
        (work / "next-root").mkdir(parents=True, exist_ok=True)
        run([str(next_root), "--degrees", "1,2,4,6,8", "--bits", "64,200", "--count", "1000", "--out",
             str(work / "next-root")])
        problems += compare("next-root.csv", bench / "next-root.csv", work / "next-root" / "next-root.csv",
                            ["bits", "degree"])
    if subprocess.run([sys.executable, str(bench / "splice.py"), "--check"]).returncode != 0:
        problems.append("a page shows a table that differs from data/bench/ (splice.py --check)")
    for p in problems:
        print(p)
    print(f"bench_reproduces: {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
