// SPDX-License-Identifier: Apache-2.0
#pragma once
// SHA-256 (OpenSSL) of decoded arrays as dbdreader's reference hashes them:
// time then values, each as little-endian float64.
#include <openssl/evp.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace glider::slocum::test {

inline std::string sha256_of_arrays(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<unsigned char> bytes;
  bytes.reserve((t.size() + v.size()) * 8);
  for (const auto* array : {&t, &v}) {
    for (const double x : *array) {
      auto bits = std::bit_cast<std::uint64_t>(x);
      for (int i = 0; i < 8; ++i, bits >>= 8) bytes.push_back(static_cast<unsigned char>(bits & 0xFF));
    }
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 15];
  }
  return hex;
}

}  // namespace glider::slocum::test
