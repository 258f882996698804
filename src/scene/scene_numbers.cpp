#include "kvd/detail/scene/scene_numbers.hpp"

namespace kvd::scene {

namespace {

class Finder {
public:
  explicit Finder(const std::function<bool(const Q&)>& bad) : bad_(bad) {}
  std::optional<Number_place> found;

  void number(const Q& q, const std::string& at, int power = 0) {
    if (!found && bad_(q)) found = Number_place{at, power, q};
  }
  void poly(const QPoly& p, const std::string& at) {
    const auto& c = p.coefficients();
    for (std::size_t i = 0; i < c.size(); ++i) number(c[i], at, static_cast<int>(i));
  }
  void point(const Motion_point& p, const std::string& at) {
    for (int k = 0; k < 4; ++k) poly(p[k], at + "/" + std::to_string(k));
  }

private:
  const std::function<bool(const Q&)>& bad_;
};

}  // namespace

std::optional<Number_place> first_number(const Scene& s, const std::function<bool(const Q&)>& bad) {
  Finder f(bad);
  f.point(s.x, "/decomposition/x");
  f.point(s.z, "/decomposition/z");
  for (std::size_t o = 0; o < s.objects.size() && !f.found; ++o) {
    const Object& obj = s.objects[o];
    const std::string at = "/objects/" + std::to_string(o);
    for (std::size_t i = 0; i < obj.vertex_count; ++i)
      for (int k = 0; k < 4; ++k)
        f.number(s.rest[obj.first_vertex + i][k], at + "/vertices/" + std::to_string(i) + "/" + std::to_string(k));
    const Motion& m = obj.motion;
    switch (m.kind) {
      case Motion::Kind::none: break;
      case Motion::Kind::translation:
        for (std::size_t k = 0; k < 3; ++k) f.poly(m.translation[k], at + "/motion/translation/" + std::to_string(k));
        break;
      case Motion::Kind::matrix:
        for (std::size_t r = 0; r < 4; ++r)
          for (std::size_t c = 0; c < 4; ++c)
            f.poly(m.matrix[r][c], at + "/motion/matrix/" + std::to_string(r) + "/" + std::to_string(c));
        break;
      case Motion::Kind::vertices:
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
          f.point(m.vertices[i], at + "/motion/vertices/" + std::to_string(i));
        break;
    }
  }
  return f.found;
}

}  // namespace kvd::scene
