// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/mission_reload.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <new>
#include <system_error>

#include "glider/firmware/app/reload_arena.hpp"
#include "glider/firmware/comms/directory_entries.hpp"

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

bool is_directory_entry(int dir, const char* name, unsigned char type) {
  if (type != DT_UNKNOWN) return type == DT_DIR;
  struct stat st {};
  return ::fstatat(dir, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode);
}

// fs::remove_all without the heap (it reads folders with opendir, which
// mallocs): the staging folder, two levels of plain files. Entries go while
// the folder is read, so it is read again until nothing is left.
void remove_tree(const fs::path& path, int depth = 0) {
  constexpr int kMaxDepth = 8;
  constexpr int kMaxPasses = 64;
  for (int pass = 0; pass < kMaxPasses && depth <= kMaxDepth; ++pass) {
    bool removed = false;
    const bool opened =
        comms::for_each_directory_entry(path.c_str(), [&](int dir, const char* name, unsigned char type) {
          if (is_directory_entry(dir, name, type)) {
            remove_tree(path / name, depth + 1);
          } else {
            ::unlinkat(dir, name, 0);
          }
          removed = true;
          return true;
        });
    if (!opened || !removed) break;
  }
  ::rmdir(path.c_str());
}

// Copies `from` to `to` by a temporary name and a rename: a reader never
// sees half a file.
void publish_copy(const fs::path& from, const fs::path& to) {
  std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely (-Wrestrict) on that
  name += to.filename().string();
  name += ".tmp";
  const fs::path temp = to.parent_path() / name;
  fs::copy_file(from, temp, fs::copy_options::overwrite_existing);
  fs::rename(temp, to);
}

// Written without the heap: the arena may be what ran out.
void refuse_out_of_arena(const char* what, char* refusal, std::size_t size) {
  std::snprintf(refusal, size,
                "%s needs more than the reload arena's %zu bytes; the old plan is flown (docs/comms.md, "
                "Control-F and the heap)",
                what, reload_arena::capacity());
}

}  // namespace

bool MissionFileReloader::install(FlightSoftware& flight, const char* received_path, char* refusal, std::size_t size) {
  // First: everything below is freed before it ends (reload_arena.hpp).
  const reload_arena::Scope arena;
  try {
    std::string why;
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
      remove_tree(stage);
      fs::create_directories(stage / "missions");
      fs::create_directories(stage / "mafiles");
      fs::copy_file(mission_, stage / "missions" / mission_.filename());
      const fs::path mafiles = mafiles_folder(mission_);
      comms::for_each_directory_entry(mafiles.c_str(), [&](int dir, const char* name, unsigned char /*type*/) {
        struct stat st {};
        const fs::path file = mafiles / name;
        if (file.extension() == ".ma" && ::fstatat(dir, name, &st, 0) == 0 && S_ISREG(st.st_mode)) {
          fs::copy_file(file, stage / "mafiles" / name);
        }
        return true;
      });
      const fs::path staged = stage / (ext == ".mi" ? "missions" : "mafiles") / received.filename();
      fs::copy_file(received, staged, fs::copy_options::overwrite_existing);
      const PreparedMission prepared = prepare_mission(stage / "missions" / mission_.filename(), setup_, options_);
      if (prepared.config) {
        flight.replace_plan(prepared.config->plan);
        publish_copy(received, ext == ".mi" ? mission_ : mafiles / received.filename());
        remove_tree(stage);
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
      remove_tree(stage);
    }
    std::snprintf(refusal, size, "%s", why.empty() ? "mission file refused" : why.c_str());
  } catch (const std::bad_alloc&) {
    refuse_out_of_arena("the upload's check", refusal, size);
  } catch (const std::exception& e) {
    std::snprintf(refusal, size, "%s", e.what());
  }
  return false;
}

bool MissionFileReloader::reread(FlightSoftware& flight, char* refusal, std::size_t size) {
  // First: everything below is freed before it ends (reload_arena.hpp).
  const reload_arena::Scope arena;
  try {
    std::string why;
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
    std::snprintf(refusal, size, "%s", why.empty() ? "mission refused" : why.c_str());
  } catch (const std::bad_alloc&) {
    refuse_out_of_arena("the mission re-read", refusal, size);
  } catch (const std::exception& e) {
    std::snprintf(refusal, size, "%s", e.what());
  }
  return false;
}

}  // namespace glider::fw::app
