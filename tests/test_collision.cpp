// The collision response X-collide (thesis 7.3.3): the reversal time and the
// reversed motions exactly, the motion changes of a hand-built scene written
// out, and on collision scenes a run validated at every event whose objects
// never interpenetrate, checked exactly at rational times between events.
#include <catch2/catch.hpp>

#include <random>

#include "kernels.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kinetic/collision.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/in_triangle.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/detail/scene/triangle_intersection.hpp"

using namespace kvd;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }
const Exact_kernel k;

kinetic::Simulation<Exact_time> run(const scene::Scene& s, kinetic::Update u,
                                    kinetic::Certificate_set set = kinetic::Certificate_set::reduced) {
  kinetic::Options o;
  o.update = u;
  o.certificates = set;
  o.max_events = 1000;
  return kinetic::simulate(k, s, o);
}

// The instants of a run in order: the start, every batch and every motion
// change, and the time limit.
std::vector<Exact_time> instants(const scene::Scene& s, const kinetic::Simulation<Exact_time>& sim) {
  std::vector<Exact_time> out{Exact_time(s.start)};
  kinetic::in_run_order(
      sim, [&](std::size_t c) { out.push_back(Exact_time(sim.motion_changes[c].time)); },
      [&](std::size_t b) { out.push_back(sim.batches[b].time); });
  if (sim.limit && k.compare(out.back(), Exact_time(*sim.limit)) < 0) out.push_back(Exact_time(*sim.limit));
  return out;
}

// No two triangles meet with the motions in force, at a rational strictly
// inside every interval between consecutive instants and at every motion
// change; the instants never go back.
void check_never_interpenetrate(const scene::Scene& s, const kinetic::Simulation<Exact_time>& sim) {
  std::vector<mpq_class> probes;
  for (const auto& c : sim.motion_changes) probes.push_back(c.time);
  const std::vector<Exact_time> at = instants(s, sim);
  for (std::size_t i = 1; i < at.size(); ++i) {
    REQUIRE(k.compare(at[i - 1], at[i]) <= 0);
    if (k.compare(at[i - 1], at[i]) < 0) probes.push_back(kinetic::rational_between(at[i - 1], at[i]));
  }
  for (const mpq_class& q : probes) {
    const scene::Scene now = kinetic::motions_at(s, sim.motion_changes, q);
    const auto met = scene::first_conflict(now, scene::triangles_at(now, q));
    INFO("t = " << q.get_str());
    CHECK(!met);
    if (met) UNSCOPED_INFO("triangles " << met->first << " and " << met->second << " meet");
  }
  CHECK(probes.size() >= sim.batches.size());
}

// The same batches at the same exact times, the same motion changes.
void check_same_run(const kinetic::Simulation<Exact_time>& a, const kinetic::Simulation<Exact_time>& b) {
  REQUIRE(a.batches.size() == b.batches.size());
  for (std::size_t i = 0; i < a.batches.size(); ++i) {
    CHECK(k.compare(a.batches[i].time, b.batches[i].time) == 0);
    CHECK(a.batches[i].failing == b.batches[i].failing);
    CHECK(a.batches[i].structure == b.batches[i].structure);
  }
  REQUIRE(a.motion_changes.size() == b.motion_changes.size());
  for (std::size_t i = 0; i < a.motion_changes.size(); ++i) {
    CHECK(a.motion_changes[i].time == b.motion_changes[i].time);
    CHECK(a.motion_changes[i].objects == b.motion_changes[i].objects);
    CHECK(a.motion_changes[i].motions == b.motion_changes[i].motions);
    CHECK(a.motion_changes[i].batches_before == b.motion_changes[i].batches_before);
  }
  CHECK(a.structure_hash == b.structure_hash);
}
}  // namespace

