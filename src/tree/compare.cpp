#include "kvd/tree/compare.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include "kvd/detail/tree/digest.hpp"
#include "kvd/detail/tree/subtree_hashes.hpp"

namespace kvd::tree {

namespace {

// The fragment's vertices in canonical order.
std::vector<Symbolic_vertex> canonical_vertices(const Fragment& f) {
  const Fragment c = canonical(f);
  if (const auto* v = std::get_if<Symbolic_vertex>(&c)) return {*v};
  if (const auto* e = std::get_if<Edge_fragment>(&c)) return {e->a, e->b};
  return std::get<Triangle_fragment>(c).corners;
}

}  // namespace

Node_content content(const Node& n) { return {n.cut, canonical_vertices(n.fragment)}; }

std::string canonical_text(const Node& n) {
  const char* kind = n.cut.kind == Symbolic_plane::Kind::P ? "P" : n.cut.kind == Symbolic_plane::Kind::E ? "E" : "T";
  std::string r = kind + std::to_string(n.cut.id) + ":";
  bool first = true;
  for (const auto& v : canonical_vertices(n.fragment)) {
    r += (first ? "" : ",") + symbolic::to_string(v);
    first = false;
  }
  return r;
}

Fragment canonical(Fragment f) {
  if (auto* e = std::get_if<Edge_fragment>(&f)) {
    if (e->b < e->a) std::swap(e->a, e->b);
  } else if (auto* t = std::get_if<Triangle_fragment>(&f)) {
    const auto first = std::min_element(t->corners.begin(), t->corners.end()) - t->corners.begin();
    std::rotate(t->corners.begin(), t->corners.begin() + first, t->corners.end());
    std::rotate(t->sides.begin(), t->sides.begin() + first, t->sides.end());
  }
  return f;
}

std::string canonical_serialisation(const Kvd_tree& t) {
  // Iterative pre-order: a stack of pending nodes and literal brackets.
  std::string out;
  std::vector<std::variant<int, const char*>> stack;
  if (t.root >= 0) stack.emplace_back(t.root);
  while (!stack.empty()) {
    const auto item = stack.back();
    stack.pop_back();
    if (const auto* lit = std::get_if<const char*>(&item)) {
      out += *lit;
      continue;
    }
    const Node& n = t.nodes[static_cast<std::size_t>(std::get<int>(item))];
    out += canonical_text(n);
    // Pushed in reverse: "[" left "][" right "]".
    stack.emplace_back("]");
    if (n.right >= 0) stack.emplace_back(n.right);
    stack.emplace_back("][");
    if (n.left >= 0) stack.emplace_back(n.left);
    stack.emplace_back("[");
  }
  return out;
}

std::string node_hash(const Node& n, const std::string& left, const std::string& right) {
  return sha256_hex(canonical_text(n) + "[" + left + "][" + right + "]");
}

std::string structure_hash(const Kvd_tree& t) { return Subtree_hashes(t).root(); }

std::optional<std::string> first_difference(const Kvd_tree& a, const Kvd_tree& b) {
  std::vector<std::tuple<int, int, std::string>> stack{{a.root, b.root, "root"}};
  while (!stack.empty()) {
    const auto [i, j, path] = stack.back();
    stack.pop_back();
    if (i < 0 && j < 0) continue;
    if (i < 0 || j < 0)
      return "at " + path + ": a subtree is present only in the " + (i < 0 ? "second" : "first") + " tree (" +
             canonical_text((i < 0 ? b : a).nodes[static_cast<std::size_t>(i < 0 ? j : i)]) + ")";
    const Node& m = a.nodes[static_cast<std::size_t>(i)];
    const Node& n = b.nodes[static_cast<std::size_t>(j)];
    if (m.cut != n.cut)
      return "at " + path + ": the cuts differ: " + symbolic::to_string(m.cut) + " against " + symbolic::to_string(n.cut);
    if (canonical_vertices(m.fragment) != canonical_vertices(n.fragment))
      return "at " + path + ": the fragments of " + symbolic::to_string(m.cut) + " differ: " + to_string(m.fragment) +
             " against " + to_string(n.fragment);
    stack.emplace_back(m.right, n.right, path + "/+");
    stack.emplace_back(m.left, n.left, path + "/-");
  }
  return std::nullopt;
}

}  // namespace kvd::tree
