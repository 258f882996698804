#include "json_writer.hpp"

#include "kvd/detail/scene/exact_number.hpp"

namespace kvd::scene {

namespace {

void print(const Json_out& v, int indent, std::string& out) {
  const std::string compact = v.dump();
  if (compact.size() + static_cast<std::size_t>(indent) <= 100 || !v.is_structured() || v.empty()) {
    out += compact;
    return;
  }
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  out += v.is_object() ? "{\n" : "[\n";
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += pad;
    if (v.is_object()) out += Json_out(it.key()).dump() + ": ";
    print(*it, indent + 2, out);
  }
  out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + (v.is_object() ? "}" : "]");
}

}  // namespace

Json_out number_json(const mpq_class& q) { return exact_text(q); }

Json_out poly_json(const Poly<mpq_class>& p) {
  if (p.degree() <= 0) return number_json(p[0]);
  Json_out a = Json_out::array();
  for (const auto& c : p.coefficients()) a.push_back(number_json(c));
  return a;
}

std::string pretty_json(const Json_out& doc) {
  std::string out;
  print(doc, 0, out);
  return out + "\n";
}

}  // namespace kvd::scene
