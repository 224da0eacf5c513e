// SPDX-License-Identifier: Apache-2.0
#pragma once
// Slocum mission files, read as text: a `.mi` file of `sensor:` lines and
// `behavior:` blocks of `b_arg: name(unit) value` lines, and the `.ma`
// argument files a block pulls in with `b_arg: args_from_file(enum) N`
// (mafiles/<first 6 letters of the behaviour><NN>.ma, with <start:b_arg> and
// <start:waypoints> sections). This layer knows the syntax only; what the
// firmware makes of it is mission_loader.hpp. Init time: allocates, never
// throws; every problem becomes a Diagnostic with file and line.
#include <filesystem>
#include <string>
#include <vector>

namespace glider::fw::mission_file {

enum class Severity { kWarning, kError };

struct Diagnostic {
  Severity severity = Severity::kError;
  std::string file;
  int line = 0;  // 0: the file as a whole
  std::string message;
  // "file:line: error: message" (the compiler convention editors understand).
  std::string text() const;
};

struct SourceLocation {
  std::string file;
  int line = 0;
};

struct MiArg {
  std::string name;  // as written, e.g. "d_target_depth"
  std::string unit;  // inside the parentheses, e.g. "m"
  double value = 0.0;
  SourceLocation where;
};

struct MiWaypoint {
  double lon_nmea = 0.0;  // Slocum lists longitude first
  double lat_nmea = 0.0;
  SourceLocation where;
};

struct MiBehavior {
  std::string name;  // lower case
  SourceLocation where;
  std::vector<MiArg> args;  // the .mi's own and those of its .ma file, in order
  std::vector<MiWaypoint> waypoints;
  bool has_waypoint_section = false;
};

struct MiDocument {
  std::vector<MiArg> sensors;  // `sensor:` lines
  std::vector<MiBehavior> behaviors;
  std::vector<Diagnostic> diagnostics;
  bool has_errors() const;
};

// Reads a .mi file and the .ma files it includes. The .ma files are looked
// for in <dir>/mafiles, <dir>/../mafiles and <dir> (the glider's own
// layout is missions/ next to mafiles/).
MiDocument read_mi_file(const std::filesystem::path& path);

// The same from text (tests); `.ma` files are looked for next to `source_dir`.
MiDocument parse_mi_text(const std::string& text, const std::string& file_name,
                         const std::filesystem::path& source_dir);

// One argument file from text (tests, fuzzing): a document with one behavior
// `behavior_name` holding the file's arguments and waypoints, and its problems.
MiDocument parse_ma_text(const std::string& text, const std::string& file_name, const std::string& behavior_name);

}  // namespace glider::fw::mission_file
