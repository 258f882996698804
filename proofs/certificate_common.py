"""What the checks of both certificate formats share (proofs/check-certificate,
proofs/event-order-certificate.md): the failed-check exception, JSON reading
that keeps exact number text, rationals and scene numbers, integer
polynomials with Sturm sequences, real algebraic numbers and their exact
comparison, and the checks of event roots (check 3) and event order
(check 4). Exact throughout: Python integers and fractions, SymPy
polynomials over QQ; no floating point.
"""

import json
import re
import sys
from fractions import Fraction
from math import gcd

# Python 3.11 refuses to convert integers of more than 4,300 digits to and
# from text by default; the formats allow numbers of 10,001 digits, and
# their products in a certificate have more.
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)


class Invalid(Exception):
    """A failed check: `place` names where in the file, `msg` what failed."""

    def __init__(self, check, place, msg):
        Exception.__init__(self, msg)
        self.check = check
        self.place = place
        self.msg = msg


# ---------------------------------------------------------------------------
# JSON reading

class JFloat(str):
    """The exact text of a JSON number with a fraction or exponent part."""


class DuplicateKey(ValueError):
    pass


def _pairs(pairs):
    out = {}
    for k, v in pairs:
        if k in out:
            raise DuplicateKey("duplicate key %r" % k)
        out[k] = v
    return out


def _bad_constant(name):
    raise ValueError("not a JSON number: %s" % name)


def load_json(text):
    return json.loads(text, object_pairs_hook=_pairs, parse_float=JFloat, parse_constant=_bad_constant)


# ---------------------------------------------------------------------------
# numbers

RATIONAL_RE = re.compile(r"-?[0-9]+(/[0-9]+)?\Z")
INTEGER_RE = re.compile(r"-?[0-9]+\Z")
SCENE_INT_RE = re.compile(r"-?[0-9]+\Z")
SCENE_DEC_RE = re.compile(r"-?[0-9]+(\.[0-9]+)?([eE][+-]?([0-9]+))?\Z")
SCENE_FRAC_RE = re.compile(r"-?[0-9]+/[0-9]+\Z")
JSON_FLOAT_RE = re.compile(r"-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?([0-9]+))?\Z")


def parse_rational(v, check, place):
    """A certificate-file rational: the string "p/q" or "n"."""
    if type(v) is not str or not RATIONAL_RE.match(v):
        raise Invalid(check, place, "expected a rational string \"p/q\" or \"n\", found %s" % show(v))
    if "/" in v:
        n, d = v.split("/")
        if int(d) == 0:
            raise Invalid(check, place, "rational %r has a zero denominator" % v)
        return Fraction(int(n), int(d))
    return Fraction(int(v))


def parse_int_string(v, check, place):
    if type(v) is not str or not INTEGER_RE.match(v):
        raise Invalid(check, place, "expected a decimal integer string, found %s" % show(v))
    return int(v)


def parse_json_int(v, check, place, minimum=None):
    if type(v) is not int:
        raise Invalid(check, place, "expected a JSON integer, found %s" % show(v))
    if minimum is not None and v < minimum:
        raise Invalid(check, place, "expected an integer >= %d, found %d" % (minimum, v))
    return v


def scene_number(v, place):
    """A scene number (SCENE_FORMAT.md): JSON integer, JSON decimal text, or string."""
    check = 1
    if type(v) is int:
        return Fraction(v)
    if type(v) is JFloat:
        m = JSON_FLOAT_RE.match(v)
        if not m:
            raise Invalid(check, place, "unparsable number %s" % v)
        if m.group(4) is not None and int(m.group(4)) > 10000:
            raise Invalid(check, place, "exponent above 10000 in %s" % v)
        return Fraction(str(v))
    if type(v) is str:
        if SCENE_INT_RE.match(v):
            return Fraction(int(v))
        if SCENE_FRAC_RE.match(v):
            n, d = v.split("/")
            if int(d) == 0:
                raise Invalid(check, place, "number %r has a zero denominator" % v)
            return Fraction(int(n), int(d))
        m = SCENE_DEC_RE.match(v)
        if m:
            if m.group(3) is not None and int(m.group(3)) > 10000:
                raise Invalid(check, place, "exponent above 10000 in %r" % v)
            return Fraction(v)
        raise Invalid(check, place, "not a number: %r" % v)
    raise Invalid(check, place, "expected a number, found %s" % show(v))


def show(v):
    s = json.dumps(v) if not isinstance(v, JFloat) else str(v)
    return s if len(s) <= 80 else s[:77] + "..."


def fmt_rat(x):
    return str(x.numerator) if x.denominator == 1 else "%d/%d" % (x.numerator, x.denominator)


# ---------------------------------------------------------------------------
# integer polynomials (coefficient lists, constant term first) and signs

def sgn(x):
    return (x > 0) - (x < 0)


