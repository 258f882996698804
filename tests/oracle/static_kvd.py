#!/usr/bin/env python3
"""An independent oracle for the static KVD construction (thesis 5.3.3).

Usage: static_kvd.py SCENE.json [--time T] [--seed S] [--perturb K] [--stats]

--perturb K moves vertex i by 2^-K (i+1, (i+1)^2, (i+1)^3) before building:
for a static scene and K large enough, the tree must be the library's tree
of the unperturbed scene, whose ties the symbolic perturbation breaks.
       static_kvd.py --self-check

Prints the KVD of the scene at the instant T (default: the scene's start) in
the format of `kvd build SCENE --tree` (Kvd_tree::describe): one node a line,
pre-order, the root unsigned, each child indented two spaces per level and
marked "-" (left, the negative side of its parent's plane) or "+" (right).

Written from the thesis (chapters 4, 5), the scene format page and the design
notes only, in exact rational arithmetic (fractions.Fraction), so that it can
check the C++ construction. It deliberately does NOT implement the symbolic
tie-breaking of DESIGN.md section 4: every sign is taken at the instant T
itself, and a sign that is exactly zero without the vertex lying on the plane
by construction raises Degenerate (exit status 3) instead of guessing. On such
scenes (shared coordinates, coplanar faces, a sign that only "just after T"
decides) the oracle has no answer; that is the point, not a bug.

Also unsupported (exit status 3): a Euclidean decomposition point x or z
(the axis vertex kind of DESIGN.md section 4), and any split that the thesis
says cannot happen in a scene of non-intersecting triangles (a fragment
crossing a T-plane, an internal P-side crossing another P-plane).

Conventions (proofs/plucker-conventions.md, proofs/classification.md; checked
against the hand-derived comments of tests/test_build.cpp by --self-check):
points are (X, Y, Z, W), W last, Euclidean points scaled to W = 1; a plane
spanned by p, q, r is the covector m with m.s = det[p; q; r; s], and s is on
its positive side iff det > 0. The planes are
  P(V) = x v z v V        (det[x; z; V; s])
  E(e) = a v b v z        (det[a; b; z; s], e = (a, b) as first seen)
  T(t) = i v j v k        (det[i; j; k; s], the triangle's written order)

A vertex is ON a plane only by construction (thesis 5.3.1): the planes it was
built from, the planes through the scene features it lies on, and one case
proofs/classification.md does not list: P(w) and the E-planes of the edges
at w all contain the vertical line w v z, so an internal vertex built from
two of them lies on all of them (see Oracle.on_z_line). Every ON answer is
also checked to be an exact zero, and every other sign to be non-zero.

Motion is used only to place the vertices at T and to put static triangles
first in the priority order; the tree at T-just-after equals the tree of that
configuration whenever no sign is zero at T, which is exactly when the oracle
answers. --stats prints the node and sign counts, and the classifications
decided ON by the vertical-line rule, on stderr. Exit status: 0 tree printed,
2 usage, 3 degenerate or unsupported scene; an internal inconsistency
(including the geometric self-check `verify` of the built tree) raises.
"""

import json
import sys
from fractions import Fraction

MASK64 = (1 << 64) - 1


class Degenerate(Exception):
    """The oracle cannot decide without a tie-breaking rule."""


class Unsupported(Exception):
    """Outside what this oracle implements."""


# ---------------------------------------------------------------------------
# Scene input (scene format page: numbers, polynomials, derived structure,
# priority order).

def number(v):
    if isinstance(v, bool) or v is None:
        raise ValueError("not a number: %r" % (v,))
    if isinstance(v, (int, Fraction)):
        return Fraction(v)
    if isinstance(v, str):
        return Fraction(v)
    raise ValueError("not a number: %r" % (v,))


def poly(v):
    """A polynomial in t: a number or a list [c0, c1, ...]."""
    if isinstance(v, list):
        return [number(c) for c in v]
    return [number(v)]


def poly_at(p, t):
    r = Fraction(0)
    for c in reversed(p):
        r = r * t + c
    return r


def poly_degree(p):
    d = -1
    for i, c in enumerate(p):
        if c != 0:
            d = i
    return d


def split_mix64(seed):
    state = seed & MASK64
    while True:
        state = (state + 0x9E3779B97F4A7C15) & MASK64
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        yield z ^ (z >> 31)


