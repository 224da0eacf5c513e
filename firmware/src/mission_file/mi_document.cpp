// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/mission_file/mi_document.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

#include "glider/config/value_limits.hpp"

namespace glider::fw::mission_file {
namespace {

// The whole file, read with POSIX calls: no stdio FILE, whose buffer is
// glibc's own malloc (a mission re-read in flight takes its memory from the
// reload arena instead of the heap: glider/firmware/app/reload_arena.hpp).
bool read_whole_file(const std::filesystem::path& path, std::string& text) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      return n == 0;
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

std::string strip_comment(const std::string& s) {
  const auto hash = s.find('#');
  return trim(hash == std::string::npos ? s : s.substr(0, hash));
}

bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;
  const auto result = std::from_chars(first, last, value);
  // from_chars reads "nan" and "inf": no file value may be either.
  return result.ec == std::errc() && result.ptr == last && std::isfinite(value);
}

// Calls fn(where, line, lower-case line) for every line that is not blank
// once its comment is removed; returns the number of lines read.
template <typename Fn>
int for_each_line(std::istream& in, const std::string& file, Fn&& fn) {
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const std::string line = strip_comment(raw);
    if (!line.empty()) fn(SourceLocation{file, number}, line, lower(line));
  }
  return number;
}

struct Reader {
  MiDocument& doc;

  void error(const SourceLocation& at, std::string message) {
    doc.diagnostics.push_back({Severity::kError, at.file, at.line, std::move(message)});
  }

  // "name(unit) value" after the "b_arg:" or "sensor:" keyword.
  bool parse_arg(const std::string& body, const SourceLocation& at, MiArg& arg) {
    const auto open = body.find('(');
    const auto close = body.find(')', open == std::string::npos ? 0 : open);
    if (open == std::string::npos || close == std::string::npos) {
      error(at, "expected 'name(unit) value', got '" + config::shorten(body) + "'");
      return false;
    }
    arg.name = lower(trim(body.substr(0, open)));
    arg.unit = trim(body.substr(open + 1, close - open - 1));
    const std::string value = trim(body.substr(close + 1));
    if (arg.name.empty()) {
      error(at, "argument without a name");
      return false;
    }
    if (!parse_number(value, arg.value)) {
      error(at, "value of " + config::shorten(arg.name) + " is not a finite number: '" + config::shorten(value) + "'");
      return false;
    }
    arg.where = at;
    return true;
  }

