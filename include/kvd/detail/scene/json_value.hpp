// A JSON document tree that keeps what the scene format needs and
// nlohmann::json drops: the raw text of every number (numbers are exact) and
// the order of keys. Built by a SAX reader that rejects duplicate keys and
// nesting deeper than `max_depth` while parsing, so no input can exhaust the
// stack or the memory through nesting.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kvd::scene {

struct Json_value {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool boolean = false;
  std::string text;  // a number's raw text, or a string's value
  std::vector<Json_value> items;                          // array
  // A key and its value. Declared here, defined below: a std::pair of an
  // incomplete type may not be instantiated, a vector of one may (C++17).
  struct Member;
  std::vector<Member> members;  // object, in file order

  const Json_value* find(const std::string& key) const;
};

struct Json_value::Member {
  std::string first;  // the key
  Json_value second;  // its value
};

inline constexpr int max_depth = 64;
// Files above this size are refused before parsing.
inline constexpr std::size_t max_file_bytes = std::size_t(64) << 20;

// Parses `text`; on failure returns false and sets `error` (with the byte
// offset). Strict JSON: one value, nothing after it. One leading UTF-8
// byte-order mark is skipped (nlohmann's parser does; RFC 8259 section 8.1
// allows it), and the format page says so.
bool parse_json(const std::string& text, Json_value& out, std::string& error);

const char* kind_name(Json_value::Kind k);

// The value of the string member `key` of the top-level object, read without
// building the tree and stopping there; "" when the text is not an object
// with such a member (or is malformed before it).
std::string top_level_string(const std::string& text, const std::string& key);

}  // namespace kvd::scene
