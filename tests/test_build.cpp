// KVD construction: a hand-checked whole tree, statistics, and the same tree
// from every kernel on a scene in general position.
#include <algorithm>
#include <catch2/catch.hpp>

#include "kernels.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

using namespace kvd;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

// The single triangle's tree (hand-derived in the test below).
const std::string single_triangle_tree =
    "P(0) [SV(v0)]\n"
    "  + P(1) [SV(v1)]\n"
    "    - E(0) [SV(v0) SV(v1) SE(e0)]\n"
    "      + E(2) [SV(e2,P1) SV(v0) SE(e2)]\n"
    "        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]\n"
    "    + P(2) [SV(v2)]\n"
    "      - E(1) [SV(v1) SV(v2) SE(e1)]\n"
    "        + E(2) [SV(v2) SV(e2,P1) SE(e2)]\n"
    "          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]\n";

template <class K>
tree::Kvd_tree build_at(const K& k, const scene::Scene& s, long t) {
  const predicates::Classifier<K> c(k, s);
  return tree::build(c, kvd::test::at(k, t));
}
}  // namespace

TEST_CASE("a single triangle gives the hand-checked tree", "[build]") {
  // v0 = (0,0,0), v1 = (4,1,0), v2 = (1,3,1); P-planes y = 0, 1, 3 with +y
  // positive; E-planes 4y - x (e0), 11 - 2x - 3y (e1), 3x - y (e2), positive
  // as written; the P-plane y = 1 cuts e2 at X = (1/3, 1, 1/3) and the
  // triangle along SE(P1,T0).
  const std::string expected = single_triangle_tree;
  const kvd::Exact_kernel k;
  const tree::Kvd_tree t = build_at(k, load("single-triangle.json"), 0);
  CHECK(t.describe() == expected);
  const auto st = t.statistics();
  CHECK(st.p_nodes == 3);
  CHECK(st.e_nodes == 4);
  CHECK(st.t_nodes == 2);
  CHECK(st.height == 6);
  // The canonical serialisation, and the structure hash over it node by
  // node (tree/compare.hpp), as Python's hashlib computes it from the
  // nine node texts below (an implementation independent of ours).
  CHECK(tree::canonical_serialisation(t) ==
        "P0:SV(v0)[][P1:SV(v1)[E0:SV(v0),SV(v1)[][E2:SV(v0),SV(e2,P1)[][T0:SV(v0),SV(v1),SV(e2,P1)[][]]]]"
        "[P2:SV(v2)[E1:SV(v1),SV(v2)[][E2:SV(v2),SV(e2,P1)[][T0:SV(v1),SV(v2),SV(e2,P1)[][]]]][]]]");
  CHECK(tree::structure_hash(t) == "d4c5de78b1b276d7f7ef8803cbeb213c0ac1ec639956ec29539c546cb5d8f706");
  // The same from the definition H(n) = SHA256(TEXT(n) "[" H(left) "][" H(right) "]").
  const auto h = [](const std::string& text, const std::string& l = "", const std::string& r = "") {
    return tree::sha256_hex(text + "[" + l + "][" + r + "]");
  };
  const std::string right = h("P2:SV(v2)", h("E1:SV(v1),SV(v2)", "", h("E2:SV(v2),SV(e2,P1)", "", h("T0:SV(v1),SV(v2),SV(e2,P1)"))));
  const std::string left = h("E0:SV(v0),SV(v1)", "", h("E2:SV(v0),SV(e2,P1)", "", h("T0:SV(v0),SV(v1),SV(e2,P1)")));
  CHECK(tree::structure_hash(t) == h("P0:SV(v0)", "", h("P1:SV(v1)", left, right)));
}

