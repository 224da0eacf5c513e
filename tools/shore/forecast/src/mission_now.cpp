// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/mission_now.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "glider/firmware/geo.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

namespace {

// As mi_document looks for a mission's .ma files.
fs::path mafiles_folder(const fs::path& mission) {
  const fs::path dir = mission.parent_path();
  for (const fs::path& candidate : {dir / "mafiles", dir / ".." / "mafiles"}) {
    if (fs::is_directory(candidate)) return candidate;
  }
  return dir;
}

bool is_mission_file(const fs::path& p) { return p.extension() == ".ma" || p.extension() == ".mi"; }

// The firmware's install(): the mission's files staged with `changes` in
// their places (in order), loaded by the one mission setup.
fw::app::PreparedMission staged(const fs::path& mission, const std::vector<fs::path>& changes,
                                const fw::app::VehicleSetup& setup, const fs::path& stage) {
  fs::remove_all(stage);
  fs::create_directories(stage / "missions");
  fs::create_directories(stage / "mafiles");
  fs::copy_file(mission, stage / "missions" / mission.filename());
  for (const fs::directory_entry& entry : fs::directory_iterator(mafiles_folder(mission))) {
    if (entry.is_regular_file() && entry.path().extension() == ".ma") {
      fs::copy_file(entry.path(), stage / "mafiles" / entry.path().filename());
    }
  }
  for (const fs::path& change : changes) {
    const fs::path to = stage / (change.extension() == ".mi" ? "missions" : "mafiles") / change.filename();
    fs::copy_file(change, to, fs::copy_options::overwrite_existing);
  }
  return fw::app::prepare_mission(stage / "missions" / mission.filename(), setup, {});
}

// The staged path means nothing to the pilot: name the file as given.
std::string first_message(const fw::app::PreparedMission& prepared, const fs::path& stage, const fs::path& file) {
  std::string why;
  for (const std::string& line : fw::app::mission_messages(prepared, true)) {
    why = line;
    break;
  }
  if (why.empty()) why = prepared.refusal;
  for (const std::string& prefix :
       {(stage / "mafiles" / file.filename()).string(), (stage / "missions" / file.filename()).string()}) {
    for (std::size_t at = why.find(prefix); at != std::string::npos; at = why.find(prefix)) {
      why.replace(at, prefix.size(), file.string());
    }
  }
  const std::string stage_text = stage.string() + "/";
  for (std::size_t at = why.find(stage_text); at != std::string::npos; at = why.find(stage_text)) {
    why.replace(at, stage_text.size(), "");
  }
  return why;
}

// The file the shore kept of a delivered NAME: to-glider/sent/<stamp>_NAME, the latest.
std::optional<fs::path> sent_copy(const fs::path& glider_dir, const std::string& name) {
  const fs::path sent = glider_dir / "to-glider" / "sent";
  if (!fs::is_directory(sent)) return std::nullopt;
  std::optional<fs::path> best;
  for (const fs::directory_entry& entry : fs::directory_iterator(sent)) {
    const std::string file = entry.path().filename().string();
    if (entry.is_regular_file() && file.ends_with("_" + name) && (!best || file > best->filename().string())) {
      best = entry.path();
    }
  }
  return best;
}

}  // namespace

fs::path find_mission(const fs::path& glider_dir, const std::string& explicit_mission, const std::string& named) {
  if (!explicit_mission.empty()) {
    if (!fs::is_regular_file(explicit_mission)) throw std::runtime_error(explicit_mission + ": no such mission file");
    return explicit_mission;
  }
  const fs::path folder = glider_dir / "mission";
  std::vector<fs::path> found;
  if (fs::is_directory(folder)) {
    for (const fs::path& dir : {folder, folder / "missions"}) {
      if (!fs::is_directory(dir)) continue;
      for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
        if (entry.is_regular_file() && entry.path().extension() == ".mi") found.push_back(entry.path());
      }
    }
  }
  for (const fs::path& p : found) {
    std::string a = p.filename().string(), b = named;
    std::transform(a.begin(), a.end(), a.begin(), ::tolower);
    std::transform(b.begin(), b.end(), b.begin(), ::tolower);
    if (!b.empty() && a == b) return p;
  }
  if (found.size() == 1) return found.front();
  if (found.empty()) {
    throw std::runtime_error(folder.string() +
                             ": no mission: keep the glider's .mi in mission/missions/ and its .ma files in "
                             "mission/mafiles/ (or give --mission FILE.mi)");
  }
  throw std::runtime_error(folder.string() + ": " + std::to_string(found.size()) + " .mi files and the glider named '" +
                           named + "': give --mission FILE.mi");
}

