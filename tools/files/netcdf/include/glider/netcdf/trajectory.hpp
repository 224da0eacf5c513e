// SPDX-License-Identifier: Apache-2.0
#pragma once
// A flight log's samples as the community formats want them: one entry per
// row of the log (the CSV conversion's rows, in its order), in the formats'
// units, NaN where the log has no value. Both writers (OG1.0, IOOS) start here.
#include <cstdint>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"

namespace glider::netcdf {

struct Trajectory {
  std::vector<double> time_s;                       // seconds since 1970 (m_present_time)
  std::vector<double> depth_m;                      // m_depth (else the CTD pressure as depth), + down
  std::vector<double> pressure_dbar;                // sci_water_pressure x 10
  std::vector<double> temperature_c;                // sci_water_temp
  std::vector<double> conductivity_s_m;             // sci_water_cond
  std::vector<double> salinity;                     // PSS-78 from the CTD (model/seawater.hpp)
  std::vector<double> density_kg_m3;                // TEOS-10 in-situ density from the CTD
  std::vector<double> dr_latitude, dr_longitude;    // m_lat/m_lon (the glider's dead reckoning), decimal degrees
  std::vector<double> gps_latitude, gps_longitude;  // m_gps_lat/m_gps_lon new fixes (repeats dropped), degrees
  std::vector<double> latitude, longitude;          // every sample: dead reckoning interpolated in time (see .cpp)
  std::vector<double> heading_deg, pitch_deg, roll_deg;
  std::vector<double> pumped_cc;              // m_ballast_pumped (else m_de_oil_vol) as logged
  std::vector<double> pitch_rad, ballast_cc;  // flight-model inputs (forward filled, see .cpp)
  std::vector<flightlog::Phase> phase;
  std::vector<std::int32_t> profile;  // 1, 2, ... within a dive or climb; 0 outside any
  std::size_t profiles = 0;
  std::string depth_source;  // "m_depth" or "sci_water_pressure"
  std::size_t size() const { return time_s.size(); }
};

struct ProfileOptions {
  double min_depth_change_m = 3.0;  // a shallower glide is a bob, not a profile
  // Gaps up to this are bridged by the phase finder; scaled up on thinned
  // logs (3 x the median sample interval) so that thinning does not read as gaps.
  double max_gap_s = 30.0;
};

// Throws flightlog::FlightLogError when the log has no depth at all.
Trajectory make_trajectory(const flightlog::FlightLog& log, const ProfileOptions& options = {});

// PHASE codes of the OG vocabulary (vocabularyCollection/phase.md).
std::int8_t og_phase_code(flightlog::Phase phase);

// The log's value per row: a forward fill of the last value up to max_age_s
// (a sensor logged only when it changes, e.g. the pump's volume), NaN beyond.
std::vector<double> forward_fill(const std::vector<double>& time, const flightlog::Column& values, double max_age_s);
// Linear interpolation in time between the finite values, no extrapolation
// further than max_gap_s... of an interval: NaN across gaps longer than max_gap_s.
std::vector<double> interpolate(const std::vector<double>& time, const std::vector<double>& values, double max_gap_s);

}  // namespace glider::netcdf
