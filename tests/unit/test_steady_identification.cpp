// SPDX-License-Identifier: Apache-2.0
// Steady-glide identification (paper 000 sec. 3): on glides made by the
// project's own steady solver with hidden trim errors, and on the papers'
// tables (tests/data/papers).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "glider/identification/least_squares.hpp"
#include "glider/identification/steady_identification.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/units.hpp"

using namespace glider;
using namespace glider::identification;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The papers' small CSV tables: `#` comment lines, a header, numbers.
std::vector<std::map<std::string, std::string>> read_table(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::vector<std::string> header;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& key) { return std::stod(row.at(key)); }

// Paper 000 Table 1. Ballast m_b is printed in cc, + heavier (1 cc ~ 1 g);
// battery position in cm.
std::vector<SteadyGlideSample> graver_table1() {
  std::vector<SteadyGlideSample> samples;
  for (const auto& row : read_table(GLIDER_SOURCE_DIR "/tests/data/papers/graver2003_table1_steady_glides.csv")) {
    samples.push_back({number(row, "pitch_deg") * kDeg, number(row, "depth_rate_m_s"), number(row, "ballast_cc") * 1e-3,
                       number(row, "battpos_cm") * 1e-2, 0.0});
  }
  return samples;
}

// Half the last printed digit, as a uniform error's standard deviation.
double printed_sd(double half_step) { return half_step / std::sqrt(3.0); }

// The hidden truth of the synthetic glides: WE01 flying 40 g light, 17 %
// more profile drag than identified in paper 000, and its battery 0.1 in
// further forward than the slide reports.
constexpr double kHiddenOffsetKg = -0.040;
constexpr double kHiddenCd0 = 0.25;
constexpr double kHiddenPitchTrimM = 0.1 * kMetresPerInch;

struct Synthetic {
  model::VehicleParams nominal;
  std::vector<SteadyGlideSample> samples;
};

// Dives and climbs at +-150..250 cc over the battery travel, where the
// vehicle glides at 20-40 deg of pitch, from the forward equilibrium solver
// (force and moment balance of the full model).
Synthetic synthetic_glides() {
  Synthetic s{model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"), {}};
  model::VehicleParams truth = s.nominal;
  truth.buoyancy_offset_kg = kHiddenOffsetKg;
  truth.hydro.cd0 = kHiddenCd0;
  truth.battery.x_at_zero_m += kHiddenPitchTrimM;
  const model::GliderDynamics dynamics(truth, model::still_water(truth.trim_density_kg_m3));
  for (double cc : {-250.0, -200.0, -150.0, 150.0, 200.0, 250.0}) {
    for (int step = -10; step <= 10; ++step) {
      model::MassInputs m;
      m.pumped_volume_m3 = cc * 1e-6;
      m.battery_pos_m = step * 0.1 * kMetresPerInch;
      const auto eq = model::solve_equilibrium(dynamics, m, 100.0);
      if (!eq.glide || std::abs(eq.glide->pitch_rad) < 20.0 * kDeg || std::abs(eq.glide->pitch_rad) > 40.0 * kDeg) {
        continue;
      }
      s.samples.push_back({eq.glide->pitch_rad, eq.glide->depth_rate_m_s,
                           -truth.trim_density_kg_m3 * m.pumped_volume_m3, m.battery_pos_m, 0.0});
    }
  }
  return s;
}

double larger(double a, double b) { return std::isnan(a) ? b : (std::isnan(b) ? a : std::max(a, b)); }

}  // namespace

TEST_GROUP(SteadyIdentification) {
  model::VehicleParams we01 = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  LiftModel lift = lift_model_of(we01);
};

