// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `glider-shore serve --http ...` is told (docs/console.md).
#include <cstddef>
#include <filesystem>
#include <string>

namespace glider::shore::web {

struct ConsoleConfig {
  std::filesystem::path root;  // the shore's root (one folder per glider)
  std::string address = "127.0.0.1";
  unsigned port = 0;
  std::string port_file;                // the port actually bound, once listening
  std::filesystem::path users_file;     // accounts; needed off loopback or with force_auth
  bool force_auth = false;              // --http-auth: log in even on loopback
  double session_ttl_s = 8 * 3600.0;    // a login lasts this long
  std::filesystem::path sessions_file;  // logins kept across a restart (empty: in memory only)
  std::string local_user;               // who acts on loopback without login (journaled)
  std::filesystem::path web_dir;        // the pages (static/)
  std::filesystem::path leaflet_dir;    // Debian's libjs-leaflet
  std::string forecast_program;         // glider-forecast, for rehearsals ("" = not found)
  std::size_t max_upload_bytes = 256 * 1024;
  int threads = 256;      // HTTP worker threads (each event stream holds one)
  int max_streams = 100;  // event streams at once; more get 503
  // Alerts (docs/console.md, "Alerts").
  std::string notify_command;    // run through /bin/sh -c with GLIDER_ALERT_* in the environment
  std::string escalate_command;  // empty: the notify command with GLIDER_ALERT_LEVEL=escalate
  double missed_call_margin_s = 1800.0;
  double surface_limit_s = 3600.0;
  double surface_gap_s = 2400.0;  // calls closer than this are one stay at the surface
  double escalate_after_s = 1800.0;
  double repeat_s = 900.0;
  double tick_s = 0.5;  // how often the folders are looked at
};

bool is_ip_address(const std::string& address);  // an IPv4 or IPv6 literal
bool is_loopback(const std::string& address);    // 127.0.0.0/8 or ::1

}  // namespace glider::shore::web
