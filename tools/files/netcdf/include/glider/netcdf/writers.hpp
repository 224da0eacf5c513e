// SPDX-License-Identifier: Apache-2.0
#pragma once
// The two community formats written from a trajectory (docs/netcdf.md):
//   - OG1.0 (OceanGliders format 1.0): one NetCDF-4 trajectory file per deployment;
//   - IOOS NGDAC v2 (IOOS_Glider_NetCDF_v2.0.nc): one file per profile.
// Both through the NetCDF C library. The required elements are those of
// format_rules.hpp, and the tests check every written file against it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/netcdf/dataset_sink.hpp"
#include "glider/netcdf/deployment_metadata.hpp"
#include "glider/netcdf/flight_products.hpp"
#include "glider/netcdf/trajectory.hpp"

namespace glider::netcdf {

struct WriteContext {
  const Trajectory* trajectory = nullptr;
  const DeploymentMetadata* metadata = nullptr;  // required by the files; og1_dataset() goes without
  const FlightProducts* products = nullptr;      // nullptr: no vehicle given, no flight-model variables
  double created_s = 0.0;                        // date_created (SOURCE_DATE_EPOCH in tests: deterministic files)
  std::string history;                           // the command that wrote the file
};

// OG1.0 id "<platform_serial>_<start_date>_<data_mode>" (start = deployment time).
std::string og1_id(const DeploymentMetadata& metadata);
void write_og1(const std::filesystem::path& path, const WriteContext& context);
// The same dataset in memory, by the same writer (the Python module's xarray
// Dataset). context.metadata may be null: the elements it gives are left out.
MemoryDataset og1_dataset(const WriteContext& context);

// One file per profile in `directory` (created if missing), named as the
// NGDAC asks: <glider>_<profile start yyyymmddTHHMMSS>Z_<rt|delayed>.nc.
// Returns the files written (none when the trajectory has no profile).
std::vector<std::filesystem::path> write_ioos(const std::filesystem::path& directory, const WriteContext& context);

}  // namespace glider::netcdf