TEST_CASE("simplest_rational: the smallest denominator in a closed interval", "[collision]") {
  using test::q;
  CHECK(kinetic::simplest_rational(q(1, 3), q(1, 2)) == q(1, 2));
  CHECK(kinetic::simplest_rational(q(3, 10), q(7, 20)) == q(1, 3));
  CHECK(kinetic::simplest_rational(q(7, 10), q(7, 10)) == q(7, 10));
  CHECK(kinetic::simplest_rational(q(-1, 2), q(-1, 3)) == q(-1, 2));
  CHECK(kinetic::simplest_rational(q(3, 2), q(5, 2)) == 2);
  CHECK(kinetic::simplest_rational(mpq_class(-1), mpq_class(1)) == 0);
  CHECK(kinetic::simplest_rational(q(355, 113) - q(1, 100000), q(355, 113) + q(1, 100000)) == q(355, 113));
  // Against a search of every smaller denominator, on random intervals.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 300; ++i) {
    const mpq_class lo = q(static_cast<long>(rng() % 2001) - 1000, 1 + static_cast<long>(rng() % 97));
    const mpq_class hi = lo + q(1 + static_cast<long>(rng() % 50), 1 + static_cast<long>(rng() % 5000));
    const mpq_class r = kinetic::simplest_rational(lo, hi);
    INFO("[" << lo.get_str() << ", " << hi.get_str() << "] gave " << r.get_str());
    REQUIRE((lo <= r && r <= hi));
    for (long d = 1; d < r.get_den().get_si(); ++d) {
      mpz_class n;
      mpz_class ld = mpz_class(lo.get_num() * d);
      mpz_cdiv_q(n.get_mpz_t(), ld.get_mpz_t(), lo.get_den_mpz_t());  // the least n with n/d >= lo
      REQUIRE(q(n.get_si(), d) > hi);
    }
  }
}

TEST_CASE("the reversal time lies strictly between the last batch and the collision, close to it", "[collision]") {
  using test::q;
  // sqrt(2) (a root of t^2 - 2 in (1, 2)) after 1, and the rational 3 after 5/2.
  const Exact_time root2 = Exact_time::algebraic({-2, 0, 1}, 1, 2);
  const mpq_class r = kinetic::reversal_time(Exact_time(mpq_class(1)), root2);
  CHECK(k.compare(Exact_time(r), Exact_time(mpq_class(1))) > 0);
  CHECK(k.compare(Exact_time(r), root2) < 0);
  CHECK(k.compare(Exact_time(r + (r - 1) / 7), root2) > 0);  // sqrt(2) - r < (r - 1) / 7
  const mpq_class s = kinetic::reversal_time(Exact_time(q(5, 2)), Exact_time(q(3, 1)));
  CHECK((q(5, 2) < s && s < q(3, 1)));
  CHECK(s >= q(3, 1) - q(1, 32));
  CHECK(s <= q(3, 1) - q(1, 128));
}

TEST_CASE("a reversed motion keeps the position at r and negates every velocity", "[collision]") {
  using test::q;
  scene::Motion m;
  m.kind = scene::Motion::Kind::matrix;
  std::mt19937_64 rng(3);
  auto random_poly = [&] {
    std::vector<mpq_class> c;
    for (int i = 0; i < 4; ++i) c.push_back(q(static_cast<long>(rng() % 21) - 10, 1 + static_cast<long>(rng() % 7)));
    return scene::QPoly(std::move(c));
  };
  for (auto& row : m.matrix)
    for (auto& p : row) p = random_poly();
  for (auto& p : m.translation) p = random_poly();
  m.vertices.push_back({{random_poly(), random_poly(), random_poly(), scene::QPoly(1)}});
  const mpq_class r = q(7, 3);
  const scene::Motion rev = scene::reversed(m, r);
  auto check = [&](const scene::QPoly& p, const scene::QPoly& p_rev) {
    CHECK(p_rev(r) == p(r));
    CHECK(p_rev.derivative()(r) == -p.derivative()(r));
    CHECK(p_rev.derivative().derivative()(r) == p.derivative().derivative()(r));
    CHECK(p_rev(r + 1) == p(r - 1));
  };
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) check(m.matrix[i][j], rev.matrix[i][j]);
  for (std::size_t i = 0; i < 3; ++i) check(m.translation[i], rev.translation[i]);
  for (int i = 0; i < 4; ++i) check(m.vertices[0][i], rev.vertices[0][i]);
  CHECK(scene::reversed(rev, r) == m);
}

