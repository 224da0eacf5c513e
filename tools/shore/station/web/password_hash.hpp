// SPDX-License-Identifier: Apache-2.0
#pragma once
// Console passwords, stored only as a scrypt hash (OpenSSL's EVP_PBE_scrypt,
// RFC 7914) with a random salt: "scrypt$N$r$p$SALT_HEX$HASH_HEX". The cost is
// OWASP's scrypt minimum (N = 2^17, r = 8, p = 1: 128 MiB, ~0.3 s here), so a
// stolen users file costs an attacker that much per guess. Hashes are computed
// one at a time (a login storm cannot take 128 MiB per request).
#include <string>

namespace glider::shore::web {

std::string hash_password(const std::string& password);
// Constant-time comparison; false for a malformed stored hash.
bool verify_password(const std::string& password, const std::string& stored);

// SHA-256 of `text` as 64 lowercase hex digits (OpenSSL).
std::string sha256_hex(const std::string& text);

// n random bytes as 2n lowercase hex digits (OpenSSL's RAND_bytes; throws if it fails).
std::string random_hex(std::size_t bytes);

}  // namespace glider::shore::web