// Sec. 3.1 reads back what the steady solver flew: angle of attack, speed and
// the drag coefficient of the polar.
TEST(SteadyIdentification, LiftEquationInvertsTheSteadySolver) {
  for (double m0 : {0.25, 0.1, -0.18, -0.25}) {
    for (double path_deg : {26.0, 30.0, 45.0}) {  // the best glide is ~20 deg
      const auto steady = model::steady_glide_for_path(we01.hydro, 1025.0, path_deg, m0);
      CHECK_TRUE(steady.glide.has_value());
      const model::SteadyGlide& g = *steady.glide;
      const auto read = glide_from_lift(lift, {g.pitch_rad, g.depth_rate_m_s, m0 + 0.03, 0.0, 0.0}, -0.03);
      CHECK_TRUE(read.has_value());
      DOUBLES_EQUAL(g.alpha_rad, read->alpha_rad, 1e-10);
      DOUBLES_EQUAL(g.speed_m_s, read->speed_m_s, 1e-9);
      DOUBLES_EQUAL(m0, read->net_buoyancy_kg, 1e-15);
      DOUBLES_EQUAL(0.214 + 32.3 * g.alpha_rad * g.alpha_rad, read->drag_coefficient, 1e-8);
    }
  }
}

TEST(SteadyIdentification, GlidesThatCannotBeReadAreRefused) {
  CHECK_FALSE(glide_from_lift(lift, {-0.45, 0.2, -0.1, 0.0, 0.0}).has_value());  // descending while light
  CHECK_FALSE(glide_from_lift(lift, {-0.45, 0.0, 0.2, 0.0, 0.0}).has_value());   // no depth rate
  CHECK_FALSE(glide_from_lift(lift, {0.45, -0.2, 0.2, 0.0, 0.0}).has_value());   // climbing while heavy
  const std::vector<SteadyGlideSample> dives_only{{-0.45, 0.2, 0.2, 0.0, 0.0}, {-0.5, 0.22, 0.2, 0.0, 0.0}};
  const BuoyancyOffsetEstimate e = estimate_buoyancy_offset(lift, dives_only);
  CHECK_FALSE(e.ok);
  CHECK(e.error.find("both down and up") != std::string::npos);
}

// y = 1 + 2 x + e on x = 0..3, e = (+1, -1, -1, +1) / 10: RSS = 0.04, dof 2,
// (X^T X)^-1 = [[0.7, -0.3], [-0.3, 0.2]].
TEST(SteadyIdentification, LeastSquaresStandardErrorsAreTheTextbookOnes) {
  Eigen::MatrixXd x(4, 2);
  x << 1, 0, 1, 1, 1, 2, 1, 3;
  Eigen::VectorXd y(4);
  y << 1.1, 2.9, 4.9, 7.1;
  const LinearFit fit = least_squares(x, y);
  CHECK_TRUE(fit.ok);
  LONGS_EQUAL(2, fit.dof);
  DOUBLES_EQUAL(1.0, fit.coefficients[0], 1e-12);
  DOUBLES_EQUAL(2.0, fit.coefficients[1], 1e-12);
  DOUBLES_EQUAL(std::sqrt(0.02), fit.residual_sd, 1e-12);
  DOUBLES_EQUAL(std::sqrt(0.02 * 0.7), fit.standard_errors[0], 1e-12);
  DOUBLES_EQUAL(std::sqrt(0.02 * 0.2), fit.standard_errors[1], 1e-12);
  const LinearFit exact = least_squares(x.topRows(2), y.head(2));
  CHECK_TRUE(exact.ok);
  CHECK_TRUE(std::isnan(exact.standard_errors[0]));
}

// One dive and one climb at exactly equal |pitch|: the criterion is the
// paper's, and the offset follows from the depth rates and ballasts alone
// (see buoyancy_offset.hpp), whatever the lift curve.
TEST(SteadyIdentification, SymmetricPairNeedsNoLiftCurve) {
  const double dive_rate = 0.189;
  const double climb_rate = -0.243;
  const double dive_ballast = 0.2395;
  const double climb_ballast = -0.2404;
  const std::vector<SteadyGlideSample> pair{{-27.2 * kDeg, dive_rate, dive_ballast, 0.0, 0.0},
                                            {27.2 * kDeg, climb_rate, climb_ballast, 0.0, 0.0}};
  const double d2 = dive_rate * dive_rate;
  const double c2 = climb_rate * climb_rate;
  const double expected = (-climb_ballast * d2 - dive_ballast * c2) / (d2 + c2);
  BuoyancyOffsetOptions options;
  options.trend_degree = 0;
  const BuoyancyOffsetEstimate e = estimate_buoyancy_offset(lift, pair, options);
  CHECK_TRUE(e.ok);
  DOUBLES_EQUAL(expected, e.offset_kg, 1e-8);
  LiftModel other = lift;
  other.hydro.cl_alpha *= 1.3;
  other.density_kg_m3 = 1010.0;
  DOUBLES_EQUAL(expected, estimate_buoyancy_offset(other, pair, options).offset_kg, 1e-8);
}