TEST_CASE("the single triangle with reversed orientation gives the hand-checked tree", "[build]") {
  // Triangle (0, 2, 1): P-cuts in the order P(0), P(2), P(1); edges e0 = (0,2),
  // e1 = (2,1), e2 = (1,0) with E-planes y - 3x, 2x + 3y - 11 and x - 4y
  // (positive as written). P(1), y = 1, cuts e0 at X = SV(e0,P1) =
  // (1/3, 1, 1/3) and the triangle along SE(P1,T0); v1 = (4,1,0) is on the
  // negative side of E(0) (-11), X on the negative sides of E(2) (-11/3) and
  // E(1) (-22/3).
  const std::string expected =
      "P(0) [SV(v0)]\n"
      "  + P(2) [SV(v2)]\n"
      "    - P(1) [SV(v1)]\n"
      "      - E(0) [SV(v0) SV(e0,P1) SE(e0)]\n"
      "        - E(2) [SV(v1) SV(v0) SE(e2)]\n"
      "          - T(0) [SV(v0) SE(e0), SV(e0,P1) SE(P1,T0), SV(v1) SE(e2)]\n"
      "      + E(0) [SV(e0,P1) SV(v2) SE(e0)]\n"
      "        - E(1) [SV(v2) SV(v1) SE(e1)]\n"
      "          - T(0) [SV(e0,P1) SE(e0), SV(v2) SE(e1), SV(v1) SE(P1,T0)]\n";
  const scene::Scene s = scene::read_scene(R"({"format": "kvd-scene/1", "objects": [
      {"vertices": [[0,0,0],[4,1,0],[1,3,1]], "triangles": [[0,2,1]]}]})",
                                           "reversed.json");
  CHECK(build_at(kvd::Exact_kernel(), s, 0).describe() == expected);
}

TEST_CASE("two triangles in separate P-slabs give the hand-checked tree", "[build]") {
  // The copy (vertices 3-5) has y >= 10 > 3: every one of its cuts passes
  // P(0), P(1), P(2) on the positive side, and below P(2) it builds the
  // single-triangle tree again, with E-planes 4(y-10) - x, 11 - 2x - 3(y-10)
  // and 3x - (y-10), and the thread vertex X' = (1/3, 11, 1/3).
  const std::string expected =
      single_triangle_tree +
      "      + P(3) [SV(v3)]\n"
      "        + P(4) [SV(v4)]\n"
      "          - E(3) [SV(v3) SV(v4) SE(e3)]\n"
      "            + E(5) [SV(e5,P4) SV(v3) SE(e5)]\n"
      "              + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]\n"
      "          + P(5) [SV(v5)]\n"
      "            - E(4) [SV(v4) SV(v5) SE(e4)]\n"
      "              + E(5) [SV(v5) SV(e5,P4) SE(e5)]\n"
      "                + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]\n";
  CHECK(build_at(kvd::Exact_kernel(), load("two-slabs.json"), 0).describe() == expected);
}

// The next three trees are of scenes with ties that the symbolic
// perturbation breaks (shared y-coordinates, an edge parallel to z). Each was
// checked against tests/oracle/static_kvd.py, an independent implementation
// of the construction in exact rationals, run on the same scene with every
// vertex i moved by an explicit 2^-k (i+1, (i+1)^2, (i+1)^3) for k from 12 to
// 100: it gives these trees line for line (CTest static_kvd_oracle).

