#!/usr/bin/env python3
"""Write a tampered copy of an event-order certificate (kvd-event-order/2).

Usage: tamper.py IN TAMPERING OUT
       tamper.py --list

Each tampering changes what the file claims, not only its spelling, so that
proofs/check-certificate must reject the copy (exit 1). Every choice is
deterministic (the first place in the file where the tampering applies):

  swap-order         the first two consecutive events with different times
                     (event i+1 has order "<") exchange all their data except
                     the "order" fields, which stay in place: the file now
                     claims the later time first.
  move-root          the first event whose polynomial has another distinct
                     real root gets an isolating interval of that root (the
                     next larger one, else the next smaller one). If no event
                     polynomial has a second real root, the first event's
                     interval is shifted to [hi + 1, hi + 2], which holds no
                     root (the only real root is <= hi).
  claim-equal        the first "<" after the first event becomes "=".
  drop-certificate   the first event's certificate is removed from the active
                     list of the interval that ends at that event.
  drop-event         the first batch that has an interval after it is
                     deleted; its two neighbouring intervals are merged,
                     keeping the active list of the earlier one (which holds
                     the certificates that fail at the deleted time); later
                     motion changes keep their place among the other events.
  change-polynomial  the constant term of one certificate polynomial changes
                     by the smallest of +1, -1, +2, -2, ... that keeps it
                     primitive and distinct, in the certificates table and in
                     every event of that certificate. The certificate is the
                     lowest-id one that no event refers to, else certificate 0.
  move-vertex        one rest coordinate of one scene vertex a certificate
                     depends on changes by +1 (or, for a "vertices" motion,
                     the constant term of that coordinate's polynomial). The
                     certificate, vertex and coordinate (y, then x, then z)
                     are the first, in file order, for which the recomputed
                     polynomial (without perturbation) stays non-zero and is
                     no longer a constant multiple of the listed one.
  shift-reversal     the first motion change's reversal time moves earlier,
                     by 1/64 of the gap to the event before it (at most 1); the
                     new motions stay those reversed at the old time.
  late-contact       the first motion change's contact becomes a later root
                     of another certificate in force before the change: the
                     first of them, in the interval's order, with a root
                     isolated after the contact's interval. The real contact
                     is then a failure before the claimed one.
  unreversed-motion  the first motion change's first object keeps the motion
                     it had before (the scene's) instead of the reversed one.

Exit status: 0 written; 3 the tampering does not apply to this file (for
example, no events); 2 usage error or unreadable input.
Standard library only.
"""

import json
import re
import sys
from fractions import Fraction
from math import gcd

# Certificates may hold integers of more than the 4,300 digits Python 3.11
# converts by default (proofs/certificate_common.py).
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)

class NotApplicable(Exception):
    pass


# ---------------------------------------------------------------------------
# polynomials over Q: Fraction lists, constant term first

def trim(a):
    a = list(a)
    while a and a[-1] == 0:
        a.pop()
    return a


def padd(a, b):
    n = max(len(a), len(b))
    return trim([(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)])


def pneg(a):
    return [-x for x in a]


def psub(a, b):
    return padd(a, pneg(b))


def pmul(a, b):
    if not a or not b:
        return []
    out = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                out[i + j] += x * y
    return trim(out)


def pdivmod(a, b):
    a = [Fraction(x) for x in trim(a)]
    b = trim(b)
    q = [Fraction(0)] * max(len(a) - len(b) + 1, 1)
    while len(a) >= len(b) and a:
        c = a[-1] / b[-1]
        k = len(a) - len(b)
        q[k] = c
        for i, y in enumerate(b):
            a[i + k] -= c * y
        a = trim(a)
    return trim(q), a


def pgcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, pdivmod(a, b)[1]
    return a


def pderiv(a):
    return trim([i * a[i] for i in range(1, len(a))])


def peval(a, x):
    acc = Fraction(0)
    for c in reversed(a):
        acc = acc * x + c
    return acc


def sign(x):
    return (x > 0) - (x < 0)


def proportional(a, b):
    a, b = trim(a), trim(b)
    if len(a) != len(b) or not a:
        return False
    return all(x * b[-1] == y * a[-1] for x, y in zip(a, b))


