// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ASCII part of a DINKUM binary file: `key: value` tag lines, then (when
// not factored out into a cache file) the sensor list lines
// `s: T|F <sensor index> <index in this file or -1> <bytes> <name> <unit>`.
#include <cstddef>
#include <string>
#include <string_view>

#include "glider/slocum/binary_file.hpp"

namespace glider::slocum::detail {

// Parses the tag lines from the start of `bytes`; `pos` ends after them.
Header parse_header(std::string_view bytes, std::size_t& pos, const std::string& source);

// Parses header.total_num_sensors list lines from `text` at `pos` (which ends
// after them); keeps the sensors stored in the file, in line order, and
// checks their number against sensors_per_cycle. `offset_base` is added to
// offsets in errors (0 for a cache file, which is its own source).
SensorList parse_sensor_list(std::string_view text, std::size_t& pos, const Header& header, const std::string& source);

}  // namespace glider::slocum::detail
