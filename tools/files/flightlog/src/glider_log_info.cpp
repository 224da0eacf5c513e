// SPDX-License-Identifier: Apache-2.0
// glider-log-info: what is in a flight log (docs/flight-log.md): rows, time
// span, sampling, columns with their fill, metadata, dives and climbs. Reads
// the log exactly as the analysis tools do, so it also checks a log.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/flightlog/binary_log.hpp"
#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"
#include "glider/slocum/log_loader.hpp"
#include "glider/utc_time.hpp"

namespace fl = glider::flightlog;

namespace {

constexpr double kLongGapS = 20.0;  // the real logs' surface gaps are 20-230 s

// "2016-06-23T17:51:11Z" for Unix times; nothing for mission-relative time.
std::string utc(double unix_time_s) {
  if (unix_time_s < 1.0e8) return "";  // before 1973: not an epoch time
  return glider::utc::format_iso(unix_time_s);
}

void print_time(const fl::FlightLog& log) {
  const fl::Column& t = log.time();
  const double span_s = t.back() - t.front();
  std::printf("time     : %.3f .. %.3f s, span %.1f s (%.2f h)\n", t.front(), t.back(), span_s, span_s / 3600.0);
  if (const std::string start = utc(t.front()); !start.empty()) {
    std::printf("           %s .. %s\n", start.c_str(), utc(t.back()).c_str());
  }
  if (t.size() < 2) return;
  std::vector<double> steps(t.size());
  std::adjacent_difference(t.begin(), t.end(), steps.begin());
  steps.erase(steps.begin());  // the first element is t[0] itself
  const auto long_gaps = std::count_if(steps.begin(), steps.end(), [](double s) { return s > kLongGapS; });
  const double longest = *std::max_element(steps.begin(), steps.end());
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  std::printf("sampling : median %.2f s, longest gap %.1f s, %ld gaps over %.0f s\n", steps[steps.size() / 2], longest,
              static_cast<long>(long_gaps), kLongGapS);
}

void print_phases(const fl::FlightLog& log) {
  const std::optional<fl::DepthSeries> depth = fl::depth_series(log);
  if (!depth) {
    std::printf("depth    : none (no m_depth or sci_water_pressure column): no dive/climb segmentation\n");
    return;
  }
  // fmin/fmax skip the empty samples (NaN).
  const auto& d = depth->depth_m;
  const double nan = std::nan("");
  const double shallowest =
      std::accumulate(d.begin(), d.end(), nan, [](double a, double b) { return std::fmin(a, b); });
  const double deepest = std::accumulate(d.begin(), d.end(), nan, [](double a, double b) { return std::fmax(a, b); });
  std::printf("depth    : %.2f .. %.2f m (from %s%s)\n", shallowest, deepest, depth->source.c_str(),
              depth->source == "m_depth" ? "" : " x 10 m/bar");
  const std::vector<fl::Phase> phases = fl::classify_phases(log);
  const std::vector<fl::Segment> segments = fl::find_segments(log.time(), depth->depth_m, phases);
  const fl::GlideCounts glides = fl::count_glides(segments);
  std::printf("glides   : %zu dives, %zu climbs (over 3 m)\n", glides.dives, glides.climbs);
  std::printf("samples  :");  // share of the rows in each phase
  for (const fl::Phase phase :
       {fl::Phase::kSurface, fl::Phase::kDive, fl::Phase::kClimb, fl::Phase::kInflection, fl::Phase::kUnknown}) {
    const auto n = std::count(phases.begin(), phases.end(), phase);
    std::printf("%s %s %.1f %%", phase == fl::Phase::kSurface ? "" : ",", std::string(fl::to_string(phase)).c_str(),
                100.0 * static_cast<double>(n) / static_cast<double>(phases.size()));
  }
  std::printf("\n");
}

void print_columns(const fl::FlightLog& log) {
  std::printf("columns  : %zu\n", log.column_names().size());
  for (const std::string& name : log.column_names()) {
    const std::string unit(fl::unit_of(name));
    std::printf("  %-24s %-10s %6.1f %% filled\n", name.c_str(), unit.empty() ? "-" : unit.c_str(),
                100.0 * log.fill_fraction(name));
  }
}

void print_metadata(const fl::FlightLog& log) {
  std::printf("metadata : %zu entries, %zu vehicle.*\n", log.metadata().size(), log.vehicle_metadata().size());
  for (const fl::MetadataEntry& entry : log.metadata()) {
    std::printf("  %s: %s\n", entry.key.c_str(), entry.value.c_str());
  }
}

// "a|b" -> {"a", "b"}: the header needs one of them.
std::vector<std::string> alternatives(const std::string& spec) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = spec.find('|', start);
    names.push_back(spec.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
    if (bar == std::string::npos) return names;
    start = bar + 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-log-info", "Summarize a flight-log CSV (docs/flight-log.md)");
  CLI::App& app = tool.app();
  glider::slocum::LogSource source;
  fl::ReadOptions options;
  std::vector<std::string> required;
  std::string to_csv;
  app.add_option("log", source.inputs,
                 "flight log: a CSV, or a glider's binary files (.dbd/.ebd..., .dcd/.ecd...: files, a directory or "
                 "globs)")
      ->required();
  app.add_option("--cache", source.cache_dirs, "sensor-list cache directory for binary files");
  app.add_option("--time-column", options.time_column, "strictly increasing time column")->capture_default_str();
  app.add_option("--require", required,
                 "a column the log must have, or alternatives as a|b (repeatable; replaces the default "
                 "m_depth|sci_water_pressure, m_pitch, m_ballast_pumped|m_de_oil_vol)");
  app.add_option("--to-csv", to_csv,
                 "write the CSV text of a binary SIL log (.glb, docs/flight-log.md) to this file, then summarize");
  return tool.run(argc, argv, [&]() -> int {
    if (!to_csv.empty()) {
      if (source.inputs.size() != 1) return tool.fail(glider::cli::kUsage, "--to-csv converts one log");
      const std::string problem = fl::write_binary_rows_as_csv(source.inputs.front(), to_csv);
      if (!problem.empty()) return tool.fail(glider::cli::kError, problem);
    }
    if (!required.empty()) {
      options.required.clear();
      for (const std::string& spec : required) options.required.push_back(alternatives(spec));
    }

    {  // errors (FlightLogError names file, line and column) are printed by cli::Tool
      std::vector<glider::slocum::Warning> warnings;
      const fl::FlightLog log = glider::slocum::load_flight_log(source, options, &warnings);
      for (const auto& w : warnings) std::fprintf(stderr, "glider-log-info: warning: %s\n", w.text().c_str());
      std::printf("log      : %s\n", log.source().c_str());
      std::printf("rows     : %zu\n", log.rows());
      std::printf("end      : %s\n", log.end().describe(log.rows()).c_str());
      print_time(log);
      print_phases(log);
      print_columns(log);
      print_metadata(log);
    }
    return static_cast<int>(glider::cli::kOk);
  });
}