class Sturm:
    def __init__(self, p):
        p = trim([Fraction(x) for x in p])
        g = pgcd(p, pderiv(p))
        p = pdivmod(p, g)[0] if len(g) > 1 else p  # square-free part
        self.p = p
        chain = [p, pderiv(p)]
        while len(chain[-1]) > 1:
            r = pdivmod(chain[-2], chain[-1])[1]
            if not r:
                break
            chain.append(pneg(r))
        self.chain = chain

    def var(self, x):
        signs = [sign(peval(s, x)) for s in self.chain]
        signs = [s for s in signs if s]
        return sum(1 for u, v in zip(signs, signs[1:]) if u != v)

    def count_closed(self, lo, hi):
        return self.var(lo) - self.var(hi) + (1 if peval(self.p, lo) == 0 else 0)

    def count_half_open(self, lo, hi):
        """Roots in (lo, hi]."""
        return self.var(lo) - self.var(hi)

    def roots(self):
        """Closed isolating intervals [lo, hi] of all distinct real roots, ascending."""
        p = self.p
        if len(p) < 2:
            return []
        bound = 1 + max(abs(c / p[-1]) for c in p[:-1])
        out = []
        stack = [(-bound, bound)]
        while stack:
            lo, hi = stack.pop()
            n = self.count_half_open(lo, hi)
            if n == 0:
                continue
            if n == 1:
                out.append(self.tighten(lo, hi))
                continue
            mid = (lo + hi) / 2
            stack.append((mid, hi))
            stack.append((lo, mid))
        out.sort()
        return out

    def first_root_after(self, x):
        """A closed isolating interval of the least root greater than x, within (x, +inf); None if none."""
        p = self.p
        if len(p) < 2:
            return None
        hi = max(x, Fraction(0)) + 1 + max(abs(c / p[-1]) for c in p[:-1])
        lo = x
        if self.count_half_open(lo, hi) == 0:
            return None
        while self.count_half_open(lo, hi) > 1:
            mid = (lo + hi) / 2
            if self.count_half_open(lo, mid) >= 1:
                hi = mid
            else:
                lo = mid
        return self.tighten(lo, hi)

    def tighten(self, lo, hi):
        """From (lo, hi] holding one root to a closed interval holding exactly that root."""
        if peval(self.p, hi) == 0:
            return (hi, hi)
        while self.count_closed(lo, hi) != 1:
            mid = (lo + hi) / 2
            if self.count_half_open(lo, mid) == 1:
                hi = mid
                if peval(self.p, hi) == 0:
                    return (hi, hi)
            else:
                lo = mid
        return (lo, hi)


def rat(s):
    return Fraction(s)


def fmt(x):
    return str(x.numerator) if x.denominator == 1 else "%d/%d" % (x.numerator, x.denominator)


# ---------------------------------------------------------------------------
# the scene's geometry (unperturbed; enough to choose a vertex that matters)

def number(v):
    if isinstance(v, bool):
        raise ValueError("boolean is not a number")
    if isinstance(v, int):
        return Fraction(v)
    return Fraction(str(v))


def poly(v):
    return trim([number(c) for c in v]) if isinstance(v, list) else trim([number(v)])


class Scene:
    def __init__(self, doc):
        self.doc = doc
        dc = doc.get("decomposition") or {}
        self.x = [poly(c) for c in dc["x"]] if "x" in dc else [[Fraction(1)], [], [], []]
        self.z = [poly(c) for c in dc["z"]] if "z" in dc else [[], [], [Fraction(1)], []]
        self.where = []  # global vertex -> (object index, local index)
        self.edges, self.tris = [], []
        for oi, ob in enumerate(doc["objects"]):
            base = len(self.where)
            self.where.extend((oi, i) for i in range(len(ob["vertices"])))
            seen = {}
            for tr in ob["triangles"]:
                self.tris.append(tuple(base + i for i in tr))
                for a, b in ((tr[0], tr[1]), (tr[1], tr[2]), (tr[2], tr[0])):
                    key = (min(a, b), max(a, b))
                    if key not in seen:
                        seen[key] = len(self.edges)
                        self.edges.append((base + a, base + b))

    def vertex(self, g):
        oi, li = self.where[g]
        ob = self.doc["objects"][oi]
        r = [poly(c) for c in ob["vertices"][li]]
        if len(r) == 3:
            r.append([Fraction(1)])
        m = ob.get("motion")
        if not m:
            return r
        if "translation" in m:
            d = [poly(c) for c in m["translation"]]
            return [padd(r[i], pmul(d[i], r[3])) for i in range(3)] + [r[3]]
        if "matrix" in m:
            M = [[poly(c) for c in row] for row in m["matrix"]]
            out = []
            for i in range(4):
                acc = []
                for j in range(4):
                    acc = padd(acc, pmul(M[i][j], r[j]))
                out.append(acc)
            return out
        return [poly(c) for c in m["vertices"][li]]


