// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/csv_export.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace glider::slocum {

void write_csv(const Deployment& deployment, std::ostream& out) {
  const flightlog::FlightLog& log = deployment.log;
  for (const flightlog::MetadataEntry& entry : log.metadata()) out << "# " << entry.key << ": " << entry.value << "\n";
  out << "# columns_empty_means: not updated in that cycle or not valid\n";
  const std::vector<std::string>& names = log.column_names();
  std::vector<const flightlog::Column*> columns;
  std::vector<const char*> formats;
  for (std::size_t c = 0; c < names.size(); ++c) {
    out << (c ? "," : "") << names[c];
    columns.push_back(&log.column(names[c]));
    const bool is_time = &log.column(names[c]) == &log.time();
    formats.push_back(is_time ? "%.5f" : (deployment.stored_bytes[c] == 8 ? "%.12g" : "%.7g"));
  }
  out << "\n";
  std::string line;
  char field[64];
  for (std::size_t r = 0; r < log.rows(); ++r) {
    line.clear();
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) line += ',';
      const double v = (*columns[c])[r];
      if (std::isnan(v)) continue;
      const int n = std::snprintf(field, sizeof field, formats[c], v);
      line.append(field, static_cast<std::size_t>(n));
    }
    line += '\n';
    out << line;
  }
}

}  // namespace glider::slocum
