// SPDX-License-Identifier: Apache-2.0
#include "glider/health/segments.hpp"
#include "glider/flightlog/gaps.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "glider/diagnose/stored_on_change.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/log_loader.hpp"

namespace glider::health {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Rank of a flight file by completeness (lower is better), of a science
// file likewise; -1: not that kind.
int flight_rank(const std::string& ext) {
  static const std::vector<std::string> order{".dbd", ".dcd", ".mbd", ".mcd", ".sbd", ".scd"};
  const auto it = std::find(order.begin(), order.end(), ext);
  return it == order.end() ? -1 : static_cast<int>((it - order.begin()) / 2);
}
int science_rank(const std::string& ext) {
  static const std::vector<std::string> order{".ebd", ".ecd", ".nbd", ".ncd", ".tbd", ".tcd"};
  const auto it = std::find(order.begin(), order.end(), ext);
  return it == order.end() ? -1 : static_cast<int>((it - order.begin()) / 2);
}

std::string fingerprint_of(const std::vector<std::string>& files) {
  std::ostringstream out;
  for (const std::string& f : files) {
    std::error_code error;
    const auto size = fs::file_size(f, error);
    const auto time = fs::last_write_time(f, error);
    out << fs::path(f).filename().string() << ':' << (error ? 0 : size) << ':'
        << (error ? 0 : time.time_since_epoch().count()) << ';';
  }
  return out.str();
}

struct SlocumGroup {
  std::string stem;
  std::string flight, science;
  int flight_rank = 99, science_rank = 99;
};

}  // namespace

std::optional<std::string> glider_of_file(const std::string& path) {
  static const std::regex kSlocumName(R"(^([A-Za-z][A-Za-z0-9_]*)-[0-9]{4}-[0-9]{1,3}-[0-9]+-[0-9]+)");
  const std::string name = fs::path(path).filename().string();
  std::smatch m;
  if (std::regex_search(name, m, kSlocumName)) return m[1].str();
  return std::nullopt;
}

std::vector<SegmentFiles> find_segments(const std::vector<std::string>& inputs) {
  std::vector<SegmentFiles> segments;
  std::set<std::string> seen;
  auto add = [&](SegmentFiles s) {
    if (!seen.insert(s.name).second) {
      throw BadInput(s.files.front() + ": segment " + s.name + " is given twice (a duplicate); give each once");
    }
    s.fingerprint = fingerprint_of(s.files);
    segments.push_back(std::move(s));
  };
  for (const std::string& input : inputs) {
    if (lower(fs::path(input).extension().string()) == ".csv" && fs::is_regular_file(input)) {
      add({fs::path(input).stem().string(), {input}, false, {}});
      continue;
    }
    // Slocum files: grouped by stem, in the reader's segment order.
    std::vector<SlocumGroup> groups;
    for (const fs::path& file : slocum::deployment_files({input})) {
      const std::string ext = lower(file.extension().string());
      const std::string stem = file.stem().string();
      if (groups.empty() || groups.back().stem != stem) {
        auto it = std::find_if(groups.begin(), groups.end(), [&](const SlocumGroup& g) { return g.stem == stem; });
        if (it == groups.end()) {
          groups.push_back({stem, {}, {}});
        } else {
          std::rotate(it, it + 1, groups.end());  // keep working on it at the back
        }
      }
      SlocumGroup& g = groups.back();
      if (const int r = flight_rank(ext); r >= 0 && r < g.flight_rank) {
        g.flight = file.string();
        g.flight_rank = r;
      } else if (const int s = science_rank(ext); s >= 0 && s < g.science_rank) {
        g.science = file.string();
        g.science_rank = s;
      }
    }
    for (const SlocumGroup& g : groups) {
      SegmentFiles s;
      s.name = g.stem;
      if (!g.flight.empty()) s.files.push_back(g.flight);
      if (!g.science.empty()) s.files.push_back(g.science);
      if (s.files.empty()) continue;
      s.decimated = g.flight.empty() ? g.science_rank > 0 : g.flight_rank > 0;
      add(std::move(s));
    }
  }
  return segments;
}

LoadedSegment load_segment(const SegmentFiles& files, const std::vector<fs::path>& cache_dirs) {
  LoadedSegment s;
  s.files = files;
  try {
    std::vector<slocum::Warning> warnings;
    flightlog::FlightLog log = slocum::load_flight_log({files.files, cache_dirs}, {}, &warnings);
    for (const auto& w : warnings) s.warnings.push_back(w.text());
    if (log.rows() == 0) throw std::runtime_error("no rows");
    s.start_s = log.time().front();
    s.end_s = log.time().back();
    s.log = files.decimated ? hold_slow_columns(log, 900.0) : log;
    s.raw = std::move(log);
  } catch (const std::exception& error) {
    s.problem = error.what();
  }
  return s;
}

flightlog::FlightLog hold_slow_columns(const flightlog::FlightLog& log, double max_age_s) {
  // The rule is the diagnosis's (glider-diagnose reads an .sbd the same way).
  return diagnose::hold_stored_columns(log, max_age_s, true);
}

}  // namespace glider::health
