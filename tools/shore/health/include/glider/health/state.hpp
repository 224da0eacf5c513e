// SPDX-License-Identifier: Apache-2.0
#pragma once
// Health's incremental state (ROOT/GLIDER/health/state.json): each segment's
// measurement, keyed by its files' fingerprint, and the alerts raised at the
// last update. Written atomically (a temporary beside it, then rename(2));
// read back only when every check passes: a damaged or inconsistent file is
// never trusted, the data are measured again instead.
#include <optional>
#include <string>
#include <vector>

#include "glider/health/assess.hpp"
#include "glider/health/measure.hpp"

namespace glider::health {

inline constexpr const char* kStateSchema = "glider-health-state/1";
// Bumped whenever a segment's measurement changes (another fit, another
// rule for the data): a state measured otherwise is measured again.
// 2: 2 s RK4 steps, the lag floored at the sampling; 3: m_fin of decimated
// files as stored; 4: the Reynolds prior for a vehicle file silent on the
// exponent, the heading command held between stores, a fresh skin-friction
// anchor per flight (session 34); 5: the dynamic track reads a decimated
// file's depth, pitch and ballast as stored (diagnose's track.cpp, session 35);
// 6: the Reynolds prior's uncertainty in the intervals, intervals checked
// against the residual's profile, the ballast's knot before a change (session
// 36, which changed measurements without the bump), each value's shared shift
// stored (session 37); 7: the heading fit on diagnose's heading vehicle and
// on every yo (session 38); 8: the fin not judged on a segment that turned
// too little (fin_spread_deg stored, session 38); 9: nor on one whose heading
// turned too little (heading_spread_deg stored, session 39); 10: the fin
// projected on the command and the lagged heading (fin_instrument.hpp, session 42);
// 11: that projection the instrument of the logged fin (fin_iv.hpp, session 42);
// 12: the battery per km's pitch at each depth reading interpolated (session 45).
inline constexpr int kMeasurementVersion = 12;

struct HealthState {
  std::string glider;
  std::string vehicle_key;  // the nominal vehicle's file text hash: another vehicle invalidates every value
  double seconds_apart = 0.0;
  std::vector<SegmentMeasurement> segments;
  std::vector<Alert> alerts;
};

std::string state_json(const HealthState& state);

// The state in `path`, or none with `problem` set (no file: problem empty).
// Checks: JSON, schema, every field's type and range (finite times, intervals
// around their values), unique segment names, times in order.
std::optional<HealthState> read_state(const std::string& path, std::string& problem);

// Writes `text` to `path` by a temporary in the same folder, fsync, rename.
void write_atomically(const std::string& path, const std::string& text);

}  // namespace glider::health
