// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "glider/firmware/comms/zmodem_protocol.hpp"

namespace glider::fw::comms::zmodem {

// A ZFILE subpacket: "name\0length mtime mode serial files-left bytes-left\0",
// length in decimal, mtime and mode in octal (the specification's layout).
struct FileInfo {
  std::array<char, kMaxName + 1> name{};
  std::size_t name_length = 0;
  std::int64_t length = -1;  // -1: not given
  std::int64_t mtime = 0;    // seconds since 1970, 0: not given
  std::string_view name_view() const { return {name.data(), name_length}; }
};

// False if the subpacket is not a file header or the name is not a plain,
// safe file name (letters, digits, '.', '_', '-'; no path, no leading dot).
bool parse_file_info(std::span<const std::uint8_t> data, FileInfo& info);
bool is_safe_name(std::string_view name);
// Writes the ZFILE subpacket for `info` into out; returns its length (0 if
// it does not fit).
std::size_t format_file_info(const FileInfo& info, int files_left, std::int64_t bytes_left,
                             std::span<std::uint8_t> out);

}  // namespace glider::fw::comms::zmodem
