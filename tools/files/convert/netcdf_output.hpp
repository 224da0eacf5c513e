// SPDX-License-Identifier: Apache-2.0
#pragma once
// glider-convert's --format og1|ioos: a deployment to the community NetCDF
// formats through tools/files/netcdf (docs/netcdf.md).
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
inline std::vector<std::string> netcdf_columns() {
  return {"m_depth", "sci_water_pressure", "sci_water_temp", "sci_water_cond", "m_lat",
          "m_lon",   "m_gps_lat",          "m_gps_lon",      "m_heading",      "m_pitch",
          "m_roll",  "m_ballast_pumped",   "m_de_oil_vol",   "m_depth_state",  "m_depth_rate"};
}
// The command as typed: the files' history attribute.
inline std::string command_line(int argc, char** argv) {
  std::string text = "glider-convert";
  for (int i = 1; i < argc; ++i) text += std::string(" ") + argv[i];
  return text;
}

// Writes the file(s) (netcdf_output.cpp: native builds only); returns the exit code (kError for an IOOS request on
// data without a profile: that format has no file to write).
int write_netcdf(const slocum::Deployment& deployment, const NetcdfRequest& request, const std::string& out);

}  // namespace glider::convert