TEST_CASE("the thesis's three-triangle cycle gives the expected tree", "[build]") {
  // Triangles a (T0), b (T1), c (T2) overlap cyclically; the scene's order
  // (seed 0) puts c first, so P(6) (v6, y = 5) is the root and P(7) (v7,
  // y = -1) its left child. v3 = (5, -1, 1) has the same y as v7: the
  // perturbation moves v_i by (i+1)^2 ε in y, so y(v3) + 16ε < y(v7) + 64ε
  // and P(3) goes left of P(7). The cycle is broken by the E-cuts of c, E(6)
  // and E(8), which split a and b into fragments that can be ordered.
  const std::string expected =
      "P(6) [SV(v6)]\n"
      "  - P(7) [SV(v7)]\n"
      "    - P(3) [SV(v3)]\n"
      "      + E(3) [SV(v3) SV(e3,P7) SE(e3)]\n"
      "        + E(5) [SV(e5,P7) SV(v3) SE(e5)]\n"
      "          + T(1) [SV(v3) SE(e3), SV(e3,P7) SE(P7,T1), SV(e5,P7) SE(e5)]\n"
      "    + P(8) [SV(v8)]\n"
      "      - E(6) [SV(e6,P8) SV(v7) SE(e6)]\n"
      "        - P(0) [SV(v0)]\n"
      "          + E(0) [SV(v0) SV(e0,E6) SE(e0)]\n"
      "            + E(2) [SV(e2,E6) SV(v0) SE(e2)]\n"
      "              + T(0) [SV(v0) SE(e0), SV(e0,E6) SE(E6,T0), SV(e2,E6) SE(e2)]\n"
      "        + E(7) [SV(v7) SV(v8) SE(e7)]\n"
      "          - P(1) [SV(v1)]\n"
      "            - E(0) [SV(e0,E7) SV(v1) SE(e0)]\n"
      "              - E(3) [SV(e3,P7) SV(e3,E0) SE(e3)]\n"
      "                + E(5) [SV(e5,E0) SV(e5,P7) SE(e5)]\n"
      "                  + T(1) [SV(e3,P7) SE(e3), SV(e3,E0) SE(E0,T1), SV(e5,E0) SE(e5), SV(e5,P7) SE(P7,T1)]\n"
      "              + T(0) [SV(e0,E7) SE(e0), SV(v1) SE(P1,T0), SV(P1,E7,T0) SE(E7,T0)]\n"
      "                + E(3) [SV(e3,E0) SV(e3,P1) SE(e3)]\n"
      "                  + E(5) [SV(e5,P1) SV(e5,E0) SE(e5)]\n"
      "                    + T(1) [SV(e3,E0) SE(e3), SV(e3,P1) SE(P1,T1), SV(e5,P1) SE(e5), SV(e5,E0) SE(E0,T1)]\n"
      "            + P(2) [SV(v2)]\n"
      "              - E(1) [SV(v1) SV(v2) SE(e1)]\n"
      "                - E(3) [SV(e3,E1) SV(e3,P2) SE(e3)]\n"
      "                  + E(5) [SV(e5,P2) SV(e5,E1) SE(e5)]\n"
      "                    + T(1) [SV(e3,E1) SE(e3), SV(e3,P2) SE(P2,T1), SV(e5,P2) SE(e5), SV(e5,E1) SE(E1,T1)]\n"
      "                + E(2) [SV(v2) SV(e2,E7) SE(e2)]\n"
      "                  + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,E7) SE(E7,T0), SV(P1,E7,T0) SE(P1,T0)]\n"
      "                    + E(3) [SV(e3,P1) SV(e3,E1) SE(e3)]\n"
      "                      + E(5) [SV(e5,E1) SV(e5,P1) SE(e5)]\n"
      "                        + T(1) [SV(e3,P1) SE(e3), SV(e3,E1) SE(E1,T1), SV(e5,E1) SE(e5), SV(e5,P1) SE(P1,T1)]\n"
      "              + P(5) [SV(v5)]\n"
      "                - E(3) [SV(e3,P2) SV(e3,P5) SE(e3)]\n"
      "                  + E(5) [SV(v5) SV(e5,P2) SE(e5)]\n"
      "                    + T(1) [SV(e3,P2) SE(e3), SV(e3,P5) SE(P5,T1), SV(v5) SE(e5), SV(e5,P2) SE(P2,T1)]\n"
      "                + E(3) [SV(e3,P5) SV(e3,P8) SE(e3)]\n"
      "                  + E(4) [SV(e4,P8) SV(v5) SE(e4)]\n"
      "                    + T(1) [SV(e3,P5) SE(e3), SV(e3,P8) SE(P8,T1), SV(e4,P8) SE(e4), SV(v5) SE(P5,T1)]\n"
      "          + T(2) [SV(e6,P8) SE(e6), SV(v7) SE(e7), SV(v8) SE(P8,T2)]\n"
      "            + E(0) [SV(e0,E6) SV(e0,E7) SE(e0)]\n"
      "              + E(2) [SV(e2,E7) SV(e2,E6) SE(e2)]\n"
      "                + T(0) [SV(e0,E6) SE(e0), SV(e0,E7) SE(E7,T0), SV(e2,E7) SE(e2), SV(e2,E6) SE(E6,T0)]\n"
      "      + E(6) [SV(v6) SV(e6,P8) SE(e6)]\n"
      "        - P(4) [SV(v4)]\n"
      "          - E(3) [SV(e3,E6) SV(v4) SE(e3)]\n"
      "            + E(4) [SV(v4) SV(e4,E6) SE(e4)]\n"
      "              + T(1) [SV(e3,E6) SE(e3), SV(v4) SE(e4), SV(e4,E6) SE(E6,T1)]\n"
      "        + E(8) [SV(v8) SV(v6) SE(e8)]\n"
      "          - E(3) [SV(e3,P8) SV(e3,E8) SE(e3)]\n"
      "            + E(4) [SV(e4,E8) SV(e4,P8) SE(e4)]\n"
      "              + T(1) [SV(e3,P8) SE(e3), SV(e3,E8) SE(E8,T1), SV(e4,E8) SE(e4), SV(e4,P8) SE(P8,T1)]\n"
      "          + T(2) [SV(v6) SE(e6), SV(e6,P8) SE(P8,T2), SV(v8) SE(e8)]\n"
      "            - E(3) [SV(e3,E8) SV(e3,E6) SE(e3)]\n"
      "              + E(4) [SV(e4,E6) SV(e4,E8) SE(e4)]\n"
      "                + T(1) [SV(e3,E8) SE(e3), SV(e3,E6) SE(E6,T1), SV(e4,E6) SE(e4), SV(e4,E8) SE(E8,T1)]\n";
  const auto t = build_at(kvd::Exact_kernel(), load("cycle3.json"), 0);
  CHECK(t.describe() == expected);
  const auto st = t.statistics();
  CHECK(st.p_nodes == 9);
  CHECK(st.nodes == 56);
}