TEST_CASE("collisions.json: each landing and the head-on meeting reverse the objects that meet", "[collision][kinetic]") {
  // Written out: the flat triangle lands face down at t = 2, the tilted one
  // on a vertex at t = 3, the twins both at t = 4 (one motion change), the
  // head-on pair meets face to face at t = 6. Every landing object falls at
  // a constant speed, so its reversed motion is z + (t - 2r) * speed.
  const scene::Scene s = load("collisions.json");
  const auto set = GENERATE(kinetic::Certificate_set::reduced, kinetic::Certificate_set::full);
  const auto sim = run(s, kinetic::Update::rebuild, set);
  CHECK(sim.valid());
  INFO(sim.failure);
  CHECK(!sim.collision);
  REQUIRE(sim.motion_changes.size() == 4);
  const std::vector<std::vector<std::size_t>> objects{{1}, {2}, {3, 4}, {5, 6}};
  const long collisions[] = {2, 3, 4, 6};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& c = sim.motion_changes[i];
    INFO("motion change " << i);
    CHECK(c.objects == objects[i]);
    CHECK(k.compare(c.collision, Exact_time(mpq_class(collisions[i]))) == 0);
    CHECK(c.time < collisions[i]);
    const Exact_time before = c.batches_before ? sim.batches[c.batches_before - 1].time : Exact_time(s.start);
    CHECK(k.compare(before, Exact_time(c.time)) < 0);
    if (i + 1 < 4) CHECK(c.batches_before <= sim.motion_changes[i + 1].batches_before);
  }
  // The flat triangle: z = -t becomes z = t - 2r.
  const auto& flat = sim.motion_changes[0];
  CHECK(flat.motions[0].kind == scene::Motion::Kind::translation);
  CHECK(flat.motions[0].translation[2] == scene::QPoly({-2 * flat.time, 1}));
  // The right twin falls at speed 2: z = -2t becomes z = 2t - 4r.
  const auto& twins = sim.motion_changes[2];
  CHECK(twins.motions[1].translation[2] == scene::QPoly({-4 * twins.time, 2}));
  check_never_interpenetrate(s, sim);
  if (set == kinetic::Certificate_set::reduced) check_same_run(sim, run(s, kinetic::Update::local));
}

TEST_CASE("a triangle sliding in another's plane is reversed where they first meet", "[collision][kinetic]") {
  // In the plane z = 0 for good, so every sign between the two is the
  // perturbation's and none changes when they meet: a corner of the mover
  // reaches the floor's side at t = 8, or the mover's side reaches the
  // floor's corner (4, -4) at t = 6. The build that the crossing of the
  // floor's wall asks for finds the mover's fragment in the floor's plane
  // and inside it. A third triangle stays above.
  const auto [mover, contact] = GENERATE(table<const char*, long>({
      {R"([["10","0","0"],["11","0","0"],["10","1","0"]])", 8},
      {R"([["10","-6","0"],["10","-2","0"],["13","-4","0"]])", 6}}));
  const auto seed = GENERATE(0, 1, 2);
  const scene::Scene s = scene::read_scene(
      R"({"format": "kvd-scene/1", "time": {"start": "0", "end": "12"}, "priority": {"seed": )" + std::to_string(seed) +
          R"(}, "objects": [
    {"vertices": [["-4","-4","0"],["4","-4","0"],["0","4","0"]], "triangles": [[0,1,2]]},
    {"vertices": )" + mover + R"(, "triangles": [[0,1,2]], "motion": {"translation": [["0","-1"],["0","0"],["0","0"]]}},
    {"vertices": [["-2","-2","3"],["2","-2","3"],["0","2","3"]], "triangles": [[0,1,2]]}]})",
      "inline.json");
  const auto [update, set] = GENERATE(table<kinetic::Update, kinetic::Certificate_set>(
      {{kinetic::Update::local, kinetic::Certificate_set::reduced},
       {kinetic::Update::reinsert, kinetic::Certificate_set::reduced},
       {kinetic::Update::rebuild, kinetic::Certificate_set::full}}));
  INFO("contact " << contact << ", seed " << seed);
  const auto sim = run(s, update, set);
  CHECK(sim.valid());
  CHECK(!sim.collision);
  REQUIRE(sim.motion_changes.size() == 1);
  CHECK(sim.motion_changes[0].objects == std::vector<std::size_t>{1});
  CHECK(k.compare(sim.motion_changes[0].collision, Exact_time(mpq_class(contact))) == 0);
  check_never_interpenetrate(s, sim);
}

