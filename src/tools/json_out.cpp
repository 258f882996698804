#include "json_out.hpp"
#include "report.hpp"

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

Json filter_json(const Exact_kernel& k) {
  const Filter_statistics& s = k.statistics();
  const Stage_counts& c = s.classify;
  const long decided = c.filter + c.exact + c.after + c.perturbation;
  const auto pair = [](const Stage_counts& n) { return Json{{"filter", n.filter}, {"exact", n.exact}}; };
  const double share = decided ? static_cast<double>(c.filter) / static_cast<double>(decided) : 0;
  return {{"on", k.filtered()},
          {"classify",
           {{"filter", c.filter}, {"exact", c.exact}, {"after", c.after}, {"perturbation", c.perturbation},
            {"filter_share", decimal(fixed(share, 4))}}},
          {"sign_at", pair(s.sign_at)},
          {"compare", pair(s.compare)},
          {"walk", pair(s.walk)}};
}

}  // namespace kvd::cli