def det3(a, b, c):
    return padd(psub(pmul(a[0], psub(pmul(b[1], c[2]), pmul(b[2], c[1]))),
                     pmul(a[1], psub(pmul(b[0], c[2]), pmul(b[2], c[0])))),
                pmul(a[2], psub(pmul(b[0], c[1]), pmul(b[1], c[0]))))


def join3(p, q, r):
    m = []
    for j in range(4):
        cols = [k for k in range(4) if k != j]
        d = det3([p[k] for k in cols], [q[k] for k in cols], [r[k] for k in cols])
        m.append(d if (3 + j) % 2 == 0 else pneg(d))
    return m


def dot(h, p):
    acc = []
    for i in range(4):
        acc = padd(acc, pmul(h[i], p[i]))
    return acc


def meet(a, b, h):
    hb, ha = dot(h, b), dot(h, a)
    return [psub(pmul(hb, a[i]), pmul(ha, b[i])) for i in range(4)]


NAME = re.compile(r"(SV\([^()]*\)|[PET]\([0-9]+\)|P\(SV\([^()]*\)\))")


class Geo:
    def __init__(self, scene):
        self.s = scene

    def v(self, i):
        return self.s.vertex(i)

    def plane(self, k, i):
        if k == "P":
            return join3(self.s.x, self.s.z, self.v(i))
        if k == "E":
            a, b = self.s.edges[i]
            return join3(self.v(a), self.v(b), self.s.z)
        a, b, c = self.s.tris[i]
        return join3(self.v(a), self.v(b), self.v(c))

    def point(self, name):
        body = name[3:-1]
        parts = body.split(",")
        if len(parts) == 1:
            return self.v(int(parts[0][1:]))
        if parts[0] == "L":
            return meet(self.s.x, self.s.z, self.plane("T", int(parts[1][1:])))
        if len(parts) == 2 and parts[0][0] == "v":
            return meet(self.v(int(parts[0][1:])), self.s.z, self.plane("T", int(parts[1][1:])))
        if len(parts) == 2:
            a, b = self.s.edges[int(parts[0][1:])]
            return meet(self.v(a), self.v(b), self.plane(parts[1][0], int(parts[1][1:])))
        return join3(*[self.plane(p[0], int(p[1:])) for p in parts])

    def polynomial(self, kind, features):
        a, b = features.split(" ")
        if kind == "ET":
            (a0, a1), (c0, c1) = self.s.edges[int(a[2:-1])], self.s.edges[int(b[2:-1])]
            return dot(join3(self.v(a0), self.v(a1), self.v(c0)), self.v(c1))
        if kind == "II":
            return dot(join3(self.s.x, self.s.z, self.point(b[2:-1])), self.point(a))
        return dot(self.plane(b[0], int(b[2:-1])), self.point(a))


def vertices_of(scene, features):
    """The scene vertices a feature string depends on, in order of first mention."""
    out = []

    def add(v):
        if v not in out:
            out.append(v)

    for tok in re.finditer(r"(?:(SV)\(([^()]*)\))|(?:([PET])\(([0-9]+)\))", features):
        if tok.group(1):
            parts = tok.group(2).split(",")
            for p in parts:
                if p == "L":
                    continue
                k, i = p[0], int(p[1:])
                if k == "v" or k == "P":
                    add(i)
                elif k in "eE":
                    for v in scene.edges[i]:
                        add(v)
                elif k == "T":
                    for v in scene.tris[i]:
                        add(v)
        else:
            k, i = tok.group(3), int(tok.group(4))
            if k == "P":
                add(i)
            elif k == "E":
                for v in scene.edges[i]:
                    add(v)
            else:
                for v in scene.tris[i]:
                    add(v)
    return out


# ---------------------------------------------------------------------------
# tamperings

def batches_of(events):
    out = []
    for i, e in enumerate(events):
        if e["order"] == "<" or not out:
            out.append([i])
        else:
            out[-1].append(i)
    return out


def swap_order(doc):
    ev = doc["events"]
    for i in range(len(ev) - 1):
        if ev[i + 1]["order"] == "<":
            a, b = dict(ev[i]), dict(ev[i + 1])
            oa, ob = a["order"], b["order"]
            b["order"], a["order"] = oa, ob
            ev[i], ev[i + 1] = b, a
            return "events %d and %d exchanged" % (i, i + 1)
    raise NotApplicable("no two consecutive events with different times")