namespace {
// A static vertical wall (object 0) and a vertical pane (object 1) moving
// towards it from a parallel plane, lying in the wall's plane at exactly
// t = 1 (y = 0; x = y in the "rotated" scenes, the pane moving along
// (-1, 1, 0); others as said), and a horizontal triangle (object 2) far
// away.
struct Flat_scene {
  const char* name;
  const char* wall;
  const char* pane;
  const char* translation;
  bool meet;  // whether the two meet at t = 1
  const char* wall_triangles = "[[0,1,2]]";
  const char* pane_triangles = "[[0,1,2]]";
};
const Flat_scene flat_scenes[] = {
    {"the pane inside the wall", "[[0,0,0],[4,0,0],[0,0,4]]", "[[1,1,1],[2,1,1],[1,1,2]]", "[0,[0,-1],0]", true},
    {"the wall inside the pane", "[[1,0,1],[2,0,1],[1,0,2]]", "[[0,1,0],[4,1,0],[0,1,4]]", "[0,[0,-1],0]", true},
    // A star: each crosses two sides of the other, no corner inside it.
    {"crossing, no corner inside", "[[0,0,0],[6,0,0],[3,0,6]]", "[[0,1,4],[6,1,4],[3,1,-2]]", "[0,[0,-1],0]", true},
    {"rotated, the pane inside", "[[0,0,0],[4,4,0],[0,0,4]]", "[[2,0,1],[3,1,1],[2,0,2]]", "[[0,-1],[0,1],0]", true},
    {"rotated, crossing", "[[0,0,0],[6,6,0],[3,3,6]]", "[[1,-1,4],[7,5,4],[4,2,-2]]", "[[0,-1],[0,1],0]", true},
    // In x + y = 0; the full set's failures name threads (a point of a
    // pane's edge against the wall's E-plane), not the pane's corners.
    {"in x + y = 0", "[[-1,1,3],[0,0,-1],[1,-1,3]]", "[[-2,4,0],[4,-2,0],[4,-2,4]]", "[[0,-1],[0,-1],0]", true},
    // Two triangles each, in x + 2y = 0: the wall's first meets the pane's
    // first, and the certificates that fail name the wall's second.
    {"two triangles each", "[[-6,3,-2],[-4,2,-3],[4,-2,-4],[-8,4,2],[0,0,3],[6,-3,4]]",
     "[[3,1,-3],[-5,5,2],[-5,5,-2],[-1,3,0],[5,0,-2],[7,-1,2]]", "[[0,-1],[0,-2],0]", true, "[[0,1,2],[3,4,5]]",
     "[[0,1,2],[3,4,5]]"},
    // In 2x = y: the pane's corner reaches the wall's corner (0, 0, 3), and
    // the one certificate failing is VV against P of that corner, y = 0.
    {"corner to corner", "[[2,4,3],[2,4,-1],[0,0,3]]", "[[-1,-7,0],[-2,-9,2],[2,-1,3]]", "[[0,-2],[0,1],0]", true},
    // Beside the wall in its plane at t = 1, apart.
    {"a near miss", "[[0,0,0],[4,0,0],[0,0,4]]", "[[5,1,1],[6,1,1],[5,1,2]]", "[0,[0,-1],0]", false},
    {"rotated, a near miss", "[[0,0,0],[4,4,0],[0,0,4]]", "[[6,4,1],[7,5,1],[6,4,2]]", "[[0,-1],[0,1],0]", false},
};

scene::Scene flat_scene(const Flat_scene& f, int seed) {
  return scene::read_scene(std::string(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 2}, "priority": {"seed": )") +
                               std::to_string(seed) + R"(}, "objects": [
    {"vertices": )" + f.wall + R"(, "triangles": )" + f.wall_triangles + R"(},
    {"vertices": )" + f.pane + R"(, "triangles": )" + f.pane_triangles + R"(, "motion": {"translation": )" +
                               f.translation + R"(}},
    {"vertices": [[20,20,5],[24,20,5],[20,24,5]], "triangles": [[0,1,2]]}]})",
                           "inline.json");
}
}  // namespace

