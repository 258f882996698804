"""Segment scenes: the check of a kvd-segment-event-order/1 certificate.

The file `kvd certify SEGMENT_SCENE --out FILE` writes for the kinetic
cylindrical BSP of moving segments (seed 003); the format and what it
proves are in proofs/event-order-certificate.md, "Segment scenes". Every
certificate's polynomials are recomputed from the scene embedded in the file
(format kvd-segments/1, SEGMENT_FORMAT.md) with the formulas below, which
restate src/segments/segment_predicates.cpp without using it.

Points are homogeneous (X, Y, W) over Q[t]; a x b is the cross product
(a1 b2 - a2 b1, a2 b0 - a0 b2, a0 b1 - a1 b0): the line through two points,
or the meet of two lines.
  endpoint e = 2s + k of segment s: its point3 under the segment's motion,
    times the least common multiple of its coefficients' denominators (so
    its coefficients are integers), all three coordinates negated when W < 0
    at the scene's start;
  perturbed, endpoint e is (X + eps lam_e W, Y + eps lam_e^2 W, W), with
    lam_e = 2 a + 1 + (e mod 2), a = 2 p i + (i^2 mod p), i = e div 2 and p
    the smallest prime >= max(2, n) for n segments;
  line(s) = P0 x P1, P0 and P1 its endpoints 2s and 2s + 1;
  point "sI.K" is endpoint 2I + K; point "sIxsJ" (I < J) is line(I) x line(J);
  dx(s) = X1 W0 - X0 W1;
  side factors of a point q against segment s: [line(s) . q, dx(s)], then
    W(q) unless q is an endpoint.
The factors of each certificate, in this order:
  x_order (a, b):   [X_a W_b - X_b W_a], then W_a if a is a crossing, then
                    W_b if b is a crossing; the sign of x(a) - x(b);
  side (p, s):      the side factors of p against s; +1 when p is above s;
  order_at (p, i, j): with q = p's point and v = (W_q, 0, -X_q) the vertical
                    line through it, the side factors of line(i) x v against
                    j; the sign of y_i - y_j at x(p).
A factor that vanishes identically in t is replaced by the first coefficient
in eps of its perturbed version that does not. Factors of degree >= 1 are the
certificate's polynomials, in order; the constant ones only enter its sign,
the product of the signs of all factors.

Checks (numbered as for the triangle format; the first failure is reported):
  1. structure: keys, types, point names and segment ids in range, no
     identity (a point compared with itself, a point on the segment it is
     compared with), signs +1 or -1, rationals and polynomials well formed;
  2. every certificate's polynomials equal, exactly and in order, the
     non-constant factors recomputed from the scene;
  3. every event's interval isolates exactly one distinct real root of the
     factor it names, of the stated multiplicity, which is odd;
  4. the order: "<" strictly, "=" exactly, the first event after start;
  5. the intervals: one before each batch, and a last one up to `end` (or
     +infinity) when the file has one; `end` after the last batch and within
     the scene's span; every event's certificate active on the interval that
     ends at the event;
  6. on every interval, no factor of an active certificate changes sign
     strictly inside (a root of odd multiplicity), and the certificate's sign
     there is its recorded sign, so the sign when made is the sign just after
     the instant it was made; at the end of the interval, every active
     certificate with a factor changing sign there is an event of that batch.
"""

import re
from fractions import Fraction

from certificate_common import (Alg, Arith, Invalid, batches_of, check_keys, check_order, fmt_rat, lcm, lowest_eps,
                                padd, parse_actives, parse_interval, parse_json_int, parse_order,
                                parse_rational, pmul, qq_to_ints, root_alg, scene_number, scene_poly, show)

