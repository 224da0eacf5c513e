// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_lz4_sink.hpp"

#include <lz4.h>

#include <cstring>

namespace glider::fw {

static_assert(LZ4_COMPRESSBOUND(SlocumLz4Sink::kBlockBytes) + 2 <=
                  2 + SlocumLz4Sink::kBlockBytes + SlocumLz4Sink::kBlockBytes / 255 + 16,
              "the block buffer holds LZ4's worst case");

// "x.dbd" -> "x.dcd", "x.sbd" -> "x.scd", "x.cac" -> "x.ccc".
bool SlocumLz4Sink::open(int slot, const char* name) {
  const std::size_t length = std::strlen(name);
  if (length + 1 > name_.size() || length < 4 || name[length - 4] != '.') return false;
  std::memcpy(name_.data(), name, length + 1);
  char* extension = name_.data() + length - 3;
  const bool cache = std::strcmp(extension, "cac") == 0;
  const bool data = extension[1] == 'b' && extension[2] == 'd';
  if (!cache && !data) return false;
  extension[1] = 'c';  // the middle letter in both
  return inner_.open(slot, name_.data());
}

bool SlocumLz4Sink::write(int slot, const char* data, std::size_t size) {
  for (std::size_t at = 0; at < size; at += kBlockBytes) {
    const std::size_t n = size - at < kBlockBytes ? size - at : kBlockBytes;
    const int packed =
        LZ4_compress_default(data + at, block_.data() + 2, static_cast<int>(n), static_cast<int>(block_.size() - 2));
    if (packed <= 0 || packed > 0xFFFF) return false;
    block_[0] = static_cast<char>((packed >> 8) & 0xFF);
    block_[1] = static_cast<char>(packed & 0xFF);
    if (!inner_.write(slot, block_.data(), static_cast<std::size_t>(packed) + 2)) return false;
  }
  return true;
}

}  // namespace glider::fw
