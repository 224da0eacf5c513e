// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Zmodem transfer over the call, done by Debian's lrzsz (sz/rz) run as a
// child process: the shore pumps bytes between the socket and the child's
// stdin/stdout, so it sees the end of the call (carrier lost) at once, bounds
// the transfer in time and counts its bytes. rz runs in the glider's
// .incoming/ folder; what it wrote is published only when complete.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glider::shore {

struct ZmodemRun {
  int exit_code = -1;         // the child's exit status (128 + signal when killed)
  bool carrier_lost = false;  // the glider hung up (socket closed) during the transfer
  bool timed_out = false;     // no byte either way for the idle limit, or the total limit passed
  bool stopped = false;       // the shore is shutting down
  std::uint64_t bytes_from_glider = 0, bytes_to_glider = 0;
  std::string diagnostics;  // the child's stderr
  std::string leftover;     // read from the glider after the child had finished (console text again)
};

// Runs `argv` (sz/rz and its options) in `cwd` with the call as its stdin and
// stdout. `first_bytes` were already read from the socket (the start of the
// glider's Zmodem stream) and are given to the child first. `stop` ends it early.
ZmodemRun run_zmodem_child(const std::vector<std::string>& argv, const std::filesystem::path& cwd, int socket_fd,
                           const std::string& first_bytes, double idle_timeout_s, double total_timeout_s,
                           const std::atomic<bool>& stop);

// The files rz received completely, from its -v diagnostics: every
// "Receiving: NAME" followed by another one or by "Transfer complete".
std::vector<std::string> completed_receptions(const std::string& diagnostics);

}  // namespace glider::shore