def shuffled_ids(n, seed):
    """Fisher-Yates from the back, j = next() mod (i + 1)."""
    a = list(range(n))
    g = split_mix64(seed)
    for i in range(n - 1, 0, -1):
        j = next(g) % (i + 1)
        a[i], a[j] = a[j], a[i]
    return a


class Scene:
    def __init__(self, doc, time=None, seed=None, perturb=None):
        if doc.get("format") != "kvd-scene/1":
            raise ValueError("not a kvd-scene/1 document")
        self.t = number(doc.get("time", {}).get("start", 0)) if time is None else time
        dec = doc.get("decomposition", {})
        self.x = [poly_at(poly(c), self.t) for c in dec.get("x", [1, 0, 0, 0])]
        self.z = [poly_at(poly(c), self.t) for c in dec.get("z", [0, 0, 1, 0])]
        if self.x[3] != 0 or self.z[3] != 0:
            raise Unsupported("a Euclidean decomposition point (axis vertices, W scaling) is not implemented")

        self.pos = []          # Euclidean position of each global vertex at t
        self.triangles = []    # global vertex ids (i, j, k)
        self.tri_moving = []
        self.first_triangle = []
        for o in doc["objects"]:
            first_v = len(self.pos)
            self.first_triangle.append(len(self.triangles))
            motion = o.get("motion")
            moving = False
            for local, r in enumerate(o["vertices"]):
                if len(r) == 4:  # a point4 of constants
                    rest = [poly_at(poly(c), 0) for c in r]
                else:
                    rest = [number(c) for c in r] + [Fraction(1)]
                h, deg = self.move(motion, rest, local)
                moving = moving or deg > 0
                if h[3] == 0:
                    raise ValueError("vertex at infinity")
                self.pos.append(tuple(c / h[3] for c in h[:3]))
            for tri in o["triangles"]:
                self.triangles.append(tuple(first_v + i for i in tri))
                self.tri_moving.append(moving)

        if perturb is not None:
            # An explicit ε = 2^-perturb on the library's moment curve: vertex
            # i moves by ε (i+1, (i+1)^2, (i+1)^3) (DESIGN.md section 4).
            eps = Fraction(1, 2 ** perturb)
            self.pos = [tuple(p[k] + eps * (i + 1) ** (k + 1) for k in range(3)) for i, p in enumerate(self.pos)]

        # Edges in order of first appearance: (i,j), (j,k), (k,i).
        self.edges, self.tri_edges, edge_id = [], [], {}
        for tri in self.triangles:
            te = []
            for s in range(3):
                a, b = tri[s], tri[(s + 1) % 3]
                key = (min(a, b), max(a, b))
                if key not in edge_id:
                    edge_id[key] = len(self.edges)
                    self.edges.append((a, b))
                te.append(edge_id[key])
            self.tri_edges.append(tuple(te))
        nv, ne, nt = len(self.pos), len(self.edges), len(self.triangles)
        self.vertex_edges = [[] for _ in range(nv)]
        for e, (a, b) in enumerate(self.edges):
            self.vertex_edges[a].append(e)
            self.vertex_edges[b].append(e)
        self.vertex_triangles = [[] for _ in range(nv)]
        self.edge_triangles = [[] for _ in range(ne)]
        for t in range(nt):
            for v in self.triangles[t]:
                self.vertex_triangles[v].append(t)
            for e in self.tri_edges[t]:
                self.edge_triangles[e].append(t)

        # Priority order.
        pr = doc.get("priority", {})
        if seed is None and "order" in pr:
            order = [self.first_triangle[o] + t for o, t in pr["order"]]
        else:
            s = int(pr.get("seed", 0)) if seed is None else seed
            shuffled = shuffled_ids(nt, s)
            order = [t for t in shuffled if not self.tri_moving[t]] + [t for t in shuffled if self.tri_moving[t]]
        self.order = order
        tpo = [0] * nt
        for p, t in enumerate(order):
            tpo[t] = p
        # Cuts with their priorities: a shared vertex or edge is cut once,
        # with the highest priority (smallest number) among its triangles.
        vprio, eprio = {}, {}
        for t in range(nt):
            base = 7 * tpo[t]
            for s in range(3):
                v, e = self.triangles[t][s], self.tri_edges[t][s]
                vprio[v] = min(vprio.get(v, base + s), base + s)
                eprio[e] = min(eprio.get(e, base + 3 + s), base + 3 + s)
        cuts = [(p, "P", v) for v, p in vprio.items()] + [(p, "E", e) for e, p in eprio.items()]
        cuts += [(7 * tpo[t] + 6, "T", t) for t in range(nt)]
        cuts.sort()
        assert len({p for p, _, _ in cuts}) == len(cuts)
        self.cuts = [(k, i) for _, k, i in cuts]

    def move(self, motion, rest, local):
        """Homogeneous position at t of a rest position, and the motion's degree."""
        t = self.t
        if motion is None:
            return rest, 0
        if "translation" in motion:
            d = [poly(c) for c in motion["translation"]]
            deg = max(poly_degree(p) for p in d)
            return [rest[i] + poly_at(d[i], t) * rest[3] for i in range(3)] + [rest[3]], deg
        if "matrix" in motion:
            m = [[poly(c) for c in row] for row in motion["matrix"]]
            deg = max(poly_degree(p) for row in m for p in row)
            return [sum(poly_at(m[i][j], t) * rest[j] for j in range(4)) for i in range(4)], deg
        if "vertices" in motion:
            ps = [[poly(c) for c in p] for p in motion["vertices"]]
            deg = max(poly_degree(c) for p in ps for c in p)
            return [poly_at(c, t) for c in ps[local]], deg
        raise ValueError("unknown motion %r" % (motion,))


