// SPDX-License-Identifier: Apache-2.0
// The autopilot replay's caches (heading_models.hpp AutopilotReplay): a
// replay kept across many values answers each bit for bit as a fresh one
// does, and where the law never holds its integrator kept for a gain (the
// replays that move only the gain on the error or the rate reuse it) is the
// law's own, stepped.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

#include "glider/diagnose/heading_models.hpp"

using namespace glider::diagnose;

namespace {

// A log of the autopilot's rows: a 4 s cycle with jitter, every 40th gap
// two or three cycles long (the law steps at the unlogged cycles), the fin
// centred for 5 rows every 60 (the surface: the rate restarts, the
// integrator is kept), a NaN heading in each glide (no prediction; away
// from the long gaps, whose unlogged cycles would read it and leave the
// integrator NaN from there on), the
// command changing at each centring, the heading wandering round it.
HeadingTrack autopilot_track() {
  HeadingTrack t;
  std::mt19937_64 rng(20261128);
  std::normal_distribution<double> jitter(0.0, 0.1), wander(0.0, 0.03);
  double time = 0.0, heading = 0.2;
  for (std::size_t i = 0; i < 600; ++i) {
    time += 4.0 * (i % 40 == 39 ? static_cast<double>(2 + (i / 40) % 2) : 1.0) + jitter(rng);
    heading += wander(rng);
    const bool centred = i % 60 < 5;
    t.row_time_s.push_back(time);
    t.row_heading_rad.push_back(i % 60 == 30 ? std::nan("") : heading);
    t.row_command_rad.push_back((i / 60) % 2 == 0 ? 0.3 : -2.9);
    t.row_gliding.push_back(!centred);
    t.row_depth_m.push_back(centred ? 0.0 : 2.0 + static_cast<double>(i % 60));
  }
  t.fin_max_rad = 0.45;
  return t;
}

std::vector<std::size_t> all_rows(const HeadingTrack& t) {
  std::vector<std::size_t> rows(t.row_time_s.size());
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  return rows;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

HeadingValues law(double gain, double integral, double dgain, double delay, double deadband) {
  HeadingValues v{};
  at(v, HeadingEffect::kAutopilotGain) = gain;
  at(v, HeadingEffect::kAutopilotIntegral) = integral;
  at(v, HeadingEffect::kAutopilotDgain) = dgain;
  at(v, HeadingEffect::kAutopilotDelay) = delay;
  at(v, HeadingEffect::kAutopilotDeadband) = deadband;
  return v;
}

// How many of `asked`, replayed in order by one replay, differ from a fresh
// replay's answer (under both clocks).
int differing(const HeadingTrack& t, const std::vector<HeadingValues>& asked) {
  const std::vector<std::size_t> rows = all_rows(t);
  int differ = 0;
  for (const AutopilotClock clock : {AutopilotClock::kMeasured, AutopilotClock::kNominal}) {
    AutopilotReplay kept(t, AutopilotSettings{}, clock);
    std::vector<double> cached, fresh;
    for (const HeadingValues& v : asked) {
      kept.predict(v, rows, cached);
      AutopilotReplay(t, AutopilotSettings{}, clock).predict(v, rows, fresh);
      if (!same_bits(cached, fresh)) ++differ;
    }
  }
  return differ;
}

// The law stepped row by row through AutopilotLaw::step on the heading as
// logged (no autopilot delay, every cycle logged: what the replay reads is
// then the rows themselves, but before a NaN, read across it), the
// measured clock.
std::vector<double> stepped_law(const HeadingTrack& t, const AutopilotSettings& settings, const HeadingValues& v) {
  AutopilotLaw law = AutopilotLaw::from(v, settings, t.fin_max_rad);
  std::vector<double> out(t.row_time_s.size(), std::nan(""));
  double last = std::nan("");
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!t.row_gliding[i]) {
      law.output = 0.0;
      last = std::nan("");
      continue;
    }
    // Read between this row and the next (0 s past this one): NaN where
    // the next heading is NaN.
    const bool next_nan = i + 1 < out.size() && !std::isfinite(t.row_heading_rad[i + 1]);
    const double heading = next_nan ? std::nan("") : t.row_heading_rad[i];
    if (!std::isfinite(heading)) continue;
    const double dt = i > 0 ? t.row_time_s[i] - t.row_time_s[i - 1] : 0.0;
    const double rate = std::isfinite(last) && dt > 0.0 ? std::remainder(heading - last, 2.0 * M_PI) / dt : 0.0;
    out[i] = law.step(std::remainder(t.row_command_rad[i] - heading, 2.0 * M_PI), rate, dt);
    last = heading;
  }
  return out;
}

}  // namespace

TEST_GROUP(AutopilotReplay){};

