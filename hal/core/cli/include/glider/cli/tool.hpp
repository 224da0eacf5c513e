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
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "glider/config/value_limits.hpp"

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

// The largest seed a --seed option takes (any non-negative 64-bit integer).
inline constexpr std::int64_t kMaxSeed = std::numeric_limits<std::int64_t>::max();

// A number option as the program declared it: what --list-numeric-options
// prints, so tests/cli can try every one with NaN, inf and out-of-range values.
struct NumberOption {
  const CLI::Option* option = nullptr;
  std::string command;               // "" for the program itself, else its subcommand
  std::vector<std::string> leading;  // arguments that must come first (positionals before it)
  bool integer = false;
  double min = 0.0;  // a number option's range
  double max = 0.0;
  std::int64_t integer_min = 0;  // an integer option's (exact: a double cannot hold INT64_MAX)
  std::int64_t integer_max = 0;
  std::string unit;
};

// The range check of a number option (text as typed): finite and in [min, max]
// ("--heading-deg: value nan is outside the allowed range [-360, 360] deg").
class NumberCheck : public CLI::Validator {
 public:
  explicit NumberCheck(const config::Range& range);
};
// The same for an integer option: a whole number in [min, max] ("1e308",
// "2.5" and "nan" refused, naming the range).
class IntegerCheck : public CLI::Validator {
 public:
  IntegerCheck(std::int64_t min, std::int64_t max, const std::string& unit);
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

  // Every number option of every program is declared through these: the
  // range is part of the declaration (as the file keys' tables in
  // glider/config/value_limits.hpp), the value is checked while the command
  // line is parsed (usage error, exit 2), and the option is listed by the
  // hidden --list-numeric-options. `command` is a subcommand (or app()).
  CLI::Option* add_number(const std::string& name, double& value, const config::Range& range, const std::string& help) {
    return add_number(&app_, name, value, range, help);
  }
  CLI::Option* add_number(CLI::App* command, const std::string& name, double& value, const config::Range& range,
                          const std::string& help);
  // A list of numbers (--window-m 10,35): each one checked.
  CLI::Option* add_numbers(const std::string& name, std::vector<double>& values, const config::Range& range,
                           const std::string& help);
  template <typename Int>
  CLI::Option* add_integer(const std::string& name, Int& value, std::int64_t min, std::int64_t max,
                           const std::string& unit, const std::string& help) {
    return add_integer(&app_, name, value, min, max, unit, help);
  }
  template <typename Int>
  CLI::Option* add_integer(CLI::App* command, const std::string& name, Int& value, std::int64_t min, std::int64_t max,
                           const std::string& unit, const std::string& help) {
    static_assert(std::is_integral_v<Int>, "add_integer is for integer options; add_number for the others");
    using Limits = std::numeric_limits<Int>;
    if (min < static_cast<std::int64_t>(Limits::min()) ||
        static_cast<std::uint64_t>(max) > static_cast<std::uint64_t>(Limits::max())) {
      throw std::logic_error(name + ": range does not fit the option's integer type");
    }
    CLI::Option* option = command->add_option(name, value, help)->check(IntegerCheck(min, max, unit));
    record(command, option, NumberOption{option, {}, {}, true, 0.0, 0.0, min, max, unit});
    return option;
  }
  // Arguments the test must give before `option` (a positional's earlier positionals).
  void set_leading(const CLI::Option* option, std::vector<std::string> leading);

  // Parses the command line and runs `body`; returns the exit code. Usage
  // errors print CLI11's message and exit kUsage; --help exits kOk; exceptions
  // from `body` are printed once as "<name>: <what>".
  int run(int argc, char** argv, const std::function<int()>& body);

  // Prints "<name>: <message>" (or the JSON error) and returns `code`.
  int fail(ExitCode code, const std::string& message) const;

 private:
  void record(CLI::App* command, const CLI::Option* option, NumberOption number);
  // --list-numeric-options: the table above as JSON, plus any number option
  // declared without a range (the test fails on those).
  [[nodiscard]] std::string numeric_options_json();

  std::string name_;
  CLI::App app_;
  std::vector<NumberOption> numbers_;
  const bool* json_ = nullptr;
};

}  // namespace glider::cli
