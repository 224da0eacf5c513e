// SPDX-License-Identifier: Apache-2.0
#include "console_actions.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../glider_folders.hpp"
#include "../surface_dialog.hpp"
#include "glider_reader.hpp"
#include "run_program.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

constexpr double kRehearsalTimeoutS = 60.0;

ActionResult refuse(int status, const std::string& message) { return {status, {{"ok", false}, {"error", message}}}; }

bool text_file(const std::string& content) {
  for (unsigned char c : content) {
    if (c != '\n' && c != '\r' && c != '\t' && (c < 0x20 || c > 0x7e)) return false;
  }
  return true;
}

// The rehearsal of CONTRACTS.md: exit 0 ok, 1 refused, 4 aborts, 2 usage; anything else is a failed rehearsal.
json rehearse(const ConsoleConfig& config, const fs::path& glider_dir, const fs::path& file) {
  if (config.forecast_program.empty()) {
    return {{"verdict", "not rehearsed"}, {"message", "glider-forecast was not found: queued without a rehearsal"}};
  }
  const ProgramResult run =
      run_program({config.forecast_program, "rehearse", "--glider-dir", glider_dir.string(), file.string(), "--json"},
                  kRehearsalTimeoutS);
  json result = json::parse(run.out, nullptr, false);
  if (!result.is_object()) {
    result = read_json(glider_dir / "forecast" / "rehearsals" / (file.filename().string() + ".json"));
  }
  if (!result.is_object()) {
    result = read_json(glider_dir / "forecast" / "rehearsals" / (file.stem().string() + ".json"));
  }
  if (!result.is_object()) result = json::object();
  result["exit_code"] = run.exit_code;
  if (run.timed_out) {
    result["verdict"] = "failed";
    result["message"] = "the rehearsal took longer than 60 s";
  } else if (run.exit_code == 0) {
    result["verdict"] = "ok";
  } else if (run.exit_code == 4) {
    result["verdict"] = "aborts";
  } else if (run.exit_code == 1) {
    result["verdict"] = "refused";
  } else {
    result["verdict"] = "failed";
  }
  if (!result.contains("message")) {  // its error (JSON mode), else the last line it wrote on stderr
    std::string why = result.value("error", "");
    if (why.empty()) {
      std::string err = run.err;
      while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
      why = err.substr(err.find_last_of('\n') == std::string::npos ? 0 : err.find_last_of('\n') + 1);
    }
    result["message"] =
        "glider-forecast rehearse exit " + std::to_string(run.exit_code) + (why.empty() ? "" : ": " + why);
  }
  return result;
}

json base_entry(const std::string& user, const std::string& action) {
  return {{"utc", format_utc(now_unix())}, {"user", user}, {"action", action}};
}

}  // namespace

