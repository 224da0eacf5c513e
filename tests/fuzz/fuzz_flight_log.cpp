// SPDX-License-Identifier: Apache-2.0
// The flight-log CSV reader on arbitrary text, with the default contract and
// with no required columns (every column kept). A bad log is a
// FlightLogError; a crash or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "glider/flightlog/flight_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fl = glider::flightlog;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fl::ReadOptions loose;
  loose.required.clear();
  for (const fl::ReadOptions& options : {fl::ReadOptions{}, loose}) {
    try {
      const fl::FlightLog log = fl::parse_flight_log(text, "fuzz.csv", options);
      (void)log.end().describe(log.rows());
      for (const auto& name : log.column_names()) (void)log.fill_fraction(name);
    } catch (const fl::FlightLogError&) {
    }
  }
  return 0;
}