TEST_CASE("vertical triangles landing flat in one plane are reversed when they overlap there", "[collision][kinetic]") {
  // No VT certificate watches a vertical triangle's plane: the failures at
  // t = 1 are VV (a P-plane y = const is the wall's plane), VE (the E-plane
  // of a wall's edge is its plane), TT of the wall's corners against the
  // pane, or the full set's threads, and the pane's vertex in the wall (or
  // a triangle of either in the plane meeting one of the other) makes them
  // a contact. A near miss is none: the run passes t = 1.
  const auto f = GENERATE(from_range(std::begin(flat_scenes), std::end(flat_scenes)));
  const auto seed = GENERATE(0, 1, 2);
  const auto [update, set] = GENERATE(table<kinetic::Update, kinetic::Certificate_set>(
      {{kinetic::Update::local, kinetic::Certificate_set::reduced},
       {kinetic::Update::reinsert, kinetic::Certificate_set::reduced},
       {kinetic::Update::rebuild, kinetic::Certificate_set::full}}));
  INFO(f.name << ", seed " << seed);
  const scene::Scene s = flat_scene(f, seed);
  // The oracle: unreversed, the two meet at t = 1 exactly when they overlap.
  CHECK(scene::first_conflict(s, scene::triangles_at(s, mpq_class(1))).has_value() == f.meet);
  const auto sim = run(s, update, set);
  CHECK(sim.valid());
  CHECK(!sim.collision);
  if (f.meet) {
    REQUIRE(sim.motion_changes.size() == 1);
    CHECK(sim.motion_changes[0].objects == std::vector<std::size_t>{1});
    CHECK(k.compare(sim.motion_changes[0].collision, Exact_time(mpq_class(1))) == 0);
    CHECK(sim.motion_changes[0].contact.find("vertical") != std::string::npos);
  } else {
    CHECK(sim.motion_changes.empty());
    CHECK(k.compare(sim.time_reached, Exact_time(mpq_class(2))) == 0);
  }
  check_never_interpenetrate(s, sim);
  // And at t = 1 itself, with the motions in force: reversed, or apart.
  const scene::Scene now = kinetic::motions_at(s, sim.motion_changes, mpq_class(1));
  CHECK(!scene::first_conflict(now, scene::triangles_at(now, mpq_class(1))));
}

TEMPLATE_TEST_CASE("every kernel answers vertical triangles landing flat alike", "[collision][kinetic]", KVD_ALL_KERNELS) {
  const auto f = GENERATE(from_range(std::begin(flat_scenes), std::end(flat_scenes)));
  INFO(f.name);
  const scene::Scene s = flat_scene(f, 1);
  TestType kernel;
  kinetic::Options o;
  o.max_events = 1000;
  const auto sim = kinetic::simulate(kernel, s, o);
  CHECK(sim.valid());
  CHECK(!sim.collision);
  REQUIRE(sim.motion_changes.size() == (f.meet ? 1u : 0u));
  if (f.meet) {
    CHECK(std::abs(kernel.to_double(sim.motion_changes[0].collision) - 1.0) < 1e-6);
    CHECK(sim.motion_changes[0].time < 1);
    CHECK(sim.motion_changes[0].objects == std::vector<std::size_t>{1});
  }
}

TEMPLATE_TEST_CASE("coplanar_triangles_meet: two triangles in one plane meet by a corner inside or by crossing sides",
                   "[collision]", KVD_ALL_KERNELS) {
  // All in the plane y = 0 at t = 0 (object 1 reaches it then): triangle 0
  // is the wall; 1 lies inside it, 2 crosses it like a star, 3 touches its
  // long side with a corner, 4 shares a line with its base, overlapping,
  // 5 is beside it, 6 beside its long side.
  const scene::Scene s = scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": -1, "end": 1}, "objects": [
    {"vertices": [[0,0,0],[6,0,0],[3,0,6]], "triangles": [[0,1,2]]},
    {"vertices": [[2,0,1],[3,0,1],[3,0,2], [0,0,4],[6,0,4],[3,0,-2], [5,0,2],[7,0,2],[7,0,4],
                  [5,0,0],[9,0,0],[7,0,-1], [8,0,0],[9,0,0],[8,0,1], [6,0,4],[8,0,3],[8,0,5]],
     "triangles": [[0,1,2],[3,4,5],[6,7,8],[9,10,11],[12,13,14],[15,16,17]],
     "motion": {"translation": [0,[0,-1],0]}}]})",
                                           "inline.json", {.seed = std::nullopt, .allow_intersecting = true});
  TestType k;
  const predicates::Classifier<TestType> c(k, s);
  const auto at0 = k.time(from_rational<typename TestType::FT>(mpq_class(0)));
  const bool expected[] = {true, true, true, true, false, false};
  for (std::size_t t = 1; t <= 6; ++t) {
    INFO("triangle " << t);
    CHECK(predicates::coplanar_triangles_meet(c, t, 0, at0) == expected[t - 1]);
    CHECK(predicates::coplanar_triangles_meet(c, 0, t, at0) == expected[t - 1]);
  }
}

