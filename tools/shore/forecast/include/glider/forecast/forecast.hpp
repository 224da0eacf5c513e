// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the glider surfaces next (issue 24 part 3; docs/forecast.md): the
// rest of the dive cycle flown in SIL - the real firmware against the
// vehicle model, in-process - from the last fix, Monte-Carlo over the
// current's and the model's uncertainty, with the baseline "the last
// depth-averaged current persists" beside it. Also the rehearsal of a .ma
// or .mi before it is sent.
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "glider/forecast/current_estimate.hpp"
#include "glider/forecast/forecast_settings.hpp"
#include "glider/forecast/glide_pitch.hpp"
#include "glider/forecast/mission_now.hpp"
#include "glider/forecast/surfacing_history.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::forecast {

struct ForecastOptions {
  std::string mission;     // --mission FILE.mi (default: GLIDER/mission/)
  std::string vehicle;     // --vehicle FILE (default: health/vehicle.toml, else boards/gliders.toml's)
  std::string boards_dir;  // for gliders.toml (default: glider::cli::boards_dir())
  int runs = 200;
  int threads = 2;
  std::uint64_t seed = 1;
  double max_working_depth_m = 100.0;
  double drag_sigma = 0.05;           // 1 sigma of the drag coefficient's relative error
  double buoyancy_sigma_kg = 0.010;   // 1 sigma of the vehicle's net buoyancy trim
  double max_dive_s = 12.0 * 3600.0;  // a run with no surfacing by then counts as "no_surfacing"
  int waypoint = -1;  // --waypoint: the active waypoint now (-1: replayed from the events since the plan began)
  std::vector<std::filesystem::path> rehearse;  // files applied after the queue (rehearsal)
  bool include_queue = true;
  bool write = true;     // write forecast/forecast.json
  PriorOverrides prior;  // the command line's; GLIDER/forecast.toml's otherwise (forecast_settings.hpp)
  // --tide FILE: the pilot's tidal constituents for the place (tide_table.hpp): the tidal prior's tide is
  // then the table's, its phase known (docs/forecast.md, session 44). Empty: an M2 of random phase.
  std::filesystem::path tide_table;
  // The model's drag scaled until its dead-reckoned speed through the water
  // is the glider's (docs/forecast.md, speed term): by default only when the
  // glider's DR speed is calibrated for its pitch sensor (speed_term.hpp),
  // --speed-correction: always, --no-speed-correction: never.
  bool speed_correction = false;
  bool speed_correction_calibrated = true;
  // The glider's dead-reckoned speed calibrated for its pitch sensor's scale,
  // read from the steady glides it sent home (speed_term.hpp; on:
  // --pitch-calibration). Off by default: it wins on SIL truths whose navigator
  // counts slow through a biased pitch sensor by construction, but the real
  // comet's own log says its navigator did not (m_avg_speed 0.265 m/s, the
  // model's 0.27), and its forecast from surfacing 1 loses with it, 68 m ->
  // 1174 m (docs/forecast.md, speed term).
  bool pitch_calibration = false;
  // The model's firmware dead-reckons through the glider's pitch sensor (its
  // scale read as above), its navigator's mean speed as slow (off:
  // --no-glider-dead-reckoning: the vehicle file's DR).
  bool glider_dead_reckoning = true;
  // The model's flight calibrated to the glider's steady-glide depth rates
  // read from from-glider/ (depth_rate_calibration.hpp): with the pitch servo
  // the hull's pitch (the sensor's scale), with the battery fixed the drag;
  // and the buoyancy's offset (--no-depth-rate-calibration: off). Flown by
  // default only under the servo: with the battery fixed it is said, not
  // flown, unless depth_rate_drag (--depth-rate-drag) - on the one real
  // fixed-battery glider it lost the position (comet-2019 from surfacing 1:
  // 68 -> 469 m) and on SIL the positions were mixed (docs/forecast.md).
  bool depth_rate_calibration = true;
  bool depth_rate_drag = false;
};

