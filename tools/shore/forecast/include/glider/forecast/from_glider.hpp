// SPDX-License-Identifier: Apache-2.0
#pragma once
// The files the glider sent home, as the shore keeps them:
// GLIDER_DIR/from-glider/*.csv, glider-convert's conversions of the .sbd /
// .tbd / .dbd. The speed term reads the glider's pitch and heading from them.
#include <filesystem>
#include <string>
#include <vector>

namespace glider::forecast {

// GLIDER_DIR/from-glider/*.csv in name order (none without the folder).
std::vector<std::filesystem::path> from_glider_files(const std::filesystem::path& glider_dir);

// The file's header (its first line not a `#` comment) names every one of
// `names`: a science file without them is passed over, not an error.
bool header_names(const std::filesystem::path& path, const std::vector<std::string>& names);

}  // namespace glider::forecast
