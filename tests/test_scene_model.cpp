// The scene model: derived edges and incidence, priority order, cut
// priorities, motion evaluation, and the writer's round trip.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/detail/scene/priority.hpp"
#include "kvd/scene/scene_io.hpp"

namespace fs = std::filesystem;
using namespace kvd::scene;

namespace {
std::vector<fs::path> scenes_in(const fs::path& dir) {
  std::vector<fs::path> r;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") r.push_back(e.path());
  std::sort(r.begin(), r.end());
  return r;
}
}  // namespace

TEST_CASE("every bundled and shared sample scene loads and round-trips exactly", "[scene]") {
  auto files = scenes_in(fs::path(KVD_SOURCE_DIR) / "data");
  const auto shared = scenes_in(fs::path(KVD_SOURCE_DIR) / ".." / "shared" / "scenes");
  if (shared.empty()) WARN("the shared sample scenes are not beside the repository; checking data/ only");
  files.insert(files.end(), shared.begin(), shared.end());
  REQUIRE(files.size() >= 7);
  for (const auto& f : files) {
    INFO(f.string());
    const Scene s = load_scene(f.string());
    const std::string text = write_scene(s);
    const Scene again = read_scene(text, "written");
    CHECK(again == s);
    CHECK(write_scene(again) == text);
    CHECK(again.priority_order == s.priority_order);
    CHECK(again.edges == s.edges);
  }
}

TEST_CASE("exact numbers follow the format's grammar", "[scene]") {
  std::string why;
  CHECK(*parse_exact_number("-12", why) == -12);
  CHECK(*parse_exact_number("0.1", why) == mpq_class(1, 10));
  CHECK(*parse_exact_number("-2.5e-3", why) == mpq_class(-1, 400));
  CHECK(*parse_exact_number("1E+9", why) == 1000000000);
  CHECK(*parse_exact_number("6/4", why) == mpq_class(3, 2));
  CHECK(*parse_exact_number("-7/2", why) == mpq_class(-7, 2));
  CHECK(*parse_exact_number("007", why) == 7);
  CHECK_FALSE(parse_exact_number("", why));
  CHECK_FALSE(parse_exact_number("-", why));
  CHECK_FALSE(parse_exact_number("1/2/3", why));
  CHECK_FALSE(parse_exact_number("1.5/2", why));
  CHECK_FALSE(parse_exact_number("1e+10001", why));
  CHECK(why.find("10000") != std::string::npos);
  CHECK(exact_text(mpq_class(-7, 2)) == "-7/2");
}

TEST_CASE("SplitMix64 gives the published sequence", "[scene][priority]") {
  Split_mix64 g(0);
  CHECK(g.next() == 0xe220a8397b1dcdafULL);
  CHECK(g.next() == 0x6e789e6aa1b965f4ULL);
  CHECK(g.next() == 0x06c45d188009454fULL);
  // A fixed seed gives a fixed shuffle, and every id once.
  const auto a = shuffled_ids(50, 7), b = shuffled_ids(50, 7), c = shuffled_ids(50, 8);
  CHECK(a == b);
  CHECK(a != c);
  auto sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) CHECK(sorted[i] == i);
}

TEST_CASE("edges, incidence and cut priorities follow the format page", "[scene]") {
  // A quad (two triangles sharing edge 0-2) that moves, and a static triangle.
  const Scene s = read_scene(R"({"format": "kvd-scene/1", "priority": {"seed": 3}, "objects": [
      {"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "triangles": [[0,1,2],[0,2,3]],
       "motion": {"translation": [[0,1], 0, 0]}},
      {"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]]}]})",
                             "quad.json");
  REQUIRE(s.edges.size() == 8);
  // First appearance: (0,1), (1,2), (2,0), then (2,3), (3,0), then the static triangle.
  CHECK(s.edges[0] == std::array<std::size_t, 2>{0, 1});
  CHECK(s.edges[2] == std::array<std::size_t, 2>{2, 0});
  CHECK(s.edges[3] == std::array<std::size_t, 2>{2, 3});
  CHECK(s.triangle_edges[1] == std::array<std::size_t, 3>{2, 3, 4});
  CHECK(s.edge_triangles[2] == std::vector<std::size_t>{0, 1});
  CHECK(s.vertex_edges[0] == std::vector<std::size_t>{0, 2, 4});
  // Static first, whatever the seed.
  CHECK(s.priority_order[0] == 2);
  CHECK(s.triangle_priority[2] == 0);
  CHECK(s.moving_triangle_count() == 2);
  CHECK(s.max_motion_degree() == 1);
  // Cut priorities: 7 TPO + slot, shared features take the smaller number.
  const std::size_t p0 = 7 * s.triangle_priority[0], p1 = 7 * s.triangle_priority[1];
  CHECK(s.triangle_cut_priority[0] == p0 + 6);
  CHECK(s.vertex_cut_priority[0] == std::min(p0 + 0, p1 + 0));
  CHECK(s.vertex_cut_priority[2] == std::min(p0 + 2, p1 + 1));
  CHECK(s.edge_cut_priority[2] == std::min(p0 + 5, p1 + 3));
  CHECK(s.vertex_cut_priority[6] == 2);
  // --seed replaces the order; an explicit order is kept even if moving first.
  Load_options o;
  o.seed = 99;
  CHECK(read_scene(write_scene(s), "w", o).priority_spec.seed == 99);
  const Scene explicit_order = read_scene(R"({"format": "kvd-scene/1", "priority": {"order": [[0,1],[1,0],[0,0]]}, "objects": [
      {"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "triangles": [[0,1,2],[0,2,3]], "motion": {"translation": [[0,1], 0, 0]}},
      {"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]]}]})",
                                          "order.json");
  CHECK(explicit_order.priority_order == std::vector<std::size_t>{1, 2, 0});
}

TEST_CASE("vertices evaluate under each motion form", "[scene]") {
  const Scene s = read_scene(R"({"format": "kvd-scene/1", "objects": [
      {"vertices": [[1,0,0],[0,1,0],[0,0,1]], "triangles": [[0,1,2]],
       "motion": {"translation": [[0,"1/2"], 0, [0,0,"-1/100"]]}},
      {"vertices": [[3,0,9],[0,3,9],[3,3,10]], "triangles": [[0,1,2]],
       "motion": {"matrix": [[[1,0,-1],[0,-2],0,0],[[0,2],[1,0,-1],0,0],[0,0,[1,0,1],0],[0,0,0,[1,0,1]]]}},
      {"vertices": [[0,0,20],[1,0,20],[0,1,20]], "triangles": [[0,1,2]],
       "motion": {"vertices": [[0,0,20,1],[[1,1],0,20,1],[0,1,[40,2],2]]}}]})",
                             "motions.json");
  // Translation at t = 2: (1 + 1, 0, 0 - 4/100).
  CHECK(s.position_at(0, 2) == QPoint{{2, 0, mpq_class(-1, 25), 1}});
  // Rotation by 2 atan(t) about z at t = 1 is a quarter turn: (3,0,9) -> (0,3,9), scaled by 1+t^2 = 2.
  CHECK(s.position_at(3, 1) == QPoint{{0, 6, 18, 2}});
  CHECK(s.max_motion_degree() == 2);
  // Deforming: vertex 2 of the third object at t = 1 is (0,1,42,2) = (0, 1/2, 21).
  CHECK(s.position_at(8, 1) == QPoint{{0, 1, 42, 2}});
  CHECK(s.position(7)[0] == QPoly{1, 1});
}
