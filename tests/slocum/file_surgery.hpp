// SPDX-License-Identifier: Apache-2.0
#pragma once
// Making test files from the real ones: the byte layout of a decoded file
// (where each cycle starts), its little-endian twin, and small edits.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "glider/slocum/binary_file.hpp"

namespace glider::slocum::test {

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Offsets of the known-bytes cycle, each data cycle's 'd' and the end 'X',
// walked independently of the decoder from the decoded sensor sizes.
struct Layout {
  std::size_t known_bytes = 0;
  std::vector<std::size_t> cycles;
  std::size_t end = 0;
};

inline Layout walk(const std::string& bytes, const BinaryFile& file) {
  Layout layout;
  layout.known_bytes = file.binary_offset();
  const std::size_t state_bytes = file.header().state_bytes_per_cycle;
  std::size_t pos = layout.known_bytes + 16;
  while (bytes.at(pos) == 'd') {
    layout.cycles.push_back(pos);
    std::size_t values = 0;
    for (std::size_t i = 0; i < file.sensors().size(); ++i) {
      const auto state = (static_cast<unsigned char>(bytes[pos + 1 + i / 4]) >> (6 - 2 * (i % 4))) & 3U;
      if (state == 2) values += static_cast<std::size_t>(file.sensors()[i].bytes);
    }
    pos += 1 + state_bytes + values;
  }
  layout.end = pos;
  return layout;
}

// The same file as a little-endian glider writes it: the known bytes and
// every value byte-swapped, the ASCII header and state bytes unchanged.
inline std::string little_endian_twin(const std::string& bytes, const BinaryFile& file) {
  std::string twin = bytes;
  const Layout layout = walk(bytes, file);
  const auto swap = [&twin](std::size_t at, std::size_t n) {
    for (std::size_t i = 0; i < n / 2; ++i) std::swap(twin[at + i], twin[at + n - 1 - i]);
  };
  swap(layout.known_bytes + 2, 2);
  swap(layout.known_bytes + 4, 4);
  swap(layout.known_bytes + 8, 8);
  const std::size_t state_bytes = file.header().state_bytes_per_cycle;
  for (const std::size_t cycle : layout.cycles) {
    std::size_t value = cycle + 1 + state_bytes;
    for (std::size_t i = 0; i < file.sensors().size(); ++i) {
      const auto state = (static_cast<unsigned char>(bytes[cycle + 1 + i / 4]) >> (6 - 2 * (i % 4))) & 3U;
      if (state != 2) continue;
      const auto n = static_cast<std::size_t>(file.sensors()[i].bytes);
      swap(value, n);
      value += n;
    }
  }
  return twin;
}

}  // namespace glider::slocum::test
