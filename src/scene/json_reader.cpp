#include "kvd/detail/scene/json_reader.hpp"

#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::scene {

using Kind = Json_value::Kind;

void Json_reader::fail(const std::string& at, const std::string& what) const {
  throw Scene_error(source_ + ": " + (at.empty() ? "/" : at) + ": " + what);
}

void Json_reader::expect(const Json_value& v, Kind k, const std::string& at) const {
  if (v.kind != k) fail(at, std::string("expected ") + kind_name(k) + ", found " + kind_name(v.kind));
}

void Json_reader::expect_object(const Json_value& v, const std::string& at, std::initializer_list<const char*> allowed,
                                std::initializer_list<const char*> required) const {
  expect(v, Kind::object, at);
  for (const auto& [key, value] : v.members) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      fail(at + "/" + key, "unknown key \"" + key + "\" (expected one of: " + list + ")");
    }
  }
  for (const char* r : required)
    if (!v.find(r)) fail(at, std::string("missing required key \"") + r + "\"");
}

mpq_class Json_reader::number(const Json_value& v, const std::string& at) const {
  if (v.kind != Kind::number && v.kind != Kind::string)
    fail(at, std::string("expected a number, found ") + kind_name(v.kind));
  std::string why;
  auto q = parse_exact_number(v.text, why);
  // A long text is quoted by its first characters only.
  if (!q) fail(at, why + ": \"" + (v.text.size() > 40 ? v.text.substr(0, 40) + "..." : v.text) + "\"");
  return *q;
}

Poly<mpq_class> Json_reader::poly(const Json_value& v, const std::string& at) const {
  if (v.kind != Kind::array) return Poly<mpq_class>(number(v, at));
  if (v.items.size() > static_cast<std::size_t>(max_motion_degree) + 1)
    fail(at, "a polynomial of " + std::to_string(v.items.size()) + " coefficients (the degree in t is at most " +
                 std::to_string(max_motion_degree) + ")");
  std::vector<mpq_class> c;
  for (std::size_t i = 0; i < v.items.size(); ++i) c.push_back(number(v.items[i], at + "/" + std::to_string(i)));
  return Poly<mpq_class>(std::move(c));
}

const std::vector<Json_value>& Json_reader::array(const Json_value& v, const std::string& at, std::size_t size) const {
  expect(v, Kind::array, at);
  if (size && v.items.size() != size)
    fail(at, "expected an array of " + std::to_string(size) + " entries, found " + std::to_string(v.items.size()));
  return v.items;
}

std::vector<Poly<mpq_class>> Json_reader::polys(const Json_value& v, const std::string& at, std::size_t size) const {
  const auto& items = array(v, at, size);
  std::vector<Poly<mpq_class>> p;
  for (std::size_t i = 0; i < size; ++i) p.push_back(poly(items[i], at + "/" + std::to_string(i)));
  return p;
}

std::vector<std::vector<Poly<mpq_class>>> Json_reader::matrix(const Json_value& v, const std::string& at,
                                                              std::size_t size) const {
  const auto& rows = array(v, at, size);
  std::vector<std::vector<Poly<mpq_class>>> m;
  for (std::size_t i = 0; i < size; ++i) m.push_back(polys(rows[i], at + "/" + std::to_string(i), size));
  return m;
}

std::uint64_t Json_reader::unsigned_integer(const Json_value& v, const std::string& at) const {
  if (v.kind != Kind::number || v.text.find_first_not_of("0123456789") != std::string::npos)
    fail(at, "expected a non-negative integer");
  const mpz_class z(v.text, 10);
  if (z > mpz_class("18446744073709551615")) fail(at, "integer above 2^64 - 1");
  return std::stoull(v.text);
}

std::size_t Json_reader::index(const Json_value& v, const std::string& at, std::size_t n, const char* what) const {
  if (v.kind != Kind::number || v.text.find_first_not_of("0123456789") != std::string::npos)
    fail(at, std::string("expected ") + what + " index (a non-negative integer)");
  if (v.text.size() > 18 || std::stoull(v.text) >= n)
    fail(at, std::string(what) + " index " + v.text + " out of range (" + std::to_string(n) + " available)");
  return static_cast<std::size_t>(std::stoull(v.text));
}

}  // namespace kvd::scene
