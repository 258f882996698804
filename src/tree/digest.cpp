#include "kvd/detail/tree/digest.hpp"

#include <array>
#include <cstdint>
#include <stdexcept>

#ifdef KVD_HAVE_OPENSSL
#include <openssl/evp.h>
#endif

namespace kvd::tree {

namespace {

// Lower-case hex; written out by hand, as every Merkle node of a batch is hashed.
std::string hex(const unsigned char* digest, std::size_t length) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out(2 * length, '0');
  for (std::size_t i = 0; i < length; ++i) {
    out[2 * i] = digits[digest[i] >> 4];
    out[2 * i + 1] = digits[digest[i] & 0xf];
  }
  return out;
}

constexpr std::uint32_t k[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

constexpr std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

// One 64-byte block into the state h (FIPS 180-4, section 6.2.2).
void compress(std::array<std::uint32_t, 8>& h, const unsigned char* block) {
  std::uint32_t w[64];
  for (int i = 0; i < 16; ++i)
    w[i] = std::uint32_t(block[4 * i]) << 24 | std::uint32_t(block[4 * i + 1]) << 16 |
           std::uint32_t(block[4 * i + 2]) << 8 | std::uint32_t(block[4 * i + 3]);
  for (int i = 16; i < 64; ++i) {
    const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
    const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
    w[i] = w[i - 16] + s0 + w[i - 7] + s1;
  }
  std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], hh = h[7];
  for (int i = 0; i < 64; ++i) {
    const std::uint32_t t1 = hh + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + k[i] + w[i];
    const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    hh = g;
    g = f;
    f = e;
    e = d + t1;
    d = c;
    c = b;
    b = a;
    a = t1 + t2;
  }
  const std::uint32_t add[8] = {a, b, c, d, e, f, g, hh};
  for (int i = 0; i < 8; ++i) h[static_cast<std::size_t>(i)] += add[i];
}

}  // namespace

std::string sha256_hex_portable(const std::string& bytes) {
  std::array<std::uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t i = 0;
  for (; i + 64 <= bytes.size(); i += 64) compress(h, data + i);
  // The tail, a 1 bit, zeros, and the length in bits (big-endian).
  unsigned char last[128] = {};
  const std::size_t rest = bytes.size() - i;
  for (std::size_t j = 0; j < rest; ++j) last[j] = data[i + j];
  last[rest] = 0x80;
  const std::size_t blocks = rest + 9 <= 64 ? 1 : 2;
  const std::uint64_t bits = std::uint64_t(bytes.size()) * 8;
  for (int j = 0; j < 8; ++j) last[blocks * 64 - 1 - static_cast<std::size_t>(j)] = static_cast<unsigned char>(bits >> (8 * j));
  for (std::size_t b = 0; b < blocks; ++b) compress(h, last + 64 * b);
  unsigned char digest[32];
  for (int j = 0; j < 8; ++j)
    for (int m = 0; m < 4; ++m) digest[4 * j + m] = static_cast<unsigned char>(h[static_cast<std::size_t>(j)] >> (24 - 8 * m));
  return hex(digest, sizeof digest);
}

std::string sha256_hex(const std::string& bytes) {
#ifdef KVD_HAVE_OPENSSL
  // One context and one fetched algorithm per thread: a batch hashes every
  // node on its changed paths, and EVP_Digest makes and fetches both each time.
  struct Context {
    EVP_MD_CTX* ctx = EVP_MD_CTX_new();
    EVP_MD* md = EVP_MD_fetch(nullptr, "SHA256", nullptr);
    ~Context() {
      EVP_MD_free(md);
      EVP_MD_CTX_free(ctx);
    }
  };
  thread_local const Context c;
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (!c.ctx || !c.md || EVP_DigestInit_ex(c.ctx, c.md, nullptr) != 1 ||
      EVP_DigestUpdate(c.ctx, bytes.data(), bytes.size()) != 1 || EVP_DigestFinal_ex(c.ctx, digest, &length) != 1)
    throw std::runtime_error("SHA-256 failed");
  return hex(digest, length);
#else
  return sha256_hex_portable(bytes);
#endif
}

}  // namespace kvd::tree
