// Reading the parts that the project's JSON formats share (kvd-scene/1 and
// kvd-segments/1): typed values, objects with known keys, exact numbers and
// polynomials in t, indices. Every rejection throws Scene_error with the
// message "SOURCE: /json/pointer: what was expected" ("/" for the document).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "kvd/detail/scene/json_value.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd::scene {

class Json_reader {
public:
  explicit Json_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& at, const std::string& what) const;
  void expect(const Json_value& v, Json_value::Kind k, const std::string& at) const;
  // An object with only the given keys, all of `required` among them.
  void expect_object(const Json_value& v, const std::string& at, std::initializer_list<const char*> allowed,
                     std::initializer_list<const char*> required) const;
  // An exact number (the format's grammar, kvd/detail/scene/exact_number.hpp).
  mpq_class number(const Json_value& v, const std::string& at) const;
  // A number, or an array of coefficients of degree at most max_motion_degree.
  Poly<mpq_class> poly(const Json_value& v, const std::string& at) const;
  // An array, of exactly `size` entries unless size is 0.
  const std::vector<Json_value>& array(const Json_value& v, const std::string& at, std::size_t size = 0) const;
  // An array of `size` polynomials (a homogeneous point such as a point4, or
  // a translation).
  std::vector<Poly<mpq_class>> polys(const Json_value& v, const std::string& at, std::size_t size) const;
  // A size x size matrix of polynomials, row by row (a homogeneous motion).
  std::vector<std::vector<Poly<mpq_class>>> matrix(const Json_value& v, const std::string& at, std::size_t size) const;
  std::uint64_t unsigned_integer(const Json_value& v, const std::string& at) const;
  // An index below n; `what` names it in messages ("a vertex").
  std::size_t index(const Json_value& v, const std::string& at, std::size_t n, const char* what) const;

private:
  std::string source_;
};

}  // namespace kvd::scene
