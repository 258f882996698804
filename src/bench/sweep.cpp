#include "sweep.hpp"

#include <algorithm>
#include <filesystem>

#include "cli.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/segments/segment_generators.hpp"

namespace kvd::bench {

std::vector<std::size_t> sizes_option(const std::string& suite, const std::string& text, const std::string& flag,
                                      const std::string& what) {
  std::vector<std::size_t> sizes;
  for (const std::string& item : cli::comma_list(text)) {
    if (item.size() > 6 || item.find_first_not_of("0123456789") != std::string::npos || std::stoul(item) == 0)
      throw cli::Usage_error("kvd bench " + suite + ": " + flag + " expects positive numbers of " + what +
                             " such as 25,50,100, got '" + text + "'");
    sizes.push_back(std::stoul(item));
  }
  if (sizes.empty()) throw cli::Usage_error("kvd bench " + suite + ": " + flag + " needs at least one size");
  std::sort(sizes.begin(), sizes.end());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  return sizes;
}

scene::Scene generated(const std::string& suite, const std::string& family, std::size_t size, const scene::Q& moving,
                       int degree) {
  scene::Uniform_params p;
  p.triangles = size;
  p.moving = moving;
  p.degree = degree;
  p.seed = 1;
  try {
    return family == "uniform-scale" ? scene::uniform_scale(p) : scene::uniform_density(p);
  } catch (const scene::Generator_error& e) {
    throw cli::Usage_error("kvd bench " + suite + ": generating " + family + " " + std::to_string(size) + ": " +
                           e.what());
  }
}

segments::Segment_scene generated_segments(const std::string& suite, segments::Segment_family family, std::size_t n,
                                           std::size_t m, segments::Crossings crossings) {
  segments::Segment_generator_options o;
  o.family = family;
  o.n = n;
  o.seed = 1;
  o.crossings = crossings;
  o.moving = m;
  try {
    return segments::generate_segments(o);
  } catch (const scene::Generator_error& e) {
    throw cli::Usage_error("kvd bench " + suite + ": generating " + std::to_string(n) + " segments: " + e.what());
  }
}

void check_out(const std::string& suite, const std::string& dir) {
  if (dir.find('\'') != std::string::npos) throw cli::Usage_error("kvd bench " + suite + ": --out must not contain a quote");
}

void make_out(const std::string& suite, const std::string& dir) {
  check_out(suite, dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw cli::Usage_error("kvd bench " + suite + ": cannot create " + dir + " (" + ec.message() + ")");
}

}  // namespace kvd::bench
