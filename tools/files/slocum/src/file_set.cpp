// SPDX-License-Identifier: Apache-2.0
// Which files make a deployment, and their order.
#include <glob.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <tuple>

#include "glider/slocum/deployment.hpp"

namespace glider::slocum {
namespace {

namespace fs = std::filesystem;

// Sort key: the glider's name, then the numbers of the name in order
// (comet-2016-174-05-003: 2016, 174, 5, 3; 01600003: 1600003), then flight
// before science (so a row's science follows its flight file in messages).
struct SegmentKey {
  std::string prefix;
  std::vector<unsigned long long> numbers;
  int science = 0;
  std::string name;
  bool operator<(const SegmentKey& other) const {
    return std::tie(prefix, numbers, science, name) < std::tie(other.prefix, other.numbers, other.science, other.name);
  }
};

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

SegmentKey segment_key(const fs::path& path) {
  SegmentKey key;
  key.name = path.filename().string();
  const std::string stem = path.stem().string();
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dash = stem.find('-', start);
    parts.push_back(stem.substr(start, dash == std::string::npos ? std::string::npos : dash - start));
    if (dash == std::string::npos) break;
    start = dash + 1;
  }
  // Leading non-numeric parts are the glider's name; the numeric tail is the segment.
  std::size_t first_number = parts.size();
  while (first_number > 0 && all_digits(parts[first_number - 1]) && parts[first_number - 1].size() <= 18)
    --first_number;
  for (std::size_t i = 0; i < first_number; ++i) key.prefix += (i ? "-" : "") + parts[i];
  for (std::size_t i = first_number; i < parts.size(); ++i) key.numbers.push_back(std::stoull(parts[i]));
  const std::string ext = path.extension().string();
  const char kind = ext.size() > 1 ? static_cast<char>(std::tolower(static_cast<unsigned char>(ext[1]))) : ' ';
  key.science = (kind == 'e' || kind == 't' || kind == 'n') ? 1 : 0;
  return key;
}

bool has_glob_characters(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

void add_directory(const fs::path& dir, std::vector<fs::path>& out) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && is_binary_data_name(entry.path())) out.push_back(entry.path());
  }
}

void add_glob(const std::string& pattern, std::vector<fs::path>& out) {
  glob_t matches{};
  const int status = ::glob(pattern.c_str(), 0, nullptr, &matches);
  if (status == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) {
      const fs::path path(matches.gl_pathv[i]);
      if (is_binary_data_name(path)) out.push_back(path);
    }
  }
  globfree(&matches);
}

}  // namespace

std::vector<fs::path> deployment_files(const std::vector<std::string>& inputs) {
  std::vector<fs::path> files;
  for (const std::string& input : inputs) {
    std::error_code error;
    if (fs::is_directory(input, error)) {
      add_directory(input, files);
    } else if (fs::exists(input, error)) {
      if (!is_binary_data_name(input)) {
        throw std::runtime_error(input +
                                 ": not a Slocum data file name (.dbd .ebd .sbd .tbd .mbd .nbd or the "
                                 "compressed .dcd .ecd .scd .tcd .mcd .ncd)");
      }
      files.emplace_back(input);
    } else if (has_glob_characters(input)) {
      add_glob(input, files);
    } else {
      throw std::runtime_error(input + ": no such file or directory");
    }
  }
  if (files.empty()) {
    std::string list;
    for (const std::string& input : inputs) list += (list.empty() ? "" : ", ") + input;
    throw std::runtime_error("no Slocum data files (.dbd .ebd ... .dcd .ecd ...) in: " + list);
  }
  std::vector<std::pair<SegmentKey, fs::path>> keyed;
  for (const fs::path& path : files) keyed.emplace_back(segment_key(path), path);
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  files.clear();
  for (auto& [key, path] : keyed) {
    if (files.empty() || files.back() != path) files.push_back(std::move(path));
  }
  return files;
}

}  // namespace glider::slocum
