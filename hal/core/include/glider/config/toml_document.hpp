// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading the project's TOML configuration files (vehicles, missions, boards)
// with errors that name the file, the line and the problem. Init-time only:
// this throws and allocates, the flight loop never calls it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glider/config/value_limits.hpp"

namespace glider::config {

// "path:line:column: problem" (line/column omitted when not known).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TomlDocument {
 public:
  static TomlDocument load(const std::filesystem::path& path);
  static TomlDocument parse(std::string_view text, const std::string& source_name);

  TomlDocument(TomlDocument&&) noexcept;
  TomlDocument& operator=(TomlDocument&&) noexcept;
  ~TomlDocument();

  const std::string& source() const { return source_; }

  bool has(std::string_view dotted_key) const;
  double number(std::string_view dotted_key) const;
  double number_or(std::string_view dotted_key, double fallback) const;
  std::int64_t integer(std::string_view dotted_key) const;
  std::int64_t integer_or(std::string_view dotted_key, std::int64_t fallback) const;
  // An array of numbers (integers accepted); empty if the key is absent.
  std::vector<double> numbers_or_empty(std::string_view dotted_key) const;
  // The same, refused with file:line:column, key, value and range unless
  // finite and inside `range` (value_limits.hpp). Every number the vehicle
  // or a tool acts on is read through these.
  double number(std::string_view dotted_key, const Range& range) const;
  double number_or(std::string_view dotted_key, double fallback, const Range& range) const;
  std::int64_t integer(std::string_view dotted_key, std::int64_t min, std::int64_t max) const;
  std::int64_t integer_or(std::string_view dotted_key, std::int64_t fallback, std::int64_t min, std::int64_t max) const;
  std::vector<double> numbers_or_empty(std::string_view dotted_key, const Range& range) const;
  bool boolean_or(std::string_view dotted_key, bool fallback) const;
  std::string string(std::string_view dotted_key) const;
  std::string string_or(std::string_view dotted_key, std::string fallback) const;

  // Every leaf key of the document that no accessor has asked for is a typo
  // or an unsupported setting: report the first one with its line.
  void reject_unknown_keys() const;
  // The same for the keys under `table.` only (a table one reader owns, as
  // a vehicle file's [fitted]: `ruder = false` must not keep the rudder).
  void reject_unknown_keys_in(std::string_view table) const;
  // Keys under `table.` belong to another reader of the same file (e.g. the
  // [fitted] table of a vehicle file, read by the firmware): reject_unknown_keys()
  // leaves them to it.
  void leave_table(std::string_view table) const;

  // "file:line:col" of the key's value (the file alone when the key is absent).
  std::string where(std::string_view dotted_key) const;

  // "file:line:col: message" for the key's value (or the file alone).
  [[noreturn]] void fail(std::string_view dotted_key, const std::string& message) const;

 private:
  struct Impl;
  TomlDocument(std::unique_ptr<Impl> impl, std::string source);
  double raw_number(std::string_view dotted_key) const;  // any double, NaN included
  std::unique_ptr<Impl> impl_;
  std::string source_;
  mutable std::set<std::string, std::less<>> used_;
  mutable std::vector<std::string> left_tables_;
};

}  // namespace glider::config