FORMAT = "kvd-segment-event-order/1"
TOP_KEYS = ["format", "scene", "start", "end", "stopped_by", "certificates", "events", "intervals"]
CERT_KEYS = ["kind", "points", "segments", "sign", "polynomials"]
EVENT_KEYS = ["certificate", "factor", "interval", "multiplicity", "order"]
STOPPED = {"events", "until", "exhausted"}
# kind: (number of points, number of segments)
KINDS = {"x_order": (2, 0), "side": (1, 1), "order_at": (1, 2)}
ENDPOINT_RE = re.compile(r"s(0|[1-9][0-9]*)\.([01])\Z")
CROSSING_RE = re.compile(r"s(0|[1-9][0-9]*)xs(0|[1-9][0-9]*)\Z")


# ---------------------------------------------------------------------------
# the scene

def rest_point(v, place):
    if not isinstance(v, list) or len(v) not in (2, 3):
        raise Invalid(1, place, "expected [x, y] or a point3 [X, Y, W] of numbers, found %s" % show(v))
    p = [scene_number(c, "%s[%d]" % (place, i)) for i, c in enumerate(v)] + [Fraction(1)] * (3 - len(v))
    if p[2] == 0:
        raise Invalid(1, place, "W = 0: not a Euclidean point")
    return [[c] if c else [] for c in p]


def point3(v, place):
    if not isinstance(v, list) or len(v) != 3:
        raise Invalid(1, place, "expected a point3 [X, Y, W] of polynomials, found %s" % show(v))
    return [scene_poly(c, "%s[%d]" % (place, i)) for i, c in enumerate(v)]


def moved(rest, motion, place):
    """The two endpoints (point3s of Fraction lists) of a segment at rest `rest` under `motion`."""
    if motion is None:
        return rest
    if not isinstance(motion, dict) or len(motion) != 1:
        raise Invalid(1, place, "expected exactly one of translation, matrix, endpoints")
    (form, arg), = motion.items()
    if form == "translation":
        if not isinstance(arg, list) or len(arg) != 2:
            raise Invalid(1, place + ".translation", "expected [dx, dy]")
        d = [scene_poly(c, "%s.translation[%d]" % (place, i)) for i, c in enumerate(arg)]
        return [[padd(r[0], pmul(d[0], r[2])), padd(r[1], pmul(d[1], r[2])), r[2]] for r in rest]
    if form == "matrix":
        if not isinstance(arg, list) or len(arg) != 3 or any(not isinstance(row, list) or len(row) != 3 for row in arg):
            raise Invalid(1, place + ".matrix", "expected a 3x3 array of polynomials")
        M = [[scene_poly(arg[i][j], "%s.matrix[%d][%d]" % (place, i, j)) for j in range(3)] for i in range(3)]
        return [[padd(padd(pmul(M[i][0], r[0]), pmul(M[i][1], r[1])), pmul(M[i][2], r[2])) for i in range(3)]
                for r in rest]
    if form == "endpoints":
        if not isinstance(arg, list) or len(arg) != 2:
            raise Invalid(1, place + ".endpoints", "expected two point3s")
        return [point3(p, "%s.endpoints[%d]" % (place, k)) for k, p in enumerate(arg)]
    raise Invalid(1, place, "unknown motion form %r" % form)


def peval(p, x):
    acc = Fraction(0)
    for c in reversed(p):
        acc = acc * x + c
    return acc