def move_root(doc):
    ev = doc["events"]
    if not ev:
        raise NotApplicable("no events")
    for i, e in enumerate(ev):
        st = Sturm([int(c) for c in e["polynomial"]])
        roots = st.roots()
        if len(roots) < 2:
            continue
        lo, hi = rat(e["interval"][0]), rat(e["interval"][1])
        k = next(j for j, (a, b) in enumerate(roots) if st.count_closed(max(a, lo), min(b, hi)) == 1
                 if max(a, lo) <= min(b, hi))
        j = k + 1 if k + 1 < len(roots) else k - 1
        a, b = roots[j]
        e["interval"] = [fmt(a), fmt(b)]
        return "event %d: interval of another root [%s, %s]" % (i, fmt(a), fmt(b))
    e = ev[0]
    hi = rat(e["interval"][1])
    e["interval"] = [fmt(hi + 1), fmt(hi + 2)]
    return "event 0: interval shifted to [%s, %s], no root" % (fmt(hi + 1), fmt(hi + 2))


def claim_equal(doc):
    ev = doc["events"]
    for i in range(1, len(ev)):
        if ev[i]["order"] == "<":
            ev[i]["order"] = "="
            return "event %d: \"<\" -> \"=\"" % i
    raise NotApplicable("no \"<\" after the first event")


def instants(doc):
    """The run order of batches and motion changes: ("batch", first event) or ("change", index)."""
    out = []
    changes = doc.get("motion_changes", [])  # none in a segment certificate
    j = 0
    for members in batches_of(doc["events"]):
        while j < len(changes) and changes[j]["after_events"] <= members[0]:
            out.append(("change", j))
            j += 1
        out.append(("batch", members[0]))
    out.extend(("change", k) for k in range(j, len(changes)))
    return out


def drop_certificate(doc):
    ev = doc["events"]
    if not ev:
        raise NotApplicable("no events")
    c = ev[0]["certificate"]
    k = instants(doc).index(("batch", 0))  # the interval that ends at event 0
    act = doc["intervals"][k]["active"]
    if c not in act:
        raise NotApplicable("the input is already invalid: certificate %d not active on interval %d" % (c, k))
    act.remove(c)
    return "interval %d: certificate %d removed" % (k, c)


def drop_event(doc):
    ev = doc["events"]
    ivs = doc["intervals"]
    order = instants(doc)
    for b, members in enumerate(batches_of(ev)):
        k = order.index(("batch", members[0]))
        if k + 1 < len(ivs):
            doc["events"] = [e for i, e in enumerate(ev) if i not in set(members)]
            del ivs[k + 1]
            for c in doc.get("motion_changes", []):
                if c["after_events"] > members[0]:
                    c["after_events"] -= len(members)
            return "batch %d (events %d..%d) deleted, intervals %d and %d merged" % (
                b, members[0], members[-1], k, k + 1)
    raise NotApplicable("no batch with an interval after it")


def first_change(doc):
    if not doc["motion_changes"]:
        raise NotApplicable("no motion changes")
    return doc["motion_changes"][0]


def shift_reversal(doc):
    c = first_change(doc)
    r = rat(c["time"])
    before = rat(doc["events"][c["after_events"] - 1]["interval"][1]) if c["after_events"] else rat(doc["start"])
    if before >= r:
        raise NotApplicable("the previous event's interval reaches the reversal time")
    shifted = r - min(Fraction(1), (r - before) / 64)
    c["time"] = fmt(shifted)
    return "motion change 0: reversal time %s -> %s, motions kept" % (fmt(r), fmt(shifted))


def late_contact(doc):
    c = first_change(doc)
    contact_hi = rat(c["failing"][0]["interval"][1])
    k = instants(doc).index(("change", 0))
    for cid in doc["intervals"][k]["active"]:
        cert = doc["certificates"][cid]
        st = Sturm([int(x) for x in cert["polynomial"]])
        later = st.first_root_after(contact_hi)
        if later:
            a, b = later
            c["failing"] = [{"certificate": cid, "kind": cert["kind"], "features": cert["features"],
                             "polynomial": cert["polynomial"], "interval": [fmt(a), fmt(b)], "multiplicity": 1}]
            return "motion change 0: the contact is now certificate %d at [%s, %s], after the real one" % (
                cid, fmt(a), fmt(b))
    raise NotApplicable("no certificate in force before the change has a root after the contact")


def unreversed_motion(doc):
    c = first_change(doc)
    o = c["objects"][0]
    before = doc["scene"]["objects"][o].get("motion")
    if before is None:
        raise NotApplicable("object %d had no motion" % o)
    c["motions"][0] = before
    return "motion change 0: object %d keeps its motion instead of reversing it" % o


