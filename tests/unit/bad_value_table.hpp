// SPDX-License-Identifier: Apache-2.0
#pragma once
// The bad-value table's machinery, shared by every file format's test
// (tests/unit/test_value_limits.cpp: missions, vehicles, environments;
// tests/cli/test_board_limits.cpp: target and actuator boards): each number
// key of a format is set to NaN, +-inf, +-1e308, 0, -1 and an integer that
// overflows; a value outside the key's published range must be refused with
// file:line, the key, the value and the range.
#include <CppUTest/TestHarness.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/config/value_limits.hpp"

namespace glider::test::bad_values {

using config::ConfigError;
using config::KeyRange;

inline const char* const kOverflow = "99999999999999999999";  // > INT64_MAX, and a TOML parse error
inline const std::vector<std::string> kBadValues{"nan", "inf", "-inf", "1e308", "-1e308", "0", "-1", kOverflow};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

inline std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b);
}

// Sets `dotted = value` in a TOML text (replacing the key or adding it to its
// table); returns the text and, through `line`, the key's 1-based line.
inline std::string set_toml_key(const std::string& text, const std::string& dotted, const std::string& value,
                                int& line) {
  std::vector<std::string> lines = split_lines(text);
  const auto dot = dotted.rfind('.');
  const std::string table = dot == std::string::npos ? "" : dotted.substr(0, dot);
  const std::string name = dot == std::string::npos ? dotted : dotted.substr(dot + 1);
  std::size_t begin = 0;
  if (!table.empty()) {
    begin = lines.size();
    for (std::size_t i = 0; i < lines.size(); ++i) {
      // "[pump]   # comment" too: board files comment their tables.
      const std::string t = trimmed(lines[i]);
      const std::string header = "[" + table + "]";
      if (t.rfind(header, 0) != 0) continue;
      const std::string rest = trimmed(t.substr(header.size()));
      if (rest.empty() || rest[0] == '#') begin = i + 1;
    }
    if (begin == lines.size()) {
      lines.push_back("[" + table + "]");
      begin = lines.size();
    }
  }
  std::size_t end = begin;
  while (end < lines.size() && trimmed(lines[end]).rfind('[', 0) != 0) ++end;
  for (std::size_t i = begin; i < end; ++i) {
    const std::string t = trimmed(lines[i]);
    if (t.rfind(name, 0) == 0 && trimmed(t.substr(name.size())).rfind('=', 0) == 0) {
      lines[i] = name + " = " + value;
      line = static_cast<int>(i) + 1;
      return join_lines(lines);
    }
  }
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(begin), name + " = " + value);
  line = static_cast<int>(begin) + 1;
  return join_lines(lines);
}

// Tries every bad value on every key of one TOML format; returns the number of
// (key, value) cases tried.
inline int try_toml_format(const std::string& base, const std::vector<KeyRange>& keys,
                           const std::function<void(const std::string&)>& load,
                           const std::function<std::string(const KeyRange&, const std::string&)>& value_text) {
  load(base);  // the base text itself loads: refusals below are the value's doing
  int cases = 0;
  for (const KeyRange& key : keys) {
    for (const std::string& bad : kBadValues) {
      ++cases;
      int line = 0;
      const std::string text = set_toml_key(base, key.key, value_text(key, bad), line);
      const double value = std::strtod(bad.c_str(), nullptr);
      const bool accepted_by_range = glider::config::within(value, key.range) && bad != kOverflow;
      const std::string what = std::string(key.key) + " = " + bad;
      try {
        load(text);
        if (!accepted_by_range) FAIL(("accepted " + what).c_str());
      } catch (const ConfigError& error) {
        const std::string message = error.what();
        if (accepted_by_range) continue;  // documented: refused by a check between keys
        CHECK_TEXT(contains(message, "bad.toml:" + std::to_string(line) + ":"), (what + ": " + message).c_str());
        if (bad == kOverflow) continue;  // a TOML syntax error: the place is all there is
        CHECK_TEXT(contains(message, key.key), (what + ": " + message).c_str());
        CHECK_TEXT(contains(message, glider::config::show_value(value)), (what + ": " + message).c_str());
        CHECK_TEXT(contains(message, "allowed range"), (what + ": " + message).c_str());
      }
    }
  }
  return cases;
}

inline std::string scalar(const KeyRange&, const std::string& bad) { return bad; }

}  // namespace glider::test::bad_values
