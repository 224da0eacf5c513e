// SPDX-License-Identifier: Apache-2.0
#pragma once
// Flight health at a surfacing: the glider's segments found in the inputs,
// only the segments the state does not hold yet measured (one new segment
// per surfacing: one segment's fits), the deployment assessed from all
// stored measurements, the state written back atomically.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "glider/health/assess.hpp"
#include "glider/health/measure.hpp"
#include "glider/health/segments.hpp"
#include "glider/health/state.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::health {

struct HealthOptions {
  std::vector<std::string> inputs;  // files, folders, globs
  std::vector<std::filesystem::path> cache_dirs;
  std::string state_path;  // empty: no state (every segment measured)
  model::VehicleParams vehicle;
  std::string vehicle_source;  // said in the output
  // Logs whose clock starts at 0 (the SIL's) are placed this far apart in
  // the order found; 0: such logs are refused.
  double seconds_apart = 0.0;
  std::function<void(const std::string& note)> progress;
  AssessOptions assess;
};

struct HealthRun {
  std::string glider;
  std::string vehicle_source;
  std::vector<SegmentMeasurement> segments;  // in time order
  Assessment assessment;
  std::vector<std::string> notes;  // the state rebuilt, segments not judged, reader warnings
  std::size_t measured = 0, reused = 0;
  double cost_s = 0.0;  // wall time of the whole update
};

// Throws BadInput (two gliders mixed, a duplicate, out of order, SIL clocks
// without a placement): the state file is then left as it was.
HealthRun update_health(const HealthOptions& options);

// The key of a vehicle in the state: another vehicle file means new values.
std::string vehicle_key(const model::VehicleParams& vehicle);

}  // namespace glider::health