MissionNow mission_now(const fs::path& glider_dir, const fs::path& mission_file, const fw::app::VehicleSetup& setup,
                       const std::vector<Surfacing>& history, const std::vector<fs::path>& extra, bool include_queue) {
  MissionNow now;
  now.mission_file = mission_file;
  const fw::app::PreparedMission launch = fw::app::prepare_mission(mission_file, setup, {});
  if (!launch.config) {
    now.refusal = first_message(launch, fs::path(), mission_file);
    return now;
  }
  now.config = *launch.config;
  const fs::path stage = glider_dir / "forecast" / ".staging";

  // Delivered changes, in the order of the calls that took them; the fixes
  // after the last one say which waypoint is active.
  std::vector<fs::path> changes;
  std::size_t replay_from = 0;
  for (std::size_t i = 0; i < history.size(); ++i) {
    for (const std::string& name : history[i].files_delivered) {
      if (!is_mission_file(name)) continue;
      const std::optional<fs::path> copy = sent_copy(glider_dir, name);
      if (!copy) {
        now.notes.push_back(name + " was delivered in " + history[i].file.filename().string() +
                            " but to-glider/sent/ has no copy: not applied");
        continue;
      }
      std::vector<fs::path> trial = changes;
      trial.push_back(*copy);
      const fw::app::PreparedMission p = staged(mission_file, trial, setup, stage);
      if (p.config) {
        changes = trial;
        now.config.plan = p.config->plan;
        now.applied.push_back(copy->filename().string());
        replay_from = i + 1;  // the glider restarts its list after this call's fix
      } else {
        now.notes.push_back(
            name + " (delivered) was refused by the glider's loader: " + first_message(p, stage, copy->filename()));
      }
    }
  }
  std::vector<fs::path> pending;
  if (include_queue && fs::is_directory(glider_dir / "to-glider")) {
    std::vector<fs::path> queued;
    for (const fs::directory_entry& entry : fs::directory_iterator(glider_dir / "to-glider")) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && name[0] != '.' && is_mission_file(entry.path())) queued.push_back(entry.path());
    }
    std::sort(queued.begin(), queued.end());
    pending = queued;
  }
  for (const fs::path& p : extra) pending.push_back(p);
  for (const fs::path& file : pending) {
    if (file.extension() == ".mi" && file.filename() != mission_file.filename()) {
      now.refusal = file.string() + ": not the flown mission (" + mission_file.filename().string() +
                    "); the glider keeps it and does not apply it";
      fs::remove_all(stage);
      return now;
    }
    std::vector<fs::path> trial = changes;
    trial.push_back(file);
    const fw::app::PreparedMission p = staged(mission_file, trial, setup, stage);
    if (!p.config) {
      // The loader may name the .mi line that reads the file: say which file it is.
      now.refusal = first_message(p, stage, file);
      if (now.refusal.find(file.filename().string()) == std::string::npos) {
        now.refusal = file.filename().string() + ": refused by the glider's mission loader: " + now.refusal;
      }
      fs::remove_all(stage);
      return now;
    }
    changes = trial;
    now.config.plan = p.config->plan;
    now.applied.push_back(file.filename().string());
    replay_from = history.size();  // applied at the next call: the list starts again
  }
  fs::remove_all(stage);

  now.replay_from = replay_from;
  return now;
}

fw::MissionPlan remaining_plan(const MissionNow& now) {
  fw::MissionPlan plan = now.config.plan;
  if (plan.waypoint_count == 0) return plan;
  for (std::int32_t i = 0; i < plan.waypoint_count; ++i) {
    plan.waypoints[static_cast<std::size_t>(i)] =
        now.config.plan.waypoints[static_cast<std::size_t>((now.active_waypoint + i) % plan.waypoint_count)];
  }
  if (plan.legs_to_run == fw::kLegsOnce) {
    plan.legs_to_run = std::max<std::int32_t>(1, plan.waypoint_count - now.waypoints_reached);
  } else if (plan.legs_to_run > 0) {
    plan.legs_to_run = std::max<std::int32_t>(1, plan.legs_to_run - now.waypoints_reached);
  }
  return plan;
}

}  // namespace glider::forecast
