#include "cli.hpp"

#include <nlohmann/json.hpp>

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

std::string json_string(const std::string& s) { return nlohmann::json(s).dump(); }

}  // namespace kvd::cli
