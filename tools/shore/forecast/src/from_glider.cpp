// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/from_glider.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace glider::forecast {
namespace fs = std::filesystem;

std::vector<fs::path> from_glider_files(const fs::path& glider_dir) {
  std::vector<fs::path> paths;
  const fs::path from = glider_dir / "from-glider";
  if (!fs::is_directory(from)) return paths;
  for (const fs::directory_entry& e : fs::directory_iterator(from)) {
    if (e.is_regular_file() && e.path().extension() == ".csv") paths.push_back(e.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

bool header_names(const fs::path& path, const std::vector<std::string>& names) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> header;
    std::stringstream row(line);
    std::string name;
    while (std::getline(row, name, ',')) header.push_back(name);
    return std::all_of(names.begin(), names.end(), [&](const std::string& n) {
      return std::find(header.begin(), header.end(), n) != header.end();
    });
  }
  return false;
}

void for_each_from_glider_log(const fs::path& glider_dir, const std::vector<std::string>& columns,
                              const std::string& what, std::vector<std::string>& notes,
                              const std::function<void(const flightlog::FlightLog&)>& use) {
  flightlog::ReadOptions read;
  read.required.clear();
  for (const std::string& c : columns) read.required.push_back({c});
  read.columns = columns;
  for (const fs::path& path : from_glider_files(glider_dir)) {
    if (!header_names(path, columns)) continue;  // another kind of file (science data): nothing wrong
    try {
      use(flightlog::read_flight_log(path, read));
    } catch (const std::exception& e) {
      notes.push_back("from-glider: " + path.filename().string() + " not read for the " + what + ": " + e.what());
    }
  }
}

}  // namespace glider::forecast
