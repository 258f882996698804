#include "kvd/symbolic/symbolic.hpp"

namespace kvd::symbolic {

std::string to_string(const Symbolic_plane& p) {
  const char* k = p.kind == Symbolic_plane::Kind::P ? "P" : p.kind == Symbolic_plane::Kind::E ? "E" : "T";
  return std::string(k) + "(" + std::to_string(p.id) + ")";
}

std::string to_string(const Symbolic_edge& e) {
  switch (e.kind) {
    case Symbolic_edge::Kind::edge: return "SE(e" + std::to_string(e.a) + ")";
    case Symbolic_edge::Kind::pt: return "SE(P" + std::to_string(e.a) + ",T" + std::to_string(e.b) + ")";
    case Symbolic_edge::Kind::et: return "SE(E" + std::to_string(e.a) + ",T" + std::to_string(e.b) + ")";
  }
  return "SE(?)";
}

std::string to_string(const Symbolic_vertex& v) {
  const auto& i = v.ids;
  auto s = [](std::size_t x) { return std::to_string(x); };
  switch (v.kind) {
    case Symbolic_vertex::Kind::endpoint: return "SV(v" + s(i[0]) + ")";
    case Symbolic_vertex::Kind::intersection: return "SV(e" + s(i[0]) + ",E" + s(i[1]) + ")";
    case Symbolic_vertex::Kind::thread: return "SV(e" + s(i[0]) + ",P" + s(i[1]) + ")";
    case Symbolic_vertex::Kind::internal_intersection: return "SV(E" + s(i[0]) + ",E" + s(i[1]) + ",T" + s(i[2]) + ")";
    case Symbolic_vertex::Kind::internal_thread: return "SV(P" + s(i[0]) + ",E" + s(i[1]) + ",T" + s(i[2]) + ")";
    case Symbolic_vertex::Kind::axis: return "SV(L,T" + s(i[0]) + ")";
    case Symbolic_vertex::Kind::plumb: return "SV(v" + s(i[0]) + ",T" + s(i[1]) + ")";
  }
  return "SV(?)";
}

}  // namespace kvd::symbolic
