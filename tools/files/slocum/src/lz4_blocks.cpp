// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/lz4_blocks.hpp"

#include <lz4.h>

#include <stdexcept>

namespace glider::slocum {
namespace {

// The glider writes 32 KiB blocks; a little more room costs nothing and
// accepts writers with other block sizes up to what 16 bits can frame.
constexpr std::size_t kMaxBlockOutput = 64 * 1024;

}  // namespace

Decompressed decompress_blocks(std::string_view compressed, const std::string& source) {
  Decompressed out;
  out.bytes.reserve(compressed.size() * 4);
  std::size_t pos = 0;
  while (pos < compressed.size()) {
    const std::size_t block_start = pos;
    if (compressed.size() - pos < 2) {
      out.damage = Warning{source, block_start, "truncated LZ4 block header (1 byte left)"};
      return out;
    }
    const auto high = static_cast<unsigned char>(compressed[pos]);
    const auto low = static_cast<unsigned char>(compressed[pos + 1]);
    const std::size_t size = (static_cast<std::size_t>(high) << 8) | low;
    pos += 2;
    if (size == 0 || size > compressed.size() - pos) {
      out.damage = Warning{source, block_start,
                           "LZ4 block of " + std::to_string(size) + " bytes, but " +
                               std::to_string(compressed.size() - pos) + " bytes left in the file"};
      return out;
    }
    const std::size_t old_size = out.bytes.size();
    out.bytes.resize(old_size + kMaxBlockOutput);
    const int produced = LZ4_decompress_safe(compressed.data() + pos, out.bytes.data() + old_size,
                                             static_cast<int>(size), static_cast<int>(kMaxBlockOutput));
    if (produced < 0) {
      out.bytes.resize(old_size);
      out.damage = Warning{source, block_start, "LZ4 block does not decompress (corrupt data)"};
      return out;
    }
    out.bytes.resize(old_size + static_cast<std::size_t>(produced));
    pos += size;
  }
  return out;
}

std::string compress_blocks(std::string_view raw, std::size_t block_size) {
  if (block_size == 0 || block_size > kMaxBlockOutput) throw std::invalid_argument("LZ4 block size out of range");
  std::string out;
  std::string block(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(block_size))), '\0');
  for (std::size_t pos = 0; pos < raw.size(); pos += block_size) {
    const std::size_t n = std::min(block_size, raw.size() - pos);
    const int size =
        LZ4_compress_default(raw.data() + pos, block.data(), static_cast<int>(n), static_cast<int>(block.size()));
    if (size <= 0 || size > 0xFFFF) throw std::runtime_error("LZ4 block does not fit a 16-bit size");
    out.push_back(static_cast<char>((size >> 8) & 0xFF));
    out.push_back(static_cast<char>(size & 0xFF));
    out.append(block.data(), static_cast<std::size_t>(size));
  }
  return out;
}

}  // namespace glider::slocum
