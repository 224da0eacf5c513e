// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small comma-separated tables with `#` comment lines and a header (the
// papers' numbers in tests/data/papers).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace glider::validate {

struct TableRow {
  std::map<std::string, std::string> fields;
  double number(const std::string& name) const;  // throws std::runtime_error naming the field
  const std::string& text(const std::string& name) const;
};

std::vector<TableRow> read_table(const std::filesystem::path& path);

}  // namespace glider::validate
