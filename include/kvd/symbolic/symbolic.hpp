// Symbolic planes, edges and vertices (thesis 5.1): cuts and fragment
// corners named by the scene features that define them, never by
// coordinates. Ids are the scene's global vertex, edge and triangle ids.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace kvd::symbolic {

// SP(V): the P-plane through vertex V containing both decomposition
// directions; SP(E): the E-plane through edge E containing z; SP(T): the
// plane of triangle T.
struct Symbolic_plane {
  enum class Kind { P, E, T };
  Kind kind;
  std::size_t id;
  auto operator<=>(const Symbolic_plane&) const = default;
};

// SE(e): a scene edge; SE(V,T): P-plane of V meets the plane of T;
// SE(E,T): E-plane of E meets the plane of T.
struct Symbolic_edge {
  enum class Kind { edge, pt, et };
  Kind kind;
  std::size_t a, b;  // (e, -), (V, T) or (E, T)
  auto operator<=>(const Symbolic_edge&) const = default;
};

// The five vertices of thesis 5.1.3, plus the one a Euclidean decomposition
// point needs (DESIGN.md section 4): with z Euclidean every P-plane contains
// the line L = x ∨ z, and L meets a triangle's plane in a vertex lying on all
// P-planes at once. And one name for the point where the line w ∨ z through
// a scene vertex w meets a triangle's plane: P(w) and the E-plane of every
// edge at w all contain that line, so an internal thread (w, E, T) with w on
// E and an internal intersection (E1, E2, T) of two edges at w are that same
// point; `canonical` (incidence.hpp) renames them to plumb(w, T).
struct Symbolic_vertex {
  enum class Kind {
    endpoint,               // (v)
    intersection,           // (e, E): scene edge e meets the E-plane of edge E
    thread,                 // (e, V): scene edge e meets the P-plane of vertex V
    internal_intersection,  // (E1, E2, T), E1 < E2: two E-planes meet the plane of T
    internal_thread,        // (V, E, T): a P-plane and an E-plane meet the plane of T
    axis,                   // (T): L = x ∨ z meets the plane of T
    plumb                   // (w, T): the line w ∨ z through scene vertex w meets the plane of T
  };
  Kind kind;
  std::array<std::size_t, 3> ids{};
  auto operator<=>(const Symbolic_vertex&) const = default;

  static Symbolic_vertex endpoint(std::size_t v) { return {Kind::endpoint, {v, 0, 0}}; }
  static Symbolic_vertex intersection(std::size_t e, std::size_t cut_edge) { return {Kind::intersection, {e, cut_edge, 0}}; }
  static Symbolic_vertex thread(std::size_t e, std::size_t cut_vertex) { return {Kind::thread, {e, cut_vertex, 0}}; }
  static Symbolic_vertex internal_intersection(std::size_t e1, std::size_t e2, std::size_t t) {
    return {Kind::internal_intersection, {std::min(e1, e2), std::max(e1, e2), t}};
  }
  static Symbolic_vertex internal_thread(std::size_t v, std::size_t e, std::size_t t) {
    return {Kind::internal_thread, {v, e, t}};
  }
  static Symbolic_vertex axis(std::size_t t) { return {Kind::axis, {t, 0, 0}}; }
  static Symbolic_vertex plumb(std::size_t w, std::size_t t) { return {Kind::plumb, {w, t, 0}}; }
};

// An edge fragment (SV1, SV2, SE), and a triangle fragment: corners and the
// edges leaving them, in a fixed cyclic orientation.
struct Edge_fragment {
  Symbolic_vertex a, b;
  Symbolic_edge edge;
  auto operator<=>(const Edge_fragment&) const = default;
};
struct Triangle_fragment {
  std::vector<Symbolic_vertex> corners;
  std::vector<Symbolic_edge> sides;  // sides[i] runs from corners[i] to corners[i+1]
  auto operator<=>(const Triangle_fragment&) const = default;
};

// The scene features a symbolic vertex is built from, by its kind: calls
// vertex(i), edge(i) or triangle(i) for each of its ids in order.
template <class OnVertex, class OnEdge, class OnTriangle>
void for_each_feature(const Symbolic_vertex& v, OnVertex&& vertex, OnEdge&& edge, OnTriangle&& triangle) {
  using K = Symbolic_vertex::Kind;
  const auto& [a, b, c] = v.ids;
  switch (v.kind) {
    case K::endpoint: vertex(a); break;
    case K::intersection: edge(a), edge(b); break;
    case K::thread: edge(a), vertex(b); break;
    case K::internal_intersection: edge(a), edge(b), triangle(c); break;
    case K::internal_thread: vertex(a), edge(b), triangle(c); break;
    case K::axis: triangle(a); break;
    case K::plumb: vertex(a), triangle(b); break;
  }
}

// Hashes, for the caches and indexes that look these up by name.
struct Symbolic_hash {
  static std::size_t mix(std::size_t h, std::size_t v) { return h * 0x9e3779b97f4a7c15ull + v; }
  std::size_t operator()(std::size_t id) const { return id; }
  std::size_t operator()(const Symbolic_plane& p) const { return mix(static_cast<std::size_t>(p.kind), p.id); }
  std::size_t operator()(const Symbolic_edge& e) const { return mix(mix(static_cast<std::size_t>(e.kind), e.a), e.b); }
  std::size_t operator()(const Symbolic_vertex& v) const {
    std::size_t h = static_cast<std::size_t>(v.kind);
    for (std::size_t id : v.ids) h = mix(h, id);
    return h;
  }
  std::size_t operator()(const Edge_fragment& f) const { return mix(mix((*this)(f.a), (*this)(f.b)), (*this)(f.edge)); }
  std::size_t operator()(const Triangle_fragment& f) const { return mix((*this)(f.corners), (*this)(f.sides)); }
  template <class T>
  std::size_t operator()(const std::vector<T>& v) const {
    std::size_t h = v.size();
    for (const T& x : v) h = mix(h, (*this)(x));
    return h;
  }
  template <class... T>
  std::size_t operator()(const std::variant<T...>& v) const {
    return mix(v.index(), std::visit([this](const auto& x) { return (*this)(x); }, v));
  }
  template <class A, class B>
  std::size_t operator()(const std::pair<A, B>& ab) const {
    return mix((*this)(ab.first), (*this)(ab.second));
  }
};

// Readable names for traces and test messages: "P(3)", "SV-thread(e4,P2)".
std::string to_string(const Symbolic_plane& p);
std::string to_string(const Symbolic_edge& e);
std::string to_string(const Symbolic_vertex& v);

}  // namespace kvd::symbolic
