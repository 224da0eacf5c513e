// SPDX-License-Identifier: Apache-2.0
#include "console_cli.hpp"

#include <termios.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "console_actions.hpp"
#include "user_accounts.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;

void add_console_options(glider::cli::Tool& tool, CLI::App* serve, CLI::App& app, ConsoleOptions& o) {
  ConsoleConfig& c = o.config;
  serve->add_option("--http", o.http,
                    "serve the pilot's console on ADDR:PORT (e.g. 127.0.0.1:8080; port 0 = any free port); "
                    "off unless given; any address but loopback needs --users (docs/console.md)");
  serve->add_option("--http-port-file", c.port_file, "write the console's port to this file");
  serve->add_option("--users", o.users_file, "console accounts file (default ROOT/console.users)");
  serve->add_flag("--http-auth", c.force_auth, "require a login on loopback too");
  serve->add_option("--sessions", o.sessions_file,
                    "logins kept across a restart (default ROOT/console.sessions; cookies stored as SHA-256)");
  serve->add_option("--notify", c.notify_command,
                    "alert command, run by /bin/sh -c with GLIDER_ALERT_ID/GLIDER/KIND/LEVEL/MESSAGE/CHECK set");
  serve->add_option("--escalate", c.escalate_command, "escalation command (default: --notify with LEVEL=escalate)");
  serve->add_option("--forecast-program", c.forecast_program,
                    "rehearsal program (default: glider-forecast beside glider-shore, or on PATH)");
  serve->add_option("--web-dir", c.web_dir, "the console's pages (default: the source tree's, else installed)");
  serve->add_option("--leaflet-dir", c.leaflet_dir, "Leaflet (default /usr/share/javascript/leaflet)")
      ->capture_default_str();
  struct Seconds {
    const char* name;
    double* value;
    double min, max;
    const char* help;
  };
  for (const Seconds& s :
       {Seconds{"--session-ttl", &c.session_ttl_s, 1.0, 7 * 86400.0, "seconds a login lasts"},
        Seconds{"--missed-call-margin", &c.missed_call_margin_s, 0.0, 7 * 86400.0,
                "seconds after the expected call (forecast p90) before a missed-call alert"},
        Seconds{"--surface-limit", &c.surface_limit_s, 1.0, 7 * 86400.0, "seconds at the surface before an alert"},
        Seconds{"--escalate-after", &c.escalate_after_s, 1.0, 7 * 86400.0,
                "seconds an alert may stay unacknowledged before it is escalated"},
        Seconds{"--alert-repeat", &c.repeat_s, 1.0, 7 * 86400.0, "seconds between repeats of an unacknowledged alert"},
        Seconds{"--http-tick", &c.tick_s, 0.05, 60.0, "seconds between looks at the folders"}}) {
    tool.add_number(serve, s.name, *s.value, {s.min, s.max, "s"}, s.help)->capture_default_str();
  }
  tool.add_integer(serve, "--max-upload", c.max_upload_bytes, 1024, 16 << 20, "bytes",
                   "largest .ma/.mi accepted from the page")
      ->capture_default_str();
  tool.add_integer(serve, "--http-threads", c.threads, 8, 1024, "", "HTTP worker threads")->capture_default_str();
  tool.add_integer(serve, "--max-streams", c.max_streams, 1, 1000, "", "event streams at once (each holds a thread)")
      ->capture_default_str();

  o.user = app.add_subcommand("user", "console accounts: user add NAME --role pilot|viewer (password on stdin)");
  CLI::App* add = o.user->add_subcommand("add", "add or replace a user")->fallthrough();
  o.user->require_subcommand(1);
  add->add_option("NAME", o.user_name, "user name (1-32 of A-Z a-z 0-9 _ . -)")->required();
  add->add_option("--role", o.role, "pilot (may act) or viewer")
      ->check(CLI::IsMember({"pilot", "viewer"}))
      ->capture_default_str();
  o.user->add_option("--users", o.users_file, "accounts file (default ROOT/console.users)");
  add->add_option("--users", o.users_file, "accounts file (default ROOT/console.users)");
}

