// SPDX-License-Identifier: Apache-2.0
#pragma once
// Publishing what rz received: a complete file moves from .incoming/ to
// from-glider/ by rename(2) (same file system), so a reader of from-glider/
// never sees a partial file; a Slocum binary file is then converted to CSV
// beside it with the project's reader (tools/files/slocum, as glider-convert).
#include <filesystem>
#include <string>
#include <vector>

#include "glider_folders.hpp"
#include "surfacing_event.hpp"

namespace glider::shore {

// Publishes `name` from folders.incoming (a file rz reported complete).
ReceivedFile publish_received(const GliderFolders& folders, const std::string& name,
                              const std::vector<std::filesystem::path>& cache_dirs);

// Files still in .incoming/ (partial receptions kept for Zmodem resume).
std::vector<std::string> partial_receptions(const GliderFolders& folders);

// True for the Slocum binary kinds glider-convert reads (.sbd/.tbd/.dbd/... and LZ4 .scd/.tcd/...).
bool is_slocum_data_file(const std::filesystem::path& path);

}  // namespace glider::shore