// (a) The project's own steady solver flies glides with a hidden offset, drag
// and pitch trim; the identification with the nominal vehicle finds them.
// Noiseless, the only approximation is the quadratic |a| trend over 20-40 deg
// of pitch (0.2 g): tolerances 0.5 g, 0.3 % of cd0, 0.2 on cd_alpha2.
TEST(SteadyIdentification, RecoversHiddenOffsetDragAndPitchTrim) {
  const Synthetic s = synthetic_glides();
  CHECK(s.samples.size() >= 30);
  BuoyancyOffsetOptions options;
  options.trend_degree = 2;
  const SteadyIdentification id = identify_steady_glides(s.nominal, lift_model_of(s.nominal), s.samples, options);
  CHECK_TRUE(id.ok());
  DOUBLES_EQUAL(kHiddenOffsetKg, id.buoyancy.offset_kg, 0.0005);
  DOUBLES_EQUAL(kHiddenCd0, id.drag.cd0, 0.001);
  DOUBLES_EQUAL(32.3, id.drag.cd_alpha2_per_rad2, 0.2);
  DOUBLES_EQUAL(0.1, id.pitch.pitch_trim_offset_in(), 0.002);
  DOUBLES_EQUAL(s.nominal.hydro.cm_alpha_m, id.pitch.cm_alpha_viscous_m, 0.01);
  // Munk included, the total is paper 000's C_M = 0.63 a (less the 1 % that
  // the vehicle file's rounding of 3.655 and sin a cos a take).
  DOUBLES_EQUAL(0.63, id.pitch.cm_alpha_total_m, 0.02);
  // A linear trend is cruder over this pitch range, still within 1.5 g.
  options.trend_degree = 1;
  DOUBLES_EQUAL(kHiddenOffsetKg, estimate_buoyancy_offset(lift_model_of(s.nominal), s.samples, options).offset_kg,
                0.0015);
  UT_PRINT(("synthetic, noiseless: offset " + std::to_string(id.buoyancy.offset_kg * 1e3) + " g, cd0 " +
            std::to_string(id.drag.cd0) + ", cd_alpha2 " + std::to_string(id.drag.cd_alpha2_per_rad2) +
            ", pitch trim " + std::to_string(id.pitch.pitch_trim_offset_in()) + " in")
               .c_str());
}