void finish_console_config(ConsoleOptions& o, const std::string& root, const std::string& self_path) {
  ConsoleConfig& c = o.config;
  c.root = root;
  c.users_file = o.users_file.empty() ? fs::path(root) / "console.users" : fs::path(o.users_file);
  c.sessions_file = o.sessions_file.empty() ? fs::path(root) / "console.sessions" : fs::path(o.sessions_file);
  const std::size_t colon = o.http.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    throw glider::cli::ToolError(glider::cli::kUsage, "--http " + o.http + ": give ADDR:PORT, e.g. 127.0.0.1:8080");
  }
  c.address = o.http.substr(0, colon);
  if (c.address.size() > 2 && c.address.front() == '[' && c.address.back() == ']') {
    c.address = c.address.substr(1, c.address.size() - 2);
  }
  const std::string port = o.http.substr(colon + 1);
  if (port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(port) > 65535) {
    throw glider::cli::ToolError(glider::cli::kUsage,
                                 "--http " + o.http + ": port '" + port + "' is outside the allowed range [0, 65535]");
  }
  c.port = static_cast<unsigned>(std::stoul(port));
  if (!is_ip_address(c.address)) {
    throw glider::cli::ToolError(glider::cli::kUsage, "--http " + o.http + ": '" + c.address +
                                                          "' is not an IPv4 or IPv6 address (e.g. 127.0.0.1, [::1])");
  }
  if (!is_loopback(c.address) || c.force_auth) {
    if (!fs::is_regular_file(c.users_file)) {
      throw glider::cli::ToolError(glider::cli::kUsage,
                                   "--http " + o.http + (c.force_auth ? " with --http-auth" : " is off loopback") +
                                       ": every request then needs a login, and " + c.users_file.string() +
                                       " does not exist (glider-shore user add NAME --role pilot)");
    }
  }
  if (c.web_dir.empty()) {
    c.web_dir = GLIDER_CONSOLE_SOURCE_WEB_DIR;  // the source tree's pages, else the installed ones
    if (!fs::is_directory(c.web_dir)) c.web_dir = GLIDER_CONSOLE_INSTALLED_WEB_DIR;
  }
  if (c.leaflet_dir.empty()) c.leaflet_dir = "/usr/share/javascript/leaflet";
  c.forecast_program = find_forecast_program(c.forecast_program, self_path);
  if (c.local_user.empty()) {
    const char* user = std::getenv("USER");
    c.local_user = user != nullptr && *user != '\0' ? std::string("local:") + user : "local";
  }
}

int run_user_add(ConsoleOptions& o, const std::string& root) {
  const fs::path file = o.users_file.empty() ? fs::path(root) / "console.users" : fs::path(o.users_file);
  const bool terminal = ::isatty(STDIN_FILENO) != 0;
  termios saved{};
  if (terminal) {
    std::fprintf(stderr, "password for %s (8 characters or more): ", o.user_name.c_str());
    ::tcgetattr(STDIN_FILENO, &saved);
    termios quiet = saved;
    quiet.c_lflag &= ~static_cast<tcflag_t>(ECHO);
    ::tcsetattr(STDIN_FILENO, TCSANOW, &quiet);
  }
  std::string password;
  std::getline(std::cin, password);
  if (terminal) {
    ::tcsetattr(STDIN_FILENO, TCSANOW, &saved);
    std::fprintf(stderr, "\n");
  }
  if (!password.empty() && password.back() == '\r') password.pop_back();
  fs::create_directories(file.parent_path().empty() ? fs::path(".") : file.parent_path());
  add_account(file, o.user_name, o.role, password);
  std::printf("user %s (%s) written to %s\n", o.user_name.c_str(), o.role.c_str(), file.c_str());
  return glider::cli::kOk;
}

}  // namespace glider::shore::web
