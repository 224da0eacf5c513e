// SPDX-License-Identifier: Apache-2.0
// glider-shore: the shore station a glider calls at each surfacing (RUDICS
// over TCP), and the pilot's commands to queue work for its next call and to
// see where things stand. docs/comms.md, "Shore station".
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider_folders.hpp"
#include "received_files.hpp"
#include "shore_server.hpp"
#include "surface_dialog.hpp"
#include "surfacing_event.hpp"
#include "web/console_cli.hpp"
#include "web/console_server.hpp"

namespace fs = std::filesystem;
namespace shore = glider::shore;

namespace {

std::string default_root() {
  if (const char* root = std::getenv("GLIDER_SHORE_ROOT"); root != nullptr && *root != '\0') return root;
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return std::string(home) + "/glider-shore";
  return "glider-shore";
}

// A .ma/.mi is rehearsed before it is queued (docs/forecast.md): one the
// glider's loader refuses, or whose forecast aborts, is not queued unless
// `force`, and a forced one is journaled in logs/queue.journal.
void rehearse_before_queue(const fs::path& glider_dir, const fs::path& file, bool force) {
  const std::string ext = file.extension().string();
  if (ext != ".ma" && ext != ".mi") return;
  glider::forecast::Rehearsal r;
  try {
    r = glider::forecast::rehearse(glider_dir, file, {});
  } catch (const std::exception& e) {
    std::printf("not rehearsed: %s\n", e.what());
    return;
  }
  std::printf("rehearsal of %s: %s: %s\n", r.file.c_str(), r.verdict.c_str(), r.message.c_str());
  if (r.verdict == "ok") return;
  if (!force) {
    throw std::runtime_error(file.string() + ": not queued: " + r.verdict + ": " + r.message +
                             " (--force queues it anyway)");
  }
  const std::string line = glider::forecast::format_utc(static_cast<double>(std::time(nullptr))) + " * queued " +
                           r.file + " with --force: " + r.verdict + ": " + r.message + "\n";
  fs::create_directories(glider_dir / "logs");
  std::ofstream journal(glider_dir / "logs" / "queue.journal", std::ios::app);
  journal << line;
  if (!journal) throw std::runtime_error((glider_dir / "logs" / "queue.journal").string() + ": cannot write");
}

int queue_work(const fs::path& root, const std::string& glider, const std::vector<std::string>& files,
               const std::vector<std::string>& commands, bool force) {
  if (files.empty() && commands.empty()) {
    throw glider::cli::ToolError(glider::cli::kUsage, "queue: give a FILE or --command");
  }
  const shore::GliderFolders folders = shore::glider_folders(root, glider, true);
  for (const std::string& file : files) {
    const fs::path source(file);
    if (!fs::is_regular_file(source)) throw std::runtime_error(file + ": not a readable file");
    const std::string name = source.filename().string();
    if (name.empty() || name[0] == '.') throw std::runtime_error(file + ": a hidden file name cannot be sent");
    rehearse_before_queue(folders.base, source, force);
    shore::copy_file_atomically(source, folders.to_glider / name);
    std::printf("queued file %s for %s\n", name.c_str(), glider.c_str());
  }
  for (const std::string& command : commands) {
    shore::queue_command(folders, command);
    std::printf("queued command '%s' for %s\n", command.c_str(), glider.c_str());
  }
  return glider::cli::kOk;
}

nlohmann::json glider_status(const fs::path& root, const std::string& glider) {
  const shore::GliderFolders folders = shore::glider_folders(root, glider, false);
  nlohmann::json out{{"glider", glider}};
  fs::path last_event;
  if (fs::is_directory(folders.logs)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(folders.logs)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > 15 && name.compare(name.size() - 15, 15, ".surfacing.json") == 0 &&
          (last_event.empty() || entry.path().filename() > last_event.filename())) {
        last_event = entry.path();
      }
    }
  }
  out["last_surfacing"] = nullptr;
  if (!last_event.empty()) {
    std::ifstream in(last_event);
    const nlohmann::json event = nlohmann::json::parse(in, nullptr, false);
    if (!event.is_discarded()) {
      out["last_surfacing"] = {{"event", last_event.filename().string()},
                               {"call_start_utc", event.value("call_start_utc", "")},
                               {"reasons", event.value("reasons", nlohmann::json::array())},
                               {"gps", event.value("gps", nlohmann::json())},
                               {"end_reason", event.value("end_reason", "")},
                               {"files_received", event.value("files_received", nlohmann::json::array()).size()}};
    }
  }
  nlohmann::json files = nlohmann::json::array();
  for (const fs::path& file : shore::queued_files(folders)) files.push_back(file.filename().string());
  out["queued_files"] = files;
  out["queued_commands"] = fs::exists(folders.base) ? shore::queued_commands(folders) : std::vector<std::string>{};
  out["partial_files"] = shore::partial_receptions(folders);
  return out;
}