def change_polynomial(doc):
    certs = doc["certificates"]
    if not certs:
        raise NotApplicable("no certificates")
    used = {e["certificate"] for e in doc["events"]}
    cid = next((i for i in range(len(certs)) if i not in used), 0)
    c = certs[cid]
    keys = {(d["kind"], d["features"], tuple(d["polynomial"])) for d in certs}
    p = [int(x) for x in c["polynomial"]]
    for k in (1, -1, 2, -2, 3, -3, 4, -4, 5, -5):
        q = [p[0] + k] + p[1:]
        g = 0
        for x in q:
            g = gcd(g, x)
        qs = [str(x) for x in q]
        if g == 1 and (c["kind"], c["features"], tuple(qs)) not in keys:
            break
    else:
        raise NotApplicable("no small change keeps the polynomial primitive")
    c["polynomial"] = qs
    n = 0
    for e in doc["events"]:
        if e["certificate"] == cid:
            e["polynomial"] = list(qs)
            n += 1
    return "certificate %d: constant term %d -> %d (and %d events)" % (cid, p[0], q[0], n)


def move_vertex(doc):
    if not doc["certificates"]:
        raise NotApplicable("no certificates")
    scene_doc = doc["scene"]
    scene = Scene(scene_doc)
    geo = Geo(scene)
    for cid, c in enumerate(doc["certificates"]):
        listed = [Fraction(int(x)) for x in c["polynomial"]]
        if not proportional(geo.polynomial(c["kind"], c["features"]), listed):
            continue  # decided by the perturbation: not used here
        for v in vertices_of(scene, c["features"]):
            oi, li = scene.where[v]
            ob = scene_doc["objects"][oi]
            for coord in (1, 0, 2):
                saved = json.dumps(ob)
                m = ob.get("motion")
                if m and "vertices" in m:
                    p = poly(m["vertices"][li][coord])
                    p = padd(p, [Fraction(1)])
                    m["vertices"][li][coord] = [fmt(x) for x in p] if p else "0"
                else:
                    p = padd(poly(ob["vertices"][li][coord]), [Fraction(1)])
                    ob["vertices"][li][coord] = fmt(p[0]) if p else "0"
                new = geo.polynomial(c["kind"], c["features"])
                if new and not proportional(new, listed):
                    return "scene vertex %d (object %d, vertex %d): coordinate %s + 1; certificate %d (%s %s) " \
                           "changes" % (v, oi, li, "xyz"[coord], cid, c["kind"], c["features"])
                ob.clear()
                ob.update(json.loads(saved))
    raise NotApplicable("no certificate depends on a single vertex coordinate in a detectable way")


ACTIONS = {"swap-order": swap_order, "move-root": move_root, "claim-equal": claim_equal,
           "drop-certificate": drop_certificate, "drop-event": drop_event,
           "change-polynomial": change_polynomial, "move-vertex": move_vertex, "shift-reversal": shift_reversal,
           "late-contact": late_contact, "unreversed-motion": unreversed_motion}


def main(argv, actions=ACTIONS, text=__doc__):
    """The command line of a tampering script with these actions (tamper_segments.py has its own)."""
    name = argv[0].rsplit("/", 1)[-1]
    if len(argv) == 2 and argv[1] in ("--help", "-h"):
        sys.stdout.write(text)
        return 0
    if len(argv) == 2 and argv[1] == "--list":
        sys.stdout.write("\n".join(actions) + "\n")
        return 0
    if len(argv) != 4 or argv[2] not in actions:
        sys.stderr.write("usage: %s IN TAMPERING OUT   (TAMPERING: %s)\n" % (name, ", ".join(actions)))
        return 2
    try:
        with open(argv[1], encoding="utf-8") as fh:
            # JSON numbers with a fraction or exponent (allowed in the scene) keep their exact text as a
            # string, which the scene format reads as the same exact decimal.
            doc = json.load(fh, parse_float=str)
    except (OSError, ValueError) as ex:
        sys.stderr.write("%s: cannot read %s: %s\n" % (name, argv[1], ex))
        return 2
    try:
        what = actions[argv[2]](doc)
    except NotApplicable as ex:
        sys.stderr.write("%s: %s does not apply: %s\n" % (name, argv[2], ex))
        return 3
    except (KeyError, TypeError, ValueError, IndexError) as ex:
        sys.stderr.write("%s: %s: the input is not a certificate this script understands: %r\n"
                         % (name, argv[2], ex))
        return 2
    with open(argv[3], "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
        fh.write("\n")
    sys.stdout.write("%s: %s\n" % (argv[2], what))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