struct RunOutcome {
  bool surfaced = false;
  bool aborted = false;
  std::string cause;                         // abort cause id, or "no_surfacing"
  double time_s = 0.0;                       // from the dive start (the last call's end)
  double east_m = 0.0, north_m = 0.0;        // from the last fix
  std::int32_t waypoints_reached = 0;        // counted by the firmware in this run
  double dr_east_m = 0.0, dr_north_m = 0.0;  // the firmware's dead-reckoned position on surfacing
  double average_speed_m_s = 0.0;            // the navigator's mean glide speed then (m_avg_speed)
  double yo_climb_s = 0.0;                   // mean length of the yos' climbs (inflection to the next dive; 0: none)
  GlidePitch glide_pitch;                    // the steady glides' pitch (the speed term's pitch calibration)
};

struct Ellipse {
  double semi_major_m = 0.0, semi_minor_m = 0.0,
         orientation_deg = 0.0;  // orientation: of the major axis, deg from north, clockwise
};

struct Forecast {
  std::string glider;
  double made_utc_s = 0.0;
  double fix_lat_deg = 0.0, fix_lon_deg = 0.0, fix_utc_s = 0.0;
  double dive_utc_s = 0.0;
  bool have_surfacing = false;  // at least one run surfaced
  double lat_deg = 0.0, lon_deg = 0.0;
  double east_m = 0.0, north_m = 0.0;  // median, from the fix
  double time_utc_s = 0.0, time_p10_utc_s = 0.0, time_p90_utc_s = 0.0;
  Ellipse ellipse;
  double abort_risk = 0.0;  // the runs' (the SIL flights' own aborts), not the glider's
  std::map<std::string, double> abort_causes;
  bool glider_aborted = false;     // the last call's Because: names an abort (the glider waits for the pilot)
  std::string glider_abort_cause;  // its ABORT HISTORY's last cause, as printed
  bool baseline_ok = false;
  double baseline_lat_deg = 0.0, baseline_lon_deg = 0.0, baseline_time_utc_s = 0.0;
  double baseline_east_m = 0.0, baseline_north_m = 0.0;
  CurrentEstimate current, baseline_current;
  TidalPrior prior;             // the pilot's (or the default) prior the current used
  TidalPrior favoured;          // the widths the estimates favour (evidence mode)
  double dr_speed_ratio = 1.0;  // true over dead-reckoned speed through the water (the model's calibration)
  // The glider's own dead-reckoned speed through the water over its recent
  // dives against the model's on the coming one (1: not measured; said, not applied).
  double glider_speed_ratio = 1.0;
  int speed_dives = 0;
  double speed_drag_factor = 1.0;  // the drag factor applied to the vehicle (--speed-correction; 1: none)
  double speed_drag_sigma = 0.0;   // its 1-sigma (relative) from the pitch calibration, drawn in the runs
  // The glider's pitch sensor: hull pitch = pitch_scale x m_pitch from its
  // steady glides against the model's (1, 0 samples: not read), and the
  // factor its dead-reckoned speed is low by for it (speed_term.hpp).
  double pitch_scale = 1.0, pitch_scale_sigma = 0.0, pitch_dr_speed_factor = 1.0;
  int pitch_samples = 0;
  // The depth-rate calibration (depth_rate_calibration.hpp): read (have),
  // applied, and what it set.
  bool depth_rate_have = false, depth_rate_applied = false, depth_rate_servo = false;
  double depth_rate_pitch_scale = 1.0, depth_rate_drag_factor = 1.0, depth_rate_buoyancy_kg = 0.0;
  double nominal_average_speed_m_s = 0.0;  // the vehicle file's still-water flight's m_avg_speed (0: none)
  double depth_rate_glider_dive_m_s = 0.0, depth_rate_glider_climb_m_s = 0.0;
  double depth_rate_model_dive_m_s = 0.0, depth_rate_model_climb_m_s = 0.0;
  // The model's own miss on the glider's recent dives, flown again with the
  // current each one measured (the waypoint replay's flights): RMS east and
  // north and their correlation, over `model_miss_dives` dives of the last
  // day (0: none to check, no term added).
  double model_miss_east_m = 0.0, model_miss_north_m = 0.0, model_miss_correlation = 0.0;
  int model_miss_dives = 0;
  int runs = 0;
  double wall_s = 0.0;
  std::string mission;
  std::string vehicle_source;
  std::vector<std::string> queued_applied;
  std::vector<std::string> notes;
  std::string refusal;  // the firmware refuses the mission or a queued/rehearsed file
};

