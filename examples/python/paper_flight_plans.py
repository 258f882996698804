"""Flight-plan changes on the paper's certificates (seed 003, Lemma 3.1):
turns segments back at an instant, each in a run of its own, and prints how
many certificates each change made again against k_i, the number of
segments crossing it then. Segments moving by a translation are turned back
(the velocity reversed), static ones set moving; other motions are skipped.
usage: python3 paper_flight_plans.py SCENE AT [EVERY]
(every EVERY-th segment, default 10; AT a fraction such as 1/40)"""
import json
import statistics
import sys
from fractions import Fraction

import kvd


def poly(p):
    return [Fraction(c) for c in (p if isinstance(p, list) else [p])]


def value(p, t):
    return sum(c * t ** i for i, c in enumerate(p))


def endpoints_at(seg, t):
    # The endpoints at t of a static or translating segment, else None.
    motion = seg.get("motion")
    dx, dy = (poly(p) for p in motion["translation"]) if motion else ([Fraction(0)], [Fraction(0)])
    if motion and "translation" not in motion:
        return None
    return [(Fraction(x) + value(dx, t), Fraction(y) + value(dy, t)) for x, y in seg["endpoints"]]


def orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def crossing(s, r):
    return orient(*s, r[0]) * orient(*s, r[1]) < 0 and orient(*r, s[0]) * orient(*r, s[1]) < 0


def turned_back(seg, t):
    # The translation from where the segment is at t, its velocity reversed
    # (a static one starts moving right).
    motion = seg.get("motion")
    dx, dy = (poly(p) for p in motion["translation"]) if motion else ([Fraction(0)], [Fraction(0)])
    new = []
    for p in (dx, dy):
        v = -sum(i * c * t ** (i - 1) for i, c in enumerate(p) if i) or Fraction(1)
        new.append([str(value(p, t) - v * t), str(v)])
    return {"translation": new}


def main():
    path, at = sys.argv[1], Fraction(sys.argv[2])
    every = int(sys.argv[3]) if len(sys.argv) > 3 else 10
    text = json.load(open(path))
    scene = kvd.load_segments(path)
    now = [endpoints_at(seg, at) for seg in text["segments"]]
    rows = []
    for i in range(0, len(now), every):
        if now[i] is None:
            continue
        k_i = sum(1 for j, r in enumerate(now) if j != i and r is not None and crossing(now[i], r))
        run = kvd.PaperSegments(scene, events=10**6, validate=False)
        batch = run.set_motion(i, turned_back(text["segments"][i], at), at)
        rows.append((i, k_i, batch["certificates_made"], batch["certificates"], len(batch["failing"])))
        print(f"s{i}: k_i = {k_i}, {batch['certificates_made']} certificates made of {batch['certificates']}, "
              f"{len(batch['failing'])} failing at once")
    made = [r[2] for r in rows]
    per = [r[2] / (r[1] + 1) for r in rows]
    print(f"{len(rows)} changes at t = {at}: certificates made median {statistics.median(made)}, max {max(made)} "
          f"of {rows[0][3]} in force; per k_i + 1 median {statistics.median(per):.2f}, max {max(per):.2f}")


if __name__ == "__main__":
    main()