// The same with seeded measurement noise (0.2 deg, 3 mm/s, 2 g, 0.5 mm per
// glide). Tolerances from a Monte Carlo over 100 seeds of exactly this set-up
// (error / stated standard error, the larger of fit and propagated): offset
// rms 0.84, pitch trim 0.92, cm_alpha 0.96, max 2.7: three standard errors.
// The drag polar is biased by half a standard error (rms 1.16 and 1.23, max
// 3.3): errors in variables, see drag_fit.hpp: four standard errors.
TEST(SteadyIdentification, RecoversThemFromNoisyGlides) {
  Synthetic s = synthetic_glides();
  const SampleUncertainty sd{0.2 * kDeg, 0.003, 0.002, 0.0005};
  std::mt19937 rng(20030101);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (SteadyGlideSample& x : s.samples) {
    x.pitch_rad += sd.pitch_rad * unit(rng);
    x.depth_rate_m_s += sd.depth_rate_m_s * unit(rng);
    x.ballast_net_kg += sd.ballast_kg * unit(rng);
    x.battery_pos_m += sd.battery_pos_m * unit(rng);
  }
  BuoyancyOffsetOptions options;
  options.trend_degree = 2;
  options.input_sd = sd;
  const SteadyIdentification id = identify_steady_glides(s.nominal, lift_model_of(s.nominal), s.samples, options);
  CHECK_TRUE(id.ok());
  const BuoyancyOffsetEstimate& b = id.buoyancy;
  CHECK(b.uncertainty_kg > 0.0005 && b.uncertainty_kg < 0.003);
  CHECK(std::abs(b.offset_kg - kHiddenOffsetKg) < 3.0 * b.uncertainty_kg);
  CHECK(std::abs(id.drag.cd0 - kHiddenCd0) < 4.0 * larger(id.drag.cd0_se, id.drag.cd0_input_se));
  CHECK(std::abs(id.drag.cd_alpha2_per_rad2 - 32.3) <
        4.0 * larger(id.drag.cd_alpha2_se_per_rad2, id.drag.cd_alpha2_input_se_per_rad2));
  CHECK(std::abs(id.pitch.pitch_trim_offset_m - kHiddenPitchTrimM) <
        3.0 * larger(id.pitch.pitch_trim_offset_se_m, id.pitch.pitch_trim_offset_input_se_m));
  CHECK(std::abs(id.pitch.cm_alpha_viscous_m - s.nominal.hydro.cm_alpha_m) <
        3.0 * larger(id.pitch.cm_alpha_viscous_se_m, id.pitch.cm_alpha_viscous_input_se_m));
  UT_PRINT(
      ("synthetic, noisy: offset " + std::to_string(b.offset_kg * 1e3) + " +- " +
       std::to_string(b.uncertainty_kg * 1e3) + " g, cd0 " + std::to_string(id.drag.cd0) + " +- " +
       std::to_string(larger(id.drag.cd0_se, id.drag.cd0_input_se)) + ", cd_alpha2 " +
       std::to_string(id.drag.cd_alpha2_per_rad2) + " +- " +
       std::to_string(larger(id.drag.cd_alpha2_se_per_rad2, id.drag.cd_alpha2_input_se_per_rad2)) + ", pitch trim " +
       std::to_string(id.pitch.pitch_trim_offset_in()) + " +- " +
       std::to_string(larger(id.pitch.pitch_trim_offset_se_m, id.pitch.pitch_trim_offset_input_se_m) / kMetresPerInch) +
       " in, cm_alpha viscous " + std::to_string(id.pitch.cm_alpha_viscous_m) + " +- " +
       std::to_string(larger(id.pitch.cm_alpha_viscous_se_m, id.pitch.cm_alpha_viscous_input_se_m)))
          .c_str());
}

// Table 1 was computed by the authors WITH their -73 g offset: the lift
// equation reproduces its printed angles of attack and drag coefficients
// only then (the data file's header says otherwise; it is wrong there).
TEST(SteadyIdentification, Graver2003Table1IsPrintedWithTheOffset) {
  const auto rows = read_table(GLIDER_SOURCE_DIR "/tests/data/papers/graver2003_table1_steady_glides.csv");
  const std::vector<SteadyGlideSample> samples = graver_table1();
  LONGS_EQUAL(3, samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const GlideFromLift g = *glide_from_lift(lift, samples[i], -0.073);
    DOUBLES_EQUAL(number(rows[i], "aoa_deg"), g.alpha_rad / kDeg, 0.05);
    DOUBLES_EQUAL(number(rows[i], "cd_frontal"), g.drag_coefficient, 0.005);
    const GlideFromLift bare = *glide_from_lift(lift, samples[i], 0.0);
    CHECK(std::abs(number(rows[i], "aoa_deg") - bare.alpha_rad / kDeg) > 0.5);
  }
}

