// SPDX-License-Identifier: Apache-2.0
#include "password_hash.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/rand.h>

#include <cstdint>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace glider::shore::web {
namespace {

constexpr std::uint64_t kN = 1U << 17U;
constexpr std::uint64_t kR = 8;
constexpr std::uint64_t kP = 1;
constexpr std::size_t kHashBytes = 32;
constexpr std::uint64_t kMaxMemory = 256ULL << 20U;  // above 128 N r p: the largest cost accepted
std::mutex kdf_mutex;                                // one 128 MiB hash at a time

std::string to_hex(const std::vector<unsigned char>& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (unsigned char b : bytes) {
    out += digits[b >> 4U];
    out += digits[b & 15U];
  }
  return out;
}

bool from_hex(const std::string& text, std::vector<unsigned char>& out) {
  if (text.empty() || text.size() % 2 != 0) return false;
  out.clear();
  for (std::size_t i = 0; i < text.size(); i += 2) {
    unsigned value = 0;
    for (std::size_t k = 0; k < 2; ++k) {
      const char c = text[i + k];
      unsigned d = 0;
      if (c >= '0' && c <= '9') {
        d = static_cast<unsigned>(c - '0');
      } else if (c >= 'a' && c <= 'f') {
        d = static_cast<unsigned>(c - 'a' + 10);
      } else {
        return false;
      }
      value = value * 16 + d;
    }
    out.push_back(static_cast<unsigned char>(value));
  }
  return true;
}

std::vector<unsigned char> scrypt(const std::string& password, const std::vector<unsigned char>& salt, std::uint64_t n,
                                  std::uint64_t r, std::uint64_t p, std::size_t length) {
  std::vector<unsigned char> key(length);
  std::lock_guard<std::mutex> lock(kdf_mutex);
  if (EVP_PBE_scrypt(password.data(), password.size(), salt.data(), salt.size(), n, r, p, kMaxMemory, key.data(),
                     key.size()) != 1) {
    throw std::runtime_error("scrypt failed (OpenSSL EVP_PBE_scrypt)");
  }
  return key;
}

}  // namespace

std::string sha256_hex(const std::string& text) {
  std::vector<unsigned char> digest(EVP_MAX_MD_SIZE);
  unsigned int size = 0;
  if (EVP_Digest(text.data(), text.size(), digest.data(), &size, EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
  }
  digest.resize(size);
  return to_hex(digest);
}

std::string random_hex(std::size_t bytes) {
  std::vector<unsigned char> buffer(bytes);
  if (RAND_bytes(buffer.data(), static_cast<int>(buffer.size())) != 1) {
    throw std::runtime_error("no random bytes (OpenSSL RAND_bytes)");
  }
  return to_hex(buffer);
}

std::string hash_password(const std::string& password) {
  std::vector<unsigned char> salt;
  from_hex(random_hex(16), salt);
  const std::vector<unsigned char> key = scrypt(password, salt, kN, kR, kP, kHashBytes);
  std::ostringstream out;
  out << "scrypt$" << kN << "$" << kR << "$" << kP << "$" << to_hex(salt) << "$" << to_hex(key);
  return out.str();
}

bool verify_password(const std::string& password, const std::string& stored) {
  std::vector<std::string> parts;
  std::istringstream in(stored);
  for (std::string part; std::getline(in, part, '$');) parts.push_back(part);
  if (parts.size() != 6 || parts[0] != "scrypt") return false;
  std::uint64_t n = 0, r = 0, p = 0;
  try {
    n = std::stoull(parts[1]);
    r = std::stoull(parts[2]);
    p = std::stoull(parts[3]);
  } catch (const std::exception&) {
    return false;
  }
  // Only costs this program could have written (a power of two up to 2^20, r and p small).
  if (n < 2 || n > (1U << 20U) || (n & (n - 1)) != 0 || r < 1 || r > 32 || p < 1 || p > 4) return false;
  std::vector<unsigned char> salt, expected;
  if (!from_hex(parts[4], salt) || !from_hex(parts[5], expected) || expected.size() > 64) return false;
  const std::vector<unsigned char> key = scrypt(password, salt, n, r, p, expected.size());
  return CRYPTO_memcmp(key.data(), expected.data(), key.size()) == 0;
}

}  // namespace glider::shore::web