bool valid_upload_name(const std::string& name) {
  if (name.size() < 4 || name.size() > 64 || name[0] == '.') return false;
  for (char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  const std::string ext = name.substr(name.size() - 3);
  return ext == ".ma" || ext == ".mi";
}

bool valid_command(const std::string& command) {
  if (command.empty() || command.size() > 128) return false;
  bool visible = false;
  for (unsigned char c : command) {
    if (c < 0x20 || c > 0x7e) return false;
    visible = visible || c != ' ';
  }
  return visible;
}

void journal_action(const ConsoleConfig& config, const std::string& glider, json entry) {
  const std::string line = entry.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  const fs::path path = config.root / glider / "actions.journal";
  // One write(2) with O_APPEND: lines of concurrent actions never interleave.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(path.string() + ": cannot write");
  const bool written = ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
  ::close(fd);
  if (!written) throw std::runtime_error(path.string() + ": cannot write");
}

ActionResult queue_file(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                        const std::string& name, const std::string& content, bool force) {
  if (!valid_upload_name(name)) {
    return refuse(400, "file name '" + name.substr(0, 80) +
                           "': a plain NAME.ma or NAME.mi of 4-64 letters, digits, '_', '-', '.' is allowed");
  }
  if (content.empty() || content.size() > config.max_upload_bytes) {
    return refuse(400, name + ": " + std::to_string(content.size()) + " bytes, allowed 1-" +
                           std::to_string(config.max_upload_bytes));
  }
  if (!text_file(content)) return refuse(400, name + ": not a text file (a .ma/.mi is printable ASCII)");
  const GliderFolders folders = glider_folders(config.root, glider, false);
  if (!fs::is_directory(folders.base)) return refuse(404, "no glider '" + glider + "' has called this shore");
  fs::create_directories(folders.to_glider);
  const fs::path staging = folders.base / ".staging";
  fs::create_directories(staging);
  const fs::path staged = staging / name;
  write_file_atomically(staged, content);
  json rehearsal = rehearse(config, folders.base, staged);
  const std::string verdict = rehearsal.value("verdict", "failed");
  const bool accepted = verdict == "ok" || verdict == "not rehearsed" || force;
  json entry = base_entry(user, "queue_file");
  entry["file"] = name;
  entry["bytes"] = content.size();
  entry["rehearsal"] = {{"verdict", verdict}, {"message", rehearsal.value("message", "")}};
  entry["forced"] = force && verdict != "ok" && verdict != "not rehearsed";
  entry["result"] = accepted ? "queued" : "not queued: the rehearsal says " + verdict;
  if (accepted) copy_file_atomically(staged, folders.to_glider / name);
  fs::remove(staged);
  journal_action(config, glider, entry);
  return {accepted ? 200 : 409, {{"ok", accepted}, {"action", entry}, {"rehearsal", rehearsal}}};
}

ActionResult queue_command_action(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                                  const std::string& command) {
  if (!valid_command(command)) {
    return refuse(400, "command: 1-128 printable ASCII characters are allowed (as the glider's console takes)");
  }
  const GliderFolders folders = glider_folders(config.root, glider, false);
  if (!fs::is_directory(folders.base)) return refuse(404, "no glider '" + glider + "' has called this shore");
  queue_command(folders, command);
  json entry = base_entry(user, "queue_command");
  entry["command"] = command;
  entry["result"] = "queued";
  journal_action(config, glider, entry);
  return {200, {{"ok", true}, {"action", entry}}};
}

ActionResult cancel_file(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                         const std::string& name) {
  if (!valid_upload_name(name)) return refuse(400, "file name '" + name.substr(0, 80) + "': not a queued .ma/.mi name");
  const GliderFolders folders = glider_folders(config.root, glider, false);
  const fs::path file = folders.to_glider / name;
  std::error_code error;
  if (!fs::is_regular_file(file) || !fs::remove(file, error) || error) {
    return refuse(404, name + " is not queued for " + glider + " (sent already?)");
  }
  json entry = base_entry(user, "cancel_file");
  entry["file"] = name;
  entry["result"] = "cancelled";
  journal_action(config, glider, entry);
  return {200, {{"ok", true}, {"action", entry}}};
}

ActionResult cancel_command(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                            std::size_t index, const std::string& command) {
  if (!valid_command(command)) return refuse(400, "command: not a queued command");
  const GliderFolders folders = glider_folders(config.root, glider, false);
  if (!fs::is_directory(folders.base) || !remove_command(folders, index, command)) {
    return refuse(404, "command '" + command + "' is not queued at position " + std::to_string(index + 1) + " for " +
                           glider + " (sent already?)");
  }
  json entry = base_entry(user, "cancel_command");
  entry["command"] = command;
  entry["result"] = "cancelled";
  journal_action(config, glider, entry);
  return {200, {{"ok", true}, {"action", entry}}};
}

std::string find_forecast_program(const std::string& given, const std::string& self_path) {
  if (!given.empty()) return given;
  std::error_code error;
  const fs::path self = fs::canonical(self_path, error);
  if (!error) {
    // Build tree: BUILD/tools/shore/station/glider-shore -> BUILD/tools/shore/forecast/glider-forecast;
    // installed: same folder.
    for (const fs::path& candidate :
         {self.parent_path().parent_path() / "forecast" / "glider-forecast", self.parent_path() / "glider-forecast"}) {
      if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
  }
  if (const char* path = std::getenv("PATH"); path != nullptr) {
    std::istringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');) {
      const fs::path candidate = fs::path(dir) / "glider-forecast";
      if (!dir.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
  }
  return "";
}

}  // namespace glider::shore::web