# ---------------------------------------------------------------------------
# Exact projective geometry.

def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def plane_through(p, q, r):
    """The covector m with m.s = det[p; q; r; s] for every s (Laplace along s)."""
    rows = [p, q, r]
    m = []
    for j in range(4):
        minor = [[row[c] for c in range(4) if c != j] for row in rows]
        m.append((-1) ** (3 + j) * det3(minor))
    if all(c == 0 for c in m):
        raise Degenerate("the three points spanning a plane are collinear")
    return tuple(m)


def dot(m, p):
    return m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3]


def h(p):
    return (p[0], p[1], p[2], Fraction(1))


# ---------------------------------------------------------------------------
# Symbolic vertices and edges (thesis 5.1), printed as `kvd build --tree` does.
#   ("v", i)               SV(vi)           endpoint
#   ("th", e, V)           SV(ee,PV)        thread: scene edge e meets P(V)
#   ("in", e, E)           SV(ee,EE)        intersection: scene edge e meets E(E)
#   ("ith", V, E, T)       SV(PV,EE,TT)     internal thread
#   ("iin", E1, E2, T)     SV(EE1,EE2,TT)   internal intersection, E1 < E2
#   ("pl", w, T)           SV(vw,TT)        the line w v z meets T (plumb point)
# Sides: ("e", e) SE(ee); ("PT", V, T) SE(PV,TT); ("ET", E, T) SE(EE,TT).

def sv_name(v):
    k = v[0]
    if k == "v":
        return "SV(v%d)" % v[1]
    if k == "th":
        return "SV(e%d,P%d)" % (v[1], v[2])
    if k == "in":
        return "SV(e%d,E%d)" % (v[1], v[2])
    if k == "ith":
        return "SV(P%d,E%d,T%d)" % v[1:]
    if k == "iin":
        return "SV(E%d,E%d,T%d)" % v[1:]
    if k == "pl":
        return "SV(v%d,T%d)" % v[1:]
    raise AssertionError(v)


def se_name(s):
    if s[0] == "e":
        return "SE(e%d)" % s[1]
    if s[0] == "PT":
        return "SE(P%d,T%d)" % s[1:]
    if s[0] == "ET":
        return "SE(E%d,T%d)" % s[1:]
    raise AssertionError(s)


def plane_name(pl):
    return "%s(%d)" % pl