TEMPLATE_TEST_CASE("a build at an instant finds coplanar triangles meeting exactly when the scene oracle does",
                   "[collision]", KVD_ALL_KERNELS) {
  // The floor in z = 0, and in the same plane a triangle sliding in -x
  // through it (the two meet on [5, 10]) and one sliding beside it, never
  // meeting. The build at each instant 1/8 past a quarter throws, naming the
  // floor and the mover, exactly when scene::first_conflict finds them
  // meeting. (At 10 itself they touch, and are apart just after, where the
  // build's tree holds.)
  const scene::Scene s = scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": "0", "end": "30"}, "objects": [
    {"vertices": [["-4","-4","0"],["4","-4","0"],["0","4","0"]], "triangles": [[0,1,2]]},
    {"vertices": [["10","0","0"],["11","0","0"],["10","1","0"]], "triangles": [[0,1,2]],
     "motion": {"translation": [["-3","-1"],["0","0"],["0","0"]]}},
    {"vertices": [["10","5","0"],["11","5","0"],["10","6","0"]], "triangles": [[0,1,2]],
     "motion": {"translation": [["0","-1"],["0","0"],["0","0"]]}}]})",
                                           "inline.json");
  TestType kernel;
  const predicates::Classifier<TestType> c(kernel, s);
  int met = 0;
  for (long q = 0; q < 4 * 20; ++q) {
    const mpq_class t(2 * q + 1, 8);
    INFO("t = " << t.get_str());
    const bool oracle = scene::first_conflict(s, scene::triangles_at(s, t)).has_value();
    met += oracle;
    try {
      tree::build(c, kernel.time(from_rational<typename TestType::FT>(t)));
      CHECK(!oracle);
    } catch (const tree::Build_error& e) {
      CHECK(oracle);
      REQUIRE(e.contact);
      CHECK(kinetic::contact_objects(s, *e.contact) == std::vector<std::size_t>{0, 1});
    }
  }
  CHECK(met == 20);  // 41/8 to 79/8
}

TEST_CASE("generated collision scenes validate at every event and never interpenetrate", "[collision][kinetic]") {
  // A tenth of the triangles moving (as kvd bench thesis generates them):
  // the first two sizes meet before the scene's end. Local and rebuild
  // updates give the same run, motion changes included.
  std::size_t changes = 0;
  for (std::size_t n : {25, 50}) {
    scene::Uniform_params p;
    p.triangles = n;
    p.moving = mpq_class(1, 10);
    p.seed = 1;
    const scene::Scene s = scene::read_scene(scene::write_scene(scene::uniform_density(p)), "generated");
    INFO(n << " triangles");
    const auto local = run(s, kinetic::Update::local);
    CHECK(local.valid());
    INFO(local.failure);
    CHECK(local.stopped != kinetic::Stop::collision);
    check_never_interpenetrate(s, local);
    check_same_run(local, run(s, kinetic::Update::rebuild));
    changes += local.motion_changes.size();
  }
  CHECK(changes >= 1);
}

TEMPLATE_TEST_CASE("every kernel answers the collisions of collisions.json alike", "[collision][kinetic]", KVD_ALL_KERNELS) {
  // The floating-point kernels detect the same contacts; their reversal
  // times are rationals of their own (from their event times).
  const scene::Scene s = load("collisions.json");
  TestType kernel;
  kinetic::Options o;
  o.max_events = 1000;
  const auto sim = kinetic::simulate(kernel, s, o);
  CHECK(sim.valid());
  REQUIRE(sim.motion_changes.size() == 4);
  const long collisions[] = {2, 3, 4, 6};
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(std::abs(kernel.to_double(sim.motion_changes[i].collision) - static_cast<double>(collisions[i])) < 1e-6);
    CHECK(sim.motion_changes[i].time < collisions[i]);
  }
  CHECK(sim.motion_changes[2].objects == std::vector<std::size_t>{3, 4});
}

