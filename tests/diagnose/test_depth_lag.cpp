// SPDX-License-Identifier: Apache-2.0
// The diagnosis's depth_lag: the model's depth as a late sensor reads it.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "glider/diagnose/depth_lag.hpp"
#include "hidden_effect_flight.hpp"

using namespace glider;
using glider::diagnose::delay_depth;

TEST_GROUP(DiagnoseDepthLag){};

TEST(DiagnoseDepthLag, ReadsTheDepthLagSecondsEarlier) {
  // A turn: a parabola sampled every 1.5 s; the late sensor reads it lag
  // seconds earlier (linear between samples, exact at sample times).
  std::vector<double> t, z;
  for (int k = 0; k < 20; ++k) {
    t.push_back(1.466e9 + 1.5 * k);  // an epoch clock, as the logs'
    z.push_back(30.0 - 0.01 * (1.5 * k - 15.0) * (1.5 * k - 15.0));
  }
  std::vector<double> late = z;
  delay_depth(t, late, 3.0);  // two samples
  for (std::size_t k = 2; k < z.size(); ++k) DOUBLES_EQUAL(z[k - 2], late[k], 1e-12);
  late = z;
  delay_depth(t, late, 0.75);  // half a sample: between the two
  for (std::size_t k = 1; k < z.size(); ++k) DOUBLES_EQUAL(0.5 * (z[k - 1] + z[k]), late[k], 1e-12);
  // Before the first sample: along the first interval.
  DOUBLES_EQUAL(z[0] - 0.5 * (z[1] - z[0]), late[0], 1e-12);
}

TEST(DiagnoseDepthLag, ResolvesTheOptimisersStepOnAnEpochClock) {
  // A Jacobian step of 1.5e-8 s must move the depth although an epoch time
  // itself resolves only 2e-7 s: the lag is applied to time differences.
  std::vector<double> t{1.466e9, 1.466e9 + 1.0, 1.466e9 + 2.0, 1.466e9 + 3.0};
  std::vector<double> z{10.0, 10.1, 10.3, 10.6}, a = z, b = z;
  delay_depth(t, a, 1.0);
  delay_depth(t, b, 1.0 + 1.5e-8);
  CHECK(b[3] < a[3]);
  DOUBLES_EQUAL(-1.5e-8 * 0.2, b[3] - a[3], 1e-12);
}

TEST(DiagnoseDepthLag, NoLagLeavesTheDepth) {
  std::vector<double> t{0.0, 1.0, 2.0}, z{1.0, 2.0, 4.0}, same = z;
  delay_depth(t, same, 0.0);
  for (std::size_t k = 0; k < z.size(); ++k) DOUBLES_EQUAL(z[k], same[k], 0.0);
}

namespace {

// The log at `path` rewritten to `out` with m_depth read lag_s late (as a
// late pressure sensor would log it), linearly between rows.
void write_with_late_depth(const std::string& path, const std::string& out, double lag_s) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::size_t header = 0;
  while (header < lines.size() && lines[header].starts_with('#')) ++header;
  auto fields = [](const std::string& line) {
    std::vector<std::string> f(1);  // empty fields kept, a trailing one too
    for (char c : line) {
      if (c == ',') {
        f.emplace_back();
      } else {
        f.back().push_back(c);
      }
    }
    return f;
  };
  const std::vector<std::string> names = fields(lines[header]);
  const auto depth_column = static_cast<std::size_t>(std::find(names.begin(), names.end(), "m_depth") - names.begin());
  std::vector<std::size_t> rows;
  std::vector<double> t, z;
  for (std::size_t i = header + 1; i < lines.size(); ++i) {
    if (lines[i].starts_with('#')) continue;  // the trailer
    const std::vector<std::string> f = fields(lines[i]);
    rows.push_back(i);
    t.push_back(std::stod(f[0]));
    z.push_back(std::stod(f[depth_column]));
  }
  delay_depth(t, z, lag_s);
  std::ofstream o(out);
  for (std::size_t i = 0, r = 0; i < lines.size(); ++i) {
    if (r < rows.size() && rows[r] == i) {
      std::vector<std::string> f = fields(lines[i]);
      f[depth_column] = std::to_string(z[r++]);
      for (std::size_t k = 0; k < f.size(); ++k) o << (k ? "," : "") << f[k];
      o << '\n';
    } else {
      o << lines[i] << '\n';
    }
  }
}