class Oracle:
    def __init__(self, scene):
        self.s = scene
        self.planes = {}
        self.coords = {}     # symbolic vertex -> Euclidean point
        self.signs = 0
        for v, p in enumerate(scene.pos):
            self.coords[("v", v)] = p

    # Planes -----------------------------------------------------------
    def plane(self, pl):
        if pl not in self.planes:
            s = self.s
            kind, i = pl
            if kind == "P":
                m = plane_through(s.x, s.z, h(s.pos[i]))
            elif kind == "E":
                a, b = s.edges[i]
                m = plane_through(h(s.pos[a]), h(s.pos[b]), s.z)
            else:
                a, b, c = s.triangles[i]
                m = plane_through(h(s.pos[a]), h(s.pos[b]), h(s.pos[c]))
            self.planes[pl] = m
        return self.planes[pl]

    # Incidence by construction ------------------------------------------
    def on_by_construction(self, v):
        s = self.s
        k = v[0]
        if k == "v":
            return ({("P", v[1])} | {("E", e) for e in s.vertex_edges[v[1]]}
                    | {("T", t) for t in s.vertex_triangles[v[1]]})
        if k == "th":
            return {("P", v[2]), ("E", v[1])} | {("T", t) for t in s.edge_triangles[v[1]]}
        if k == "in":
            return {("E", v[2]), ("E", v[1])} | {("T", t) for t in s.edge_triangles[v[1]]}
        if k == "ith":
            return {("P", v[1]), ("E", v[2]), ("T", v[3])}
        if k == "iin":
            return {("E", v[1]), ("E", v[2]), ("T", v[3])}
        if k == "pl":
            return self.on_z_line(v[1]) | {("T", v[2])}
        raise AssertionError(v)

    def on_z_line(self, w):
        """The planes containing the line w v z through scene vertex w.

        P(w) and the E-plane of every edge at w contain both w and z, so
        they meet in that line. An internal vertex built from two of them,
        SV(Pw,E,T) with w an endpoint of E, or SV(E1,E2,T) with E1, E2
        sharing the endpoint w, is the point where that line meets T, and
        lies on all of them by construction, not by accident of position.
        (Not one of the incidences proofs/classification.md lists.)"""
        return {("P", w)} | {("E", e) for e in self.s.vertex_edges[w]}

    def sign(self, v, pl):
        """-1, 0 or +1: the side of symbolic vertex v w.r.t. plane pl."""
        self.signs += 1
        f = dot(self.plane(pl), self.coords[v])
        if pl in self.on_by_construction(v):
            if f != 0:  # our own bookkeeping is wrong: never hide it
                raise AssertionError("%s is on %s by construction but the value is %s" % (sv_name(v), plane_name(pl), f))
            return 0
        if f == 0:
            raise Degenerate("%s lies exactly on %s (value 0 at t = %s, not by construction)"
                             % (sv_name(v), plane_name(pl), self.s.t))
        return 1 if f > 0 else -1

    def crossing(self, name, a, b, pl):
        """The vertex `name` where segment a-b meets plane pl (exact)."""
        m = self.plane(pl)
        pa, pb = self.coords[a], self.coords[b]
        fa, fb = dot(m, pa), dot(m, pb)
        assert fa * fb < 0
        lam = fa / (fa - fb)
        p = tuple(pa[i] + lam * (pb[i] - pa[i]) for i in range(3))
        old = self.coords.get(name)
        if old is not None and old != p:
            raise AssertionError("%s computed twice with different coordinates" % sv_name(name))
        self.coords[name] = p
        return name

    # Naming of split vertices and cut sides ------------------------------
    def split_vertex(self, side, pl, tri):
        kind, i = pl
        if side[0] == "e":
            e = side[1]
            if kind == "P":
                return ("th", e, i)
            if kind == "E":
                return ("in", e, i)
            raise Unsupported("scene edge e%d crossed by %s: intersecting triangles?" % (e, plane_name(pl)))
        if side[0] == "PT":
            V, T = side[1], side[2]
            if kind == "E":
                if i in self.s.tri_edges[T]:
                    raise Unsupported("SE(P%d,T%d) crosses the E-plane of its own triangle's edge e%d" % (V, T, i))
                return self.plumb(("ith", V, i, T))
            raise Unsupported("side %s crossed by %s" % (se_name(side), plane_name(pl)))
        if side[0] == "ET":
            E, T = side[1], side[2]
            if kind == "P":
                return self.plumb(("ith", i, E, T))
            if kind == "E":
                if i in self.s.tri_edges[T]:
                    raise Unsupported("SE(E%d,T%d) crosses the E-plane of its own triangle's edge e%d" % (E, T, i))
                return self.plumb(("iin", min(E, i), max(E, i), T))
            raise Unsupported("side %s crossed by %s" % (se_name(side), plane_name(pl)))
        raise AssertionError(side)

    def plumb(self, v):
        """The one name of an internal vertex built from two planes through
        the line w v z of a scene vertex w: SV(Pw,E,T) with w an endpoint of
        E, or SV(E1,E2,T) with E1, E2 sharing w, both are where that line
        meets T."""
        s = self.s
        if v[0] == "ith" and v[1] in s.edges[v[2]]:
            return ("pl", v[1], v[3])
        if v[0] == "iin":
            shared = set(s.edges[v[1]]) & set(s.edges[v[2]])
            if shared:
                return ("pl", shared.pop(), v[3])
        return v

    def cut_side(self, pl, tri):
        kind, i = pl
        if kind == "P":
            return ("PT", i, tri)
        if kind == "E":
            return ("ET", i, tri)
        raise Unsupported("triangle T%d split by %s: intersecting triangles?" % (tri, plane_name(pl)))

    # Classification and splitting -----------------------------------------
    # A fragment is ("P", v) | ("E", e, a, b) | ("T", t, corners, sides).
    # classify returns (left_piece or None, right_piece or None).
    def classify(self, frag, pl):
        if frag[0] == "P":
            sv = self.sign(("v", frag[1]), pl)
            return (frag, None) if sv < 0 else (None, frag)  # on goes right
        if frag[0] == "E":
            _, e, a, b = frag
            sa, sb = self.sign(a, pl), self.sign(b, pl)
            if sa == 0 and sb == 0:
                raise Unsupported("edge fragment of e%d lies in %s" % (e, plane_name(pl)))
            if sa <= 0 and sb <= 0:
                return frag, None
            if sa >= 0 and sb >= 0:
                return None, frag
            x = self.crossing(self.split_vertex(("e", e), pl, None), a, b, pl)
            first, second = ("E", e, a, x), ("E", e, x, b)
            return (first, second) if sa < 0 else (second, first)
        _, t, corners, sides = frag
        n = len(corners)
        sg = [self.sign(c, pl) for c in corners]
        if all(x == 0 for x in sg):
            raise Unsupported("triangle fragment of T%d lies in %s" % (t, plane_name(pl)))
        if all(x <= 0 for x in sg):
            return frag, None
        if all(x >= 0 for x in sg):
            return None, frag
        # Walk the corners in their cyclic order from corners[0]; a corner
        # goes to the side(s) of its sign, a side whose ends have strictly
        # opposite signs contributes its crossing vertex to both pieces.
        # Each entry: (vertex, on_plane, origin) with origin ("c", i) for
        # corner i or ("x", i) for the crossing on side i.
        neg, pos = [], []
        for i in range(n):
            c, si = corners[i], sg[i]
            if si <= 0:
                neg.append((c, si == 0, ("c", i)))
            if si >= 0:
                pos.append((c, si == 0, ("c", i)))
            j = (i + 1) % n
            if si * sg[j] < 0:
                x = self.crossing(self.split_vertex(sides[i], pl, t), c, corners[j], pl)
                neg.append((x, True, ("x", i)))
                pos.append((x, True, ("x", i)))

        def piece(lst):
            cs, ss = [], []
            m = len(lst)
            for q in range(m):
                (va, on_a, oa), (vb, on_b, ob) = lst[q], lst[(q + 1) % m]
                side = None
                if oa[0] == "c" and ob == ("c", (oa[1] + 1) % n):
                    side = sides[oa[1]]
                elif oa[0] == "c" and ob == ("x", oa[1]):
                    side = sides[oa[1]]
                elif oa[0] == "x" and ob == ("c", (oa[1] + 1) % n):
                    side = sides[oa[1]]
                elif on_a and on_b:
                    side = self.cut_side(pl, t)
                else:
                    raise AssertionError("no side from %s to %s" % (sv_name(va), sv_name(vb)))
                cs.append(va)
                ss.append(side)
            assert sum(1 for x in ss if x[0] != "e" and x == self.cut_side(pl, t)) == 1
            return ("T", t, tuple(cs), tuple(ss))

        return piece(neg), piece(pos)

    # Construction ----------------------------------------------------------
    def build(self):
        s = self.s
        self.root = None
        self.node_count = 0
        for kind, i in s.cuts:
            if kind == "P":
                frag = ("P", i)
            elif kind == "E":
                a, b = s.edges[i]
                frag = ("E", i, ("v", a), ("v", b))
            else:
                tri, te = s.triangles[i], s.tri_edges[i]
                frag = ("T", i, tuple(("v", v) for v in tri), tuple(("e", e) for e in te))
            self.root = self.insert(self.root, (kind, i), frag)
        return self.root

    def insert(self, node, pl, frag):
        # node = [plane, fragment, left, right]; iterative descent with an
        # explicit stack so deep trees do not hit Python's recursion limit.
        if node is None:
            self.node_count += 1
            return [pl, frag, None, None]
        stack = [(node, frag)]
        while stack:
            nd, fr = stack.pop()
            left, right = self.classify(fr, nd[0])
            for idx, piece in ((2, left), (3, right)):
                if piece is None:
                    continue
                if nd[idx] is None:
                    self.node_count += 1
                    nd[idx] = [pl, piece, None, None]
                else:
                    stack.append((nd[idx], piece))
        return node


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def verify(o, root):
    """Geometric sanity of the built tree, independent of how it was built:
    every fragment lies in its cell (on the right side of every ancestor's
    plane), edge fragments run along their edge in the edge's direction, and
    triangle fragments are non-degenerate convex polygons in their triangle's
    plane, with the triangle's orientation, whose sides lie on the planes
    they are named after. Raises AssertionError on a violation."""
    s = o.s
    stack = [(root, [])]
    while stack:
        nd, anc = stack.pop()
        if nd is None:
            continue
        pl, frag = nd[0], nd[1]
        if frag[0] == "P":
            verts = [("v", frag[1])]
        elif frag[0] == "E":
            verts = [frag[2], frag[3]]
        else:
            verts = list(frag[2])
        pts = [o.coords[v] for v in verts]
        where = "%s %s" % (plane_name(pl), describe_fragment(frag))
        for apl, side in anc:
            for v, p in zip(verts, pts):
                f = dot(o.plane(apl), p)
                assert f * side >= 0, "%s: %s on the wrong side of ancestor %s" % (where, sv_name(v), plane_name(apl))
        if frag[0] == "E":
            e = frag[1]
            a, b = s.edges[e]
            d = sub(s.pos[b], s.pos[a])
            assert all(c == 0 for c in cross(sub(pts[0], s.pos[a]), d)), where
            assert all(c == 0 for c in cross(sub(pts[1], s.pos[a]), d)), where
            dd = sub(pts[1], pts[0])
            assert sum(dd[i] * d[i] for i in range(3)) > 0, "%s: not in the edge's direction" % where
        elif frag[0] == "T":
            t = frag[1]
            i, j, k = s.triangles[t]
            n = cross(sub(s.pos[j], s.pos[i]), sub(s.pos[k], s.pos[i]))
            m = len(pts)
            assert m >= 3 and len(set(pts)) == m, where
            for q in range(m):
                assert dot(o.plane(("T", t)), pts[q]) == 0, where
                turn = cross(sub(pts[(q + 1) % m], pts[q]), sub(pts[(q + 2) % m], pts[(q + 1) % m]))
                assert sum(turn[c] * n[c] for c in range(3)) > 0, "%s: not convex with T%d's orientation" % (where, t)
                side = frag[3][q]
                on = (("E", side[1]),) if side[0] == "e" else ((side[0][0], side[1]),)
                for spl in on:
                    for p in (pts[q], pts[(q + 1) % m]):
                        assert dot(o.plane(spl), p) == 0, "%s: side %s not on %s" % (where, se_name(side), plane_name(spl))
                if side[0] == "e":
                    assert side[1] in s.tri_edges[t], where
        stack.append((nd[2], anc + [(pl, -1)]))
        stack.append((nd[3], anc + [(pl, 1)]))


