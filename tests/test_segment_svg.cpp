// Pictures of the cylindrical BSP of segments: one element per cut, each
// clipped inside the view box, and the same bytes every time.
#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <vector>

#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/segments/segment_svg.hpp"

using namespace kvd;
using namespace kvd::segments;

namespace {

Segment_scene bundled(const std::string& name) {
  return load_segments(std::string(KVD_SOURCE_DIR) + "/data/segments/" + name + ".json");
}

Cylindrical_bsp build_at(const Segment_scene& s, const mpq_class& t) {
  const Exact_kernel k;
  const Segment_predicates<Exact_kernel> pred(k, s);
  return build_cylindrical_bsp(pred, Exact_time(t));
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Drawn_line {
  double x1, y1, x2, y2;
};

// The <line> elements of class `cls`.
std::vector<Drawn_line> lines(const std::string& svg, const std::string& cls) {
  const std::regex re("<line class=\"" + cls + "\" x1=\"([^\"]+)\" y1=\"([^\"]+)\" x2=\"([^\"]+)\" y2=\"([^\"]+)\"/>");
  std::vector<Drawn_line> out;
  for (std::sregex_iterator it(svg.begin(), svg.end(), re), end; it != end; ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  return out;
}

// The picture's elements agree with the tree's counts, and every vertical
// cut stays in the view box.
void check_picture(const Segment_scene& s, const mpq_class& t) {
  const Cylindrical_bsp bsp = build_at(s, t);
  const Bsp_counts c = bsp.counts();
  const std::string svg = segment_svg(s, bsp, t);
  INFO(s.name << " at t = " << t.get_str() << ": " << bsp.text());
  CHECK(occurrences(svg, "class=\"vertex-cut\"") == c.vertex_cuts);
  CHECK(occurrences(svg, "class=\"intersection-cut\"") == c.intersection_cuts);
  CHECK(occurrences(svg, "class=\"edge-cut\"") == c.edge_cuts);
  CHECK(occurrences(svg, "class=\"cell ") == c.leaves);
  CHECK(occurrences(svg, "class=\"endpoint\"") == s.endpoint_count());
  CHECK(svg.find("vertex cuts: " + std::to_string(c.vertex_cuts) + "<") != std::string::npos);
  CHECK(svg.find(std::to_string(c.nodes) + " nodes") != std::string::npos);
  std::smatch box;
  const std::regex box_element("class=\"view-box\" x=\"([^\"]+)\" y=\"([^\"]+)\" width=\"([^\"]+)\" height=\"([^\"]+)\"");
  REQUIRE(std::regex_search(svg, box, box_element));
  const double x0 = std::stod(box[1]), y0 = std::stod(box[2]), x1 = x0 + std::stod(box[3]), y1 = y0 + std::stod(box[4]);
  const double slack = 0.01;  // 6 significant digits
  for (const char* cls : {"vertex-cut", "intersection-cut"})
    for (const Drawn_line& l : lines(svg, cls)) {
      CHECK(l.x1 == l.x2);
      CHECK(l.x1 >= x0 - slack);
      CHECK(l.x1 <= x1 + slack);
      for (const double y : {l.y1, l.y2}) {
        CHECK(y >= y0 - slack);
        CHECK(y <= y1 + slack);
      }
      CHECK(l.y1 >= l.y2 - slack);  // the floor (y1) is below the roof, y pointing down in SVG
    }
  // The layout a page draws the picture from puts the frame, the endpoints
  // and the crossings where the picture has them, and has its caption.
  const Segment_layout layout = segment_layout(s, bsp, t);
  CHECK(layout.left == Approx(x0).margin(slack));
  CHECK(layout.top == Approx(y0).margin(slack));
  CHECK(layout.left + layout.box_width == Approx(x1).margin(slack));
  CHECK(layout.top + layout.box_height == Approx(y1).margin(slack));
  CHECK(svg.find("width=\"" + std::to_string(layout.width) + "\" height=\"" + std::to_string(layout.height) + "\"") !=
        std::string::npos);
  const std::regex circle("class=\"endpoint\" cx=\"([^\"]+)\" cy=\"([^\"]+)\"");
  std::size_t e = 0;
  for (std::sregex_iterator it(svg.begin(), svg.end(), circle), end; it != end; ++it, ++e) {
    REQUIRE(e < layout.endpoints.size());
    CHECK(layout.endpoints[e][0] == Approx(std::stod((*it)[1])).margin(slack));
    CHECK(layout.endpoints[e][1] == Approx(std::stod((*it)[2])).margin(slack));
  }
  CHECK(e == layout.endpoints.size());
  const std::regex mark("class=\"crossing\" d=\"M([^ ]+) ([^L]+)L");
  std::size_t k = 0;
  for (std::sregex_iterator it(svg.begin(), svg.end(), mark), end; it != end; ++it, ++k) {
    REQUIRE(k < layout.crossings.size());
    CHECK(layout.crossings[k].second[0] == Approx(std::stod((*it)[1]) + 4).margin(slack));
    CHECK(layout.crossings[k].second[1] == Approx(std::stod((*it)[2]) + 4).margin(slack));
  }
  CHECK(k == layout.crossings.size());
  for (const std::string& line : layout.caption)
    if (!line.empty()) CHECK(svg.find(">" + line + "<") != std::string::npos);
}

}  // namespace

TEST_CASE("the picture of two crossing segments has one element per cut, inside the view box", "[segments][svg]") {
  const Segment_scene s = bundled("two-crossing");
  const Cylindrical_bsp bsp = build_at(s, 0);
  const Bsp_counts c = bsp.counts();
  CHECK(c.vertex_cuts == 4);
  CHECK(c.intersection_cuts > 0);
  check_picture(s, 0);
  // The same bytes every time.
  CHECK(segment_svg(s, bsp, 0) == segment_svg(s, build_at(s, 0), 0));
  CHECK(segment_svg(s, bsp, 0).find("<text x=\"8\" y=\"22\">two-crossing</text>") != std::string::npos);
}

TEST_CASE("pictures of the bundled scenes agree with their trees", "[segments][svg]") {
  check_picture(bundled("concurrent-three"), 0);
  check_picture(bundled("random-100"), mpq_class(1, 3));
  for (const char* t : {"1", "2", "3", "7/2"}) check_picture(bundled("over-endpoint"), mpq_class(t));
  for (const char* t : {"1/2", "1", "3/2"}) check_picture(bundled("turning-vertical"), mpq_class(t));  // vertical at 1
}

// The three segments meet at (2, 2): every intersection cut passes through
// that one point, whatever the perturbation decides about their order.
TEST_CASE("concurrent crossings are drawn at their common point", "[segments][svg]") {
  const Segment_scene s = bundled("concurrent-three");
  const std::string svg = segment_svg(s, build_at(s, 0), 0);
  const auto cuts = lines(svg, "intersection-cut");
  REQUIRE(!cuts.empty());
  for (const Drawn_line& l : cuts) CHECK(l.x1 == cuts.front().x1);
  CHECK(occurrences(svg, "class=\"crossing\"") == 3);  // three pairs, one place
}

// A segment turning about (2, 0) lies along another one at t = 0 and crosses
// it just after: the crossing is drawn where it goes, not where the lines
// meet at 0 (everywhere).
TEST_CASE("a crossing of segments collinear at t is drawn where it is just after t", "[segments][svg]") {
  Segment_scene s;
  s.name = "collinear";
  Segment floor, turning;
  floor.rest = {Point3{0, 0, 1}, Point3{4, 0, 1}};
  turning.rest = {Point3{0, 0, 1}, Point3{0, 0, 1}};
  turning.motion.kind = Segment_motion::Kind::endpoints;
  turning.motion.endpoints = {Motion_point3{QPoly(1), QPoly({0, -1}), QPoly(1)},
                              Motion_point3{QPoly(3), QPoly({0, 1}), QPoly(1)}};
  s.segments = {floor, turning};
  s.order = std::vector<std::size_t>{0, 1};
  s.end = 1;
  s.derive();
  const Cylindrical_bsp bsp = build_at(s, 0);
  REQUIRE(bsp.counts().intersection_cuts > 0);
  const std::string svg = segment_svg(s, bsp, 0);
  const auto floor_line = lines(svg, "segment").front();
  for (const Drawn_line& l : lines(svg, "intersection-cut"))
    CHECK(l.x1 == Approx((floor_line.x1 + floor_line.x2) / 2));
  check_picture(s, 0);
}

// Two segments along one steep line, sharing an endpoint, cross in the
// perturbed scene: the crossing is drawn where the perturbation's crossing
// tends to, on their line.
TEST_CASE("a crossing of segments collinear through time is drawn on their line", "[segments][svg]") {
  Segment_scene s;
  s.name = "collinear";
  for (const long b : {1, 2}) {
    Segment seg;
    seg.rest = {Point3{0, 0, 1}, Point3{b, 13 * b, 1}};
    s.segments.push_back(seg);
  }
  s.order = std::vector<std::size_t>{0, 1};
  s.derive();
  const Cylindrical_bsp bsp = build_at(s, 0);
  REQUIRE(bsp.counts().intersection_cuts > 0);
  const std::string svg = segment_svg(s, bsp, 0);
  const Drawn_line line = lines(svg, "segment").back();
  std::smatch mark;
  REQUIRE(std::regex_search(svg, mark, std::regex("class=\"crossing\" d=\"M([^ ]+) ([^L]+)L")));
  const double x = std::stod(mark[1]) + 4, y = std::stod(mark[2]) + 4;
  CHECK(x >= std::min(line.x1, line.x2));
  CHECK(x <= std::max(line.x1, line.x2));
  CHECK(y == Approx(line.y1 + (line.y2 - line.y1) * (x - line.x1) / (line.x2 - line.x1)).margin(0.05));
  check_picture(s, 0);
}