  // An argument file: behavior_name=..., <start:b_arg> ... <end:b_arg>,
  // <start:waypoints> ... <end:waypoints>.
  void read_ma(const std::filesystem::path& path, MiBehavior& behavior, const SourceLocation& included_at) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      error(included_at, "argument file " + path.string() + " is not a regular file (a FIFO or device never ends)");
      return;
    }
    std::string text;
    if (!read_whole_file(path, text)) {
      error(included_at, "cannot open argument file " + path.string());
      return;
    }
    std::istringstream in(text);
    read_ma_stream(in, path.filename().string(), behavior, included_at);
  }

  // The argument file's text (from disk, or from memory: parse_ma_text).
  void read_ma_stream(std::istream& in, const std::string& file, MiBehavior& behavior,
                      const SourceLocation& included_at) {
    enum class Section { kNone, kArgs, kWaypoints } section = Section::kNone;
    bool named = false;
    const int lines =
        for_each_line(in, file, [&](const SourceLocation& at, const std::string& line, const std::string& key) {
          if (key.rfind("behavior_name", 0) == 0) {
            const auto eq = line.find('=');
            const std::string name = eq == std::string::npos ? "" : lower(trim(line.substr(eq + 1)));
            if (name != behavior.name) {
              error(at, "argument file is for behavior '" + config::shorten(name) + "', included by '" + behavior.name +
                            "' at " + included_at.file + ":" + std::to_string(included_at.line));
            }
            named = true;
          } else if (key == "<start:b_arg>") {
            section = Section::kArgs;
          } else if (key == "<start:waypoints>") {
            section = Section::kWaypoints;
            behavior.has_waypoint_section = true;
          } else if (key == "<end:b_arg>" || key == "<end:waypoints>") {
            section = Section::kNone;
          } else if (section == Section::kArgs && key.rfind("b_arg:", 0) == 0) {
            MiArg arg;
            if (parse_arg(trim(line.substr(6)), at, arg)) behavior.args.push_back(arg);
          } else if (section == Section::kWaypoints) {
            std::istringstream fields(line);
            std::string lon, lat, extra;
            MiWaypoint w;
            fields >> lon >> lat;
            if (!parse_number(lon, w.lon_nmea) || !parse_number(lat, w.lat_nmea) || (fields >> extra)) {
              error(at, "waypoint must be 'lon lat' (finite numbers) in NMEA ddmm.mmm, got '" + config::shorten(line) +
                            "'");
              return;
            }
            w.where = at;
            behavior.waypoints.push_back(w);
          } else {
            error(at, "unexpected line in argument file: '" + config::shorten(line) + "'");
          }
        });
    if (!named) error({file, 0}, "argument file has no behavior_name= line");
    if (section != Section::kNone) error({file, lines}, "section not closed with <end:...>");
  }

  void include(const std::filesystem::path& dir, MiBehavior& behavior, const MiArg& arg) {
    if (arg.value < 0.0) return;  // < 0: arguments from this file only (Slocum)
    const std::optional<std::int64_t> index = config::whole_number(arg.value, 0, 99);
    if (!index) {
      error(arg.where, "args_from_file: value " + config::show_value(arg.value) +
                           " is outside the allowed range [0, 99] (a whole number: NN of the .ma file)");
      return;
    }
    char number[16];
    std::snprintf(number, sizeof(number), "%02d", static_cast<int>(*index));
    const std::string file = behavior.name.substr(0, 6) + number + ".ma";
    for (const auto& candidate : {dir / "mafiles" / file, dir / ".." / "mafiles" / file, dir / file}) {
      std::error_code ec;
      if (std::filesystem::exists(candidate, ec)) {
        read_ma(candidate, behavior, arg.where);
        return;
      }
    }
    error(arg.where,
          "argument file " + file + " not found (looked in mafiles/ and ../mafiles/ of " + dir.string() + ")");
  }

  void read_mi(std::istream& in, const std::string& file, const std::filesystem::path& dir) {
    MiBehavior* current = nullptr;
    for_each_line(in, file, [&](const SourceLocation& at, const std::string& line, const std::string& key) {
      if (key.rfind("behavior:", 0) == 0) {
        doc.behaviors.push_back({lower(trim(line.substr(9))), at, {}, {}, false});
        current = &doc.behaviors.back();
        if (current->name.empty()) error(at, "behavior without a name");
      } else if (key.rfind("b_arg:", 0) == 0) {
        if (current == nullptr) {
          error(at, "b_arg outside a behavior block");
          return;
        }
        MiArg arg;
        if (!parse_arg(trim(line.substr(6)), at, arg)) return;
        if (arg.name == "args_from_file") {
          include(dir, *current, arg);
        } else {
          current->args.push_back(arg);
        }
      } else if (key.rfind("sensor:", 0) == 0) {
        MiArg arg;
        if (parse_arg(trim(line.substr(7)), at, arg)) doc.sensors.push_back(arg);
      } else {
        error(at, "expected 'behavior:', 'b_arg:' or 'sensor:', got '" + config::shorten(line) + "'");
      }
    });
  }
};

}  // namespace

std::string Diagnostic::text() const {
  // Appended piece by piece (GCC 12 warns falsely, -Wrestrict, on operator+ chains).
  std::string out;
  out.reserve(file.size() + message.size() + 24);
  out.append(file);
  if (line > 0) {
    out.push_back(':');
    out.append(std::to_string(line));
  }
  out.append(severity == Severity::kError ? ": error: " : ": warning: ");
  out.append(message);
  return out;
}

bool MiDocument::has_errors() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::kError; });
}

MiDocument parse_mi_text(const std::string& text, const std::string& file_name,
                         const std::filesystem::path& source_dir) {
  MiDocument doc;
  std::istringstream in(text);
  Reader{doc}.read_mi(in, file_name, source_dir);
  return doc;
}

MiDocument parse_ma_text(const std::string& text, const std::string& file_name, const std::string& behavior_name) {
  MiDocument doc;
  MiBehavior behavior;
  behavior.name = behavior_name;
  behavior.where = {file_name, 0};
  std::istringstream in(text);
  Reader{doc}.read_ma_stream(in, file_name, behavior, behavior.where);
  doc.behaviors.push_back(std::move(behavior));
  return doc;
}

MiDocument read_mi_file(const std::filesystem::path& path) {
  MiDocument doc;
  // A FIFO or a device would block the read forever (or never end): refused.
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    doc.diagnostics.push_back(
        {Severity::kError, path.string(), 0, "not a regular file (a FIFO, device or directory cannot be a mission)"});
    return doc;
  }
  std::string text;
  if (!read_whole_file(path, text)) {
    doc.diagnostics.push_back({Severity::kError, path.string(), 0, "cannot open mission file"});
    return doc;
  }
  std::istringstream in(text);
  Reader{doc}.read_mi(in, path.filename().string(), path.parent_path());
  return doc;
}

}  // namespace glider::fw::mission_file
