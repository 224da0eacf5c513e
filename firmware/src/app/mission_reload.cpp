// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/mission_reload.hpp"

#include <cstdio>
#include <exception>
#include <system_error>

namespace glider::fw::app {

namespace {

namespace fs = std::filesystem;

// The folder a Slocum mission's .ma files are read from (as mi_document
// looks for them: mafiles/ beside the .mi, ../mafiles/, the .mi's folder).
fs::path mafiles_folder(const fs::path& mission) {
  fs::path dir = mission.parent_path();
  for (const fs::path& candidate : {dir / "mafiles", dir / ".." / "mafiles"}) {
    if (fs::is_directory(candidate)) return candidate;
  }
  return dir;
}

// Copies `from` to `to` by a temporary name and a rename: a reader never
// sees half a file.
void publish_copy(const fs::path& from, const fs::path& to) {
  const fs::path temp = to.parent_path() / ("." + to.filename().string() + ".tmp");
  fs::copy_file(from, temp, fs::copy_options::overwrite_existing);
  fs::rename(temp, to);
}

}  // namespace

bool MissionFileReloader::install(FlightSoftware& flight, const char* received_path, char* refusal, std::size_t size) {
  std::string why;
  try {
    const fs::path received(received_path);
    const std::string ext = received.extension().string();
    if (mission_.extension() != ".mi") {
      why = received.filename().string() + ": the flown mission is not a Slocum .mi; uploads are not applied";
    } else if (ext == ".mi" && received.filename() != mission_.filename()) {
      why = received.filename().string() + ": not the flown mission (" + mission_.filename().string() +
            "); kept, not applied";
    } else {
      // The flown mission's files, staged, with the received one in its place.
      const fs::path stage = received.parent_path() / ".staging";
      fs::remove_all(stage);
      fs::create_directories(stage / "missions");
      fs::create_directories(stage / "mafiles");
      fs::copy_file(mission_, stage / "missions" / mission_.filename());
      const fs::path mafiles = mafiles_folder(mission_);
      for (const fs::directory_entry& entry : fs::directory_iterator(mafiles)) {
        if (entry.is_regular_file() && entry.path().extension() == ".ma") {
          fs::copy_file(entry.path(), stage / "mafiles" / entry.path().filename());
        }
      }
      const fs::path staged = stage / (ext == ".mi" ? "missions" : "mafiles") / received.filename();
      fs::copy_file(received, staged, fs::copy_options::overwrite_existing);
      const PreparedMission prepared = prepare_mission(stage / "missions" / mission_.filename(), setup_, options_);
      if (prepared.config) {
        flight.replace_plan(prepared.config->plan);
        publish_copy(received, ext == ".mi" ? mission_ : mafiles / received.filename());
        fs::remove_all(stage);
        return true;
      }
      for (const std::string& line : mission_messages(prepared, true)) {
        why = line;
        break;
      }
      if (why.empty()) why = prepared.refusal;
      // The staged path means nothing to the pilot: name the file as received.
      const std::string staged_text = staged.string();
      for (std::size_t at = why.find(staged_text); at != std::string::npos; at = why.find(staged_text)) {
        why.replace(at, staged_text.size(), received.filename().string());
      }
      fs::remove_all(stage);
    }
  } catch (const std::exception& e) {
    why = e.what();
  }
  std::snprintf(refusal, size, "%s", why.empty() ? "mission file refused" : why.c_str());
  return false;
}

bool MissionFileReloader::reread(FlightSoftware& flight, char* refusal, std::size_t size) {
  std::string why;
  try {
    const PreparedMission prepared = prepare_mission(mission_, setup_, options_);
    if (prepared.config) {
      flight.replace_plan(prepared.config->plan);
      return true;
    }
    // The first error names file:line, key, value and range.
    for (const std::string& line : mission_messages(prepared, true)) {
      why = line;
      break;
    }
    if (why.empty()) why = prepared.refusal;
  } catch (const std::exception& e) {
    why = e.what();
  }
  std::snprintf(refusal, size, "%s", why.empty() ? "mission refused" : why.c_str());
  return false;
}

}  // namespace glider::fw::app
