// SPDX-License-Identifier: Apache-2.0
// The fits kept on a residual function (heading_fit.hpp remembering_fits):
// every selection on it answers bit for bit as on the plain residuals - the
// selection, the closed-loop check's fit_only refit of what it chose, the
// same set from another nominal or on every sample (other problems: nothing
// of the first one's may be read) - and the refit reads what it can.
#include <CppUTest/TestHarness.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "glider/diagnose/heading_fit.hpp"
#include "glider/diagnose/heading_models.hpp"

using namespace glider::diagnose;

namespace {

// The autopilot link's effects, in the order law() takes their values.
constexpr std::array<HeadingEffect, 5> kAutopilotEffects = {
    HeadingEffect::kAutopilotGain, HeadingEffect::kAutopilotIntegral, HeadingEffect::kAutopilotDgain,
    HeadingEffect::kAutopilotDelay, HeadingEffect::kAutopilotDeadband};

// A law: gain, integral gain, dgain, delay, deadband (every other effect 0).
HeadingValues law(const std::array<double, 5>& values) {
  HeadingValues v{};
  for (std::size_t j = 0; j < values.size(); ++j) at(v, kAutopilotEffects[j]) = values[j];
  return v;
}

// An autopilot log: a 4 s cycle with jitter, the fin centred 5 rows in 60
// (a surfacing), the command changing at each, the heading wandering round
// it (an AR(1) error of ~0.05 rad: the fin mostly off its limit, so the
// gains show); the logged command is the law `flown` replayed, plus noise.
struct Log {
  HeadingTrack track;
  std::vector<double> measured;
  LinkSamples samples;
};

Log autopilot_log(std::uint64_t seed, const HeadingValues& flown) {
  Log log;
  HeadingTrack& t = log.track;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> jitter(0.0, 0.1), wander(0.0, 0.02), noise(0.0, 0.01);
  double time = 0.0, error = 0.0;
  constexpr std::size_t kRows = 480;
  for (std::size_t i = 0; i < kRows; ++i) {
    time += 4.0 + jitter(rng);
    error = 0.9 * error + wander(rng);
    const bool centred = i % 60 < 5;
    const double command = (i / 60) % 2 == 0 ? 0.3 : -0.2;
    t.row_time_s.push_back(time);
    t.row_heading_rad.push_back(command + error);
    t.row_command_rad.push_back(command);
    t.row_gliding.push_back(!centred);
    t.row_depth_m.push_back(centred ? 0.0 : 2.0 + static_cast<double>(i % 60));
  }
  t.fin_max_rad = 0.45;
  std::vector<std::size_t> rows(kRows);
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  AutopilotReplay(t, AutopilotSettings{}).predict(flown, rows, log.measured);
  for (double& c : log.measured) c += noise(rng);
  // Alternate glides fitted and held out; a glide's first half diving.
  LinkSamples& s = log.samples;
  s.yo.assign(kRows, 0);
  s.phase.assign(kRows, 0);
  for (std::size_t i = 0; i < kRows; ++i) {
    if (!t.row_gliding[i]) continue;
    const auto glide = static_cast<int>(i / 60);
    s.all.push_back(i);
    (glide % 2 == 0 ? s.train : s.heldout).push_back(i);
    (i % 60 < 30 ? s.dives : s.climbs).push_back(i);
    s.yo[i] = glide;
    s.phase[i] = i % 60 < 30 ? 0 : 1;
  }
  return log;
}

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Every number a LinkFit states, as bits (a difference in any: not the same fit).
std::vector<std::uint64_t> stated(const LinkFit& f) {
  std::vector<std::uint64_t> out;
  for (double x : {f.baseline_rms, f.baseline_rms_dive, f.baseline_rms_climb, f.baseline_heldout_rms, f.extended_rms,
                   f.extended_heldout_rms, f.gain}) {
    out.push_back(bits(x));
  }
  for (double x : f.values) out.push_back(bits(x));
  for (const HeadingFinding& h : f.findings) {
    out.push_back(static_cast<std::uint64_t>(h.effect));
    for (double x : {h.value, h.nominal, h.ci95_low, h.ci95_high, h.heldout_rms, h.gain}) out.push_back(bits(x));
  }
  for (const HeadingAmbiguity& a : f.identifiability) {
    out.push_back(static_cast<std::uint64_t>(a.alternative));
    for (double x : {a.correlation, a.alternative_value, a.chosen_heldout_rms, a.alternative_heldout_rms}) {
      out.push_back(bits(x));
    }
  }
  for (const LinkFit::ScreenedCorrelation& c : f.screen) out.push_back(bits(c.correlation));
  return out;
}

}  // namespace