// Flies `flown` (logging WE01), rewrites the CSV with the depth lag_s late
// and diagnoses that alone.
diagnose::Diagnosis diagnose_with_late_depth(const model::VehicleParams& flown, double lag_s, const sil::LogGaps& gaps,
                                             const std::string& name) {
  const hidden::Outcome clean =
      hidden::fly_and_diagnose(flown, model::still_water(1025.0), name + "_flown", 80.0, gaps);
  const std::string late = std::string(GLIDER_TEST_OUTPUT_DIR) + "/hidden_" + name + ".csv";
  write_with_late_depth(clean.log_path, late, lag_s);
  const flightlog::FlightLog log = flightlog::read_flight_log(late);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& m : log.vehicle_metadata()) entries.emplace_back(m.key, m.value);
  return diagnose::diagnose(model::vehicle_from_metadata(entries, late), diagnose::prepare_observations(log));
}

// A clean SIL flight whose depth sensor reads late: the diagnosis sees only
// the CSV. A late depth shifts every turn; without depth_lag a profile of
// vertical velocity bends there to stand in for it.
void check_hidden_late_depth(std::uint64_t seed, const sil::LogGaps& gaps, const std::string& name) {
  std::mt19937_64 rng{seed};
  const double lag_s = hidden::uniform(rng, 2.0, 6.0);
  const diagnose::Diagnosis d = diagnose_with_late_depth(hidden::we01(), lag_s, gaps, name);
  STRCMP_EQUAL("depth_lag", d.cause.c_str());
  LONGS_EQUAL(1, d.findings.size());
  const diagnose::Finding& f = d.findings.front();
  std::printf("%s: hidden %.3f s, found %.3f [%.3f, %.3f], gain %.2f\n", name.c_str(), lag_s, f.value, f.ci95_low,
              f.ci95_high, d.gain);
  DOUBLES_EQUAL(lag_s, f.value, 0.1 * lag_s);
  CHECK(f.ci95_low < lag_s && lag_s < f.ci95_high);
  CHECK(d.gain > 0.2);
}

}  // namespace

TEST(DiagnoseDepthLag, HiddenLateDepthIsNamedAndSized) { check_hidden_late_depth(20261125, {}, "depth_lag"); }

TEST(DiagnoseDepthLag, HiddenLateDepthOnAThinnedLog) {
  // Rows 2-5 s apart, as the real logs: the lag is a fraction of a row.
  check_hidden_late_depth(20261126, hidden::real_log_gaps(), "depth_lag_thinned");
}

TEST(DiagnoseDepthLag, LateDepthAndBuoyancyOffset) {
  // gliderflight-adcp's case: a heavy glider whose depth reads late, thinned
  // like a real log. Both are named and sized, and nothing else (a
  // vertical-velocity profile can stand in for both: + at the bottom turn).
  // On this flight forward selection finds them; on gliderflight-adcp itself
  // the profile is taken first and the selection without it wins
  // (diagnose.real.gliderflight_adcp_dvl).
  std::mt19937_64 rng{20261127};
  const double lag_s = hidden::uniform(rng, 2.0, 4.0);
  const double grams = hidden::uniform(rng, 25.0, 40.0);
  model::VehicleParams flown = hidden::we01();
  flown.buoyancy_offset_kg = grams * 1e-3;
  const diagnose::Diagnosis d = diagnose_with_late_depth(flown, lag_s, hidden::real_log_gaps(), "depth_lag_heavy");
  for (const auto& f : d.findings) {
    std::printf("late depth and offset: %s %.4g [%.4g, %.4g] (hidden %.3f s, %.2f g)\n", diagnose::info(f.effect).id,
                f.value, f.ci95_low, f.ci95_high, lag_s, grams);
  }
  LONGS_EQUAL(2, d.findings.size());
  for (const auto& f : d.findings) {
    if (f.effect == diagnose::Effect::kDepthLag) {
      DOUBLES_EQUAL(lag_s, f.value, 0.1 * lag_s);
    } else {
      CHECK(f.effect == diagnose::Effect::kBuoyancyOffset);
      DOUBLES_EQUAL(grams, f.value, 0.1 * grams);
    }
  }
}
