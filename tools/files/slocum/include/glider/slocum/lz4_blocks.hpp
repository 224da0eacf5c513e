// SPDX-License-Identifier: Apache-2.0
#pragma once
// The compressed Slocum files (.dcd .ecd .scd .tcd .mcd .ncd, and .ccc sensor
// caches) are a sequence of [big-endian uint16 size][raw LZ4 block], each
// block at most 32 KiB decompressed. Blocks are (de)compressed with liblz4's
// block API.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "glider/slocum/binary_file.hpp"

namespace glider::slocum {

struct Decompressed {
  std::string bytes;
  // Set when a block was truncated or did not decompress: `bytes` holds the
  // blocks before it; the offset is the block's in the compressed file.
  std::optional<Warning> damage;
};

Decompressed decompress_blocks(std::string_view compressed, const std::string& source);
// The writer's side (used to make compressed test files from real ones).
std::string compress_blocks(std::string_view raw, std::size_t block_size = 32 * 1024);

}  // namespace glider::slocum
