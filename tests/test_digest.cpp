// The SHA-256 behind the structure hash: the portable implementation on the
// examples of FIPS 180-4 and, where OpenSSL is in the build, equal to it on
// every length around the block boundaries.
#include <catch2/catch.hpp>

#include "kvd/detail/tree/digest.hpp"

using kvd::tree::sha256_hex;
using kvd::tree::sha256_hex_portable;

TEST_CASE("sha256: the standard's examples", "[digest]") {
  CHECK(sha256_hex_portable("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex_portable("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex_portable("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex_portable(std::string(1000000, 'a')) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("sha256: the portable implementation equals the one in use on every tail length", "[digest]") {
  std::string s;
  for (int n = 0; n < 300; ++n) {
    INFO(n);
    CHECK(sha256_hex_portable(s) == sha256_hex(s));
    s += static_cast<char>((n * 131 + 7) % 256);
  }
}