// (b) Paper 000 sec. 3.2 on its own Table 1: two dives (22.77 and 25.78 deg)
// bracket the one climb (23.74 deg); the linear |a| trend through the dives
// interpolates them to the climb's pitch. Result: -59 g against the paper's
// -73 g, which it found from all its glides (Table 1 holds three).
// Tolerance: the printed digits explain < 1 g, but the paper's own final
// model (-73 g, C_D = 0.214 + 32.3 a^2) misses these three depth rates by a
// few per cent; that per-glide scatter, propagated through the same
// estimator, is the spread a three-glide estimate has: we assert -73 g
// within two of it.
TEST(SteadyIdentification, Graver2003OffsetFromTable1) {
  const std::vector<SteadyGlideSample> samples = graver_table1();
  BuoyancyOffsetOptions options;
  options.trend_degree = 1;
  options.input_sd = {printed_sd(0.005 * kDeg), printed_sd(0.0005), printed_sd(0.00005), 0.0};
  const BuoyancyOffsetEstimate printed = estimate_buoyancy_offset(lift, samples, options);
  CHECK_TRUE(printed.ok);
  CHECK(printed.input_se_kg < 0.001);
  DOUBLES_EQUAL(-0.059, printed.offset_kg, 0.001);

  double sum_sq = 0.0;
  for (const SteadyGlideSample& s : samples) {
    const auto model_glide = model::steady_glide_for_pitch(we01.hydro, 1025.0, s.pitch_rad, s.ballast_net_kg - 0.073);
    const double miss = s.depth_rate_m_s - model_glide.glide->depth_rate_m_s;
    sum_sq += miss * miss;
  }
  const double scatter_m_s = std::sqrt(sum_sq / static_cast<double>(samples.size()));
  CHECK(scatter_m_s > 0.004 && scatter_m_s < 0.01);  // 3-5 % of the depth rates
  options.input_sd = {0.0, scatter_m_s, 0.0, 0.0};
  const BuoyancyOffsetEstimate scattered = estimate_buoyancy_offset(lift, samples, options);
  CHECK(std::abs(printed.offset_kg - (-0.073)) < 2.0 * scattered.input_se_kg);
  UT_PRINT(("Graver Table 1: offset " + std::to_string(printed.offset_kg * 1e3) + " g (printed digits +- " +
            std::to_string(printed.input_se_kg * 1e3) + " g; paper-model scatter " + std::to_string(scatter_m_s * 1e3) +
            " mm/s -> +- " + std::to_string(scattered.input_se_kg * 1e3) + " g); paper -73 g")
               .c_str());

  // With the polar's slope instead of the fitted trend each dive pairs with
  // the climb on its own; the two pairs agree within a few grams.
  options.alpha_per_pitch = polar_alpha_per_pitch(we01.hydro, 24.1 * kDeg);
  const BuoyancyOffsetEstimate polar = estimate_buoyancy_offset(lift, samples, options);
  CHECK_TRUE(polar.ok);
  LONGS_EQUAL(2, polar.pairs.size());
  DOUBLES_EQUAL(printed.offset_kg, polar.offset_kg, 0.002);
  CHECK(std::abs(polar.pairs[0].offset_kg - polar.pairs[1].offset_kg) < 0.005);
}

// (c) Stante et al. 2008: the measured climbs are faster than the dives at
// equal |ballast|, so the vehicle was light. The four measured segments (not
// their averages, not the authors' simulation); dBu_kg is + buoyant, the
// opposite of ballast_net_kg. Each direction was flown at one pitch (27.0
// and 27.45 deg), so the pitch correction takes the slope of WE01's polar.
TEST(SteadyIdentification, Stante2008VehicleWasLight) {
  std::vector<SteadyGlideSample> samples;
  for (const auto& row : read_table(GLIDER_SOURCE_DIR "/tests/data/papers/stante2008_steady_climbs_dives.csv")) {
    if (row.at("kind") != "measured" || row.at("case").find("avg") != std::string::npos) continue;
    samples.push_back({number(row, "pitch_deg") * kDeg, number(row, "rate_m_s"), -number(row, "dBu_kg"), 0.0, 0.0});
  }
  LONGS_EQUAL(4, samples.size());
  BuoyancyOffsetOptions options;
  options.alpha_per_pitch = polar_alpha_per_pitch(we01.hydro, 27.2 * kDeg);
  options.input_sd = {printed_sd(0.05 * kDeg), printed_sd(0.0005), printed_sd(0.000005), 0.0};
  const BuoyancyOffsetEstimate e = estimate_buoyancy_offset(lift, samples, options);
  CHECK_TRUE(e.ok);
  CHECK(e.offset_kg < 0.0);
  CHECK(e.offset_kg + 3.0 * e.uncertainty_kg < 0.0);
  UT_PRINT(("Stante 2008: offset " + std::to_string(e.offset_kg * 1e3) + " +- " +
            std::to_string(e.uncertainty_kg * 1e3) + " g")
               .c_str());
}
