// SPDX-License-Identifier: Apache-2.0
#pragma once
// The files the glider sent home, as the shore keeps them:
// GLIDER_DIR/from-glider/*.csv, glider-convert's conversions of the .sbd /
// .tbd / .dbd. The speed term reads the glider's pitch and heading from them.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"

namespace glider::forecast {

// GLIDER_DIR/from-glider/*.csv in name order (none without the folder).
std::vector<std::filesystem::path> from_glider_files(const std::filesystem::path& glider_dir);

// The file's header (its first line not a `#` comment) names every one of
// `names`: a science file without them is passed over, not an error.
bool header_names(const std::filesystem::path& path, const std::vector<std::string>& names);

// Each of the glider's files whose header names every one of `columns`,
// read with those columns (each required), handed to `use`; one that names
// them but does not read is skipped and named in `notes` ("from-glider:
// FILE not read for the WHAT: why"). The pitch, heading and depth readers
// of the speed term share it.
void for_each_from_glider_log(const std::filesystem::path& glider_dir, const std::vector<std::string>& columns,
                              const std::string& what, std::vector<std::string>& notes,
                              const std::function<void(const flightlog::FlightLog&)>& use);

}  // namespace glider::forecast