TEST_CASE("with --collisions stop a face landing flat stops the run at its exact time", "[collision][kinetic]") {
  // The flat triangle's three vertices reach the floor together: VT failures,
  // which are contacts, and no fragment ever straddles the floor's plane.
  const scene::Scene s = scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 5}, "objects": [
    {"vertices": [[-20,-20,0],[20,-20,0],[0,20,0]], "triangles": [[0,1,2]]},
    {"vertices": [[-3,-3,2],[-1,-3,2],[-2,-1,2]], "triangles": [[0,1,2]], "motion": {"translation": [0,0,[0,-1]]}}]})",
                                           "inline.json");
  kinetic::Options o;
  o.collisions = kinetic::Collisions::stop;
  const auto sim = kinetic::simulate(k, s, o);
  REQUIRE(sim.stopped == kinetic::Stop::collision);
  CHECK(k.compare(sim.time_reached, Exact_time(mpq_class(2))) == 0);
  REQUIRE(sim.collision);
  CHECK(sim.collision->find("VT") != std::string::npos);
}

// With 8 bits the epsilon swamps every certificate near the contact, so no
// reversal instant between now and the contact is clear of their roots:
// the run gives up on the collision there (it tried ever closer instants
// for ever, with ever longer rationals).
TEST_CASE("a run whose epsilon swamps the certificates near a contact ends", "[collision][kinetic][float]") {
  const scene::Scene s = load("collisions.json");
  kinetic::Options o;
  o.max_events = 300;
  const Mpfr_kernel coarse(8);
  const auto sim = kinetic::simulate(coarse, s, o);
  CHECK(sim.stopped == kinetic::Stop::collision);
  CHECK(sim.collision);
}

TEMPLATE_TEST_CASE("in_closed_triangle: a vertex in a triangle's plane touches it only inside, boundary included", "[collision]",
                   KVD_ALL_KERNELS) {
  // Object 0: a horizontal triangle (plane z = 0) and a vertical one (plane
  // y = 10). Object 1: vertices that reach z = 0 at t = 1 and y = 10 at t = 2,
  // inside, outside, on a side and at a corner.
  const scene::Scene s = scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 5}, "objects": [
    {"vertices": [[0,0,0],[4,0,0],[0,4,0],[20,10,0],[24,10,0],[20,10,4]], "triangles": [[0,1,2],[3,4,5]]},
    {"vertices": [[1,1,1],[3,3,1],[2,2,1],[0,"5/2",1],[4,0,1],
                  [21,8,1],[23,8,3],[21,8,3]], "triangles": [[0,1,3],[2,4,5],[5,6,7]],
     "motion": {"vertices": [[1,1,[1,-1],1],[3,3,[1,-1],1],[2,2,[1,-1],1],[0,"5/2",[1,-1],1],[4,0,[1,-1],1],
                             [21,[8,1],1,1],[23,[8,1],3,1],[21,[8,1],3,1]]}}]})",
                                           "inline.json", {.seed = std::nullopt, .allow_intersecting = true});
  TestType k;
  const predicates::Classifier<TestType> c(k, s);
  const auto at = [&](long t) { return k.time(from_rational<typename TestType::FT>(mpq_class(t))); };
  const auto in = [&](std::size_t v, std::size_t t, long time) {
    return predicates::in_closed_triangle(c, symbolic::Symbolic_vertex::endpoint(v), t, at(time));
  };
  // The horizontal triangle at t = 1 (vertex ids 6.. are object 1's).
  CHECK(in(6, 0, 1));    // (1, 1): inside
  CHECK(!in(7, 0, 1));   // (3, 3): outside, beyond the long side
  CHECK(in(8, 0, 1));    // (2, 2): on the long side
  CHECK(in(9, 0, 1));    // (0, 5/2): on the side x = 0
  CHECK(in(10, 0, 1));   // (4, 0): at a corner
  // The vertical triangle at t = 2.
  CHECK(in(11, 1, 2));   // (21, 10, 1): inside
  CHECK(!in(12, 1, 2));  // (23, 10, 3): outside, beyond the sloping side
  CHECK(in(13, 1, 2));   // (21, 10, 3): on the sloping side
}
