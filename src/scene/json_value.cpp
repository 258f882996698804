#include "kvd/scene/json_value.hpp"

#include <nlohmann/json.hpp>

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
    Json_value x;
    x.kind = Json_value::Kind::string;
    x.text = std::move(v);
    return put(std::move(x));
  }
  bool binary(binary_t&) override { return fail("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(Json_value::Kind::object); }
  bool key(string_t& k) override {
    Json_value& obj = *stack_.back();
    if (obj.find(k)) return fail("duplicate key \"" + k + "\"");
    obj.members.emplace_back(std::move(k), Json_value{});
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json_value::Kind::array); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override {
    if (error.empty()) error = "malformed JSON at byte " + std::to_string(position) + ": " + ex.what();
    return false;
  }

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
    if (static_cast<int>(stack_.size()) >= max_depth)
      return fail("nesting deeper than " + std::to_string(max_depth) + " levels");
    Json_value* s = slot();
    s->kind = k;
    stack_.push_back(s);
    return true;
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

}  // namespace

bool parse_json(const std::string& text, Json_value& out, std::string& error) {
  out = Json_value{};
  Builder b(out);
  const bool ok = json::sax_parse(text, &b, json::input_format_t::json, true);
  if (!ok) error = b.error.empty() ? "malformed JSON" : b.error;
  return ok;
}

}  // namespace kvd::scene
