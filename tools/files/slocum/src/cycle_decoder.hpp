// SPDX-License-Identifier: Apache-2.0
#pragma once
// The binary part of a DINKUM file: the known-bytes cycle, then data cycles
// ('d', 2-bit state per sensor, the new values), then the end marker 'X'.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glider/slocum/binary_file.hpp"

namespace glider::slocum::detail {

// 's' 'a', int16 0x1234, float 123.456, double 123456789.12345 in the
// writer's byte order: gives the order and proves IEEE-754 floats. `pos`
// ends after it. Throws SlocumError when they do not read back.
ByteOrder read_known_bytes(std::string_view bytes, std::size_t& pos, const std::string& source);

struct DecodedCycles {
  std::vector<double> cycle_time;
  std::vector<SensorSeries> series;
  bool complete = false;
  std::vector<Warning> warnings;
};

DecodedCycles decode_cycles(std::string_view bytes, std::size_t pos, const Header& header, const SensorList& sensors,
                            std::optional<std::size_t> time_index, ByteOrder order, bool skip_first_cycle,
                            const std::string& source);

}  // namespace glider::slocum::detail
