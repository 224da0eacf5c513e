// SPDX-License-Identifier: Apache-2.0
#pragma once
// An OG1.0 file (ours or another tool's, e.g. a SeaExplorer's or Seaglider's
// converted by pyglider) read back as a flight log, so that the tools that
// take a log (glider-diagnose, ...) take it too. Every numeric variable on
// N_MEASUREMENTS becomes a column (its fill -> NaN), the OG1 names the
// flight-log contract knows under the contract's names and units:
//   TIME -> m_present_time, DEPTH -> m_depth, PITCH/ROLL/HEADING (deg) -> m_pitch/m_roll/m_heading (rad),
//   PRES (dbar) -> sci_water_pressure (bar), TEMP -> sci_water_temp, CNDC (mS/cm) -> sci_water_cond (S/m),
//   PUMPED_VOLUME (cm3, this project's) -> m_ballast_pumped.
// The rest keep their names: a pump volume under another name is given with
// --rename NAME=m_ballast_pumped, as for any log. The checks are the CSV
// reader's (flightlog::ReadOptions: required columns, strictly increasing
// time), with flightlog::FlightLogError naming the file and variable.
#include <filesystem>

#include "glider/flightlog/flight_log.hpp"

namespace glider::netcdf {

// True for a file that starts like NetCDF (classic "CDF" or HDF5 / NetCDF-4).
bool is_netcdf_file(const std::filesystem::path& path);

flightlog::FlightLog read_og1_log(const std::filesystem::path& path, const flightlog::ReadOptions& options = {});

}  // namespace glider::netcdf
