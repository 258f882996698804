#include "cli.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/detail/scene/span_check.hpp"

namespace kvd::cli {

const std::string& Args::value(const std::string& flag) {
  if (done()) throw Usage_error("kvd " + command_ + ": " + flag + " needs a value");
  return next();
}

std::uint64_t Args::unsigned_value(const std::string& flag) {
  const std::string& v = value(flag);
  if (v.empty() || v.size() > 20 || v.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error("kvd " + command_ + ": " + flag + " expects a non-negative integer, got '" + v + "'");
  try {
    return std::stoull(v);
  } catch (const std::out_of_range&) {
    throw Usage_error("kvd " + command_ + ": " + flag + " is above 2^64 - 1");
  }
}

void Args::unknown(const std::string& arg) const {
  throw Usage_error("kvd " + command_ + ": unknown argument '" + arg + "' (see kvd " + command_ + " --help)");
}

namespace {

// The eye of --view: the pictures are drawn in double, so each coordinate
// must be within double's range (1e400 drew NaN).
std::array<mpq_class, 3> view_option(const std::string& command, const std::string& text) {
  std::array<mpq_class, 3> p = point_option(command, "--view", text);
  for (const mpq_class& x : p)
    if (!std::isfinite(x.get_d()))
      throw Usage_error("kvd " + command + ": --view " + text + " lies beyond double's range, in which pictures are drawn");
  return p;
}

}  // namespace

bool Scene_args::take(Args& args, const std::string& a) {
  const std::string& command = args.command();
  if (a == "--json") json = true;
  else if (a == "--seed") load.seed = args.unsigned_value(a);
  else if (a == "--allow-intersecting") load.allow_intersecting = true;
  else if (a == "--time" && wants_time) time = exact_option(command, a, args.value(a));
  else if (a == "--view" && wants_view) view = view_option(command, args.value(a));
  else if ((a == "-" || (!a.empty() && a[0] != '-')) && !path) path = a;
  else return false;
  return true;
}

scene::Scene Scene_args::load_scene(const std::string& command) const {
  return read_scene(command, read_text(command));
}

std::string Scene_args::read_text(const std::string& command) const {
  if (!path) throw Usage_error("kvd " + command + ": missing the SCENE file (see kvd " + command + " --help)");
  return scene::read_input(*path);
}

scene::Scene Scene_args::read_scene(const std::string& command, const std::string& text) const {
  scene::Scene s = scene::read_scene(text, scene::input_name(*path), load);
  if (time) require_in_span(command, "--time", *time, s);
  return s;
}

segments::Segment_scene Scene_args::read_segments(const std::string& command, const std::string& text) const {
  segments::Segment_scene s =
      segments::read_segments(text, scene::input_name(*path), segments::Segment_load_options{load.seed});
  if (time) require_in_span(command, "--time", *time, s.start, s.end);
  return s;
}

void require_in_span(const std::string& command, const std::string& flag, const mpq_class& t, const mpq_class& start,
                     const std::optional<mpq_class>& end) {
  if (!scene::in_span(t, start, end))
    throw Usage_error("kvd " + command + ": " + flag + " " + t.get_str() + " " + scene::outside_span_text(start, end));
}

const std::array<mpq_class, 3>& Scene_args::required_view(const std::string& command) const {
  if (!view) throw Usage_error("kvd " + command + ": missing --view X,Y,Z");
  return *view;
}

namespace {
using V = kinetic::Validation;
constexpr std::pair<const char*, V> validations[] = {{"every", V::every}, {"end", V::end}, {"none", V::none}};
}  // namespace

kinetic::Validation validation_option(const std::string& command, const std::string& value) {
  return choice_option<V>(command, "--validate", value, {validations[0], validations[1], validations[2]});
}

kinetic::Collisions collisions_option(const std::string& command, const std::string& value) {
  return choice_option<kinetic::Collisions>(command, "--collisions", value,
                                            {{"reverse", kinetic::Collisions::reverse}, {"stop", kinetic::Collisions::stop}});
}

const char* validation_name(kinetic::Validation v) {
  for (const auto& [name, value] : validations)
    if (value == v) return name;
  return "?";
}

mpq_class exact_option(const std::string& command, const std::string& flag, const std::string& text) {
  std::string why;
  const auto q = scene::parse_exact_number(text, why);
  if (!q) throw Usage_error("kvd " + command + ": " + flag + ": " + why + ": '" + text + "'");
  return *q;
}

std::array<mpq_class, 3> point_option(const std::string& command, const std::string& flag, const std::string& text) {
  std::array<mpq_class, 3> p;
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      throw Usage_error("kvd " + command + ": " + flag + " expects X,Y,Z, got '" + text + "'");
    p[i] = exact_option(command, flag, text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    start = comma + 1;
  }
  return p;
}

std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty() && std::find(out.begin(), out.end(), item) == out.end()) out.push_back(item);
  return out;
}

unsigned mpfr_bits(const std::string& command, const std::string& bits) {
  const std::optional<unsigned> b = Mpfr_kernel::bits_named(bits);
  if (!b) throw Usage_error("kvd " + command + ": --kernel mpfr:BITS needs BITS between 2 and 65536");
  return *b;
}

std::function<void(std::size_t, std::size_t)> progress_every_few_seconds(std::string label, std::string of) {
  using clock = std::chrono::steady_clock;
  return [label = std::move(label), of = std::move(of), last = clock::now()](std::size_t a, std::size_t b) mutable {
    if (clock::now() - last < std::chrono::seconds(2)) return;
    last = clock::now();
    if (of.empty()) std::cerr << label << ": " << a << " batches, " << b << " failures\n";
    else std::cerr << label << ": " << a << " of " << b << " " << of << "\n";
  };
}

std::string seconds_since(std::chrono::steady_clock::time_point start) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return buf;
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

bool ends_with(const std::string& name, const std::string& tail) {
  return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace kvd::cli
