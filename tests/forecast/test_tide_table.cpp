// SPDX-License-Identifier: Apache-2.0
// The pilot's tide table (docs/forecast.md, session 44): the file read and
// refused, the constituents fitted to a record with intervals (and refused on
// too short a record), and the tidal prior with a table of a tide model's
// errors against the prior without it, on synthetic waters drawn from a
// fresh seed (printed; GLIDER_TEST_SEED replays it).
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "glider/forecast/current_estimate.hpp"
#include "glider/forecast/tidal_prior.hpp"
#include "glider/forecast/tide_fit.hpp"
#include "glider/forecast/tide_table.hpp"

namespace fc = glider::forecast;
namespace fs = std::filesystem;

namespace {

std::uint32_t test_seed(const char* what) {
  std::uint32_t seed = std::random_device{}();
  if (const char* given = std::getenv("GLIDER_TEST_SEED"); given != nullptr && *given != '\0') {
    seed = static_cast<std::uint32_t>(std::strtoul(given, nullptr, 10));
  }
  std::printf("\n%s: seed %u (GLIDER_TEST_SEED=%u replays it)\n", what, seed, seed);
  return seed;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("glider_tide_table_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

const char* const kGood =
    "# a pilot's table\n"
    "reference_utc = 2019-08-21T00:00:00Z\n"
    "[M2]\n"
    "east_amplitude_m_s = 0.31\n"
    "east_phase_deg = 123.0\n"
    "north_amplitude_m_s = 0.12\n"
    "north_phase_deg = -60.0\n"
    "amplitude_sigma_m_s = 0.08\n"
    "phase_sigma_deg = 30.0\n"
    "[K1]\n"
    "east_amplitude_m_s = 0.05\n"
    "east_phase_deg = 10.0\n"
    "north_amplitude_m_s = 0.02\n"
    "north_phase_deg = 200.0\n"
    "amplitude_sigma_m_s = 0.02\n"
    "phase_sigma_deg = 40.0\n";

// The message a bad table gives (empty: it was read).
std::string refusal(const std::string& name, const std::string& text) {
  try {
    fc::read_tide_table(write(name, text));
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A synthetic water: a mean and one M2 per component (amplitude, phase).
struct Water {
  double mean[2] = {0.0, 0.0};
  double amplitude[2] = {0.0, 0.0};
  double phase_rad[2] = {0.0, 0.0};
  // The mean over [t - span/2, t + span/2], t from the reference 0.
  double at(int c, double t, double span) const {
    const double w = 2.0 * std::numbers::pi / fc::tide_constituent_period_s("M2");
    const double half = 0.5 * w * span;
    const double kept = half < 1e-9 ? 1.0 : std::sin(half) / half;
    return mean[c] + amplitude[c] * kept * std::cos(w * t - phase_rad[c]);
  }
};

}  // namespace

TEST_GROUP(ForecastTideTable){};

TEST(ForecastTideTable, AGoodTableIsReadAndWrittenBack) {
  fc::TideTable t = fc::read_tide_table(write("good.toml", kGood));
  CHECK_EQUAL(2U, t.constituents.size());
  if (t.constituents[0].name != "M2") std::swap(t.constituents[0], t.constituents[1]);  // read in the key order
  DOUBLES_EQUAL(1566345600.0, t.reference_utc_s, 1e-6);                                 // 2019-08-21T00:00:00Z
  STRCMP_EQUAL("M2", t.constituents[0].name.c_str());
  DOUBLES_EQUAL(44714.16, t.constituents[0].period_s, 0.1);
  DOUBLES_EQUAL(0.31, t.constituents[0].east.amplitude_m_s, 1e-12);
  DOUBLES_EQUAL(-60.0, t.constituents[0].north.phase_deg, 1e-12);
  DOUBLES_EQUAL(30.0, t.constituents[0].north.phase_sigma_deg, 1e-12);
  // At the reference the M2 east is 0.31 cos(-123 deg), the K1 0.05 cos(-10 deg).
  DOUBLES_EQUAL(0.31 * std::cos(-123.0 * std::numbers::pi / 180.0) + 0.05 * std::cos(-10.0 * std::numbers::pi / 180.0),
                fc::tide_mean(t, 0, t.reference_utc_s, 0.0), 1e-12);
  // Written and read again: the same current at any time (phases wrapped into [0, 360)).
  const fc::TideTable again = fc::read_tide_table(write("again.toml", fc::format_tide_table(t, "round trip")));
  for (double h = 0.0; h < 30.0; h += 2.5) {
    const double at = t.reference_utc_s + h * 3600.0;
    DOUBLES_EQUAL(fc::tide_mean(t, 1, at, 3600.0), fc::tide_mean(again, 1, at, 3600.0), 2e-4);
  }
}

TEST(ForecastTideTable, ABadTableIsRefusedNamingFileLineKeyValueAndRange) {
  std::string text = kGood;
  const std::string nan = refusal("nan.toml", text.replace(text.find("0.31"), 4, "nan"));
  CHECK_TEXT(contains(nan, "nan.toml:4: M2.east_amplitude_m_s = nan is outside [0, 3] m/s"), nan.c_str());
  text = kGood;
  const std::string range = refusal("range.toml", text.replace(text.find("40.0"), 4, "400.0"));
  CHECK_TEXT(contains(range, "range.toml:16: K1.phase_sigma_deg = 400 is outside [0, 180] deg"), range.c_str());
  text = kGood;
  const std::string key = refusal("key.toml", text.replace(text.find("phase_sigma_deg = 30"), 15, "phase_sigma"));
  CHECK_TEXT(contains(key, "key.toml:9: M2.phase_sigma: unknown key (allowed: east_amplitude_m_s"), key.c_str());
  text = kGood;
  const std::string name = refusal("name.toml", text.replace(text.find("[K1]"), 4, "[X9]"));
  CHECK_TEXT(contains(name, "name.toml:10: [X9]: 'X9' is not a tidal constituent (allowed: M2, S2"), name.c_str());
  text = kGood;
  const std::string missing = refusal("missing.toml", text.replace(text.find("north_phase_deg = 200.0\n"), 24, ""));
  CHECK_TEXT(contains(missing, "missing.toml:10: [K1] has no north_phase_deg (-360 to 360 deg)"), missing.c_str());
  text = kGood;
  const std::string word = refusal("word.toml", text.replace(text.find("0.12"), 4, "\"strong\""));
  CHECK_TEXT(contains(word, "word.toml:6: M2.north_amplitude_m_s is not a number"), word.c_str());
  const std::string no_reference = refusal("noref.toml", std::string(kGood).substr(std::string(kGood).find("[M2]")));
  CHECK_TEXT(contains(no_reference, "noref.toml: no reference_utc"), no_reference.c_str());
  const std::string local = refusal("local.toml", "reference_utc = 2019-08-21T00:00:00\n[M2]\n");
  CHECK_TEXT(contains(local, "local.toml:1: reference_utc is not a date-time with its offset"), local.c_str());
  const std::string syntax = refusal("syntax.toml", "reference_utc = 2019-08-21T00:00:00Z\n[M2\n");
  CHECK_TEXT(contains(syntax, "syntax.toml:2:"), syntax.c_str());
  const std::string none = refusal("none.toml", "reference_utc = 2019-08-21T00:00:00Z\n");
  CHECK_TEXT(contains(none, "none.toml: no constituent"), none.c_str());
  CHECK_TEXT(refusal("good_again.toml", kGood).empty(), "the good table is refused");
}

TEST_GROUP(ForecastTideFit){};

TEST(ForecastTideFit, TooShortARecordIsRefusedNamingWhatItNeeds) {
  std::vector<fc::CurrentSample> samples;
  for (int i = 0; i < 4; ++i) samples.push_back({i * 3.0 * 3600.0, 0.1, 0.0, 3.0 * 3600.0});  // 12 h of record
  try {
    fc::fit_tide(samples, {"M2"}, 0.0);
    FAIL("a 12 h record fitted M2");
  } catch (const std::runtime_error& e) {
    CHECK_TEXT(contains(e.what(), "4 estimates over 12.0 h) is too short to fit M2: it needs 12.4 h"), e.what());
  }
  for (int i = 4; i < 24; ++i) samples.push_back({i * 3.0 * 3600.0, 0.1, 0.0, 3.0 * 3600.0});  // 3 days
  try {
    fc::fit_tide(samples, {"M2", "S2"}, 0.0);
    FAIL("a 3-day record fitted M2 and S2 apart");
  } catch (const std::runtime_error& e) {
    CHECK_TEXT(contains(e.what(), "too short to fit M2, S2: it needs 354.4 h"), e.what());
  }
  // M2 and K1 apart: 1 / |f_M2 - f_K1| = 25.82 h (O1's period, by the tides' arithmetic).
  DOUBLES_EQUAL(25.82 * 3600.0, fc::tide_fit_record_needed_s({"M2", "K1"}), 0.01 * 3600.0);
}

TEST(ForecastTideFit, TheFittedConstituentsAreCoveredByTheirIntervals) {
  const std::uint32_t seed = test_seed("ForecastTideFit");
  std::mt19937 random(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Two days of 3 h dives (15 min calls), each estimate the dive's mean plus 0.03 m/s of noise.
  int covered = 0, cases = 0;
  double worst_phase_deg = 0.0;
  for (int draw = 0; draw < 200; ++draw) {
    Water w;
    for (int c = 0; c < 2; ++c) {
      w.mean[c] = 0.1 * g(random);
      w.amplitude[c] = 0.1 + 0.3 * u(random);
      w.phase_rad[c] = 2.0 * std::numbers::pi * u(random);
    }
    std::vector<fc::CurrentSample> samples;
    for (double t = 0.0; t < 48.0 * 3600.0; t += 3.25 * 3600.0) {
      const double mid = t + 1.5 * 3600.0;
      samples.push_back({mid, w.at(0, mid, 3.0 * 3600.0) + 0.03 * g(random),
                         w.at(1, mid, 3.0 * 3600.0) + 0.03 * g(random), 3.0 * 3600.0});
    }
    const fc::TideFit fit = fc::fit_tide(samples, {"M2"}, 0.0);
    for (int c = 0; c < 2; ++c) {
      const fc::TideComponent& k = c == 0 ? fit.table.constituents[0].east : fit.table.constituents[0].north;
      const double z = (k.amplitude_m_s - w.amplitude[c]) / k.amplitude_sigma_m_s;
      double dp = std::remainder(k.phase_deg - w.phase_rad[c] * 180.0 / std::numbers::pi, 360.0);
      worst_phase_deg = std::max(worst_phase_deg, std::fabs(dp));
      covered += std::fabs(z) <= fit.t95 && std::fabs(dp) <= fit.t95 * k.phase_sigma_deg ? 1 : 0;
      ++cases;
    }
  }
  std::printf("  amplitude and phase both within their 95 %% intervals in %d of %d; worst phase error %.1f deg\n",
              covered, cases, worst_phase_deg);
  // Both inside 95 % intervals (Student's t of the residual's degrees): about 0.90 when independent.
  CHECK_TEXT(covered >= static_cast<int>(0.82 * cases), "the fit's intervals do not cover its truth");
  CHECK_TEXT(worst_phase_deg < 30.0, "a two-day fit's phase is off by more than 30 deg");
}

TEST_GROUP(ForecastTidePrior){};

// One or two 3 h estimates, the next 3 h dive forecast: a table of a tide
// model's errors (phase 20-40 deg off, amplitude 20-30 % off, sigmas stated
// as 30 deg and 25 %) against the prior without it, in the same waters.
TEST(ForecastTidePrior, ATableWithATideModelsErrorsForecastsTheFirstDivesBetter) {
  const std::uint32_t seed = test_seed("ForecastTidePrior");
  std::mt19937 random(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double dive = 3.0 * 3600.0, up = 900.0;
  for (int estimates = 1; estimates <= 2; ++estimates) {
    double without2 = 0.0, with2 = 0.0, z2 = 0.0;
    int inside = 0, cases = 0, better = 0;
    for (int draw = 0; draw < 300; ++draw) {
      Water w;
      const double amplitude = 0.05 + 0.45 * u(random), direction = std::numbers::pi * u(random);
      const double phase = 2.0 * std::numbers::pi * u(random);
      for (int c = 0; c < 2; ++c) {
        w.mean[c] = 0.08 * g(random);
        const double signed_amplitude = amplitude * (c == 0 ? std::sin(direction) : std::cos(direction));
        w.amplitude[c] = std::fabs(signed_amplitude);
        w.phase_rad[c] = phase + (signed_amplitude < 0.0 ? std::numbers::pi : 0.0);
      }
      auto table = std::make_shared<fc::TideTable>();
      fc::TideConstituent m2;
      m2.name = "M2";
      m2.period_s = fc::tide_constituent_period_s("M2");
      const double dp = (u(random) < 0.5 ? -1.0 : 1.0) * (20.0 + 20.0 * u(random));
      const double da = 1.0 + (u(random) < 0.5 ? -1.0 : 1.0) * (0.2 + 0.1 * u(random));
      for (int c = 0; c < 2; ++c) {
        fc::TideComponent& k = c == 0 ? m2.east : m2.north;
        k.amplitude_m_s = w.amplitude[c] * da;
        k.phase_deg = w.phase_rad[c] * 180.0 / std::numbers::pi + dp;
        k.amplitude_sigma_m_s = 0.25 * k.amplitude_m_s;
        k.phase_sigma_deg = 30.0;
      }
      table->constituents.push_back(m2);
      const double start = 86400.0 * u(random);
      std::vector<fc::CurrentSample> samples;
      for (int e = 0; e < estimates; ++e) {
        const double mid = start + e * (dive + up) + 0.5 * dive;
        samples.push_back({mid, w.at(0, mid, dive) + 0.02 * g(random), w.at(1, mid, dive) + 0.02 * g(random), dive});
      }
      const double from = start + estimates * (dive + up), to = from + dive;
      fc::TidalPrior plain;
      fc::TidalPrior tabled;
      tabled.tide = table;
      const fc::CurrentEstimate a = fc::predict_with_prior(samples, from, to, plain);
      const fc::CurrentEstimate b = fc::predict_with_prior(samples, from, to, tabled);
      const double te = w.at(0, 0.5 * (from + to), dive), tn = w.at(1, 0.5 * (from + to), dive);
      const double ea = std::hypot(a.east_m_s - te, a.north_m_s - tn),
                   eb = std::hypot(b.east_m_s - te, b.north_m_s - tn);
      without2 += ea * ea;
      with2 += eb * eb;
      better += eb < ea ? 1 : 0;
      for (const double z : {(b.east_m_s - te) / b.sigma_east_m_s, (b.north_m_s - tn) / b.sigma_north_m_s}) {
        z2 += z * z;
        inside += std::fabs(z) <= 1.96 ? 1 : 0;
        ++cases;
      }
    }
    const double rms_without = std::sqrt(without2 / 300.0), rms_with = std::sqrt(with2 / 300.0);
    std::printf(
        "  %d estimate(s): the next dive's current RMS %.3f m/s without the table, %.3f with it (%d of 300 "
        "nearer); with it within 1.96 sigma in %d of %d components, mean z^2 %.2f\n",
        estimates, rms_without, rms_with, better, inside, cases, z2 / cases);
    CHECK_TEXT(rms_with < 0.8 * rms_without, "the table does not forecast the next dive's current better");
    CHECK_TEXT(better >= 180, "the table is not nearer in 60 % of the waters");
    CHECK_TEXT(inside >= static_cast<int>(0.85 * cases), "the table's sigma does not cover its error");
    CHECK_TEXT(z2 / cases < 1.8, "the table's sigma is too narrow");
  }
}
