// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sensor-list cache files: <crc>.cac (text, the file's list lines) or
// <crc>.ccc (the same, LZ4 block stream), in either case.
#include <memory>
#include <string>
#include <string_view>

#include "glider/slocum/binary_file.hpp"

namespace glider::slocum::detail {

// The list of a factored file, from the memo or the first cache file found in
// the search directories; throws SlocumError naming the CRC and every
// directory searched when there is none.
std::shared_ptr<const SensorList> load_cached_list(const Header& header, const std::string& source,
                                                   const ReadOptions& options);

// Writes a file's own list lines as <crc>.cac into options.cache_write_dir
// when it is set and no cache file for the CRC is there yet.
void store_list(const Header& header, std::string_view list_lines, const ReadOptions& options);

}  // namespace glider::slocum::detail