// The forecast from the glider folder (shore layout, docs/comms.md). Throws
// std::runtime_error naming the file for bad input (no fix, a malformed
// event, no mission, a vehicle that cannot glide).
Forecast make_forecast(const std::filesystem::path& glider_dir, const ForecastOptions& options);

// The glider's depth-averaged current estimates from its surfacings: the
// first event's over a segment of `first_span_s` ending at its call, each
// later one updated at its call (a fix, >= 10 min under water) over the
// segment since the call before, the DR's speed error (`ratio`, true over DR
// speed through the water) taken out where the segment's DR is known.
std::vector<CurrentSample> current_samples(const std::vector<Surfacing>& history, double ratio, double first_span_s);

// The Monte-Carlo flights alone, for the benchmark and tests: `n` runs of
// the plan from a fix, seeds options.seed + i, deterministic per seed
// whatever the thread count.
struct FlightSetup {
  model::VehicleParams vehicle;
  fw::FlightSoftwareConfig config;  // the plan already the remaining one
  fw::LatLon fix{};
  CurrentEstimate current;  // the water's (drawn from in the Monte-Carlo)
  // What the glider's navigator believes (its m_water_vx/vy at the dive): it
  // steers and dead-reckons with this; none: it has no estimate yet.
  std::optional<fw::EastNorth> firmware_current;
  double overtime_left_s = 0.0;  // the mission's overtime limit minus the mission time at the fix (0: none)
  // How long the glider had been at the surface when it dived (the call's
  // start to its end): start_when 12 counts from the call, not from the dive
  // (FlightSoftware::seed_clocks).
  double surface_time_s = 0.0;
  // start_when 9 counts from its previous firing: that was this long before
  // the arrival (the climb left then; forecast.cpp climb_left_at_firing_s).
  double clock_fired_before_s = 0.0;
  // The glider's mean glide speed at the dive (its m_avg_speed, else the
  // model's), carried over as if glided for `average_weight_s`: the runs
  // steer Slocum's law at that speed from the first moment (0: none).
  double average_speed_m_s = 0.0;
  double average_weight_s = 0.0;
};
std::vector<RunOutcome> fly_runs(const FlightSetup& setup, const ForecastOptions& options, int n, bool vary);

// The surfacing clock (docs/forecast.md "The surfacing clock"): whether
// surfacing `s` was the when_secs clock's (its Because: lines say "Every when
// secs"; one that says nothing counts when the plan has that clock), and how
// long before surfacing history[last] that clock fired (the climb left then,
// from the chain of arrivals; `longest_s` the longest such climb; 0 when the
// plan has no such clock).
bool surfaced_by_when_secs(const Surfacing& s, const fw::MissionPlan& plan);
double climb_left_at_firing_s(const std::vector<Surfacing>& history, std::size_t last, const fw::MissionPlan& plan,
                              double longest_s);

nlohmann::json forecast_json(const Forecast& f);
std::string forecast_text(const Forecast& f);

// glider-rehearsal/1: verdict ok | aborts | refused.
struct Rehearsal {
  std::string file;
  std::string verdict;
  std::string message;
  Forecast forecast;
};
// Abort risk at or above this is "aborts".
inline constexpr double kAbortVerdictRisk = 0.1;
Rehearsal rehearse(const std::filesystem::path& glider_dir, const std::filesystem::path& file, ForecastOptions options);
nlohmann::json rehearsal_json(const Rehearsal& r, const std::string& glider);
// Exit code per docs/forecast.md: 0 ok, 1 refused, 4 aborts.
int rehearsal_exit_code(const Rehearsal& r);

// The shore's call after each surfacing event (tools/shore/station/after_surfacing):
// writes forecast/forecast.json and returns one line for the call's journal
// ("forecast: next surfacing ..." or "forecast: failed: ..."); never throws
// (a problem also goes into the file's `error`).
std::string forecast_after_surfacing(const std::filesystem::path& glider_dir);

// Writes `text` to `path` by a temporary in the same folder and rename(2).
void write_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace glider::forecast