TEST_CASE("two triangles with shared heights give the expected tree", "[build]") {
  // The static floor (T0) comes first; the mover (T1) lies wholly on the
  // negative side of T(0) and of the floor's P- and E-cuts it meets, so its
  // cuts repeat the single-triangle pattern under T(0). Shared y-values
  // between the floor and the mover are ordered by the perturbation.
  const std::string expected =
      single_triangle_tree +
      "            - P(3) [SV(v3)]\n"
      "              + P(4) [SV(v4)]\n"
      "                - E(3) [SV(v3) SV(v4) SE(e3)]\n"
      "                  + E(5) [SV(e5,P4) SV(v3) SE(e5)]\n"
      "                    + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]\n"
      "                + P(5) [SV(v5)]\n"
      "                  - E(4) [SV(v4) SV(v5) SE(e4)]\n"
      "                    + E(5) [SV(v5) SV(e5,P4) SE(e5)]\n"
      "                      + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]\n";
  CHECK(build_at(kvd::Exact_kernel(), load("two-triangles.json"), 0).describe() == expected);
}

TEST_CASE("a scene with an edge parallel to z gives the expected tree", "[build]") {
  // Its E-plane a ∨ b ∨ z vanishes identically; every sign against it is the
  // first non-zero ε-coefficient (rule 4).
  const std::string expected =
      "P(0) [SV(v0)]\n"
      "  - P(8) [SV(v8)]\n"
      "    + E(7) [SV(e7,P0) SV(v8) SE(e7)]\n"
      "      - E(8) [SV(v8) SV(e8,P0) SE(e8)]\n"
      "        - T(2) [SV(e7,P0) SE(e7), SV(v8) SE(e8), SV(e8,P0) SE(P0,T2)]\n"
      "  + P(1) [SV(v1)]\n"
      "    - E(0) [SV(v0) SV(v1) SE(e0)]\n"
      "      - E(2) [SV(e2,P1) SV(v0) SE(e2)]\n"
      "        - T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]\n"
      "          + T(2) [SV(v0,T2) SE(E0,T2), SV(v1,T2) SE(P1,T2), SV(P1,E2,T2) SE(E2,T2)]\n"
      "        + E(7) [SV(e7,P1) SV(e7,P0) SE(e7)]\n"
      "          - T(2) [SV(e7,P1) SE(e7), SV(e7,P0) SE(P0,T2), SV(v0,T2) SE(E2,T2), SV(P1,E2,T2) SE(P1,T2)]\n"
      "      + E(8) [SV(e8,P0) SV(e8,P1) SE(e8)]\n"
      "        - T(2) [SV(v0,T2) SE(P0,T2), SV(e8,P0) SE(e8), SV(e8,P1) SE(P1,T2), SV(v1,T2) SE(E0,T2)]\n"
      "    + P(2) [SV(v2)]\n"
      "      - E(1) [SV(v1) SV(v2) SE(e1)]\n"
      "        - E(2) [SV(v2) SV(e2,P1) SE(e2)]\n"
      "          - T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]\n"
      "            + E(7) [SV(e7,E1) SV(e7,E2) SE(e7)]\n"
      "              - T(2) [SV(e7,E1) SE(e7), SV(e7,E2) SE(E2,T2), SV(P1,E2,T2) SE(P1,T2), SV(v1,T2) SE(E1,T2)]\n"
      "          + E(7) [SV(e7,E2) SV(e7,P1) SE(e7)]\n"
      "            - T(2) [SV(e7,E2) SE(e7), SV(e7,P1) SE(P1,T2), SV(P1,E2,T2) SE(E2,T2)]\n"
      "        + E(7) [SV(e7,P2) SV(e7,E1) SE(e7)]\n"
      "          - E(8) [SV(e8,P1) SV(e8,P2) SE(e8)]\n"
      "            - T(2) [SV(e7,P2) SE(e7), SV(e7,E1) SE(E1,T2), SV(v1,T2) SE(P1,T2), SV(e8,P1) SE(e8), SV(e8,P2) SE(P2,T2)]\n"
      "      + P(3) [SV(v3)]\n"
      "        - E(7) [SV(e7,P3) SV(e7,P2) SE(e7)]\n"
      "          - E(8) [SV(e8,P2) SV(e8,P3) SE(e8)]\n"
      "            - T(2) [SV(e7,P3) SE(e7), SV(e7,P2) SE(P2,T2), SV(e8,P2) SE(e8), SV(e8,P3) SE(P3,T2)]\n"
      "        + P(4) [SV(v4)]\n"
      "          - E(3) [SV(v3) SV(v4) SE(e3)]\n"
      "            - E(5) [SV(e5,P4) SV(v3) SE(e5)]\n"
      "              - T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]\n"
      "            + E(7) [SV(e7,P4) SV(e7,P3) SE(e7)]\n"
      "              - E(8) [SV(e8,P3) SV(e8,P4) SE(e8)]\n"
      "                - T(2) [SV(e7,P4) SE(e7), SV(e7,P3) SE(P3,T2), SV(e8,P3) SE(e8), SV(e8,P4) SE(P4,T2)]\n"
      "          + P(5) [SV(v5)]\n"
      "            - E(4) [SV(v4) SV(v5) SE(e4)]\n"
      "              - E(5) [SV(v5) SV(e5,P4) SE(e5)]\n"
      "                - T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]\n"
      "              + E(7) [SV(e7,P5) SV(e7,P4) SE(e7)]\n"
      "                - E(8) [SV(e8,P4) SV(e8,P5) SE(e8)]\n"
      "                  - T(2) [SV(e7,P5) SE(e7), SV(e7,P4) SE(P4,T2), SV(e8,P4) SE(e8), SV(e8,P5) SE(P5,T2)]\n"
      "            + P(6) [SV(v6)]\n"
      "              - E(7) [SV(e7,P6) SV(e7,P5) SE(e7)]\n"
      "                - E(8) [SV(e8,P5) SV(v6) SE(e8)]\n"
      "                  - T(2) [SV(v6) SE(P6,T2), SV(e7,P6) SE(e7), SV(e7,P5) SE(P5,T2), SV(e8,P5) SE(e8)]\n"
      "              + P(7) [SV(v7)]\n"
      "                - E(6) [SV(v6) SV(v7) SE(e6)]\n"
      "                  - E(7) [SV(v7) SV(e7,P6) SE(e7)]\n"
      "                    - T(2) [SV(v6) SE(e6), SV(v7) SE(e7), SV(e7,P6) SE(P6,T2)]\n";
  CHECK(build_at(kvd::Exact_kernel(), load("degenerate-vertical-edge.json"), 0).describe() == expected);
}

