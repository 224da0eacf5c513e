// SPDX-License-Identifier: Apache-2.0
#pragma once
// A SIL truth for the forecast's tests and benchmark: a mission flown in SIL
// in water whose current is known (a mean and an M2 tide, drawn from a seed)
// by a vehicle whose drag and trim differ from the nominal file by drawn
// amounts; each surfacing becomes a shore event (glider-shore-surfacing/1:
// fix, dead-reckoned position, m_water_vx/vy, times) in a glider folder, as
// the shore would have written it, and the true position and time of every
// surfacing are kept to score forecasts against.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glider/firmware/geo.hpp"
#include "glider/forecast/tide_table.hpp"

namespace glider::forecast {

struct TruthOptions {
  std::filesystem::path mission;  // .mi (its mafiles/ beside or above)
  std::filesystem::path vehicle;  // nominal vehicle file
  std::uint64_t seed = 1;
  int surfacings = 8;                  // fly until this many surfacings after the launch
  double utc_launch_s = 1798761600.0;  // 2027-01-01T00:00:00Z
  fw::LatLon launch{54.3161, 7.4098};
  double mean_current_max_m_s = 0.15;    // |mean| drawn up to this
  double tide_amplitude_max_m_s = 0.25;  // M2 amplitude drawn up to this
  double drag_sigma = 0.05;              // the true vehicle's drag against the file's
  double drag_factor = 1.0;              // and a fixed factor on it (a fouled or cleaner glider)
  double buoyancy_sigma_kg = 0.010;
  // The pitch sensor reads (1 + b) x the hull's pitch, b drawn uniform in
  // [-max, max] (0: a true sensor, nothing drawn): its dead reckoning and the
  // m_pitch it sends home (from-glider/) are the biased sensor's.
  double pitch_bias_max = 0.0;
  // With the mission's pitch servo: the servo holds the biased sensor's
  // pitch at the mission's, as a real servo does (the hull then at the
  // mission's / (1 + b)); false: it holds the hull's (the sensor only logs).
  bool servo_on_sensor = false;
  double max_working_depth_m = 100.0;
  // The GPS's noise, 1 sigma per axis (m): each fix the firmware dead-reckons
  // from and updates its current with, and the shore's events, carry it.
  double gps_noise_m = 3.0;
};

struct TruthSurfacing {
  double surfaced_utc_s = 0.0;          // the vehicle is up
  double dive_utc_s = 0.0;              // it dives again (the call's end)
  double lat_deg = 0.0, lon_deg = 0.0;  // truth where it surfaced
  double fix_lat_deg = 0.0, fix_lon_deg = 0.0;
  double dr_lat_deg = 0.0, dr_lon_deg = 0.0;
  bool have_dr = false;
  bool have_current = false;
  double water_vx = 0.0, water_vy = 0.0;
  double mission_time_s = 0.0;
};

struct Truth {
  std::vector<TruthSurfacing> surfacings;  // [0] is the launch
  // What the glider logs and sends home every 4 s (from-glider/ GLIDER.csv):
  // UTC, m_depth, m_pitch (its sensor's).
  std::vector<std::array<double, 3>> logged;
  std::string description;  // the drawn current and vehicle
  TideTable tide;           // the true tide (its M2; no mean: the table a tide model would give, error-free)
};

Truth fly_truth(const TruthOptions& options);

// Writes a glider folder: mission/ (the .mi and its .ma files), logs/ with
// the events of surfacings [0, upto], named `glider`, and from-glider/ with
// the last day of what it logged until surfacing `upto`.
void write_glider_folder(const Truth& truth, const TruthOptions& options, const std::string& glider, std::size_t upto,
                         const std::filesystem::path& glider_dir);

}  // namespace glider::forecast