TEST_GROUP(RememberedFits){};

// A log whose flown law has a larger gain, an integral and a cycle's delay
// over the nominal: the selection names some of them; each later question
// is answered on the plain residuals (a new problem each time) and on the
// remembering ones (one, kept), and the answers compared bit for bit. The
// seed is fresh each run (printed on failure).
TEST(RememberedFits, EverySelectionAnswersAsOnThePlainResiduals) {
  const std::uint64_t seed = std::random_device{}();
  const std::string replay_with = "seed " + std::to_string(seed);
  const HeadingValues nominal = law({0.3, 0.0, -2.0, 0.0, 0.0});
  const Log log = autopilot_log(seed, law({0.6, 0.004, -2.0, 4.0, 0.0}));
  long calls = 0;
  AutopilotReplay plain_replay(log.track, AutopilotSettings{}), kept_replay(log.track, AutopilotSettings{});
  auto against_log = [&](AutopilotReplay& replay) {
    return HeadingResiduals([&](const HeadingValues& v, std::span<const std::size_t> which, std::vector<double>& out) {
      ++calls;
      replay.predict(v, which, out);
      for (std::size_t k = 0; k < which.size(); ++k) out[k] -= log.measured[which[k]];
    });
  };
  const HeadingResiduals plain = against_log(plain_replay);
  const HeadingResiduals kept = remembering_fits(against_log(kept_replay));
  const std::vector<HeadingEffect> candidates(kAutopilotEffects.begin(), kAutopilotEffects.end());
  HeadingSelectOptions select;
  select.margins.absolute = 0.002;
  auto both = [&](const HeadingValues& from, const HeadingSelectOptions& options, long* kept_calls) {
    LinkFit a = select_heading_effects(HeadingLink::kAutopilot, candidates, from, plain, log.samples, options);
    const long before = calls;
    const LinkFit b = select_heading_effects(HeadingLink::kAutopilot, candidates, from, kept, log.samples, options);
    if (kept_calls != nullptr) *kept_calls = calls - before;
    CHECK_TEXT(stated(a) == stated(b), replay_with.c_str());
    return a;
  };
  const LinkFit selected = both(nominal, select, nullptr);
  CHECK_TEXT(!selected.findings.empty(), replay_with.c_str());  // the refits below refit a set, not the baseline alone

  // The closed-loop check's question: exactly what the selection chose.
  HeadingSelectOptions refit = select;
  refit.select = false;
  for (const HeadingFinding& f : selected.findings) refit.fit_only.push_back(f.effect);
  long refit_calls = 0;
  const long before = calls;
  both(nominal, refit, &refit_calls);
  const long plain_calls = calls - before - refit_calls;
  // Read, not refitted: fewer residual calls than on the plain residuals
  // (the selection's own five - the penalty's scale, the three baselines,
  // the final RMS - where the findings come in the selection's order; a set
  // asked in another order is another fit, made).
  CHECK_TEXT(refit_calls < plain_calls, (replay_with + ": " + std::to_string(refit_calls) + " calls kept, " +
                                         std::to_string(plain_calls) + " plain")
                                            .c_str());

  // Other problems on the same residuals: another nominal, every sample
  // trained on (another context), the deadband with the others.
  HeadingValues moved = nominal;
  at(moved, HeadingEffect::kAutopilotGain) += 0.05;
  both(moved, refit, nullptr);
  HeadingSelectOptions on_all = refit;
  on_all.fit_on_all_samples = true;
  both(nominal, on_all, nullptr);
  HeadingSelectOptions with_deadband = refit;
  with_deadband.fit_only.push_back(HeadingEffect::kAutopilotDeadband);
  both(nominal, with_deadband, nullptr);
}
