#include "kvd/detail/scene/json_value.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace kvd::scene {

const Json_value* Json_value::find(const std::string& key) const {
  for (const auto& [k, v] : members)
    if (k == key) return &v;
  return nullptr;
}

const char* kind_name(Json_value::Kind k) {
  switch (k) {
    case Json_value::Kind::null: return "null";
    case Json_value::Kind::boolean: return "a boolean";
    case Json_value::Kind::number: return "a number";
    case Json_value::Kind::string: return "a string";
    case Json_value::Kind::array: return "an array";
    case Json_value::Kind::object: return "an object";
  }
  return "?";
}

namespace {

using nlohmann::json;

// nlohmann converts JSON numbers to double and rejects those that overflow
// (1e400, or a 400-digit integer), but the scene format reads every number
// exactly from its text. So, before parsing, each number token that is not a
// small integer is rewritten as the string "\u0000TOKEN": the builder turns
// such strings back into numbers with their original text. (A string in the
// file that starts with U+0000 is thus read as a number, and then rejected
// wherever a string is expected.)
constexpr char number_mark = '\0';

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The length of the JSON number token at text[i], 0 if there is none that
// ends at a delimiter.
std::size_t number_token(const std::string& t, std::size_t i) {
  std::size_t j = i;
  if (j < t.size() && t[j] == '-') ++j;
  if (j >= t.size() || !is_digit(t[j])) return 0;
  if (t[j] == '0') ++j;
  else while (j < t.size() && is_digit(t[j])) ++j;
  if (j < t.size() && t[j] == '.') {
    if (++j >= t.size() || !is_digit(t[j])) return 0;
    while (j < t.size() && is_digit(t[j])) ++j;
  }
  if (j < t.size() && (t[j] == 'e' || t[j] == 'E')) {
    ++j;
    if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
    if (j >= t.size() || !is_digit(t[j])) return 0;
    while (j < t.size() && is_digit(t[j])) ++j;
  }
  if (j < t.size() && std::string(" \t\r\n,]}").find(t[j]) == std::string::npos) return 0;
  return j - i;
}

// Offsets in the rewritten text map back to the file through `shifts`:
// (offset in the rewritten text, bytes inserted up to there).
std::string protect_numbers(const std::string& t, std::vector<std::pair<std::size_t, std::size_t>>& shifts) {
  std::string out;
  out.reserve(t.size());
  bool in_string = false;
  std::size_t inserted = 0;
  for (std::size_t i = 0; i < t.size();) {
    const char c = t[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < t.size()) out += t[++i];
      else if (c == '"') in_string = false;
      ++i;
      continue;
    }
    if (c == '"') in_string = true;
    const bool starts_token = (c == '-' || is_digit(c)) && (i == 0 || !is_digit(t[i - 1]));
    const std::size_t n = starts_token ? number_token(t, i) : 0;
    const bool small_integer = n > 0 && n <= 18 && t.find_first_of(".eE", i) >= i + n;
    if (n > 0 && !small_integer) {
      out += "\"\\u0000";
      out.append(t, i, n);
      out += '"';
      inserted += 8;
      shifts.emplace_back(out.size(), inserted);
      i += n;
      continue;
    }
    if (n > 0) {
      out.append(t, i, n);
      i += n;
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

std::size_t original_offset(std::size_t pos, const std::vector<std::pair<std::size_t, std::size_t>>& shifts) {
  std::size_t inserted = 0;
  for (const auto& [at, total] : shifts)
    if (at <= pos) inserted = total;
  return pos >= inserted ? pos - inserted : 0;
}

// Builds the tree on an explicit stack; every callback returning false stops
// the parser at once.
class Builder : public nlohmann::json_sax<json> {
public:
  explicit Builder(Json_value& root) : root_(root) {}
  std::string error;

  bool null() override { return put(Json_value{}); }
  bool boolean(bool v) override {
    Json_value x;
    x.kind = Json_value::Kind::boolean;
    x.boolean = v;
    return put(std::move(x));
  }
  bool number_integer(number_integer_t v) override { return number(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return number(std::to_string(v)); }
  bool number_float(number_float_t, const string_t& raw) override { return number(raw); }
  bool string(string_t& v) override {
    if (!v.empty() && v[0] == number_mark) return number(v.substr(1));
    Json_value x;
    x.kind = Json_value::Kind::string;
    x.text = std::move(v);
    return put(std::move(x));
  }
  bool binary(binary_t&) override { return fail("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(Json_value::Kind::object); }
  bool key(string_t& k) override {
    Json_value& obj = *stack_.back();
    if (obj.find(k)) return fail(place(stack_.size() - 1) + "/" + pointer_token(k) + ": duplicate key \"" + k + "\"");
    obj.members.push_back({std::move(k), Json_value{}});
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json_value::Kind::array); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override {
    if (error.empty()) {
      error_position = position;
      error = ex.what();
    }
    return false;
  }
  std::size_t error_position = 0;

private:
  bool fail(std::string why) {
    error = std::move(why);
    return false;
  }
  bool number(std::string raw) {
    Json_value x;
    x.kind = Json_value::Kind::number;
    x.text = std::move(raw);
    return put(std::move(x));
  }
  // The slot the next value goes to: the root, the last key's value, or a
  // new array element.
  Json_value* slot() {
    if (stack_.empty()) return &root_;
    Json_value& top = *stack_.back();
    if (top.kind == Json_value::Kind::array) return &top.items.emplace_back();
    return &top.members.back().second;
  }
  bool put(Json_value v) {
    *slot() = std::move(v);
    return true;
  }
  bool open(Json_value::Kind k) {
    Json_value* s = slot();
    if (static_cast<int>(stack_.size()) >= max_depth)
      return fail(place(stack_.size()) + ": nesting deeper than " + std::to_string(max_depth) + " levels");
    s->kind = k;
    stack_.push_back(s);
    return true;
  }
  // The JSON pointer (RFC 6901) of the value being read inside the first
  // `levels` open containers: each one's last element or last key.
  std::string place(std::size_t levels) const {
    std::string at;
    for (std::size_t i = 0; i < levels; ++i) {
      const Json_value* c = stack_[i];
      at += "/" + (c->kind == Json_value::Kind::array ? std::to_string(c->items.size() - 1)
                                                       : pointer_token(c->members.back().first));
    }
    return at;
  }
  static std::string pointer_token(const std::string& key) {
    std::string t;
    for (char ch : key) t += ch == '~' ? "~0" : ch == '/' ? "~1" : std::string(1, ch);
    return t;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  Json_value& root_;
  // Pointers stay valid: a container is only appended to while it is on top,
  // and its elements are not pointed to until it is.
  std::vector<Json_value*> stack_;
};

// Finds the string member `key` of the top-level object and stops there.
class Member_finder : public nlohmann::json_sax<json> {
public:
  explicit Member_finder(const std::string& key) : key_(key) {}
  std::string found;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t& v) override {
    if (depth_ == 1 && wanted_ && (v.empty() || v[0] != number_mark)) {
      found = v;
      return false;
    }
    return value();
  }
  bool binary(binary_t&) override { return false; }
  bool start_object(std::size_t) override { return open(); }
  bool key(string_t& k) override {
    wanted_ = depth_ == 1 && k == key_;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return depth_ > 0 && open(); }  // a top-level array has no members
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
  // A value other than the string sought: the member, if it was `key`, is not a string.
  bool value() { return !(depth_ == 1 && wanted_); }
  bool open() {
    if (!value()) return false;
    ++depth_;
    return true;
  }
  bool close() {
    --depth_;
    return depth_ > 0;  // past the top-level object: nothing more to find
  }

  const std::string& key_;
  std::size_t depth_ = 0;
  bool wanted_ = false;
};

}  // namespace

std::string top_level_string(const std::string& text, const std::string& key) {
  std::vector<std::pair<std::size_t, std::size_t>> shifts;
  Member_finder f(key);
  json::sax_parse(protect_numbers(text, shifts), &f, json::input_format_t::json, true);
  return f.found;
}

bool parse_json(const std::string& text, Json_value& out, std::string& error) {
  out = Json_value{};
  std::vector<std::pair<std::size_t, std::size_t>> shifts;
  const std::string protected_text = protect_numbers(text, shifts);
  Builder b(out);
  const bool ok = json::sax_parse(protected_text, &b, json::input_format_t::json, true);
  if (ok) return true;
  if (b.error.empty()) error = "malformed JSON";
  else if (b.error_position == 0 && b.error.rfind("[json.exception", 0) != 0) error = b.error;
  else {
    // nlohmann's message carries a line and column of the rewritten text:
    // keep only its description, and place it in the file as written.
    std::string detail = b.error;
    const std::size_t col = detail.find(", column ");
    if (col != std::string::npos && detail.find(": ", col) != std::string::npos) detail = detail.substr(detail.find(": ", col) + 2);
    const std::size_t at = std::min(original_offset(b.error_position, shifts), text.size());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    const std::size_t line_start = text.rfind('\n', at == 0 ? 0 : at - 1);
    const std::size_t column = line_start == std::string::npos || at == 0 ? at + 1 : at - line_start;  // 1-based
    error = "malformed JSON at byte " + std::to_string(at) + " (line " + std::to_string(line) + ", column " +
            std::to_string(column) + "): " + detail;
  }
  return false;
}

}  // namespace kvd::scene
