// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs a program (no shell) with a deadline and returns its exit status and
// standard output and error (at most 1 MiB each kept); killed at the deadline.
#include <string>
#include <vector>

namespace glider::shore::web {

struct ProgramResult {
  int exit_code = -1;  // -1: could not start, killed, or signalled
  bool timed_out = false;
  std::string out, err;
};

ProgramResult run_program(const std::vector<std::string>& argv, double timeout_s);

}  // namespace glider::shore::web