// On a log of every cycle (a steady 4 s cycle with jitter: no unlogged
// ones) and no autopilot delay, the replay's outputs are the law's stepped
// row by row, bit for bit: without a heading deadband (the integrator summed
// apart from the output) and with one that holds the fin at some steps.
TEST(AutopilotReplay, TheReplayIsTheLawStepped) {
  HeadingTrack t;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> jitter(0.0, 0.1), wander(0.0, 0.01);
  double time = 0.0, heading = 0.25;
  for (std::size_t i = 0; i < 500; ++i) {
    time += 4.0 + jitter(rng);
    heading += wander(rng);
    const bool centred = i % 100 < 4;
    t.row_time_s.push_back(time);
    t.row_heading_rad.push_back(i % 100 == 50 ? std::nan("") : heading);
    t.row_command_rad.push_back((i / 100) % 2 == 0 ? 0.3 : 0.2);
    t.row_gliding.push_back(!centred);
    t.row_depth_m.push_back(centred ? 0.0 : 5.0);
  }
  t.fin_max_rad = 0.45;
  const std::vector<std::size_t> rows = all_rows(t);
  const AutopilotSettings settings;
  AutopilotReplay replay(t, settings);
  int held = 0;  // laws whose deadband moved the outputs (held the fin at some steps)
  for (const double deadband : {0.0, 0.02, 0.06}) {
    for (const double gain : {0.5, 1.5, 4.0}) {
      for (const double integral : {0.0, 0.02, 0.1}) {
        const HeadingValues v = law(gain, integral, -4.0, 0.0, deadband);
        std::vector<double> replayed;
        replay.predict(v, rows, replayed);
        CHECK_TRUE(same_bits(replayed, stepped_law(t, settings, v)));
        held += same_bits(replayed, stepped_law(t, settings, law(gain, integral, -4.0, 0.0, 0.0))) ? 0 : 1;
      }
    }
  }
  LONGS_EQUAL(18, held);
}

// Six delays of one integral gain, more than the replay keeps (four): a
// delay's buffers taken by another must not answer with the integrator
// they held under the same gain (with it left valid, 8 of the 16 answers
// differ from a fresh replay's).
TEST(AutopilotReplay, ADelayNeverReadsAnotherDelaysIntegrator) {
  const HeadingTrack t = autopilot_track();
  std::vector<HeadingValues> asked;
  for (const double delay : {0.0, 1.3, 2.6, 3.9, 5.2, 6.5, 0.0, 2.6}) asked.push_back(law(1.5, 0.02, -4.0, delay, 0.0));
  LONGS_EQUAL(0, differing(t, asked));
}

// A Jacobian's columns and steps: the gains on the error and the rate moved
// alone (the integrator kept), the integral gain moved and moved back, a
// heading deadband set and cleared at a delay kept, the same values again.
TEST(AutopilotReplay, AFitsQuestionsAreAnsweredAsAFreshReplayAnswers) {
  const HeadingTrack t = autopilot_track();
  const std::vector<HeadingValues> asked = {
      law(1.5, 0.02, -4.0, 0.7, 0.0),  law(1.6, 0.02, -4.0, 0.7, 0.0), law(1.5, 0.03, -4.0, 0.7, 0.0),
      law(1.5, 0.02, -3.0, 0.7, 0.0),  law(1.5, 0.02, -4.0, 0.8, 0.0), law(1.5, 0.02, -4.0, 0.7, 0.05),
      law(1.7, 0.02, -4.0, 0.7, 0.05), law(1.5, 0.02, -4.0, 0.7, 0.0), law(1.5, 0.02, -4.0, 0.7, 0.0),
      law(2.0, -0.01, 1.0, 0.7, 0.0),  law(1.5, 0.03, -4.0, 0.7, 0.0), law(1.5, 0.02, -4.0, 0.7, 0.0)};
  LONGS_EQUAL(0, differing(t, asked));
}

// Where the law never holds, the replay sums the integrator apart from the
// output (and keeps it); a heading deadband too small to hold any step here
// steps the law itself, cycle by cycle (AutopilotLaw::step_read): the same
// bits, fin limits and unlogged cycles included.
TEST(AutopilotReplay, TheIntegratorKeptIsTheLawsOwn) {
  const HeadingTrack t = autopilot_track();
  const std::vector<std::size_t> rows = all_rows(t);
  std::size_t predicted = 0;
  for (const AutopilotClock clock : {AutopilotClock::kMeasured, AutopilotClock::kNominal}) {
    AutopilotReplay replay(t, AutopilotSettings{}, clock);
    for (const double gain : {0.5, 1.5, 4.0}) {
      for (const double delay : {0.0, 2.1}) {
        std::vector<double> summed, stepped;
        replay.predict(law(gain, 0.05, -4.0, delay, 0.0), rows, summed);
        replay.predict(law(gain, 0.05, -4.0, delay, 1e-300), rows, stepped);
        CHECK_TRUE(same_bits(summed, stepped));
        for (const double fin : summed) predicted += std::isfinite(fin) ? 1 : 0;
      }
    }
  }
  // Most rows predict (the centred and NaN rows do not).
  CHECK_TRUE(predicted > 12 * 500);
}
