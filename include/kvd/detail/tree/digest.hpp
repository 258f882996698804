// SHA-256 of the canonical serialisation behind the structure hash
// (compare.hpp). OpenSSL's when the build found it; otherwise the portable
// implementation of FIPS 180-4 below, which is always compiled and tested
// against the standard's examples and against OpenSSL.
#pragma once

#include <string>

namespace kvd::tree {

// Lowercase hex SHA-256 of `bytes`.
std::string sha256_hex(const std::string& bytes);
// The portable implementation (no OpenSSL).
std::string sha256_hex_portable(const std::string& bytes);

}  // namespace kvd::tree