class SegmentScene:
    def __init__(self, doc):
        P = "scene"
        check_keys(doc, P, ["format", "segments"], {"format", "name", "time", "priority", "segments"})
        if doc["format"] != "kvd-segments/1":
            raise Invalid(1, P + ".format", "expected \"kvd-segments/1\", found %s" % show(doc["format"]))
        self.start, self.end = Fraction(0), None
        if "time" in doc:
            check_keys(doc["time"], P + ".time", [], {"start", "end"})
            if "start" in doc["time"]:
                self.start = scene_number(doc["time"]["start"], P + ".time.start")
            if "end" in doc["time"]:
                self.end = scene_number(doc["time"]["end"], P + ".time.end")
                if self.end <= self.start:
                    raise Invalid(1, P + ".time", "start >= end")
        if "priority" in doc:  # the tree's business, not the certificates'
            check_keys(doc["priority"], P + ".priority", [], {"seed", "order"})
        segs = doc["segments"]
        if not isinstance(segs, list) or not segs:
            raise Invalid(1, P + ".segments", "expected a non-empty array of segments")
        self.endpoints = []  # per endpoint: (X, Y, W), Fraction lists, W > 0 at the start
        for s, seg in enumerate(segs):
            sp = "%s.segments[%d]" % (P, s)
            check_keys(seg, sp, ["endpoints"], {"name", "endpoints", "motion"})
            ends = seg["endpoints"]
            if not isinstance(ends, list) or len(ends) != 2:
                raise Invalid(1, sp + ".endpoints", "expected two endpoints")
            rest = [rest_point(r, "%s.endpoints[%d]" % (sp, k)) for k, r in enumerate(ends)]
            for k, p in enumerate(moved(rest, seg.get("motion"), sp + ".motion")):
                w = peval(p[2], self.start)
                if w == 0:
                    raise Invalid(1, sp, "endpoint %d has W = 0 at the start" % k)
                den = 1
                for x in p:
                    for c in x:
                        den = lcm(den, c.denominator)
                self.endpoints.append([[c * den * (-1 if w < 0 else 1) for c in x] for x in p])
        self.n = len(segs)


def is_prime(p):
    d = 2
    while d * d <= p:
        if p % d == 0:
            return False
        d += 1
    return True


def perturbation_lambda(e, n):
    p = max(2, n)
    while not is_prime(p):
        p += 1
    i = e // 2
    a = 2 * p * i + (i * i) % p
    return 2 * a + 1 + e % 2


# ---------------------------------------------------------------------------
# the factors

def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


class Ring:
    """The endpoints over Q[t] (perturbed False) or Q[t, eps], with their lines and crossings."""

    def __init__(self, sp, scene, perturbed):
        QQ = sp.QQ
        gens = (sp.T, sp.EPS) if perturbed else (sp.T,)

        def lift(c):
            return sp.Poly.from_dict({((i, 0) if perturbed else (i,)): QQ(x.numerator, x.denominator)
                                      for i, x in enumerate(c) if x}, *gens, domain=QQ)

        self.zero = lift([])
        self.e = []
        for k, p in enumerate(scene.endpoints):
            X, Y, W = [lift(c) for c in p]
            if perturbed:
                lam = perturbation_lambda(k, scene.n)
                eps = sp.Poly.from_dict({(0, 1): QQ(1)}, *gens, domain=QQ)
                X, Y = X + eps * W * lam, Y + eps * W * (lam * lam)
            self.e.append([X, Y, W])
        self.lines = {}
        self.points = {}

    def line(self, s):
        if s not in self.lines:
            self.lines[s] = cross(self.e[2 * s], self.e[2 * s + 1])
        return self.lines[s]

    def point(self, p):
        if p[0] == "e":
            return self.e[p[1]]
        if p not in self.points:
            self.points[p] = cross(self.line(p[1]), self.line(p[2]))
        return self.points[p]

    def dx(self, s):
        p0, p1 = self.e[2 * s], self.e[2 * s + 1]
        return p1[0] * p0[2] - p0[0] * p1[2]

    def side_factors(self, q, s, q_is_endpoint):
        return [dot(self.line(s), q), self.dx(s)] + ([] if q_is_endpoint else [q[2]])

    def factors(self, c):
        kind, pts, segs = c["kind"], c["pts"], c["segs"]
        if kind == "x_order":
            a, b = pts
            pa, pb = self.point(a), self.point(b)
            return ([pa[0] * pb[2] - pb[0] * pa[2]] + ([pa[2]] if a[0] == "x" else [])
                    + ([pb[2]] if b[0] == "x" else []))
        q = self.point(pts[0])
        if kind == "side":
            return self.side_factors(q, segs[0], pts[0][0] == "e")
        vertical = [q[2], self.zero, -q[0]]
        return self.side_factors(cross(self.line(segs[0]), vertical), segs[1], False)


