// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the heading plane works on: the log's steady glides under a heading
// command, grouped in runs (one per glide), with the speed through the water
// and the lift factor the yaw model needs, and the measured yaw rate; plus
// the whole log's heading, command and fin rows for the servo and the
// autopilot, which act at every cycle.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// The log cannot be diagnosed in the heading plane (names what is missing).
class HeadingUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HeadingTrack {
  // One entry per glide sample used, runs back to back.
  std::vector<double> time_s;                   // s from the log's first row
  std::vector<double> heading_rad;              // m_heading, unwrapped along the run
  std::vector<double> speed_m_s;                // |depth rate| / |sin(glide path at the logged pitch)|
  std::vector<double> lift_factor;              // a_eff = C_L / cl_alpha at that glide's angle of attack
  std::vector<double> roll_rad;                 // the run's median m_roll (the vehicle's roll where the log has none)
  std::vector<double> roll_sample_rad;          // m_roll at each sample (that median where none): the yaw's
  std::vector<double> yaw_rate_rad_s;           // measured: the slope of heading_rad (estimator of track.hpp)
  std::vector<double> depth_m, depth_rate_m_s;  // the depth rate: the speed's (+ down)
  std::vector<flightlog::Phase> phase;
  std::vector<int> yo;
  std::vector<std::size_t> run_first;
  std::vector<std::size_t> scored;  // samples compared (after each run's settling)
  double rate_half_window_s = 0.0, max_gap_s = 0.0;
  // The yaw's fast pole (s) the vehicle link's models carry behind the
  // vehicle file's first-order lag, and the upper end of its prior (0 to
  // it, uniform): HeadingTrackOptions::yaw_fast_pole_max_s.
  double yaw_fast_pole_s = 0.0, yaw_fast_pole_max_s = 0.0;
  // The fast pole carried beside a lag the innovations measured (s; 0:
  // none, carried_fast_pole's rule): HeadingDiagnosis::yaw_lag_pole_s.
  double yaw_fast_pole_with_lag_s = 0.0;

  // Every log row (NaN where not logged): the servo and the autopilot.
  std::vector<double> row_time_s, row_heading_rad, row_command_rad, row_fin_rad, row_fin_command_rad, row_depth_m;
  // m_fin at every row (the yaw model's input): straight between its readings
  // across gaps up to max_gap_s; with fin_stored_on_change held where the
  // file's writer found it unchanged (stored_on_change.hpp).
  std::vector<double> row_fin_filled_rad;
  std::vector<int> row_yo;
  // The autopilot flies this row: m_depth_state diving (1) or climbing (2)
  // where the log has it (the flight computer's own phase), else a dive or
  // climb of the depth below 1 m.
  std::vector<bool> row_gliding;

  bool roll_logged = false;
  double median_roll_rad = 0.0;  // over the runs (NaN-free)
  double fin_max_rad = 0.0;      // the log's f_fin_safety_max, else the vehicle's
  std::size_t size() const { return time_s.size(); }
  std::size_t run_end(std::size_t run) const { return run + 1 < run_first.size() ? run_first[run + 1] : size(); }
};

struct HeadingTrackOptions {
  double min_depth_m = 2.0;
  double min_pitch_rad = 0.1745;  // flatter is no steady glide (the speed estimate fails)
  // Not scored after a run starts: after an inflection the glider takes
  // ~80 s to settle into its steady glide, and until then the angle of
  // attack (the lift factor of the roll's yaw) is larger than the steady
  // glide's at the same pitch (SIL, comet: 0.74 of it in the first 20 s,
  // 0.95 at 40-60 s, 0.99 after 80 s).
  double settle_s = 80.0;
  double min_run_s = 60.0;
  double max_gap_s = 30.0;
  double rate_half_window_s = 5.0;  // the yaw rate: slope of the heading over +-this
  // The log's m_fin is as a decimated file (.sbd) stored it: on change, at
  // most every few seconds; a row without it was checked and found unchanged
  // once the storing interval had passed (stored_on_change.hpp). false: a
  // full-resolution log, m_fin straight between its readings.
  bool fin_stored_on_change = false;
  // The yaw's fast pole, a prior, not measured: a slender glider's yaw
  // answers its tail fin through two coupled states (sway and yaw, Nomoto's
  // second-order model; the fin's side force, the wings' roll-yaw coupling
  // and the compass's own filtering add their own lags) - a dominant pole
  // (the vehicle file's yaw time constant, which turn tests see) and a
  // second, faster one that rows seconds apart cannot tell from a dead time
  // (e^{-s p} ~ 1/(1 + s p)); a first-order yaw reads it as yaw delay. Its
  // prior: uniform from 0 to this (s); the models carry its centre, and a
  // yaw delay's interval is widened by the prior's spread along the ridge
  // delay + pole = what the log measures (heading_diagnose.cpp). Negative:
  // half the vehicle file's yaw time constant (a pole within a factor two of
  // the dominant one is part of the lag a first-order turn test states);
  // 0: no fast pole (the rule before; the default here, for the heading
  // model's other users - health's fin, the heading study - where it was not
  // measured; the diagnosis's default is on: HeadingDiagnoseOptions).
  // docs/science.md "The yaw's fast pole".
  double yaw_fast_pole_max_s = 0.0;
};

// A setting the log states in its `settings_at_file_open` metadata
// ("u_hd_fin_ap_gain=1.5 ..."), as a Slocum log records them at file open.
std::optional<double> logged_setting(const flightlog::FlightLog& log, std::string_view name);

// Throws HeadingUnavailable when the log lacks m_heading, c_heading (with
// values under water), m_fin or c_fin, or has no glide under a heading
// command; flightlog::FlightLogError as the vertical plane for bad rows.
HeadingTrack prepare_heading_track(const flightlog::FlightLog& log, const model::VehicleParams& vehicle,
                                   const HeadingTrackOptions& options = {});

}  // namespace glider::diagnose
