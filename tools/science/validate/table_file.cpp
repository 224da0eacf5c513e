// SPDX-License-Identifier: Apache-2.0
#include "table_file.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace glider::validate {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

}  // namespace

const std::string& TableRow::text(const std::string& name) const {
  const auto it = fields.find(name);
  if (it == fields.end()) throw std::runtime_error("table has no column '" + name + "'");
  return it->second;
}

double TableRow::number(const std::string& name) const {
  const std::string& value = text(name);
  std::size_t used = 0;
  const double x = std::stod(value, &used);
  if (used != value.size()) throw std::runtime_error("'" + value + "' in column '" + name + "' is not a number");
  return x;
}

std::vector<TableRow> read_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::string line;
  std::vector<std::string> header;
  std::vector<TableRow> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    if (cells.size() != header.size()) throw std::runtime_error(path.string() + ": row with a wrong field count");
    TableRow row;
    for (std::size_t i = 0; i < cells.size(); ++i) row.fields[header[i]] = cells[i];
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace glider::validate