def poly_fractions(p):
    """A SymPy Poly in t as Fractions, constant first."""
    out = [Fraction(int(c.numerator), int(c.denominator)) for c in reversed(p.rep.to_list())]
    while out and out[-1] == 0:
        out.pop()
    return out


# ---------------------------------------------------------------------------
# the file

def parse_point(v, n, place):
    """("e", endpoint) or ("x", a, b), a < b."""
    if type(v) is str:
        m = ENDPOINT_RE.match(v)
        if m and int(m.group(1)) < n:
            return ("e", 2 * int(m.group(1)) + int(m.group(2)))
        m = CROSSING_RE.match(v)
        if m and int(m.group(1)) < int(m.group(2)) < n:
            return ("x", int(m.group(1)), int(m.group(2)))
    raise Invalid(1, place, "expected a point \"sI.K\" (K 0 or 1) or \"sIxsJ\" (I < J), segments < %d, found %s"
                  % (n, show(v)))


def on(p, s):
    """Whether point p lies on segment s by construction."""
    return p[1] // 2 == s if p[0] == "e" else s in p[1:]


def parse_certificate(c, n, place):
    check_keys(c, place, CERT_KEYS, set(CERT_KEYS))
    kind = c["kind"]
    if type(kind) is not str or kind not in KINDS:
        raise Invalid(1, place, "kind %s is not one of %s" % (show(kind), sorted(KINDS)))
    npts, nsegs = KINDS[kind]
    if not isinstance(c["points"], list) or len(c["points"]) != npts:
        raise Invalid(1, place + ": points", "%s names %d point(s)" % (kind, npts))
    if not isinstance(c["segments"], list) or len(c["segments"]) != nsegs:
        raise Invalid(1, place + ": segments", "%s names %d segment(s)" % (kind, nsegs))
    pts = tuple(parse_point(v, n, "%s: points[%d]" % (place, i)) for i, v in enumerate(c["points"]))
    segs = tuple(parse_json_int(v, 1, "%s: segments[%d]" % (place, i), 0) for i, v in enumerate(c["segments"]))
    if any(s >= n for s in segs):
        raise Invalid(1, place + ": segments", "segment id out of range (%d segments)" % n)
    # The identities: decided without arithmetic, never certificates.
    if kind == "x_order" and pts[0] == pts[1]:
        raise Invalid(1, place, "a point compared with itself")
    if kind != "x_order" and any(on(pts[0], s) for s in segs):
        raise Invalid(1, place, "the point lies on a segment it is compared with, by construction")
    if kind == "order_at" and segs[0] == segs[1]:
        raise Invalid(1, place, "the order of a line with itself")
    if c["sign"] not in (1, -1) or type(c["sign"]) is not int:
        raise Invalid(1, place + ": sign", "expected 1 or -1, found %s" % show(c["sign"]))
    if not isinstance(c["polynomials"], list):
        raise Invalid(1, place + ": polynomials", "expected an array of polynomials")
    polys = []
    for f, p in enumerate(c["polynomials"]):
        fp = "%s: polynomials[%d]" % (place, f)
        if not isinstance(p, list) or len(p) < 2:
            raise Invalid(1, fp, "expected an array of at least two rationals (a non-constant polynomial)")
        q = [parse_rational(x, 1, "%s[%d]" % (fp, i)) for i, x in enumerate(p)]
        if q[-1] == 0:
            raise Invalid(1, fp, "the leading (last) coefficient is zero")
        polys.append(q)
    return {"kind": kind, "pts": pts, "segs": segs, "sign": c["sign"], "polys": polys}