def ipoly_sign(c, x):
    """Sign of the integer polynomial c at the rational x (exact)."""
    n, d = x.numerator, x.denominator
    k = len(c) - 1
    if k < 0:
        return 0
    if d == 1:
        acc = 0
        for a in reversed(c):
            acc = acc * n + a
        return sgn(acc)
    acc = c[k]
    dp = 1
    for i in range(k - 1, -1, -1):
        dp *= d
        acc = acc * n + c[i] * dp
    return sgn(acc)


def lcm(a, b):
    return a // gcd(a, b) * b


def qq_to_ints(p):
    """A SymPy Poly in t over QQ, scaled by a positive rational to integer coefficients, constant first."""
    cs = p.rep.to_list()  # highest first
    den = 1
    for c in cs:
        den = lcm(den, int(c.denominator))
    out = [int(c.numerator) * (den // int(c.denominator)) for c in cs]
    out.reverse()
    while out and out[-1] == 0:
        out.pop()
    return out


class Sturm:
    """The Sturm sequence of a square-free polynomial q of degree >= 1 (SymPy's Poly.sturm, kept as
    integer coefficient lists scaled by positive factors, which keeps every sign)."""

    _next_key = 0

    def __init__(self, poly):
        self.poly = poly
        self.chain = [qq_to_ints(s) for s in poly.sturm()]
        self.q = self.chain[0]
        self.key = Sturm._next_key
        Sturm._next_key += 1
        self._var_inf = None

    def sign(self, x):
        return ipoly_sign(self.q, x)

    def var(self, x):
        v = 0
        last = 0
        for s in self.chain:
            g = ipoly_sign(s, x)
            if g:
                if last and g != last:
                    v += 1
                last = g
        return v

    def var_inf(self):
        if self._var_inf is None:
            v = 0
            last = 0
            for s in self.chain:
                g = sgn(s[-1])
                if last and g != last:
                    v += 1
                last = g
            self._var_inf = v
        return self._var_inf

    def count_closed(self, a, b):
        """Distinct real roots of q in [a, b], a <= b rational."""
        return self.var(a) - self.var(b) + (1 if self.sign(a) == 0 else 0)

    def count_open(self, a, b):
        """Distinct real roots of q in (a, b), a < b rational, b None for +infinity."""
        if b is None:
            return self.var(a) - self.var_inf()
        return self.var(a) - self.var(b) - (1 if self.sign(b) == 0 else 0)


# ---------------------------------------------------------------------------
# real algebraic numbers: a square-free q with exactly one root in [lo, hi]

class Alg:
    _next_id = 0

    def __init__(self, st, lo, hi):
        self.st = st
        self.lo = lo
        self.hi = hi
        self.id = Alg._next_id
        Alg._next_id += 1
        self.rat = False
        self.slo = 0
        if lo == hi:
            self.rat = True
        elif st.sign(lo) == 0:
            self.hi = lo
            self.rat = True
        elif st.sign(hi) == 0:
            self.lo = hi
            self.rat = True
        else:
            self.slo = st.sign(lo)

    @staticmethod
    def rational(x):
        a = Alg.__new__(Alg)
        a.st = None
        a.lo = a.hi = x
        a.rat = True
        a.slo = 0
        a.id = Alg._next_id
        Alg._next_id += 1
        return a

    def bisect(self):
        if self.rat:
            return
        m = (self.lo + self.hi) / 2
        s = self.st.sign(m)
        if s == 0:
            self.lo = self.hi = m
            self.rat = True
        elif s == self.slo:
            self.lo = m
        else:
            self.hi = m

    def describe(self):
        if self.rat:
            return fmt_rat(self.lo)
        return "the root of %s in [%s, %s]" % (show_ints(self.st.q), fmt_rat(self.lo), fmt_rat(self.hi))


def show_ints(c):
    return "[" + ", ".join('"%d"' % a for a in c) + "]"


class Arith:
    """Exact comparisons, with caches of gcds and of root memberships."""

    def __init__(self, sp):
        self.sp = sp
        self.gcd_cache = {}
        self.root_cache = {}
        self.sturm_cache = {}
        self.info_cache = {}

    def poly_info(self, ints):
        """The PolyInfo of an integer polynomial (a tuple, constant first), made once."""
        pi = self.info_cache.get(ints)
        if pi is None:
            pi = PolyInfo(self.sp, self, ints)
            self.info_cache[ints] = pi
        return pi

    def sturm_of(self, poly):
        key = tuple(qq_to_ints(poly))
        st = self.sturm_cache.get(key)
        if st is None:
            st = Sturm(poly)
            self.sturm_cache[key] = st
        return st

    def gcd_sturm(self, s1, s2):
        """Sturm data of gcd(q1, q2), or None if the gcd is constant."""
        key = (min(s1.key, s2.key), max(s1.key, s2.key))
        if key not in self.gcd_cache:
            g = s1.poly.gcd(s2.poly)
            self.gcd_cache[key] = self.sturm_of(g) if g.degree() >= 1 else None
        return self.gcd_cache[key]

    def is_root(self, a, st):
        """Whether the algebraic number a is a root of st.q."""
        if a.rat:
            return st.sign(a.lo) == 0
        key = (a.id, st.key)
        r = self.root_cache.get(key)
        if r is None:
            if st.count_closed(a.lo, a.hi) == 0:
                r = False
            else:
                g = self.gcd_sturm(a.st, st)
                r = g is not None and g.count_closed(a.lo, a.hi) > 0
            self.root_cache[key] = r
        return r

    def equal(self, a, b):
        if a.rat and b.rat:
            return a.lo == b.lo
        if a.rat or b.rat:
            r, o = (a, b) if a.rat else (b, a)
            return o.lo <= r.lo <= o.hi and o.st.sign(r.lo) == 0
        lo = max(a.lo, b.lo)
        hi = min(a.hi, b.hi)
        if lo > hi:
            return False
        g = self.gcd_sturm(a.st, b.st)
        return g is not None and g.count_closed(lo, hi) > 0

    def compare(self, a, b):
        """-1, 0, +1 as a <, =, > b."""
        if a.rat and b.rat:
            return sgn(a.lo - b.lo)
        if self.equal(a, b):
            return 0
        while True:
            if a.hi < b.lo:
                return -1
            if b.hi < a.lo:
                return 1
            a.bisect()
            b.bisect()

    def isolate(self, a, st):
        """Refine a until [lo, hi] holds no root of st.q other than a itself."""
        if a.rat:
            return
        want = 1 if self.is_root(a, st) else 0
        while not a.rat and st.count_closed(a.lo, a.hi) != want:
            a.bisect()

    def separate(self, a, b):
        """For a < b (b None: +infinity): refine until a.hi < b.lo."""
        if b is None:
            return
        while not a.hi < b.lo:
            if a.rat and b.rat:
                raise AssertionError("separate called with a >= b")
            a.bisect()
            b.bisect()

    def roots_between(self, st, a, b):
        """Distinct roots of st.q strictly between a < b (b None: +infinity)."""
        self.isolate(a, st)
        if b is not None:
            self.isolate(b, st)
        self.separate(a, b)
        return st.count_open(a.hi, None if b is None else b.lo)

    def sample(self, ints, a, b):
        """A rational strictly between a < b at which the integer polynomial ints is non-zero; with its sign."""
        self.separate(a, b)
        lo = a.hi
        k = 1
        while True:
            if b is None:
                x = lo + k
            else:
                x = lo + (b.lo - lo) / (k + 1)
            s = ipoly_sign(ints, x)
            if s != 0:
                return x, s
            k += 1


# ---------------------------------------------------------------------------
# polynomials over Q (Fraction lists, constant first) and JSON objects

def scene_poly(v, place):
    """A polynomial in t: a number or an array of numbers; returns Fractions, constant first, trimmed."""
    if isinstance(v, list):
        out = [scene_number(c, "%s[%d]" % (place, i)) for i, c in enumerate(v)]
    else:
        out = [scene_number(v, place)]
    while out and out[-1] == 0:
        out.pop()
    return out


def pmul(a, b):
    if not a or not b:
        return []
    out = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                out[i + j] += x * y
    while out and out[-1] == 0:
        out.pop()
    return out


def padd(a, b):
    n = max(len(a), len(b))
    out = [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]
    out = [Fraction(c) for c in out]
    while out and out[-1] == 0:
        out.pop()
    return out


def check_keys(obj, place, required, allowed, check=1):
    if not isinstance(obj, dict):
        raise Invalid(check, place, "expected an object, found %s" % show(obj))
    for k in required:
        if k not in obj:
            raise Invalid(check, place, "missing key %r" % k)
    for k in obj:
        if k not in allowed:
            raise Invalid(check, place, "unknown key %r" % k)


# ---------------------------------------------------------------------------
# SymPy

class SymPy:
    def __init__(self):
        import sympy
        self.Poly = sympy.Poly
        self.QQ = sympy.QQ
        self.T, self.EPS = sympy.symbols("t eps")


def lowest_eps(sp, p):
    """The lowest-order coefficient in eps of p in Q[t, eps], as a Poly in t (zero if p is zero)."""
    d = p.rep.to_dict()
    if not d:
        return sp.Poly.from_dict({}, sp.T, domain=sp.QQ)
    j = min(k[1] for k in d)
    return sp.Poly.from_dict({(k[0],): c for k, c in d.items() if k[1] == j}, sp.T, domain=sp.QQ)


class PolyInfo:
    """Square-free decomposition and Sturm data of one listed (integer) polynomial."""

    def __init__(self, sp, arith, ints):
        self.ints = list(ints)
        QQ = sp.QQ
        self.poly = sp.Poly.from_dict({(i,): QQ(c) for i, c in enumerate(ints) if c}, sp.T, domain=QQ)
        _, facs = self.poly.sqf_list()
        self.factors = [(f, m, arith.sturm_of(f)) for f, m in facs if f.degree() >= 1]
        odd = None
        for f, m, _ in self.factors:
            if m % 2 == 1:
                odd = f if odd is None else odd * f
        self.odd = arith.sturm_of(odd) if odd is not None else None


# ---------------------------------------------------------------------------
# events: their order, batches, roots; the active lists of intervals

def parse_order(v, place):
    if type(v) is not str or v not in ("<", "="):
        raise Invalid(1, place, "expected \"<\" or \"=\", found %s" % show(v))
    return v


def parse_interval(v, place):
    if not isinstance(v, list) or len(v) != 2:
        raise Invalid(1, place, "expected [lo, hi], found %s" % show(v))
    return parse_rational(v[0], 1, place + "[0]"), parse_rational(v[1], 1, place + "[1]")


def batches_of(events):
    """The batches, maximal runs of "=" after a "<", as lists of event indices; sets each event's "batch"."""
    if events and events[0]["order"] != "<":
        raise Invalid(1, "event 0: order", "the first event must be \"<\" (later than start)")
    batches = []
    for i, e in enumerate(events):
        if e["order"] == "<":
            batches.append([i])
        else:
            batches[-1].append(i)
        e["batch"] = len(batches) - 1
    return batches


def parse_actives(ivs_in, count):
    """The "intervals" array: per interval, its list of active certificate ids (< count, no repeats)."""
    if not isinstance(ivs_in, list):
        raise Invalid(1, "intervals", "expected an array")
    actives = []
    for k, iv in enumerate(ivs_in):
        place = "interval %d" % k
        check_keys(iv, place, ["active"], {"active"})
        act = iv["active"]
        if not isinstance(act, list):
            raise Invalid(1, place + ": active", "expected an array of certificate ids")
        ids = []
        for j, a in enumerate(act):
            a = parse_json_int(a, 1, "%s: active[%d]" % (place, j), 0)
            if a >= count:
                raise Invalid(1, "%s: active[%d]" % (place, j), "certificate id %d out of range" % a)
            ids.append(a)
        if len(set(ids)) != len(ids):
            raise Invalid(1, place + ": active", "a certificate id is listed twice")
        actives.append(ids)
    return actives


def root_alg(pi, lo, hi, mult, place):
    """Check 3 for one root: [lo, hi] holds exactly one distinct real root of pi's polynomial, of
    multiplicity mult, which is odd (the polynomial changes sign there). Returns that root."""
    if lo > hi:
        raise Invalid(3, place, "interval [%s, %s] has lo > hi" % (fmt_rat(lo), fmt_rat(hi)))
    found = []
    for f, m, st in pi.factors:
        n = st.count_closed(lo, hi)
        if n:
            found.append((n, m, st))
    total = sum(n for n, _, _ in found)
    if total != 1:
        raise Invalid(3, place, "interval [%s, %s] contains %d distinct real roots of the polynomial, not "
                      "exactly one" % (fmt_rat(lo), fmt_rat(hi), total))
    _, m, st = found[0]
    if m != mult:
        raise Invalid(3, place, "the root has multiplicity %d, the file states %d" % (m, mult))
    if m % 2 == 0:
        raise Invalid(3, place, "the root has even multiplicity %d: the polynomial does not change sign" % m)
    return Alg(st, lo, hi)


def check_order(arith, events, start_alg):
    """Check 4 for the events (each with its root "alg" and "order"): the first later than start_alg,
    every "<" strictly later than the event before it, every "=" equal to it."""
    for i, e in enumerate(events):
        place = "event %d" % i
        if i == 0:
            if arith.compare(start_alg, e["alg"]) >= 0:
                raise Invalid(4, place, "the event time %s is not later than start %s"
                              % (e["alg"].describe(), start_alg.describe()))
            continue
        prev = events[i - 1]["alg"]
        if e["order"] == "=":
            if not arith.equal(prev, e["alg"]):
                raise Invalid(4, place, "claimed \"=\" but its time %s differs from event %d's time %s"
                              % (e["alg"].describe(), i - 1, prev.describe()))
        else:
            c = arith.compare(prev, e["alg"])
            if c == 0:
                raise Invalid(4, place, "claimed \"<\" but its time equals event %d's time %s"
                              % (i - 1, prev.describe()))
            if c > 0:
                raise Invalid(4, place, "claimed \"<\" but its time %s is earlier than event %d's time %s"
                              % (e["alg"].describe(), i - 1, prev.describe()))
