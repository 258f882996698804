#include "json_out.hpp"

namespace kvd::cli {

namespace {

void write(const Json& v, std::string& out) {
  if (v.is_object() || v.is_array()) {
    out += v.is_object() ? '{' : '[';
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (it != v.begin()) out += ", ";
      if (v.is_object()) out += Json(it.key()).dump() + ": ";
      write(*it, out);
    }
    out += v.is_object() ? '}' : ']';
  } else if (v.is_binary()) {
    const auto& text = v.get_binary();
    out.append(text.begin(), text.end());
  } else {
    out += v.dump();
  }
}

}  // namespace

std::string json_line(const Json& v) {
  std::string out;
  write(v, out);
  return out;
}

std::string json_lines(const Json& v) {
  std::string out = "{";
  for (auto it = v.begin(); it != v.end(); ++it) {
    out += (it == v.begin() ? "\n" : ",\n") + Json(it.key()).dump() + ": ";
    if (!it->is_array() || it->empty()) {
      write(*it, out);
      continue;
    }
    for (auto item = it->begin(); item != it->end(); ++item) {
      out += item == it->begin() ? "[\n " : ",\n ";
      write(*item, out);
    }
    out += "\n]";
  }
  return out + "\n}";
}

// Held as a binary value, which nothing else in kvd's JSON is.
Json verbatim(const std::string& json_text) {
  return Json::binary(Json::binary_t::container_type(json_text.begin(), json_text.end()));
}

Json decimal(const std::string& text) { return verbatim(text); }

Json recovery_json(const kinetic::Recovery& r) {
  return {{"failed_builds", r.failed_builds}, {"refires", r.refires},
          {"stale_trees", r.stale_trees},     {"rebuilds", r.rebuilds},
          {"zones_skipped", r.zones_skipped}, {"unrepaired", r.unrepaired}};
}

Json type_counts_json(const kinetic::Type_counts& counts) {
  Json out = Json::object();
  for (std::size_t i = 0; i < counts.size(); ++i)
    out[kinetic::to_string(static_cast<kinetic::Certificate_type>(i))] = counts[i];
  return out;
}

}  // namespace kvd::cli