int show_status(const fs::path& root, bool json) {
  std::vector<std::string> gliders;
  if (fs::is_directory(root)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(root)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_directory() && name != "unidentified" && shore::valid_glider_name(name)) gliders.push_back(name);
    }
  }
  std::sort(gliders.begin(), gliders.end());
  nlohmann::json all = nlohmann::json::array();
  for (const std::string& glider : gliders) all.push_back(glider_status(root, glider));
  if (json) {
    std::printf("%s\n", all.dump(2).c_str());
    return glider::cli::kOk;
  }
  if (all.empty()) std::printf("no glider has called %s yet\n", root.c_str());
  for (const nlohmann::json& g : all) {
    std::printf("%s\n", g["glider"].get<std::string>().c_str());
    const nlohmann::json& last = g["last_surfacing"];
    if (last.is_null()) {
      std::printf("  last surfacing: none\n");
    } else {
      std::string where = "no GPS fix";
      if (last["gps"].is_object()) {
        char text[96];
        std::snprintf(text, sizeof text, "%.5f %.5f", last["gps"]["lat_deg"].get<double>(),
                      last["gps"]["lon_deg"].get<double>());
        where = text;
      }
      std::string reasons;
      for (const auto& reason : last["reasons"]) reasons += (reasons.empty() ? "" : "; ") + reason.get<std::string>();
      std::printf("  last surfacing: %s at %s, %zu files, %s%s%s\n", last["call_start_utc"].get<std::string>().c_str(),
                  where.c_str(), last["files_received"].get<std::size_t>(),
                  last["end_reason"].get<std::string>().c_str(), reasons.empty() ? "" : ", because: ", reasons.c_str());
    }
    std::printf("  queued commands: %zu, queued files: %zu, partial receptions: %zu\n", g["queued_commands"].size(),
                g["queued_files"].size(), g["partial_files"].size());
    for (const auto& c : g["queued_commands"]) std::printf("    command: %s\n", c.get<std::string>().c_str());
    for (const auto& f : g["queued_files"]) std::printf("    file: %s\n", f.get<std::string>().c_str());
  }
  return glider::cli::kOk;
}