def parse_event(e, certs, place):
    check_keys(e, place, EVENT_KEYS, set(EVENT_KEYS))
    cid = parse_json_int(e["certificate"], 1, place + ": certificate", 0)
    if cid >= len(certs):
        raise Invalid(1, place, "certificate id %d out of range (%d certificates)" % (cid, len(certs)))
    f = parse_json_int(e["factor"], 1, place + ": factor", 0)
    if f >= len(certs[cid]["polys"]):
        raise Invalid(1, place + ": factor", "certificate %d has %d polynomial(s)" % (cid, len(certs[cid]["polys"])))
    lo, hi = parse_interval(e["interval"], place + ": interval")
    mult = parse_json_int(e["multiplicity"], 1, place + ": multiplicity", 1)
    return {"cid": cid, "factor": f, "lo": lo, "hi": hi, "mult": mult,
            "order": parse_order(e["order"], place + ": order"), "place": place}


def ints(q):
    """Fractions (constant first) times a positive integer: integer coefficients, same signs everywhere."""
    d = 1
    for c in q:
        d = lcm(d, c.denominator)
    return tuple(int(c * d) for c in q)


def checked(doc, sp):
    """Checks 1-6 of the module docstring on the document; returns the summary of what was checked."""
    arith = Arith(sp)

    # ---- check 1: structure
    check_keys(doc, "file", TOP_KEYS, set(TOP_KEYS))
    scene = SegmentScene(doc["scene"])
    start = parse_rational(doc["start"], 1, "start")
    if start != scene.start:
        raise Invalid(1, "start", "start %s is not the scene's start time %s" % (fmt_rat(start), fmt_rat(scene.start)))
    end = None if doc["end"] is None else parse_rational(doc["end"], 1, "end")
    stopped = doc["stopped_by"]
    if type(stopped) is not str or stopped not in STOPPED:
        raise Invalid(1, "stopped_by", "expected one of %s, found %s" % (sorted(STOPPED), show(stopped)))
    if end is not None and stopped == "events":
        raise Invalid(1, "end", "end is %s but the run stopped at an event it did not process" % fmt_rat(end))
    if not isinstance(doc["certificates"], list):
        raise Invalid(1, "certificates", "expected an array")
    certs = [parse_certificate(c, scene.n, "certificate %d" % i) for i, c in enumerate(doc["certificates"])]
    if not isinstance(doc["events"], list):
        raise Invalid(1, "events", "expected an array")
    events = [parse_event(e, certs, "event %d" % i) for i, e in enumerate(doc["events"])]
    batches = batches_of(events)
    actives = parse_actives(doc["intervals"], len(certs))

    def describe(cid):
        c = doc["certificates"][cid]
        return "certificate %d (%s)" % (cid, " ".join([c["kind"]] + c["points"] + [str(s) for s in c["segments"]]))

    # ---- check 2: every certificate's polynomials are the scene's
    g0 = Ring(sp, scene, False)
    g1 = None
    perturbed = 0
    for i, c in enumerate(certs):
        place = describe(i)
        deciding = []
        for f, v in enumerate(g0.factors(c)):
            if v.is_zero:
                g1 = g1 or Ring(sp, scene, True)
                v = lowest_eps(sp, g1.factors(c)[f])
                perturbed += 1
                if v.is_zero:
                    raise Invalid(2, place, "factor %d vanishes identically, and so does every coefficient of its "
                                  "perturbation" % f)
            deciding.append(poly_fractions(v))
        c["const_sign"] = 1
        for q in deciding:
            if len(q) == 1:
                c["const_sign"] *= 1 if q[0] > 0 else -1
        recomputed = [q for q in deciding if len(q) > 1]
        if recomputed != c["polys"]:
            raise Invalid(2, place, "the listed polynomials %s are not the scene's, %s"
                          % (show([[fmt_rat(x) for x in q] for q in c["polys"]]),
                             show([[fmt_rat(x) for x in q] for q in recomputed])))
        c["infos"] = [arith.poly_info(ints(q)) for q in c["polys"]]
        product = sp.Poly(1, sp.T, domain=sp.QQ)
        for pi in c["infos"]:
            product = product * pi.poly
        c["product"] = qq_to_ints(product)

    # ---- check 3: the roots
    for e in events:
        e["alg"] = root_alg(certs[e["cid"]]["infos"][e["factor"]], e["lo"], e["hi"], e["mult"], e["place"])

    # ---- check 4: the order
    start_alg = Alg.rational(start)
    check_order(arith, events, start_alg)

    # ---- check 5: the intervals
    trailing = end is not None or (stopped == "exhausted" and scene.end is None)
    want = len(batches) + (1 if trailing else 0)
    if len(actives) != want:
        raise Invalid(5, "intervals", "%d intervals listed, %d required (one before each of %d batches%s)"
                      % (len(actives), want, len(batches), ", and the last one after them" if trailing else ""))
    bounds = [start_alg] + [events[b[0]]["alg"] for b in batches]
    if end is not None:
        if arith.compare(bounds[-1], Alg.rational(end)) >= 0:
            raise Invalid(5, "end", "end %s is not later than the last instant %s" % (fmt_rat(end), bounds[-1].describe()))
        if scene.end is not None and end > scene.end:
            raise Invalid(5, "end", "end %s is after the scene's end %s" % (fmt_rat(end), fmt_rat(scene.end)))
        bounds.append(Alg.rational(end))
    elif trailing:
        bounds.append(None)  # +infinity
    failing = [set(events[i]["cid"] for i in b) for b in batches]
    for i, e in enumerate(events):
        if e["cid"] not in actives[e["batch"]]:
            raise Invalid(5, "event %d" % i, "its certificate %d is not active on interval %d, which ends at the event"
                          % (e["cid"], e["batch"]))

    # ---- check 6: no failure inside an interval, the signs, every failure at its end listed
    def clean(cid, a, b):
        """Whether no factor of the certificate changes sign strictly between a and b."""
        return all(pi.odd is None or arith.roots_between(pi.odd, a, b) == 0 for pi in certs[cid]["infos"])

    def check_sign(cid, k, a, b):
        c = certs[cid]
        x, s = arith.sample(c["product"], a, b) if c["polys"] else (None, 1)
        if s * c["const_sign"] != c["sign"]:
            raise Invalid(6, "interval %d" % k, "%s has sign %d there (at t = %s), not its recorded %d"
                          % (describe(cid), s * c["const_sign"], fmt_rat(x) if x is not None else "any", c["sign"]))

    on_intervals = {}
    for k, act in enumerate(actives):
        for cid in act:
            on_intervals.setdefault(cid, []).append(k)
    runs = pairs = 0
    for cid in sorted(on_intervals):
        ks = on_intervals[cid]
        j = 0
        while j < len(ks):
            l = j
            while l + 1 < len(ks) and ks[l + 1] == ks[l] + 1:
                l += 1
            runs += 1
            pairs += l - j + 1
            # A run of intervals at once when no factor changes sign on it (instants included), else one by one.
            if clean(cid, bounds[ks[j]], bounds[ks[l] + 1]):
                check_sign(cid, ks[j], bounds[ks[j]], bounds[ks[l] + 1])
            else:
                for k in ks[j:l + 1]:
                    if not clean(cid, bounds[k], bounds[k + 1]):
                        raise Invalid(6, "interval %d" % k, "%s changes sign strictly inside the interval, between "
                                      "%s and %s" % (describe(cid), bounds[k].describe(),
                                                     "+infinity" if bounds[k + 1] is None else bounds[k + 1].describe()))
                    check_sign(cid, k, bounds[k], bounds[k + 1])
            j = l + 1
    for b, members in enumerate(batches):
        tau = bounds[b + 1]
        for cid in actives[b]:
            if cid in failing[b]:
                continue
            if any(pi.odd is not None and arith.is_root(tau, pi.odd) for pi in certs[cid]["infos"]):
                raise Invalid(6, "event %d" % members[0], "%s changes sign at this batch's time %s but is not one of "
                              "its events" % (describe(cid), tau.describe()))

    return ("%d events in %d batches, %d certificates recomputed (%d factors by the perturbation), %d intervals, "
            "%d active (certificate, interval) pairs in %d runs checked"
            % (len(events), len(batches), len(certs), perturbed, len(actives), pairs, runs))
