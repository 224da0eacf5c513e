// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `glider-shore serve` is told (docs/comms.md, "Shore station").
#include <filesystem>
#include <string>
#include <vector>

namespace glider::shore {

struct ShoreConfig {
  std::filesystem::path root;
  std::string listen_address = "127.0.0.1";  // loopback unless configured
  unsigned port = 6565;
  int max_calls = 8;                  // calls served at once; more are refused at once
  double identify_timeout_s = 120.0;  // connect -> "Vehicle Name:" seen
  double prompt_timeout_s = 120.0;    // a command -> the next GliderDOS prompt
  double transfer_idle_timeout_s = 60.0;
  double transfer_timeout_s = 3600.0;                   // one Zmodem batch
  double linger_s = 600.0;                              // after the shore's work: wait for the glider to hang up
  double call_timeout_s = 7200.0;                       // a whole call
  std::vector<std::string> fetch = {"*.sbd", "*.tbd"};  // `send` patterns asked at each call
  bool resume_mission = false;                          // type Ctrl-R when the shore's work is done
  std::vector<std::filesystem::path> cache_dirs;        // sensor-list caches for the CSV conversion
  std::size_t max_line = 4096;
  std::string sz_program = "sz", rz_program = "rz";
};

}  // namespace glider::shore