TEST_CASE("structural comparison names the first difference", "[build][compare]") {
  const kvd::Exact_kernel k;
  scene::Load_options o;
  const scene::Scene s = load("cycle3.json");
  o.seed = 1;
  const scene::Scene reseeded = scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/cycle3.json", o);
  const auto a = build_at(k, s, 0), b = build_at(k, s, 0);
  CHECK_FALSE(tree::first_difference(a, b));
  CHECK(tree::structure_hash(a) == tree::structure_hash(b));
  // Another priority order gives another tree, told apart at the root or below.
  const auto c = build_at(k, reseeded, 0);
  REQUIRE(s.priority_order != reseeded.priority_order);
  const auto diff = tree::first_difference(a, c);
  REQUIRE(diff);
  CHECK(diff->rfind("at root", 0) == 0);
  CHECK(tree::structure_hash(a) != tree::structure_hash(c));
  // A rotated triangle fragment is the same fragment.
  tree::Kvd_tree rotated = a;
  for (auto& n : rotated.nodes)
    if (auto* f = std::get_if<tree::Triangle_fragment>(&n.fragment)) {
      std::rotate(f->corners.begin(), f->corners.begin() + 1, f->corners.end());
      std::rotate(f->sides.begin(), f->sides.begin() + 1, f->sides.end());
    }
  CHECK_FALSE(tree::first_difference(a, rotated));
  // A changed fragment is reported with the node's cut.
  tree::Kvd_tree changed = a;
  for (auto& n : changed.nodes)
    if (auto* f = std::get_if<tree::Edge_fragment>(&n.fragment)) {
      f->b = symbolic::Symbolic_vertex::endpoint(99);
      break;
    }
  const auto what = tree::first_difference(a, changed);
  REQUIRE(what);
  CHECK(what->find("the fragments of E(") != std::string::npos);
}

