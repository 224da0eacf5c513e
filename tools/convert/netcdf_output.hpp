// SPDX-License-Identifier: Apache-2.0
#pragma once
// glider-convert's --format og1|ioos: a deployment to the community NetCDF
// formats through tools/netcdf (docs/netcdf.md).
#include <string>
#include <vector>

#include "glider/slocum/deployment.hpp"

namespace glider::convert {

struct NetcdfRequest {
  std::string format = "csv";
  std::string metadata;  // deployment metadata TOML
  std::string vehicle;   // empty: no flight-model products
  std::string command_line;
};

// The log columns the NetCDF writers use (others are not decoded).
std::vector<std::string> netcdf_columns();
std::string command_line(int argc, char** argv);

// Writes the file(s); returns the exit code (kError for an IOOS request on
// data without a profile: that format has no file to write).
int write_netcdf(const slocum::Deployment& deployment, const NetcdfRequest& request, const std::string& out);

}  // namespace glider::convert