def describe_fragment(frag):
    if frag[0] == "P":
        return "[%s]" % sv_name(("v", frag[1]))
    if frag[0] == "E":
        return "[%s %s SE(e%d)]" % (sv_name(frag[2]), sv_name(frag[3]), frag[1])
    return "[%s]" % ", ".join("%s %s" % (sv_name(c), se_name(sd)) for c, sd in zip(frag[2], frag[3]))


def describe(root):
    out = []
    stack = [(root, 0, "")]
    while stack:
        nd, depth, mark = stack.pop()
        if nd is None:
            continue
        out.append("%s%s%s %s\n" % ("  " * depth, mark, plane_name(nd[0]), describe_fragment(nd[1])))
        stack.append((nd[3], depth + 1, "+ "))
        stack.append((nd[2], depth + 1, "- "))
    return "".join(out)


# ---------------------------------------------------------------------------
# The sign conventions, checked against the hand-derived comments of
# tests/test_build.cpp (single triangle (0,0,0), (4,1,0), (1,3,1)).

def self_check():
    doc = {"format": "kvd-scene/1", "objects": [
        {"vertices": [[0, 0, 0], [4, 1, 0], [1, 3, 1]], "triangles": [[0, 1, 2]]}]}
    o = Oracle(Scene(doc))
    # "P-planes y = 0, 1, 3 with +y positive"
    for v, y0 in ((0, 0), (1, 1), (2, 3)):
        assert o.plane(("P", v)) == (0, 1, 0, -y0), o.plane(("P", v))
    # "E-planes 4y - x (e0), 11 - 2x - 3y (e1), 3x - y (e2), positive as written"
    assert o.plane(("E", 0)) == (-1, 4, 0, 0), o.plane(("E", 0))
    assert o.plane(("E", 1)) == (-2, -3, 0, 11), o.plane(("E", 1))
    assert o.plane(("E", 2)) == (3, -1, 0, 0), o.plane(("E", 2))
    # The T-plane's positive side is opposite to the right-hand normal.
    n = (1, -4, 11)  # (v1 - v0) x (v2 - v0)
    m = o.plane(("T", 0))
    assert all(m[i] == -n[i] for i in range(3)) and m[3] == 0, m
    # "the P-plane y = 1 cuts e2 at X = (1/3, 1, 1/3)"
    o.build()
    assert o.coords[("th", 2, 1)] == (Fraction(1, 3), Fraction(1), Fraction(1, 3))
    expected = (
        "P(0) [SV(v0)]\n"
        "  + P(1) [SV(v1)]\n"
        "    - E(0) [SV(v0) SV(v1) SE(e0)]\n"
        "      + E(2) [SV(e2,P1) SV(v0) SE(e2)]\n"
        "        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]\n"
        "    + P(2) [SV(v2)]\n"
        "      - E(1) [SV(v1) SV(v2) SE(e1)]\n"
        "        + E(2) [SV(v2) SV(e2,P1) SE(e2)]\n"
        "          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]\n")
    assert describe(o.root) == expected, describe(o.root)
    # SplitMix64 reference value (seed 0, first output), Vigna's splitmix64.c.
    assert next(split_mix64(0)) == 0xE220A8397B1DCDAF
    print("self-check passed")


