// The segment scene families: random, rotating and degenerate.
#include <set>

#include "kvd/detail/scene/priority.hpp"
#include "kvd/segments/segment_generators.hpp"

namespace kvd::segments {

namespace {

using scene::Generator_error;
using scene::Split_mix64;

constexpr int max_attempts = 1000;
// Midpoints lie on a grid of this many steps per box side.
constexpr long grid = 1000;

Q ratio(long a, long b) {
  Q q(a, b);
  q.canonicalize();
  return q;
}

long floor_long(const Q& q) {
  mpz_class r;
  mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r.get_si();
}

long ceil_long(const Q& q) {
  mpz_class r;
  mpz_cdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r.get_si();
}

// A unit vector at a random rational angle 2 atan(k/40) for |k| < 40: within
// 88 degrees of the x axis, never vertical.
std::array<Q, 2> direction(Split_mix64& g) {
  const long k = g.between(-39, 39);
  return {ratio(1600 - k * k, 1600 + k * k), ratio(80 * k, 1600 + k * k)};
}

Segment segment(const Q& x0, const Q& y0, const Q& x1, const Q& y1) {
  Segment s;
  s.rest = {Point3{x0, y0, Q(1)}, Point3{x1, y1, Q(1)}};
  return s;
}

// random and rotating: n segments of the same length, no endpoint x twice.
std::vector<Segment> random_segments(const Segment_generator_options& o, const Q& length, Split_mix64& g) {
  const Q half = length * o.box / 2;
  std::vector<Segment> out;
  std::set<Q> xs;
  for (std::size_t i = 0; i < o.n; ++i) {
    for (int attempt = 0;; ++attempt) {
      if (attempt == max_attempts)
        throw Generator_error("could not place segment " + std::to_string(i) + " with endpoints of new x after " +
                              std::to_string(max_attempts) + " attempts");
      const auto d = direction(g);
      const Q hx = abs(d[0]) * half, hy = abs(d[1]) * half;
      // A midpoint on the grid that keeps the whole segment in the box.
      const Q step = o.box / grid;
      const Q cx = step * g.between(ceil_long(hx / step), floor_long((o.box - hx) / step));
      const Q cy = step * g.between(ceil_long(hy / step), floor_long((o.box - hy) / step));
      const Q x0 = cx - d[0] * half, x1 = cx + d[0] * half;
      if (xs.count(x0) || xs.count(x1)) continue;
      xs.insert(x0);
      xs.insert(x1);
      out.push_back(segment(x0, cy - d[1] * half, x1, cy + d[1] * half));
      break;
    }
  }
  return out;
}

// One gadget of the degenerate family in local coordinates of a 10 x 10 cell.
using Local = std::array<long, 4>;  // x0, y0, x1, y1 in halves of a unit
std::vector<Local> gadget(std::size_t kind, Split_mix64& g) {
  const long j = g.between(-1, 1), k = g.between(-1, 1);
  switch (kind) {
    case 0: {  // three segments through (cx, cy), an interior point of each
      static const long dirs[7][2] = {{3, 1}, {3, -1}, {2, 2}, {2, -2}, {3, 0}, {1, 3}, {1, -3}};
      const long cx = 10 + j, cy = 10 + k;
      const std::vector<std::size_t> pick = scene::shuffled_ids(7, g.next());
      std::vector<Local> out;
      for (std::size_t i = 0; i < 3; ++i) {
        const long* d = dirs[pick[i]];
        const long a = g.between(1, 2), b = g.between(1, 2);  // the two arms, 1 or 2 times d
        out.push_back({cx - a * d[0], cy - a * d[1], cx + b * d[0], cy + b * d[1]});
      }
      return out;
    }
    case 1: {  // two collinear segments overlapping on a third of each
      static const long dirs[5][2] = {{2, 1}, {1, 2}, {2, -1}, {2, 0}, {1, -2}};
      const long* d = dirs[g.between(0, 4)];
      const long cx = 10 + j, cy = 10 + k;
      return {{cx - 3 * d[0], cy - 3 * d[1], cx + d[0], cy + d[1]}, {cx - d[0], cy - d[1], cx + 3 * d[0], cy + 3 * d[1]}};
    }
    case 2: {  // a vertical segment, and a segment above it starting at the same x
      const long x = 6 + 2 * j;
      return {{x, 4, x, 12}, {x, 14, x + 8, 18 + k}};
    }
    default: {  // two segments, one above the other, their endpoints at the same two x
      const long x0 = 4 + 2 * j, x1 = 14 + 2 * k;
      return {{x0, 4, x1, 8}, {x0, 14, x1, 10}};
    }
  }
}

std::vector<Segment> degenerate_segments(const Segment_generator_options& o, Split_mix64& g) {
  static const std::size_t sizes[4] = {3, 2, 2, 2};
  std::size_t gadgets = 0;
  for (std::size_t total = 0; total < o.n; ++gadgets) total += sizes[gadgets % 4];
  long side = 1;
  while (static_cast<std::size_t>(side * side) < gadgets) ++side;
  const Q cell = o.box / side, unit = cell / 20;  // local coordinates count halves
  std::vector<Segment> out;
  for (std::size_t i = 0; out.size() < o.n; ++i) {
    const Q ox = cell * static_cast<long>(i % static_cast<std::size_t>(side));
    const Q oy = cell * static_cast<long>(i / static_cast<std::size_t>(side));
    for (const Local& l : gadget(i % 4, g))
      if (out.size() < o.n) out.push_back(segment(ox + unit * l[0], oy + unit * l[1], ox + unit * l[2], oy + unit * l[3]));
  }
  return out;
}

// A random rational in [-scale/10, scale/10] in steps of scale/1000, never 0
// (a moving segment must move).
Q speed(const Q& scale, Split_mix64& g) {
  const long k = g.between(1, 100);
  return scale * ratio(g.between(0, 1) ? k : -k, 1000);
}

Segment_motion motion(Segment_motion_kind kind, bool vertical_only, const Segment& s, const Q& box, Split_mix64& g) {
  Segment_motion m;
  if (kind == Segment_motion_kind::rotating) {
    // The rotation by 2 atan(w t) about the midpoint c: with a = 1 - w^2 t^2,
    // b = 2 w t, W = 1 + w^2 t^2, X = a (x - cx) - b (y - cy) + cx W.
    const Q w = ratio(g.between(1, 8) * (g.between(0, 1) ? 1 : -1), 4);
    const Q cx = (s.rest[0][0] + s.rest[1][0]) / 2, cy = (s.rest[0][1] + s.rest[1][1]) / 2;
    const QPoly a{Q(1), Q(0), -w * w}, b{Q(0), 2 * w}, lift{Q(0), Q(0), 2 * w * w};  // lift = W - a
    m.kind = Segment_motion::Kind::matrix;
    m.matrix = {{{a, -b, lift * cx + b * cy}, {b, a, lift * cy - b * cx}, {QPoly(), QPoly(), a + lift}}};
    return m;
  }
  m.kind = Segment_motion::Kind::translation;
  for (std::size_t axis = 0; axis < 2; ++axis) {
    if (axis == 0 && vertical_only) continue;
    std::vector<Q> c{Q(0), speed(box, g)};
    if (kind == Segment_motion_kind::quadratic) c.push_back(speed(box, g) / 10);
    m.translation[axis] = QPoly(std::move(c));
  }
  return m;
}

Q default_length(const Segment_generator_options& o) {
  if (o.crossings == Crossings::quadratic) return Q(1, 2);
  long root = 1;
  while (static_cast<std::size_t>(root * root) < o.n) ++root;
  return Q(1, root);
}

const char* family_name(Segment_family f) {
  switch (f) {
    case Segment_family::random: return "random";
    case Segment_family::rotating: return "rotating";
    case Segment_family::degenerate: return "degenerate";
  }
  return "?";
}

const char* motion_name(Segment_motion_kind k) {
  switch (k) {
    case Segment_motion_kind::linear: return "linear";
    case Segment_motion_kind::quadratic: return "quadratic";
    case Segment_motion_kind::rotating: return "rotating";
  }
  return "?";
}

}  // namespace

Segment_scene generate_segments(const Segment_generator_options& o) {
  if (o.n == 0) throw Generator_error("a segment scene needs at least one segment");
  if (o.box <= 0) throw Generator_error("the box side must be positive");
  if (o.end <= 0) throw Generator_error("the end time must be positive");
  if (o.length && (*o.length <= 0 || *o.length > 1))
    throw Generator_error("the length is a fraction of the box side, in (0, 1]");
  const std::size_t moving = o.moving.value_or(o.n);
  if (moving > o.n) throw Generator_error("more moving segments than segments");
  const bool rotating = o.family == Segment_family::rotating;
  const Segment_motion_kind kind = o.motion.value_or(rotating ? Segment_motion_kind::rotating : Segment_motion_kind::linear);
  if (rotating && kind != Segment_motion_kind::rotating)
    throw Generator_error("the rotating family turns its segments: the motion must be rotating");
  const Q length = o.length ? *o.length : default_length(o);

  Split_mix64 g(o.seed);
  Segment_scene s;
  s.name = std::string("segments-") + family_name(o.family) + " n=" + std::to_string(o.n) +
           (o.family == Segment_family::degenerate ? "" : " length=" + length.get_str()) +
           " moving=" + std::to_string(moving) + " motion=" + motion_name(kind) + " seed=" + std::to_string(o.seed);
  s.start = 0;
  s.end = o.end;
  s.seed = o.seed;
  s.segments = o.family == Segment_family::degenerate ? degenerate_segments(o, g) : random_segments(o, length, g);
  const std::vector<std::size_t> order = scene::shuffled_ids(o.n, g.next());
  for (std::size_t k = 0; k < moving; ++k) {
    Segment& seg = s.segments[order[k]];
    seg.motion = motion(kind, o.family == Segment_family::degenerate, seg, o.box, g);
  }
  s.derive();
  return s;
}

}  // namespace kvd::segments
