// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one way a command-line program of the project starts, reports errors and
// exits. Every glider-* main is
//
//   int main(int argc, char** argv) {
//     glider::cli::Tool tool("glider-steady", "Steady glides of a vehicle model");
//     std::string vehicle = tool.vehicle_option();
//     ...add its own options to tool.app()...
//     return tool.run(argc, argv, [&] { ...; return glider::cli::kOk; });
//   }
//
// and so has the same exit codes, the same error text ("glider-steady: <what>"
// on stderr, or {"error": "<what>"} on stdout in --json mode) and the same
// shared options (--vehicle with the same default everywhere).
#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>

namespace glider::cli {

// Exit codes, the same for every program (README, "Exit codes").
enum ExitCode : int {
  kOk = 0,
  kError = 1,    // bad input (file, value) or a failure while running (device, I/O)
  kUsage = 2,    // bad command line: unknown option, missing argument, conflicting options
  kStopped = 3,  // a flight ended by an abort or stopped by a limit (sil, firmware, plant)
};

// Thrown from a tool's body for a failure that is the user's command line
// (kUsage) or another documented code; any other exception is kError.
class ToolError : public std::runtime_error {
 public:
  ToolError(ExitCode code, const std::string& what) : std::runtime_error(what), code_(code) {}
  [[nodiscard]] ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// The vehicle every tool uses when none is given: the SLOCUM WE01 of paper 000.
// Looked up as $GLIDER_BOARDS_DIR/vehicles/..., then the source tree's boards/,
// then the installed /usr/share/glider/boards/.
std::string default_vehicle_path();
// The boards/ directory the default files come from (same lookup).
std::string boards_dir();

// CLI::Range for a number: NaN passes every plain comparison, so CLI11's Range
// lets "nan" (and "inf" with an infinite bound) through. This one refuses a
// value that is not finite or not in [min, max], naming it and the range.
class FiniteRange : public CLI::Validator {
 public:
  FiniteRange(double min, double max);
};

class Tool {
 public:
  Tool(std::string name, const std::string& description);

  CLI::App& app() { return app_; }
  [[nodiscard]] const std::string& name() const { return name_; }

  // --vehicle FILE with the shared default (default_vehicle_path()).
  CLI::Option* add_vehicle_option(std::string& path);
  // --json: errors become {"error": "..."} on stdout too.
  CLI::Option* add_json_flag(bool& json);

  // Parses the command line and runs `body`; returns the exit code. Usage
  // errors print CLI11's message and exit kUsage; --help exits kOk; exceptions
  // from `body` are printed once as "<name>: <what>".
  int run(int argc, char** argv, const std::function<int()>& body);

  // Prints "<name>: <message>" (or the JSON error) and returns `code`.
  int fail(ExitCode code, const std::string& message) const;

 private:
  std::string name_;
  CLI::App app_;
  const bool* json_ = nullptr;
};

}  // namespace glider::cli