TEMPLATE_TEST_CASE("every kernel builds the same tree in general position", "[build]", kvd::Double_kernel,
                   kvd::Mpfr_kernel) {
  const scene::Scene s = load("random-20.json");
  for (long t : {0L, 1L}) {
    const auto exact = build_at(kvd::Exact_kernel(), s, t);
    const auto other = build_at(TestType(), s, t);
    CHECK(other.describe() == exact.describe());
    CHECK(tree::structure_hash(other) == tree::structure_hash(exact));
  }
}

TEST_CASE("degenerate scenes build", "[build]") {
  const kvd::Exact_kernel k;
  for (const char* name : {"boxes.json", "cycle3.json", "viewpoint.json", "rotor.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const predicates::Classifier<kvd::Exact_kernel> c(k, s);
    const auto st = tree::build(c, kvd::Exact_time(s.start)).statistics();
    CHECK(st.p_nodes == s.rest.size());  // every vertex is cut exactly once
    CHECK(st.t_nodes >= s.triangles.size());
    CHECK(st.e_nodes >= s.edges.size());
    for (const auto& [v, p] : c.unresolved_cases())
      UNSCOPED_INFO("unresolved: " << symbolic::to_string(v) << " vs " << symbolic::to_string(p));
    CHECK(c.unresolved() == 0);
  }
}

TEST_CASE("a build at T equals the build at 0 of the scene re-timed by t -> t + T", "[build]") {
  const kvd::Exact_kernel k;
  for (const char* name : {"two-triangles.json", "rotor.json", "random-20.json", "viewpoint.json"}) {
    const scene::Scene s = load(name);
    for (const mpq_class& shift : {mpq_class(1, 2), mpq_class(1), mpq_class(7, 3)}) {
      INFO(name << " at " << shift.get_str());
      const scene::Scene r = scene::retimed(s, shift);
      CHECK(scene::evaluate(r.position(0), mpq_class(0)) == s.position_at(0, shift));
      const predicates::Classifier<kvd::Exact_kernel> cs(k, s), cr(k, r);
      const auto a = tree::build(cs, kvd::Exact_time(shift));
      const auto b = tree::build(cr, kvd::Exact_time(0));
      const auto diff = tree::first_difference(a, b);
      CHECK_FALSE(diff);
      if (diff) UNSCOPED_INFO(*diff);
    }
  }
}

TEST_CASE("the double kernel's tree on degenerate scenes, recorded", "[build][double]") {
  // The degenerate-* scenes and boxes have small integer coordinates, exact
  // in double, and the lexicographic rule (perturbation included) is shared
  // code: there the double kernel's trees must be identical. cycle3's
  // fractional coordinates are not exact in double, and its epsilon tests
  // decide some near-degenerate signs differently: the difference is what
  // the floating-point build is for, and it is recorded, not asserted.
  for (const char* name : {"boxes.json", "cycle3.json", "degenerate-shared-y.json", "degenerate-vertical-edge.json",
                           "degenerate-z-on-plane.json"}) {
    const scene::Scene s = load(name);
    const auto exact = build_at(kvd::Exact_kernel(), s, 0);
    const auto fp = build_at(kvd::Double_kernel(), s, 0);
    const auto diff = tree::first_difference(exact, fp);
    WARN(name << ": double kernel " << (diff ? "differs " + *diff : std::string("builds the identical tree")));
    if (std::string(name) != "cycle3.json") CHECK_FALSE(diff);
  }
}

TEMPLATE_TEST_CASE("floating-point builds of generated scenes equal the exact build", "[build][float]", kvd::Double_kernel,
                   kvd::Mpfr_kernel) {
  // uniform-density-100 has a triangle containing the direction z: a vertex
  // of it is on the E-plane of its opposite edge for all t, which the exact
  // kernel resolves by the perturbation. A floating-point value polynomial
  // made of rounding noise must go the same way, not to "on".
  const TestType fk;
  const Exact_kernel ek;
  for (const char* name : {"uniform-density-100.json", "uniform-scale-200.json", "uniform-density-50.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const auto exact = tree::build(predicates::Classifier<Exact_kernel>(ek, s), ek.time(s.start));
    const auto fp = tree::build(predicates::Classifier<TestType>(fk, s), fk.time(from_rational<typename TestType::FT>(s.start)));
    const auto diff = tree::first_difference(exact, fp);
    CHECK_FALSE(diff);
    if (diff) UNSCOPED_INFO(*diff);
  }
}
