// SPDX-License-Identifier: Apache-2.0
#pragma once
// The real Slocum files copied into tests/data/real/dbd and dbdreader's
// reference decoding of them (reference.json).
#include <filesystem>
#include <string>

namespace glider::slocum::test {

inline std::filesystem::path real_dbd_dir() { return std::filesystem::path(GLIDER_SOURCE_DIR) / "tests/data/real/dbd"; }
// "comet-2016-174-05-003.dbd" -> its path (deployment folder from the name).
inline std::filesystem::path real_file(const std::string& name) { return real_dbd_dir() / name.substr(0, 10) / name; }
inline std::filesystem::path real_cache(const std::string& name) { return real_file(name).parent_path() / "cac"; }
inline std::filesystem::path output_dir() { return std::filesystem::path(GLIDER_TEST_OUTPUT_DIR); }

}  // namespace glider::slocum::test
