// SPDX-License-Identifier: Apache-2.0
#include "glider/health/health.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <map>

#include "glider/model/vehicle_file.hpp"

namespace glider::health {
namespace {

// Times before 1973 are not clock times: the log counts from its start (SIL).
constexpr double kEarliestClockTime_s = 1e8;

}  // namespace

std::string vehicle_key(const model::VehicleParams& vehicle) {
  return std::to_string(std::hash<std::string>{}(model::vehicle_file_text(vehicle)));
}

HealthRun update_health(const HealthOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  HealthRun run;
  run.vehicle_source = options.vehicle_source;
  const std::vector<SegmentFiles> found = find_segments(options.inputs);
  if (found.empty()) throw BadInput("no glider data (Slocum files or flight-log CSVs) in the inputs");

  // Two gliders mixed: refused before anything is measured or written.
  for (const SegmentFiles& s : found) {
    const auto g = glider_of_file(s.files.front());
    if (!g) continue;
    if (run.glider.empty()) {
      run.glider = *g;
    } else if (*g != run.glider) {
      throw BadInput(s.files.front() + ": glider '" + *g + "', but the segments before it are glider '" + run.glider +
                     "': give one glider's files at a time");
    }
  }

  const std::string key = vehicle_key(options.vehicle);
  std::map<std::string, SegmentMeasurement> stored;
  std::vector<Alert> previous;
  if (!options.state_path.empty()) {
    std::string problem;
    std::optional<HealthState> state = read_state(options.state_path, problem);
    if (!problem.empty()) {
      run.notes.push_back("state file " + options.state_path + " is damaged (" + problem +
                          "): not trusted, every segment measured again from the data");
    } else if (state && (state->glider != run.glider || state->vehicle_key != key ||
                         state->seconds_apart != options.seconds_apart)) {
      run.notes.push_back("state file " + options.state_path +
                          " is for another glider, vehicle or placement: every segment measured again");
    } else if (state) {
      for (SegmentMeasurement& m : state->segments) stored.emplace(m.name, std::move(m));
      previous = state->alerts;
    }
  }

  // Logs whose clock starts at 0 (SIL) are placed by mission: the segments
  // of one mission (<glider>-<yyyy>-<ddd>-<mission>-<segment>) share an offset.
  std::string last_mission;
  long mission_index = -1;
  for (std::size_t i = 0; i < found.size(); ++i) {
    const SegmentFiles& files = found[i];
    const std::string mission = files.name.substr(0, files.name.find_last_of('-'));
    if (mission != last_mission || mission_index < 0) {
      ++mission_index;
      last_mission = mission;
    }
    const double placement = static_cast<double>(mission_index) * options.seconds_apart;
    auto it = stored.find(files.name);
    if (it != stored.end() && it->second.fingerprint == files.fingerprint &&
        (it->second.time_offset_s == 0.0 || it->second.time_offset_s == placement)) {
      run.segments.push_back(it->second);
      run.segments.back().files = files.files;  // the same files, maybe by another path
      ++run.reused;
      continue;
    }
    if (options.progress) options.progress("measuring " + files.name);
    const LoadedSegment loaded = load_segment(files, options.cache_dirs);
    for (const std::string& w : loaded.warnings) run.notes.push_back("warning: " + w);
    double offset = 0.0;
    if (loaded.log && loaded.start_s < kEarliestClockTime_s) {
      if (options.seconds_apart <= 0.0) {
        throw BadInput(files.files.front() + ": its times count from its start (" +
                       std::to_string(std::lround(loaded.start_s)) + " s" +
                       "), not a clock: give --hours-apart H to place such logs (SIL) in the deployment");
      }
      offset = placement;
    }
    run.segments.push_back(measure_segment(options.vehicle, loaded, offset));
    ++run.measured;
  }

  // Duplicates and order, in the order found (a folder: by segment name).
  const SegmentMeasurement* last = nullptr;
  for (const SegmentMeasurement& m : run.segments) {
    if (!(m.end_s > m.start_s)) continue;  // unreadable: no times
    if (last != nullptr) {
      if (m.start_s == last->start_s && m.end_s == last->end_s) {
        throw BadInput(m.files.front() + ": the same times as " + last->files.front() +
                       " (a duplicate under another name); give each segment once");
      }
      if (m.start_s < last->end_s) {
        throw BadInput(m.files.front() + ": starts at " + utc_iso(m.start_s) + ", before the end of " +
                       last->files.front() + " (" + utc_iso(last->end_s) +
                       "): segments out of order or overlapping; give them in time order, each once");
      }
    }
    last = &m;
  }
  for (const SegmentMeasurement& m : run.segments) {
    if (!m.judged && !m.why.empty()) run.notes.push_back("not judged: " + m.why);
  }

  run.assessment = assess(run.segments, previous, options.assess);
  if (!options.state_path.empty()) {
    HealthState state;
    state.glider = run.glider;
    state.vehicle_key = key;
    state.seconds_apart = options.seconds_apart;
    state.segments = run.segments;
    state.alerts = run.assessment.alerts;
    write_atomically(options.state_path, state_json(state));
  }
  run.cost_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace glider::health
