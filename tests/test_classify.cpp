// The classification predicate: the lexicographic rule on a crossing, the
// same signs in every kernel in general position, and the symbolic
// perturbation against an explicit perturbation ε = 2^-k of the scene.
#include <catch2/catch.hpp>

#include "kernels.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/scene/scene_io.hpp"
#include "symbolic_samples.hpp"

using namespace kvd;
using kvd::predicates::Classifier;
using kvd::predicates::Rule;
using SV = kvd::symbolic::Symbolic_vertex;
using SP = kvd::symbolic::Symbolic_plane;

namespace {

scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

// A static triangle with a vertex at the origin, and a triangle far off in x
// whose vertex u = (10, t - 1, 0) crosses the P-plane y = 0 at t = 1.
const char* crossing = R"({"format": "kvd-scene/1", "objects": [
  {"vertices": [[0,0,0],[4,1,0],[0,2,1]], "triangles": [[0,1,2]]},
  {"vertices": [[10,-1,0],[11,-1,1],[10,-1,2]], "triangles": [[0,1,2]], "motion": {"translation": [0, [0,1], 0]}}]})";

}  // namespace

TEMPLATE_TEST_CASE("a vertex crossing a P-plane: value, then sign after, then value", "[classify]", KVD_ALL_KERNELS) {
  const TestType k;
  const scene::Scene s = scene::read_scene(crossing, "crossing.json");
  const Classifier<TestType> c(k, s);
  const SV u = SV::endpoint(3);
  const SP p{SP::Kind::P, 0};
  auto at = [&](long v) { return kvd::test::at(k, v); };
  CHECK(c.classify(u, p, at(0)).side == -1);
  CHECK(c.classify(u, p, at(0)).rule == Rule::value);
  CHECK(c.classify(u, p, at(1)).side == 1);
  CHECK(c.classify(u, p, at(1)).rule == Rule::after);
  CHECK(c.classify(u, p, at(2)).side == 1);
  CHECK(c.classify(SV::endpoint(0), p, at(1)).rule == Rule::incidence);
  CHECK(c.classify(SV::endpoint(0), p, at(1)).side == 0);
}

TEMPLATE_TEST_CASE("every kernel classifies a scene in general position alike", "[classify]", kvd::Double_kernel,
                   kvd::Mpfr_kernel) {
  const TestType k;
  const kvd::Exact_kernel exact;
  const scene::Scene s = load("random-20.json");
  const Classifier<TestType> c(k, s);
  const Classifier<kvd::Exact_kernel> reference(exact, s);
  long compared = 0, differ = 0;
  for (const auto& v : kvd::test::sample_vertices(s, false, 3))
    for (const auto& p : kvd::test::all_planes(s))
      for (long num : {0L, 1L}) {
        const int want = reference.side(v, p, exact.time(mpq_class(num, 2)));
        const int got = c.side(v, p, k.time(typename TestType::FT(num) / typename TestType::FT(2)));
        ++compared;
        differ += want != got;
      }
  INFO(compared << " classifications compared");
  CHECK(compared > 1000);
  CHECK(differ == 0);
}

TEST_CASE("the symbolic perturbation agrees with an explicit ε = 2^-k", "[classify][perturbation]") {
  const kvd::Exact_kernel k;
  for (const char* name : {"boxes.json", "cycle3.json", "degenerate-shared-y.json", "degenerate-vertical-edge.json",
                           "degenerate-z-on-plane.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const Classifier<kvd::Exact_kernel> symbolic(k, s);
    // The same scene with vertex i moved by 2^-k (i+1, (i+1)^2, (i+1)^3): both
    // scenes are static or translating, so moving the rest position moves the
    // vertex at every time.
    // Rule 4 makes ε infinitely small next to the time step δ of "just after
    // t": so the explicit check evaluates at t + δ with δ = 2^-(k/6) >> ε = 2^-k.
    const std::vector<unsigned long> ks{60, 90, 120};
    std::vector<scene::Scene> explicit_scenes;
    for (unsigned long bits : ks) {
      scene::Scene e = s;
      const mpq_class eps = mpq_class(1) / (mpz_class(1) << bits);
      for (std::size_t i = 0; i < e.rest.size(); ++i) {
        const long n = static_cast<long>(i) + 1;
        e.rest[i][0] += eps * n;
        e.rest[i][1] += eps * n * n;
        e.rest[i][2] += eps * n * n * n;
      }
      explicit_scenes.push_back(e);
    }
    std::vector<Classifier<kvd::Exact_kernel>> explicit_classifiers;
    for (const auto& e : explicit_scenes) explicit_classifiers.emplace_back(k, e);
    long perturbed = 0, disagreements = 0;
    // Fragment corners are finite points: vertices at infinity (two parallel
    // E-planes, say) are never built, and are left out.
    std::vector<SV> corners;
    for (const auto& v : kvd::test::sample_vertices(s, false, 6))
      if (!symbolic.motion().point(v)[3].is_zero()) corners.push_back(v);
    for (const auto& v : corners)
      for (const auto& p : kvd::test::all_planes(s))
        for (const mpq_class& t : {mpq_class(0), mpq_class(1, 3)}) {
          const auto r = symbolic.classify(v, p, kvd::Exact_time(t));
          if (r.rule != Rule::perturbation) continue;
          ++perturbed;
          for (std::size_t i = 0; i < ks.size(); ++i) {
            const mpq_class later = t + mpq_class(1) / (mpz_class(1) << (ks[i] / 6));
            const int side = explicit_classifiers[i].side(v, p, kvd::Exact_time(later));
            if (side != r.side && disagreements++ < 5)
              UNSCOPED_INFO(kvd::symbolic::to_string(v) << " vs " << kvd::symbolic::to_string(p) << " at " << t.get_str()
                                                        << ": symbolic " << r.side << ", explicit " << side << " (k = " << ks[i] << ")");
          }
        }
    INFO(perturbed << " classifications decided by the perturbation");
    CHECK(perturbed > 0);
    CHECK(disagreements == 0);
    for (const auto& v : corners)
      for (const auto& p : kvd::test::all_planes(s))
        if (symbolic.classify(v, p, kvd::Exact_time(0)).rule == Rule::unresolved)
          UNSCOPED_INFO("unresolved: " << kvd::symbolic::to_string(v) << " vs " << kvd::symbolic::to_string(p));
    CHECK(symbolic.unresolved() == 0);
  }
}