def main(argv):
    args = argv[1:]
    if args == ["--self-check"]:
        self_check()
        return 0
    path, time, seed, stats, perturb = None, None, None, False, None
    i = 0
    while i < len(args):
        a = args[i]
        if a == "--time" and i + 1 < len(args):
            time = Fraction(args[i + 1])
            i += 2
        elif a == "--seed" and i + 1 < len(args):
            seed = int(args[i + 1])
            i += 2
        elif a == "--perturb" and i + 1 < len(args):
            perturb = int(args[i + 1])
            i += 2
        elif a == "--stats":
            stats = True
            i += 1
        elif path is None and not a.startswith("--"):
            path = a
            i += 1
        else:
            sys.stderr.write("usage: static_kvd.py SCENE.json [--time T] [--seed S] [--perturb K] [--stats] | --self-check\n")
            return 2
    if path is None:
        sys.stderr.write("usage: static_kvd.py SCENE.json [--time T] [--seed S] [--perturb K] [--stats] | --self-check\n")
        return 2
    with open(path, encoding="utf-8") as f:
        doc = json.load(f, parse_float=Fraction, parse_int=int)
    try:
        o = Oracle(Scene(doc, time, seed, perturb))
        root = o.build()
        verify(o, root)
    except (Degenerate, Unsupported) as e:
        sys.stderr.write("%s: %s: %s\n" % (path, type(e).__name__, e))
        return 3
    sys.stdout.write(describe(root))
    if stats:
        sys.stderr.write("%s: %d nodes, %d signs\n" % (path, o.node_count, o.signs))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
