// SPDX-License-Identifier: Apache-2.0
#pragma once
// Checks a NetCDF file (ours or any other tool's) against the rule table of
// its format (format_rules.hpp). The format is the one the file declares
// (OG1.0: Conventions contains "OG-1.0"; IOOS: format_version
// "IOOS_Glider_NetCDF_v2.0.nc") unless one is given.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/netcdf/format_rules.hpp"

namespace glider::netcdf {

struct Finding {
  const Rule* rule = nullptr;  // nullptr: the file itself (unreadable, format unknown)
  std::string message;
};

struct CheckResult {
  std::optional<Format> format;
  std::size_t rules_checked = 0;
  std::vector<Finding> findings;
  bool ok() const { return format.has_value() && findings.empty(); }
};

// Throws NcError when the file cannot be opened as NetCDF.
CheckResult check_file(const std::filesystem::path& path, std::optional<Format> format = std::nullopt);

}  // namespace glider::netcdf