int parse_dialog_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  shore::SurfaceReport report;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && line.back() == '\r') line.pop_back();
    shore::parse_dialog_line(line, report);
  }
  std::printf("%s", shore::surface_report_json(report).c_str());
  return glider::cli::kOk;
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-shore", "Shore station for Slocum-style gliders calling over RUDICS (TCP)");
  CLI::App& app = tool.app();
  app.require_subcommand(1);
  app.fallthrough();  // --root also after the subcommand
  std::string root = default_root();
  app.add_option("--root", root, "folder of the gliders' folders (default $GLIDER_SHORE_ROOT or ~/glider-shore)")
      ->capture_default_str();

  shore::ShoreConfig config;
  std::string port_file;
  std::string fetch = "*.sbd *.tbd";
  CLI::App* serve = app.add_subcommand("serve", "listen for gliders' calls (until SIGINT/SIGTERM)");
  serve->add_option("--listen", config.listen_address, "address to listen on")->capture_default_str();
  tool.add_integer(serve, "--port", config.port, 0, 65535, "", "TCP port (0: any free port, see --port-file)")
      ->capture_default_str();
  serve->add_option("--port-file", port_file, "write the port listened on to this file");
  tool.add_integer(serve, "--max-calls", config.max_calls, 1, 256, "", "calls served at once")->capture_default_str();
  serve->add_option("--fetch", fetch, "file patterns asked for with `send` at each call (empty: none)")
      ->capture_default_str();
  serve->add_flag("--resume", config.resume_mission, "type Ctrl-R (resume the mission) when the shore's work is done");
  serve->add_option("--cache", config.cache_dirs, "sensor-list cache folder for the CSV conversion (repeatable)");
  struct SecondsOption {
    const char* name;
    double* value;
    const char* help;
  };
  for (const SecondsOption& option :
       {SecondsOption{"--identify-timeout", &config.identify_timeout_s, "seconds for the glider to say its name"},
        SecondsOption{"--prompt-timeout", &config.prompt_timeout_s, "seconds for a GliderDOS prompt after a command"},
        SecondsOption{"--transfer-idle-timeout", &config.transfer_idle_timeout_s,
                      "seconds without a byte that end a Zmodem transfer"},
        SecondsOption{"--transfer-timeout", &config.transfer_timeout_s, "seconds for one Zmodem batch"},
        SecondsOption{"--linger", &config.linger_s, "seconds to keep the call open after the shore's work"},
        SecondsOption{"--call-timeout", &config.call_timeout_s, "seconds for a whole call"}}) {
    tool.add_number(serve, option.name, *option.value, {0.1, 86400.0, "s"}, option.help)->capture_default_str();
  }
  tool.add_integer(serve, "--max-line", config.max_line, 80, 1 << 20, "bytes",
                   "longest console line kept whole (bytes)")
      ->capture_default_str();

  shore::web::ConsoleOptions console;  // --http ...: the pilot's console (docs/console.md)
  shore::web::add_console_options(tool, serve, app, console);

  std::string glider;
  std::vector<std::string> files, commands;
  CLI::App* queue = app.add_subcommand("queue", "queue files and console commands for a glider's next call");
  queue->add_option("GLIDER", glider, "the glider's name (Vehicle Name)")->required();
  queue->add_option("FILE", files, "files to send (.ma, .mi, ...)");
  queue->add_option("--command", commands, "a console command, e.g. \"put u_x 3\" (repeatable, sent in order)");
  bool force = false;
  queue->add_flag("--force", force,
                  "queue a .ma/.mi even if its rehearsal aborts or the loader refuses it (journaled)");

  bool json = false;
  CLI::App* status = app.add_subcommand("status", "the gliders: last surfacing, queued work");
  status->add_flag("--json", json, "JSON instead of text");

  std::string dialog_file;
  CLI::App* dialog = app.add_subcommand("dialog", "parse a saved surface dialog (or journal-free transcript) to JSON");
  dialog->add_option("FILE", dialog_file, "text file")->required();

  return tool.run(argc, argv, [&]() -> int {
    if (*serve) {
      config.root = root;
      config.fetch.clear();
      std::istringstream words(fetch);
      for (std::string word; words >> word;) config.fetch.push_back(word);
      std::unique_ptr<shore::web::ConsoleServer> console_server;
      if (!console.http.empty()) {
        shore::web::finish_console_config(console, root, argv[0]);
        console_server = std::make_unique<shore::web::ConsoleServer>(console.config);
        console_server->start();
      }
      shore::serve_forever(config, port_file);
      if (console_server) console_server->stop();
      return glider::cli::kOk;
    }
    if (*queue) return queue_work(root, glider, files, commands, force);
    if (*status) return show_status(root, json);
    if (*console.user) return shore::web::run_user_add(console, root);
    return parse_dialog_file(dialog_file);
  });
}
