// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_diagnose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "glider/diagnose/heading_select_delay_side.hpp"
#include "glider/diagnose/heading_select_resolution.hpp"
#include "glider/diagnose/thin.hpp"
#include "glider/fitting_core/intervals.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The current's shear is fitted from this long after a glide starts (s):
// the pitch-over and the turn it makes are done.
constexpr double kShearSettleS = 20.0;

// Plausible ranges: a dead time beyond a minute is a broken servo or loop,
// not a lag; a fin with a tenth or ten times the assumed authority is a
// different vehicle; a roll of 20 deg would show in any attitude sensor; an
// autopilot gain beyond 5 rad/rad saturates the fin at a degree of error.
const std::array<HeadingEffectInfo, kHeadingEffectCount> kInfo{{
    {"fin_delay", "s", HeadingLink::kServo, 2.0, 0.0, 60.0, true},
    {"fin_deadband", "rad", HeadingLink::kServo, 0.005, 0.0, 0.1, true, true, 0.001},
    {"yaw_delay", "s", HeadingLink::kVehicle, 2.0, 0.0, 60.0, true},
    {"fin_effectiveness", "ratio", HeadingLink::kVehicle, 0.2, 0.1, 10.0, false},
    {"roll_offset", "rad", HeadingLink::kVehicle, 0.02, -0.35, 0.35, false},
    {"yaw_time_constant", "s", HeadingLink::kVehicle, 2.0, 0.05, 60.0, true},
    {"autopilot_gain", "rad/rad", HeadingLink::kAutopilot, 0.2, 0.0, 5.0, false},
    {"autopilot_integral", "1/s", HeadingLink::kAutopilot, 0.005, -0.2, 0.2, false},
    {"autopilot_dgain", "s", HeadingLink::kAutopilot, 1.0, -30.0, 30.0, false},
    {"autopilot_delay", "s", HeadingLink::kAutopilot, 2.0, 0.0, 60.0, true},
    {"autopilot_deadband", "rad", HeadingLink::kAutopilot, 0.01, 0.0, 0.2, true, true},
    {"lift_factor", "ratio", HeadingLink::kVehicle, 0.1, 0.3, 3.0, false, false, 0.0, true},
}};

// A finding must also cut the held-out error by this much (the link's unit):
// a tenth of a degree of fin, a hundredth of a degree per second of yaw.
double min_absolute_improvement(HeadingLink link) { return link == HeadingLink::kVehicle ? 0.0002 : 0.002; }

// Alternate yos fit and are held out; phases from the depth's direction.
LinkSamples split(const std::vector<std::size_t>& all, const std::vector<int>& yo, const std::vector<bool>& diving,
                  std::size_t max_samples) {
  LinkSamples s;
  s.all = all;
  std::size_t size = 0;
  for (std::size_t i : all) size = std::max(size, i + 1);
  s.yo.assign(size, 0);
  s.phase.assign(size, 0);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const std::size_t i = all[k];
    (yo[i] % 2 == 0 ? s.train : s.heldout).push_back(i);
    (diving[k] ? s.dives : s.climbs).push_back(i);
    s.yo[i] = yo[i];
    s.phase[i] = diving[k] ? 0 : 1;
  }
  thin(s.train, max_samples);
  thin(s.heldout, max_samples);
  return s;
}

std::vector<HeadingEffect> effects_of(HeadingLink link, const std::vector<HeadingEffect>& among) {
  std::vector<HeadingEffect> out;
  for (HeadingEffect e : among) {
    if (info(e).link == link) out.push_back(e);
  }
  return out;
}

std::vector<HeadingEffect> all_effects() {
  std::vector<HeadingEffect> out;
  for (std::size_t i = 0; i < kHeadingEffectCount; ++i) {
    const auto e = static_cast<HeadingEffect>(i);
    if (!info(e).rival_only) out.push_back(e);
  }
  return out;
}

// Residuals of a prediction against a measured series.
HeadingResiduals against(
    std::function<void(const HeadingValues&, std::span<const std::size_t>, std::vector<double>&)> predict,
    const std::vector<double>& measured) {
  return [predict = std::move(predict), &measured](const HeadingValues& v, std::span<const std::size_t> which,
                                                   std::vector<double>& out) {
    predict(v, which, out);
    for (std::size_t k = 0; k < which.size(); ++k) out[k] -= measured[which[k]];
  };
}

// The autopilot's glides: each row where the law steps (a heading command,
// gliding; AutopilotReplay's kStep or kNone rows) numbered by the stretch
// between two centred ones; -1 where the fin is centred.
std::vector<int> autopilot_glides(const HeadingTrack& t) {
  std::vector<int> glide(t.row_time_s.size(), -1);
  int g = -1;
  bool was_active = false;
  for (std::size_t i = 0; i < glide.size(); ++i) {
    const bool active = std::isfinite(t.row_command_rad[i]) && t.row_gliding[i];
    if (active && !was_active) ++g;
    if (active) glide[i] = g;
    was_active = active;
  }
  return glide;
}

// The autopilot link's residuals with the integrator's state at each
// glide's start profiled out. The replay steps the integrator from the
// log's start with each row's measured interval; the glider's law need not
// (the independent truth's integrates over its nominal cycle, unclamped,
// while the fin is saturated and the error large: a few hundredths of a
// radian of integrator gained or lost in each wind-up), and from then on the
// replay misses the log's c_fin by that constant until the next wind-up (a
// truth log with a clean heading: 0.03 rad from a wind-up to its end, named an
// autopilot delay of 1.24 s cutting the held-out error 27 %). The log holds
// nothing that fixes that state but c_fin itself, so it is a nuisance per
// glide: the residual's mean over the glide's rows where neither fin is at
// its limit (there a shift of the integrator does not move the output) is
// taken off those rows. What the effects do within a glide - a gain on the
// error, a rate gain, a delay, a deadband, the integral's own build-up - is
// left to the fit; a gain on an error that is steady over a glide is not
// (docs/science.md "The autopilot's integrator at each glide's start").
HeadingResiduals integrator_per_glide(HeadingResiduals residuals, const HeadingTrack& t,
                                      const std::vector<double>& measured) {
  constexpr std::size_t kMinRows = 3;  // fewer: the glide's mean would be its residuals
  const double limit = (1.0 - 1e-3) * t.fin_max_rad;
  const std::vector<int> glide = autopilot_glides(t);
  const int glides = glide.empty() ? 0 : *std::max_element(glide.begin(), glide.end()) + 1;
  // Per row, its glide where the logged fin is off its limit (else -1): the
  // half of the test that does not move with the values, made once. The
  // sums and counts per glide and each sample's glide (-1: not free) are
  // kept between calls (sized once; a fit calls this thousands of times).
  std::vector<int> free_glide(glide.size(), -1);
  for (std::size_t i = 0; i < glide.size(); ++i) {
    if (glide[i] >= 0 && std::abs(measured[i]) < limit) free_glide[i] = glide[i];
  }
  struct Scratch {
    std::vector<double> sum;
    std::vector<std::size_t> n;
    std::vector<int> sample_glide;
  };
  // The fits on it kept (remembering_fits): the closed-loop check refits
  // the sets the selection fitted on these residuals.
  return remembering_fits([residuals = std::move(residuals), free_glide = std::move(free_glide), glides, limit,
                           &measured, scratch = std::make_shared<Scratch>()](
                              const HeadingValues& v, std::span<const std::size_t> which, std::vector<double>& out) {
    residuals(v, which, out);
    Scratch& s = *scratch;
    s.sum.assign(static_cast<std::size_t>(glides), 0.0);
    s.n.assign(static_cast<std::size_t>(glides), 0);
    s.sample_glide.assign(which.size(), -1);
    // The glide's sum is carried in a register while its samples follow one
    // another (the same additions in the same order: the same bits), stored
    // when another glide's sample comes.
    int at = -1;
    double sum = 0.0;
    for (std::size_t k = 0; k < which.size(); ++k) {
      const std::size_t i = which[k];
      const int g = free_glide[i];
      if (g < 0 || !std::isfinite(out[k])) continue;
      const double predicted = out[k] + measured[i];
      if (!(std::abs(predicted) < limit)) continue;
      s.sample_glide[k] = g;
      if (g != at) {
        if (at >= 0) s.sum[static_cast<std::size_t>(at)] = sum;
        at = g;
        sum = s.sum[static_cast<std::size_t>(g)];
      }
      sum += out[k];
      ++s.n[static_cast<std::size_t>(g)];
    }
    if (at >= 0) s.sum[static_cast<std::size_t>(at)] = sum;
    for (std::size_t k = 0; k < which.size(); ++k) {
      const int g = s.sample_glide[k];
      if (g < 0) continue;
      const auto gi = static_cast<std::size_t>(g);
      if (s.n[gi] >= kMinRows) out[k] -= s.sum[gi] / static_cast<double>(s.n[gi]);
    }
  });
}

LinkFit run_link(HeadingLink link, const HeadingValues& nominal, const HeadingResiduals& residuals,
                 const LinkSamples& samples, const HeadingDiagnoseOptions& options) {
  HeadingSelectOptions select;
  select.margins.absolute = min_absolute_improvement(link);
  select.intervals = options.intervals;
  const std::vector<HeadingEffect> candidates = effects_of(link, all_effects());
  if (!options.fit_only.empty()) {
    select.fit_only = effects_of(link, options.fit_only);
    select.select = false;
    select.fit_on_all_samples = options.fit_on_all_samples;
  }
  return select_heading_effects(link, candidates, nominal, residuals, samples, select);
}

// Half the second difference of the heading, over the glides' samples:
// white noise of sigma gives an RMS of sigma sqrt(3/2), a smooth turn none.
double heading_jitter_rad(const HeadingTrack& t) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t run = 0; run < t.run_first.size(); ++run) {
    for (std::size_t i = t.run_first[run] + 1; i + 1 < t.run_end(run); ++i) {
      const double second =
          0.5 * ((t.heading_rad[i + 1] - t.heading_rad[i]) - (t.heading_rad[i] - t.heading_rad[i - 1]));
      sum += second * second;
      ++n;
    }
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n) / 1.5) : 0.0;
}

// The closed-loop check's absolute margin, in units of the log's
// glide-to-glide scatter (heading_closed_loop.hpp): a twentieth of it.
constexpr double kClosedLoopMargin = 0.05;

// The autopilot link flown closed-loop (heading_closed_loop.hpp): the servo
// and vehicle findings and the shear are the plant.
ClosedLoopCheck check_closed_loop(const HeadingTrack& track, const model::VehicleParams& nominal,
                                  const HeadingValues& base, const HeadingDiagnosis& d,
                                  const std::function<LinkFit(const std::vector<HeadingEffect>&)>& fit_autopilot) {
  HeadingValues plant = base;
  for (const LinkFit* link : {&d.servo, &d.yaw}) {
    for (const HeadingFinding& f : link->findings) at(plant, f.effect) = f.value;
  }
  ClosedLoopOptions fly_options;
  fly_options.heading_noise_rad = d.heading_noise_rad;
  const std::function<std::vector<ClosedLoopGlide>(const HeadingValues&)> fly = [&](const HeadingValues& v) {
    return fly_closed_loop(track, nominal, d.configured, v, &d.current_shear, fly_options);
  };
  std::vector<HeadingEffect> open_loop;
  for (const HeadingFinding& f : d.autopilot.findings) open_loop.push_back(f.effect);
  fitting_core::Margins margins;
  margins.absolute = kClosedLoopMargin;
  return check_autopilot_closed_loop(open_loop, d.autopilot.candidates, plant, fit_autopilot, fly, margins);
}

// The fin's measurement on the innovations: at most this many rounds of
// noise and fin, stopped when the fin moves less than this.
constexpr int kNoiseRounds = 4;
constexpr double kFinSettled = 0.01;
// Rounds of the fin on the innovations and the selection on the rate error.
constexpr int kAlternations = 3;

// Glide samples once the pitch-over is done (kShearSettleS), split as the
// links' samples: the innovations' own (their random-yaw state takes the
// lift factor's settling that the rate error's 80 s avoid, and the turns
// onto each glide's heading - the fin moves the command asks for, not the
// ones the loop makes against the water - are what tells the fin's
// authority apart from the random yaw).
LinkSamples settled_samples(const HeadingTrack& track, std::size_t max_samples) {
  std::vector<std::size_t> samples;
  std::vector<bool> diving;
  for (std::size_t run = 0; run < track.run_first.size(); ++run) {
    for (std::size_t i = track.run_first[run] + 1; i < track.run_end(run); ++i) {
      if (track.time_s[i] - track.time_s[track.run_first[run]] < kShearSettleS) continue;
      samples.push_back(i);
      diving.push_back(track.phase[i] == flightlog::Phase::kDive);
    }
  }
  return split(samples, track.yo, diving, max_samples);
}

// The lag probe's screen (measure_fin_then_reselect): the probe (the lag
// measured beside the fin on the innovations, noise and fin refitted for
// up to kNoiseRounds rounds) cost comet-2016's diagnosis 6.3 -> 10.4 s of
// CPU on a log where the rate error names nothing and the probe stands on
// nothing. The screen asks the innovations the probe's question once,
// cheaply: the noise refined from the compass's jitter and the rate
// error's RMS (no grid: a local search, repeated while it still moves by
// its coarsest step), the lag alone on its start grid (1-40 s, the fin and
// the rest nominal), the noise refined once more at the grid's best lag,
// and the held-out yos' innovations with that lag against the vehicle
// file's, both with that noise, by half the selection's relative margin.
// Only where they are better is the probe run (docs/science.md "The yaw's lag probe
// screened").
constexpr int kScreenNoiseSearches = 4;
constexpr double kScreenNoiseMoved = 1.3;  // a field moved by more than this: search again
// Half the selection's relative margin: the screen holds the fin at the
// vehicle file's and the lag on a 1 s grid, so it reads the probe's gain
// short (a hidden yaw delay of 5.30 s the probe names 6.06 s: the screen's
// lag 2.8 % better; design seed 711435591).
constexpr double kScreenMargin = 0.5 * fitting_core::Margins{}.relative;
// The screens' grids: the lag from 1 to 40 s by 1 s; the fin's authority
// from half to two and a half times the vehicle file's by a tenth (the fin's
// screen, measure_fin_then_reselect).
constexpr std::array<double, 40> kLagScreenGrid = [] {
  std::array<double, 40> grid{};
  double lag = 1.0;
  for (double& x : grid) {
    x = lag;
    lag += 1.0;
  }
  return grid;
}();
constexpr std::array<double, 20> kFinScreenGrid{0.5, 0.6, 0.7, 0.8, 0.9, 1.1, 1.2, 1.3, 1.4, 1.5,
                                                1.6, 1.7, 1.8, 1.9, 2.0, 2.1, 2.2, 2.3, 2.4, 2.5};

// The RMS of the heading's innovations at these samples (NaN: none finite).
double innovations_rms(const HeadingTrack& track, const model::VehicleParams& nominal, const HeadingValues& values,
                       const YawNoise& noise, std::span<const std::size_t> samples) {
  std::vector<double> r;
  heading_innovations(track, nominal, values, noise, samples, r);
  double sum = 0.0;
  std::size_t n = 0;
  for (double x : r) {
    if (!std::isfinite(x)) continue;
    sum += x * x;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : kNaN;
}

YawNoise refine_noise(const HeadingTrack& track, const model::VehicleParams& nominal, const HeadingValues& values,
                      YawNoise noise, std::span<const std::size_t> samples, int searches) {
  for (int k = 0; k < searches; ++k) {
    const YawNoise next = fit_yaw_noise(track, nominal, values, noise, samples, false);
    bool moved = false;
    for (double YawNoise::*field : {&YawNoise::heading_rad, &YawNoise::disturbance_rad_s, &YawNoise::correlation_s}) {
      const double ratio = next.*field / noise.*field;
      moved = moved || ratio > kScreenNoiseMoved || ratio < 1.0 / kScreenNoiseMoved;
    }
    noise = next;
    if (!moved) break;
  }
  return noise;
}

// The screens' noise: refined from the compass's jitter and the rate
// error's RMS at the vehicle file's values (read_screen).
YawNoise screen_noise(const HeadingTrack& track, const model::VehicleParams& nominal, const HeadingValues& base,
                      const LinkSamples& samples, double heading_noise_rad, double rate_error_rms) {
  YawNoise noise;
  noise.heading_rad = std::max(heading_noise_rad, 1e-4);
  noise.disturbance_rad_s = std::max(rate_error_rms, 1e-4);
  return refine_noise(track, nominal, base, noise, samples.all, kScreenNoiseSearches);
}

// A screen's reading: the held-out yos' innovations with the grid's best
// value and with the vehicle file's (NaN: the grid's best is the file's).
struct ScreenRead {
  double with_rms = kNaN, without_rms = kNaN;
  // The grid's best predicts the held-out yos better by this relative margin.
  [[nodiscard]] bool shows(double relative_margin) const {
    return fitting_core::improves_heldout(with_rms, without_rms, fitting_core::Margins{relative_margin, 0.0});
  }
};

// One effect asked of the innovations on its grid, the rest at the vehicle
// file's values (the lag screen's steps above; the fin's screen the same).
// It shows a gain where the grid's best predicts the held-out yos better
// than the vehicle file's value by half the selection's relative margin.
ScreenRead read_screen(const HeadingTrack& track, const model::VehicleParams& nominal, const HeadingValues& base,
                       const LinkSamples& samples, YawNoise noise, HeadingEffect effect, std::span<const double> grid) {
  auto rms = [&](double value, std::span<const std::size_t> which) {
    HeadingValues v = base;
    at(v, effect) = value;
    return innovations_rms(track, nominal, v, noise, which);
  };
  const double vehicle_file = at(base, effect);
  double best = vehicle_file, best_rms = rms(best, samples.train);
  for (double value : grid) {
    if (const double x = rms(value, samples.train); x < best_rms) {
      best_rms = x;
      best = value;
    }
  }
  if (best == vehicle_file) return {};
  HeadingValues with = base;
  at(with, effect) = best;
  noise = refine_noise(track, nominal, with, noise, samples.all, 1);
  return {rms(best, samples.heldout), rms(vehicle_file, samples.heldout)};
}

// The yaw's own dynamics, measured beside the fin on the innovations where
// the rate error names them (measure_fin_then_reselect).
// The yaw's delay read beside the fast pole the models carry at its
// prior's centre (HeadingTrackOptions::yaw_fast_pole_max_s): rows seconds
// apart measure delay + pole, so a pole anywhere in its prior (0 to the
// upper end) moves the delay by the centre's distance to it - the interval
// widened by both, never below 0. The value stays the prior's centre's.
void widen_for_fast_pole(LinkFit& link, const HeadingTrack& track) {
  const double shorter = track.yaw_fast_pole_max_s - track.yaw_fast_pole_s, longer = track.yaw_fast_pole_s;
  for (HeadingFinding& f : link.findings) {
    if (f.effect != HeadingEffect::kYawDelay) continue;
    f.ci95_low = std::max(0.0, f.ci95_low - shorter);
    f.ci95_high += longer;
  }
}

// -2 log likelihood differences under this are not told apart (chi-square,
// one degree of freedom, 95 %).
constexpr double kLikelihoodSpan95 = 3.84;

// The yaw's lag (and the fin beside it) read beside the fast pole the
// first-order yaw lacks. A second pole p behind the lag delays the yaw's
// answer to each fin move; a first-order yaw reads that delay as a longer
// lag, and the fin along fin / lag as stronger - by far more than p on the
// innovations one cycle apart: the independent truth's 11.03 s lag (second
// pole 0.97 s, fin x1.689) read 14.77 s [13.39, 16.15] and fin 2.137,
// 11.74 s and 1.779 with the truth's pole switched off (docs/science.md
// "The yaw's lag beside the fast pole, profiled"). The lag and fin are
// measured again with the pole carried at its prior's centre and upper end
// (HeadingTrack::yaw_fast_pole_s, yaw_fast_pole_max_s); the innovations'
// -2 log likelihood (the noise refined at each from the pole-free
// reading's, no grid: the grid doubled the diagnosis's CPU) chooses: the likeliest
// reading's values stand, each interval spanning the readings whose
// likelihood is within kLikelihoodSpan95 of it (the poles this log cannot
// tell apart) as their equal-weight mixture. `measured` and `noise` are replaced by the likeliest's.
template <typename Measure>
void read_beside_fast_pole(const HeadingTrack& track, const model::VehicleParams& nominal, const HeadingValues& rest,
                           const std::vector<HeadingEffect>& to_measure, std::span<const std::size_t> samples,
                           std::vector<HeadingFinding>& measured, YawNoise& noise, HeadingDiagnosis& d,
                           Measure&& measure) {
  if (!(track.yaw_fast_pole_max_s > 0.0)) return;
  struct Reading {
    double pole = 0.0, cost = kNaN;
    std::vector<HeadingFinding> findings;
    YawNoise noise;
  };
  auto cost_of = [&](const HeadingTrack& on, const std::vector<HeadingFinding>& m, const YawNoise& n) {
    HeadingValues v = rest;
    for (const HeadingFinding& f : m) at(v, f.effect) = f.value;
    return innovations_cost(on, nominal, v, n, samples);
  };
  std::vector<Reading> readings = {{0.0, cost_of(track, measured, noise), measured, noise}};
  const YawNoise start = noise;
  // Each pole's reading starts from the last one's (values and noise).
  for (const double pole : {track.yaw_fast_pole_s, track.yaw_fast_pole_max_s}) {
    HeadingTrack poled = track;
    poled.yaw_fast_pole_with_lag_s = pole;
    HeadingValues from = rest;
    for (const HeadingFinding& f : readings.back().findings) at(from, f.effect) = f.value;
    noise = readings.back().noise;
    std::vector<HeadingFinding> m = measure(poled, to_measure, from, false);
    const bool complete = std::all_of(measured.begin(), measured.end(), [&](const HeadingFinding& f) {
      return std::any_of(m.begin(), m.end(), [&](const HeadingFinding& g) { return g.effect == f.effect; });
    });
    if (complete) readings.push_back({pole, cost_of(poled, m, noise), std::move(m), noise});
  }
  const auto best = std::min_element(readings.begin(), readings.end(),
                                     [](const Reading& a, const Reading& b) { return a.cost < b.cost; });
  if (!std::isfinite(best->cost)) {
    noise = start;
    return;
  }
  std::vector<HeadingFinding> chosen = best->findings;
  d.yaw_lag_pole_s = d.yaw_lag_pole_low_s = d.yaw_lag_pole_high_s = best->pole;
  std::vector<const Reading*> allowed;
  for (const Reading& r : readings) {
    if (!(r.cost <= best->cost + kLikelihoodSpan95)) continue;
    allowed.push_back(&r);
    d.yaw_lag_pole_low_s = std::min(d.yaw_lag_pole_low_s, r.pole);
    d.yaw_lag_pole_high_s = std::max(d.yaw_lag_pole_high_s, r.pole);
  }
  // Each interval: the equal-weight mixture of the allowed readings
  // (fitting_core::mixture_interval, each reading its value +- its
  // interval's half-width / kZ95), never narrower than the likeliest's.
  for (HeadingFinding& f : chosen) {
    std::vector<double> means, sigmas;
    for (const Reading* r : allowed) {
      for (const HeadingFinding& g : r->findings) {
        if (g.effect != f.effect) continue;
        means.push_back(g.value);
        sigmas.push_back(0.5 * (g.ci95_high - g.ci95_low) / fitting_core::kZ95);
      }
    }
    const fitting_core::Estimate mixed = fitting_core::mixture_interval(means, sigmas);
    f.ci95_low = std::min(f.ci95_low, mixed.low);
    f.ci95_high = std::max(f.ci95_high, mixed.high);
  }
  measured = std::move(chosen);
  noise = best->noise;
}

bool is_yaw_dynamics(HeadingEffect e) { return e == HeadingEffect::kYawTimeConstant || e == HeadingEffect::kYawDelay; }

// The rate error's verdict on the yaw's lag against its delay agrees with
// `winner` told apart on the innovations: it judged no such pair (no second
// view), or chose `winner` and told it apart.
bool rate_error_tells_apart(const std::vector<HeadingAmbiguity>& rate_pairs, HeadingEffect winner) {
  for (const HeadingAmbiguity& a : rate_pairs) {
    if (!is_yaw_dynamics(a.chosen) || !is_yaw_dynamics(a.alternative) || a.chosen == a.alternative) continue;
    if (a.ambiguous || a.chosen != winner) return false;
  }
  return true;
}

// The fin's authority measured on the heading's one-step innovations with
// the compass noise and the random yaw modelled (heading_innovations), then
// the rest of the vehicle link selected again on the rate error with that
// fin held. The rate error of the logged fin reads the fin biased in a
// closed loop (the fin answers the random yaw and the compass noise;
// docs/science.md "The fin's authority in a closed loop"); the innovations
// do not. And fin and roll offset are one column to the rate error where the
// loop holds the fin against a steady yaw (a rolled glider: the mean fin
// cancels the roll's yaw, so a stronger fin, read weaker by the bias, shows
// as a roll offset - the independent truth's fin x1.39 and x1.91 were named
// roll offsets of 0.056 and 0.098 rad, and no fin increase was ever named;
// docs/science.md "The fin measured whenever the rate error names the fin
// or a roll offset"). So when it names either, the fin is refitted here
// alone (the link's other effects at their nominal values: the rate error
// fits them jointly with the biased fin - a SIL log with a random yaw and
// the vehicle file's fin read fin 0.61 with roll offset +0.07 rad - and held
// there they bias the fin's measurement too, 0.82 [0.75, 0.90]); it is a
// finding where its interval excludes 1 (with the innovations' value and
// interval). The roll offset and the yaw's dynamics are then the rate
// error's selection with that fin held (a steady yaw the loop holds against
// is what shows the roll offset; the random yaw's state in the innovations
// takes part of it: the truth's roll offsets measured there read 0.048 for
// 0.084 and missed -0.073, where the rate error read 0.079 and -0.078).
// What the rate error named and this does not is listed as dropped. The
// held-out RMS and gains are the rate error's against the nominal.
// The yaw's time constant is measured with the fin, on the same
// innovations, and triggers the measurement too: in the closed loop the
// rate error reads a longer lag longer still (the independent truth's 12 s
// read 16.9 s, 11.8 s with its random yaw off) or as a weaker fin (12 s
// named a fin 0.65 and no lag); the innovations read 13.4 and 11.5 s. It
// stands where its interval excludes the vehicle file's; it is no
// candidate of the reselection (docs/science.md "The yaw's lag in a closed
// loop and the fin's roll"). So is the yaw's delay after the fin: the rate
// error reads it long as it reads the lag (a hidden 7.25 s read 8.63 s,
// 8.30 s with the truth's random yaw off; the innovations read 8.25 s;
// docs/science.md "The yaw's delay on the innovations").

void measure_fin_then_reselect(const HeadingTrack& track, const model::VehicleParams& nominal,
                               const HeadingValues& base, const HeadingResiduals& rate_error,
                               const LinkSamples& rate_samples, HeadingDiagnosis& d,
                               const HeadingDiagnoseOptions& options) {
  // Either named: the fin is measured.
  const bool named = std::any_of(d.yaw.findings.begin(), d.yaw.findings.end(), [](const HeadingFinding& f) {
    return f.effect == HeadingEffect::kFinEffectiveness || f.effect == HeadingEffect::kRollOffset ||
           is_yaw_dynamics(f.effect);
  });
  const bool rate_named_lag = std::any_of(d.yaw.findings.begin(), d.yaw.findings.end(), [](const HeadingFinding& f) {
    return f.effect == HeadingEffect::kYawTimeConstant;
  });
  const LinkSamples samples = settled_samples(track, options.max_fit_samples);
  // The screens' noise, refined once where a screen runs.
  std::optional<YawNoise> screens_noise;
  auto noise_for_screens = [&] {
    if (!screens_noise) {
      screens_noise = screen_noise(track, nominal, base, samples, d.heading_noise_rad, d.yaw.baseline_rms);
    }
    return *screens_noise;
  };
  const ScreenRead lag_screen = options.yaw_dynamics_probe && !rate_named_lag
                                    ? read_screen(track, nominal, base, samples, noise_for_screens(),
                                                  HeadingEffect::kYawTimeConstant, kLagScreenGrid)
                                    : ScreenRead{};
  const bool probe_lag = lag_screen.shows(kScreenMargin);
  // Where the rate error names nothing of the link, the fin is measured
  // where its screen shows a gain (the fin alone on its grid, the lag
  // screen's steps and noise): in the closed loop the rate error reads a
  // stronger fin weaker (the fin answers the random yaw) and names nothing
  // (a hidden fin x1.402 read 0.835 [0.692, 0.979] forced on it; the
  // innovations read 1.383: docs/science.md "Why the heading plane's fin is
  // sized in half the draws").
  const bool screened_fin = !named && read_screen(track, nominal, base, samples, noise_for_screens(),
                                                  HeadingEffect::kFinEffectiveness, kFinScreenGrid)
                                          .shows(kScreenMargin);
  if (!named && !probe_lag && !screened_fin) return;
  // The noise and the fin are the likeliest together, both on the same
  // settled samples: the noise fitted with the fin at its last
  // measurement, then the fin on that noise, until it settles (a noise
  // fitted at the nominal fin takes the fin's misfit as random yaw: a truth
  // log's halved fin read 0.75 [0.49, 1.00] that way, its random yaw 3.5
  // times the truth's; one fitted on every sample takes the first 20 s of
  // each glide's misfit as random yaw: a SIL log's fin x1.65 read 1.88
  // [1.35, 2.40]).
  YawNoise noise;
  noise.heading_rad = d.heading_noise_rad;
  auto measure_on = [&](const HeadingTrack& on, const std::vector<HeadingEffect>& effects, const HeadingValues& start,
                        bool noise_grid) {
    HeadingValues at_measured = start;
    LinkFit fit;
    for (int round = 0; round < kNoiseRounds; ++round) {
      noise = fit_yaw_noise(on, nominal, at_measured, noise, samples.all, noise_grid);
      const HeadingResiduals innovations = [&](const HeadingValues& v, std::span<const std::size_t> w,
                                               std::vector<double>& o) {
        heading_innovations(on, nominal, v, noise, w, o);
      };
      HeadingSelectOptions select;
      select.intervals = options.intervals;
      select.fit_only = effects;
      select.select = false;
      fit = select_heading_effects(HeadingLink::kVehicle, d.yaw.candidates, start, innovations, samples, select);
      if (fit.findings.empty()) break;
      const HeadingValues before = at_measured;
      for (const HeadingFinding& f : fit.findings) at(at_measured, f.effect) = f.value;
      if (std::abs(at(at_measured, HeadingEffect::kFinEffectiveness) - at(before, HeadingEffect::kFinEffectiveness)) <
              kFinSettled &&
          std::abs(at(at_measured, HeadingEffect::kYawTimeConstant) - at(before, HeadingEffect::kYawTimeConstant)) <
              kFinSettled * at(at_measured, HeadingEffect::kYawTimeConstant) &&
          std::abs(at(at_measured, HeadingEffect::kYawDelay) - at(before, HeadingEffect::kYawDelay)) <
              kFinSettled * std::max(at(at_measured, HeadingEffect::kYawDelay), 1.0))
        break;
    }
    return fit.findings;
  };
  auto measure = [&](const std::vector<HeadingEffect>& effects, const HeadingValues& start) {
    return measure_on(track, effects, start, true);
  };
  // The fin and the yaw's lag alone (the link's other effects at their
  // nominal values, the roll offset among them: fitted beside the fin on
  // the innovations, a SIL log's
  // random yaw read as a roll offset of 0.11 rad with the fin 1.16 [1.03,
  // 1.29] for 1).
  const LinkFit chosen = d.yaw;
  // The rest of the link, reselected with the fin held: every other
  // candidate where the fin stands (a stronger fin read weaker hid a yaw
  // time constant too); where it does not (held at 1), the roll offset (one
  // column with the fin to the rate error) and what the rate error named
  // beside it - the biased fin's misfit is still in the rate
  // error, and with the fin no longer a candidate another effect took it: a
  // clean deep log named a yaw_time_constant of 21.8 s [15.5, 28.2] that way.
  std::vector<HeadingEffect> others, named_others;
  for (HeadingEffect e : d.yaw.candidates) {
    if (e == HeadingEffect::kFinEffectiveness || is_yaw_dynamics(e)) continue;
    others.push_back(e);
    if (e == HeadingEffect::kRollOffset || std::any_of(d.yaw.findings.begin(), d.yaw.findings.end(),
                                                       [&](const HeadingFinding& f) { return f.effect == e; })) {
      named_others.push_back(e);
    }
  }
  HeadingSelectOptions reselect;
  reselect.margins.absolute = min_absolute_improvement(HeadingLink::kVehicle);
  reselect.intervals = options.intervals;
  // Where the rate error named a roll offset and not the fin, the two are
  // one column to it, and the fin measured alone on the innovations (the
  // roll at 0) takes a real roll's steady yaw: a roll offset of 0.0245 rad
  // read as a fin 1.17 [1.01, 1.33] (docs/science.md "The fin measured
  // whenever the rate error names the fin or a roll offset"). The two
  // readings - that fin with no roll, and the rate error's roll with the
  // vehicle file's fin - are compared on the held-out yos' innovations
  // (the same noise); the fin stands only where it predicts them better.
  const auto named_roll = std::find_if(chosen.findings.begin(), chosen.findings.end(),
                                       [](const HeadingFinding& f) { return f.effect == HeadingEffect::kRollOffset; });
  const bool rate_named_fin = std::any_of(chosen.findings.begin(), chosen.findings.end(), [](const HeadingFinding& f) {
    return f.effect == HeadingEffect::kFinEffectiveness;
  });
  auto heldout_rms = [&](const HeadingValues& v) { return innovations_rms(track, nominal, v, noise, samples.heldout); };
  // The fin measured on the innovations stands only where the held-out
  // yos' innovations (the same noise, the lag and delay as measured) are
  // better predicted with it than with the vehicle file's fin by the
  // selection's margins (fitting_core), as every other finding must: its
  // interval alone cannot tell the fin from a misfit the yaw model lacks -
  // on the independent truth's clean-heading deep logs fins of 0.81-1.59
  // whose intervals excluded 1 predicted the held-out yos no better or
  // worse, where hidden fins predicted them 5-19 % better (docs/science.md
  // "The fin on the innovations judged on the held-out yos"). Not the yaw's
  // lag and delay: judged so they lost a hidden delay and no spurious one.
  auto fin_predicts_heldout = [&](const HeadingValues& as_measured) {
    HeadingValues without = as_measured;
    at(without, HeadingEffect::kFinEffectiveness) = 1.0;
    return fitting_core::improves_heldout(heldout_rms(as_measured), heldout_rms(without), fitting_core::Margins{});
  };
  auto fin_beats_named_roll = [&](double fin, const HeadingValues& dynamics) {
    if (named_roll == chosen.findings.end() || rate_named_fin) return true;
    HeadingValues as_fin = dynamics, as_roll = dynamics;
    at(as_fin, HeadingEffect::kFinEffectiveness) = fin;
    at(as_roll, HeadingEffect::kRollOffset) = named_roll->value;
    return heldout_rms(as_fin) < heldout_rms(as_roll);
  };
  // Alternated: the fin with the roll offset of the last selection held,
  // then the selection with that fin held, until neither changes. (Holding
  // the selection's yaw time constant and delay too was tried: a fin x1.72
  // beside a 9.3 s lag read 1.45 instead of 1.18, but the rate error's time
  // constant reads high, and two fin pairs read within 15 % lost it:
  // docs/science.md.)
  HeadingValues rest = base;  // the last selection's roll offset, the rest nominal
  std::vector<HeadingFinding> measured, left_out;
  LinkFit again;
  bool fin_confirmed = false, reselected = false;
  auto of = [](const std::vector<HeadingFinding>& fs, HeadingEffect e) {
    return std::find_if(fs.begin(), fs.end(), [e](const HeadingFinding& f) { return f.effect == e; });
  };
  auto excludes = [](const HeadingFinding& f, double x) { return !(f.ci95_low <= x && x <= f.ci95_high); };
  // The yaw's dynamics (its lag, its delay after the fin) are measured
  // beside the fin where the rate error named them. Where it named no lag,
  // the lag is probed on the innovations (options.yaw_dynamics_probe): in
  // the closed loop the rate error misses a hidden lag (a 7.48 s lag forced
  // on it read 22.4 s, the held-out yos 6 % worse: nothing named) or names a
  // yaw delay or a weaker fin for it. The lag, and then the yaw's delay, is
  // measured alone beside the fin (the fin's misfit otherwise reads as
  // either: a fin x1.73 beside a 12.4 s lag read a yaw delay of 6.95 s) and
  // stands where its interval excludes the vehicle file's value and the
  // held-out yos' innovations are predicted better with it than without by
  // the selection's margins (fitting_core). The lag is then kept only where
  // it also predicts them better than the delay alone by the margins, or
  // the delay stands too: a first-order lag takes the fast pole a
  // first-order yaw lacks (a clean log's 3.2 s, 5.4 % better - and a dead
  // time of 0.97 s whose interval holds 0 as good; a hidden lag's delay
  // alone read 0.0-0.5 s, no better than none). Where both stand, the one
  // predicting better by the margins is named; where neither does, the
  // better one (the rate error's delay where it named one) with the other
  // stated as its ambiguous alternative (docs/science.md "The yaw's lag
  // probed on the innovations").
  std::vector<HeadingEffect> dynamics;
  for (const HeadingEffect e : {HeadingEffect::kYawTimeConstant, HeadingEffect::kYawDelay}) {
    if (of(chosen.findings, e) != chosen.findings.end()) dynamics.push_back(e);
  }
  struct Probe {
    bool stands = false;
    HeadingFinding finding;
    double heldout_rms = kNaN;  // of the innovations, with the effect and the fin as measured
    HeadingValues values;       // the vehicle file's, the effect and the fin as measured
  };
  auto probe = [&](HeadingEffect e) {
    Probe p;
    const std::vector<HeadingFinding> m = measure({HeadingEffect::kFinEffectiveness, e}, base);
    const auto f = of(m, e);
    if (f == m.end()) return p;
    HeadingValues with = base;
    for (const HeadingFinding& x : m) at(with, x.effect) = x.value;
    HeadingValues without = with;
    at(without, e) = at(base, e);
    p.finding = *f;
    p.values = with;
    p.heldout_rms = heldout_rms(with);
    p.stands = excludes(*f, at(base, e)) &&
               fitting_core::improves_heldout(p.heldout_rms, heldout_rms(without), fitting_core::Margins{});
    return p;
  };
  std::vector<HeadingAmbiguity> probed_pairs;
  auto probed_pair = [](const Probe& chosen_probe, const Probe& other, bool ambiguous) {
    HeadingAmbiguity pair;
    pair.chosen = chosen_probe.finding.effect;
    pair.alternative = other.finding.effect;
    pair.correlation = kNaN;  // judged on the held-out innovations, not by the signatures
    pair.on_innovations = true;
    pair.alternative_value = other.finding.value;
    pair.chosen_heldout_rms = chosen_probe.heldout_rms;
    pair.alternative_heldout_rms = other.heldout_rms;
    pair.ambiguous = ambiguous;
    return pair;
  };
  // The probe's fin and lag predict the held-out yos' innovations better
  // than the fin measured alone (the vehicle file's lag), both on the noise
  // fitted with the fin alone.
  auto lag_beats_fin_alone = [&](const Probe& p) {
    HeadingValues alone = base;
    for (const HeadingFinding& f : measure({HeadingEffect::kFinEffectiveness}, base)) at(alone, f.effect) = f.value;
    return heldout_rms(p.values) < heldout_rms(alone);
  };
  Probe lag, delay;
  if (probe_lag) {
    lag = probe(HeadingEffect::kYawTimeConstant);
    if (lag.stands) {
      delay = probe(HeadingEffect::kYawDelay);
      const fitting_core::Margins margins;
      const bool delay_better =
          delay.stands && fitting_core::improves_heldout(delay.heldout_rms, lag.heldout_rms, margins);
      const bool lag_better = fitting_core::improves_heldout(lag.heldout_rms, delay.heldout_rms, margins);
      const bool delay_named = std::find(dynamics.begin(), dynamics.end(), HeadingEffect::kYawDelay) != dynamics.end();
      const bool lag_chosen = lag_better || (!delay_better && !delay_named && lag.heldout_rms <= delay.heldout_rms);
      // Neither better and no delay standing: a dead time within its
      // resolution does as well, a fast pole rather than a slow one.
      const bool either = lag_better || delay.stands;
      if (either && lag_chosen) dynamics.insert(dynamics.begin(), HeadingEffect::kYawTimeConstant);
      if (either && !lag_chosen && !delay_named) dynamics.push_back(HeadingEffect::kYawDelay);
      // The pair is stated wherever both were measured and one is named:
      // ambiguous where neither predicts the held-out innovations better,
      // told apart where one does (left unstated, a delay the probe chose
      // over the lag read as decided silently: truth seed 1025022074, a
      // hidden 5.49 s yaw delay named 5.84 s with no pair).
      // Told apart only where the rate error's own verdict on the pair, if
      // it judged one, agrees: the same one chosen and told apart there
      // (the core's two views: fitting_core::indistinguishable(HeldOut)).
      // Where the rate error named the delay and the innovations the lag,
      // the log reads the one dead time as either: a hidden 4.00 s yaw
      // delay the rate error named 4.29 s [3, 6] and told apart from the
      // lag was named a 4.26 s lag "told apart" on the innovations, where
      // the delay read 0 (docs/science.md "The yaw's lag or its delay: two
      // views").
      const bool ambiguous =
          (!lag_better && !delay_better && delay.stands) ||
          ((lag_better || delay_better) &&
           !rate_error_tells_apart(chosen.identifiability,
                                   lag_chosen ? HeadingEffect::kYawTimeConstant : HeadingEffect::kYawDelay));
      const bool told_apart = (lag_better || delay_better) && either && std::isfinite(delay.heldout_rms);
      if (ambiguous || told_apart) {
        probed_pairs.push_back(lag_chosen ? probed_pair(lag, delay, ambiguous) : probed_pair(delay, lag, ambiguous));
      }
    }
  }
  // The fin and the lag traded: where the rate error names the fin or a
  // roll offset and no yaw dynamics (or the fin's screen passes), the lag's
  // screen shows a gain by the selection's full margin and the probe kept
  // no lag (its held-out gain under the margins,
  // or not told apart from a delay that does not stand), the fin measured
  // alone with the vehicle file's lag reads along fin / time constant (a
  // hidden x0.634 with an 11.3 s lag read 0.429; beside the probe's 9.1 s
  // lag 0.642). The probe's fin and lag and the fin alone are compared on
  // the held-out yos' innovations (the same noise); the better is measured.
  // The screen at the full margin keeps out a lag the first-order yaw reads
  // from the truth's fast dynamics beside a fin alone (x0.711: a 6.4 s lag,
  // its screen 1.75 %, 1.0 % better than the fin alone; the hidden lags'
  // screens 4.1-6.2 %; docs/science.md "The fin and the yaw's lag measured
  // together where both are suggested").
  if ((named || screened_fin) && dynamics.empty() && lag_screen.shows(fitting_core::Margins{}.relative) &&
      lag.finding.effect == HeadingEffect::kYawTimeConstant &&
      excludes(lag.finding, at(base, HeadingEffect::kYawTimeConstant)) && lag_beats_fin_alone(lag)) {
    dynamics.push_back(HeadingEffect::kYawTimeConstant);
    // Chosen over the delay without telling them apart: stated ambiguous.
    if (std::isfinite(delay.heldout_rms)) probed_pairs.push_back(probed_pair(lag, delay, true));
  }
  if (!named && !screened_fin && dynamics.empty()) return;
  std::vector<bool> dynamics_stand(dynamics.size(), false);
  std::vector<HeadingEffect> to_measure = {HeadingEffect::kFinEffectiveness};
  to_measure.insert(to_measure.end(), dynamics.begin(), dynamics.end());
  for (int round = 0; round < kAlternations; ++round) {
    std::vector<HeadingFinding> m = measure(to_measure, rest);
    const auto fin = of(m, HeadingEffect::kFinEffectiveness);
    if (fin == m.end() ||
        std::any_of(dynamics.begin(), dynamics.end(), [&](HeadingEffect e) { return of(m, e) == m.end(); }))
      break;
    HeadingValues at_dynamics = base;
    HeadingValues as_measured = rest;  // the values the innovations were fitted at
    for (const HeadingFinding& f : m) at(as_measured, f.effect) = f.value;
    std::vector<bool> stand(dynamics.size(), false);
    for (std::size_t k = 0; k < dynamics.size(); ++k) {
      const HeadingFinding& f = *of(m, dynamics[k]);
      at(at_dynamics, f.effect) = f.value;
      stand[k] = excludes(f, at(base, f.effect));
    }
    bool confirmed = excludes(*fin, 1.0) && fin_predicts_heldout(as_measured);
    if (confirmed && round == 0) confirmed = fin_beats_named_roll(fin->value, at_dynamics);
    auto settled = [&](HeadingEffect e, double tolerance) {
      return std::abs(of(m, e)->value - of(measured, e)->value) < tolerance;
    };
    bool same = round > 0 && confirmed == fin_confirmed && stand == dynamics_stand &&
                (!confirmed || settled(HeadingEffect::kFinEffectiveness, kFinSettled));
    for (std::size_t k = 0; same && k < dynamics.size(); ++k) {
      same = !stand[k] || settled(dynamics[k], kFinSettled * std::max(of(m, dynamics[k])->value, 1.0));
    }
    if (same) break;
    fin_confirmed = confirmed;
    dynamics_stand = stand;
    measured = m;
    left_out.clear();
    HeadingValues held = base;
    for (const HeadingFinding& f : m) {
      const auto k = std::find(dynamics.begin(), dynamics.end(), f.effect);
      const bool stands = k == dynamics.end() ? confirmed : stand[static_cast<std::size_t>(k - dynamics.begin())];
      if (stands) at(held, f.effect) = f.value;
      if (!stands) left_out.push_back(f);
    }
    again = select_heading_effects(HeadingLink::kVehicle, confirmed ? others : named_others, held, rate_error,
                                   rate_samples, reselect);
    reselected = true;
    const HeadingValues last_rest = rest;
    at(rest, HeadingEffect::kRollOffset) = at(again.values, HeadingEffect::kRollOffset);
    if (rest == last_rest) break;
  }
  auto dynamics_stands = [&](HeadingEffect e) {
    const auto k = std::find(dynamics.begin(), dynamics.end(), e);
    return k != dynamics.end() && dynamics_stand[static_cast<std::size_t>(k - dynamics.begin())];
  };
  // Not beside a yaw delay that stands: its dead time carries the pole
  // already (carried_fast_pole).
  if (options.yaw_lag_fast_pole && dynamics_stands(HeadingEffect::kYawTimeConstant) &&
      !dynamics_stands(HeadingEffect::kYawDelay)) {
    read_beside_fast_pole(track, nominal, rest, to_measure, samples.all, measured, noise, d, measure_on);
  }
  const double roll = at(rest, HeadingEffect::kRollOffset);
  if (!reselected) return;  // no fit on the innovations: the rate error's findings stand
  d.yaw_noise = noise;
  const bool fin_named = of(d.yaw.findings, HeadingEffect::kFinEffectiveness) != d.yaw.findings.end();
  if (!fin_confirmed && !fin_named && dynamics.empty() && roll == at(chosen.values, HeadingEffect::kRollOffset)) return;
  again.candidates = chosen.candidates;
  for (HeadingFinding& f : again.findings) f.nominal = at(base, f.effect);
  // The measured ones first, the fin before the lag (as the rate error ranks them).
  for (const HeadingEffect e :
       {HeadingEffect::kYawDelay, HeadingEffect::kYawTimeConstant, HeadingEffect::kFinEffectiveness}) {
    if (!(e == HeadingEffect::kFinEffectiveness ? fin_confirmed : dynamics_stands(e))) continue;
    HeadingFinding m = *of(measured, e);
    m.nominal = at(base, e);
    m.heldout_rms = again.extended_heldout_rms;
    again.findings.insert(again.findings.begin(), m);
    at(again.values, e) = m.value;
    // A held dynamics term is no candidate of the reselection, so its pairs
    // (a dead time against the slow pole: both make the yaw follow the fin
    // late) are the rate error's, judged where it named the term.
    if (e == HeadingEffect::kFinEffectiveness) continue;
    for (const HeadingAmbiguity& a : chosen.identifiability) {
      if (a.chosen == e) again.identifiability.push_back(a);
    }
    for (const HeadingAmbiguity& a : probed_pairs) {
      const bool stated =
          std::any_of(again.identifiability.begin(), again.identifiability.end(), [&](const HeadingAmbiguity& b) {
            return b.chosen == a.chosen && b.alternative == a.alternative && (b.ambiguous || !a.ambiguous);
          });
      if (a.chosen == e && !stated) again.identifiability.push_back(a);
    }
    for (const LinkFit::ScreenedCorrelation& c : chosen.screen) {
      if (c.chosen == e) again.screen.push_back(c);
    }
    // They were screened at the rate error's threshold: the reselection's is
    // unset (0) when it screened nothing, which would call every copied pair
    // judged with no verdict (a 0.745 pair "judged", truth seed 903374064).
    again.screen_correlation = std::max(again.screen_correlation, chosen.screen_correlation);
  }
  // Against the nominal's baseline (the held fin's is the reselection's).
  again.baseline_rms = chosen.baseline_rms;
  again.baseline_rms_dive = chosen.baseline_rms_dive;
  again.baseline_rms_climb = chosen.baseline_rms_climb;
  again.baseline_heldout_rms = chosen.baseline_heldout_rms;
  again.gain = 1.0 - again.extended_heldout_rms / chosen.baseline_heldout_rms;
  for (HeadingFinding& f : again.findings) f.gain = 1.0 - f.heldout_rms / chosen.baseline_heldout_rms;
  // What the rate error named and this does not: refuted (the fin and the
  // lag by their measurement on the innovations, another by the reselection).
  for (const HeadingFinding& c : chosen.findings) {
    if (of(again.findings, c.effect) != again.findings.end()) continue;
    const auto on_innovations = of(left_out, c.effect);
    again.dropped.push_back(on_innovations != left_out.end() ? *on_innovations : c);
  }
  d.yaw = again;
}

}  // namespace

const HeadingEffectInfo& info(HeadingEffect effect) { return kInfo[static_cast<std::size_t>(effect)]; }

const char* to_string(HeadingLink link) {
  switch (link) {
    case HeadingLink::kServo:
      return "servo";
    case HeadingLink::kVehicle:
      return "vehicle";
    case HeadingLink::kAutopilot:
      return "autopilot";
  }
  return "?";
}

UnexplainedYaw unexplained_yaw(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                               const ShearProfile* shear) {
  UnexplainedYaw out;
  std::vector<double> predicted;
  predict_yaw_rate(t, vehicle, values, t.scored, predicted);
  std::vector<double> r(t.size(), kNaN);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < t.scored.size(); ++k) {
    const std::size_t i = t.scored[k];
    const double from_shear = shear != nullptr ? shear_at(*shear, t.depth_m[i]) * shear_yaw_per_unit(t, i) : 0.0;
    const double x = predicted[k] + from_shear - t.yaw_rate_rad_s[i];
    r[t.scored[k]] = x;
    if (std::isfinite(x)) {
      sum += x * x;
      ++n;
    }
  }
  if (n == 0) return out;
  const double variance = sum / static_cast<double>(n);
  out.rms_rad_s = std::sqrt(variance);
  for (std::size_t lag = 1; lag < 60; ++lag) {
    double product = 0.0, dt = 0.0;
    std::size_t pairs = 0;
    for (std::size_t run = 0; run < t.run_first.size(); ++run) {
      for (std::size_t i = t.run_first[run]; i + lag < t.run_end(run); ++i) {
        if (!std::isfinite(r[i]) || !std::isfinite(r[i + lag])) continue;
        product += r[i] * r[i + lag];
        dt += t.time_s[i + lag] - t.time_s[i];
        ++pairs;
      }
    }
    if (pairs < 20) break;
    if (product / static_cast<double>(pairs) < variance / std::numbers::e) {
      out.correlation_s = dt / static_cast<double>(pairs);
      break;
    }
  }
  return out;
}

std::vector<HoldBin> count_holds(const HeadingTrack& t, double rate_deadband_rad_s) {
  constexpr double kBinRad = 2.0 * std::numbers::pi / 180.0;
  std::vector<HoldBin> bins(7);
  for (std::size_t b = 0; b < bins.size(); ++b) {
    bins[b].from_rad = kBinRad * static_cast<double>(b);
    bins[b].to_rad = b + 1 < bins.size() ? kBinRad * static_cast<double>(b + 1) : std::numbers::pi;
  }
  for (std::size_t i = 2; i < t.row_time_s.size(); ++i) {
    const bool steady = t.row_gliding[i] && t.row_gliding[i - 1] && t.row_gliding[i - 2];
    if (!steady || !std::isfinite(t.row_fin_command_rad[i]) || !std::isfinite(t.row_fin_command_rad[i - 1]) ||
        !std::isfinite(t.row_command_rad[i - 1]) || !std::isfinite(t.row_heading_rad[i - 1]) ||
        !std::isfinite(t.row_heading_rad[i - 2])) {
      continue;
    }
    const double dt = t.row_time_s[i - 1] - t.row_time_s[i - 2];
    const double rate =
        std::remainder(t.row_heading_rad[i - 1] - t.row_heading_rad[i - 2], 2.0 * std::numbers::pi) / dt;
    if (!(dt > 0.0) || std::abs(rate) >= rate_deadband_rad_s) continue;
    const double error =
        std::abs(std::remainder(t.row_command_rad[i - 1] - t.row_heading_rad[i - 1], 2.0 * std::numbers::pi));
    const std::size_t b = std::min(bins.size() - 1, static_cast<std::size_t>(error / kBinRad));
    (std::abs(t.row_fin_command_rad[i] - t.row_fin_command_rad[i - 1]) > 1e-4 ? bins[b].changed : bins[b].held)++;
  }
  return bins;
}

AutopilotSettings configured_autopilot(const flightlog::FlightLog& log) {
  AutopilotSettings s;
  const auto gain = logged_setting(log, "u_hd_fin_ap_gain");
  const auto igain = logged_setting(log, "u_hd_fin_ap_igain");
  const auto dgain = logged_setting(log, "u_hd_fin_ap_dgain");
  const auto deadband = logged_setting(log, "u_heading_rate_deadband");
  const auto heading_deadband = logged_setting(log, "u_heading_deadband");
  s.stated = gain || igain || dgain;
  s.gain = gain.value_or(s.gain);
  s.igain = igain.value_or(s.igain);
  s.dgain = dgain.value_or(s.dgain);
  s.rate_deadband_rad_s = deadband.value_or(s.rate_deadband_rad_s);
  s.heading_deadband_rad = heading_deadband.value_or(s.heading_deadband_rad);
  return s;
}

HeadingDiagnosis diagnose_heading(const model::VehicleParams& nominal, const flightlog::FlightLog& log,
                                  const HeadingDiagnoseOptions& options) {
  HeadingTrack track = prepare_heading_track(log, nominal, options.track);
  HeadingDiagnosis d;
  d.vehicle = nominal.name;
  d.configured = configured_autopilot(log);
  d.fin_max_rad = track.fin_max_rad;
  d.roll_logged = track.roll_logged;
  d.logged_roll_rad = track.median_roll_rad;
  d.runs = track.run_first.size();
  d.yaw_fast_pole_max_s = track.yaw_fast_pole_max_s;
  d.heading_noise_rad = heading_jitter_rad(track);
  d.holds = count_holds(track, d.configured.rate_deadband_rad_s);
  const HeadingValues base = nominal_heading_values(nominal, d.configured);

  // The servo and the autopilot act at every cycle under water: their rows.
  auto row_split = [&](const std::vector<std::size_t>& rows) {
    std::vector<bool> diving;
    for (std::size_t i : rows) {
      const std::size_t j = i + 1 < track.row_depth_m.size() ? i + 1 : i;
      diving.push_back(track.row_depth_m[j] >= track.row_depth_m[i > 0 ? i - 1 : i]);
    }
    return split(rows, track.row_yo, diving, options.max_fit_samples);
  };
  const LinkSamples servo_samples = row_split(servo_rows(track));
  const std::vector<double> unlogged = unlogged_cycle_times(track);
  const HeadingResiduals servo_error =
      against([&](const HeadingValues& v, std::span<const std::size_t> w,
                  std::vector<double>& o) { predict_servo_fin(track, unlogged, nominal, v, w, o); },
              track.row_fin_rad);
  d.servo = run_link(HeadingLink::kServo, base, servo_error, servo_samples, options);
  const LinkSamples autopilot_samples = row_split(autopilot_rows(track));
  const AutopilotClock clock =
      options.autopilot_clock == AutopilotClockRule::kNominal ? AutopilotClock::kNominal : AutopilotClock::kMeasured;
  AutopilotReplay autopilot_replay(track, d.configured, clock);
  // The fits on it kept (remembering_fits): the replayed integrator's
  // closed-loop check refits the sets its selection fitted.
  const HeadingResiduals replayed_residuals =
      remembering_fits(against([&](const HeadingValues& v, std::span<const std::size_t> w,
                                   std::vector<double>& o) { autopilot_replay.predict(v, w, o); },
                               track.row_fin_command_rad));
  const HeadingResiduals per_glide_residuals =
      integrator_per_glide(replayed_residuals, track, track.row_fin_command_rad);
  const bool per_glide = options.autopilot_integrator_per_glide;
  d.autopilot_integrator_per_glide = per_glide;
  d.autopilot = run_link(HeadingLink::kAutopilot, base, per_glide ? per_glide_residuals : replayed_residuals,
                         autopilot_samples, options);
  // The autopilot link's open-loop fit of exactly these effects.
  auto fit_autopilot_on = [&](const HeadingResiduals& residuals) {
    return std::function<LinkFit(const std::vector<HeadingEffect>&)>([&](const std::vector<HeadingEffect>& effects) {
      HeadingSelectOptions select;
      select.margins.absolute = min_absolute_improvement(HeadingLink::kAutopilot);
      select.intervals = options.intervals;
      select.fit_only = effects;
      select.select = false;
      return select_heading_effects(HeadingLink::kAutopilot, effects_of(HeadingLink::kAutopilot, all_effects()), base,
                                    residuals, autopilot_samples, select);
    });
  };
  std::vector<bool> diving;
  for (std::size_t i : track.scored) diving.push_back(track.phase[i] == flightlog::Phase::kDive);
  const LinkSamples yaw_samples = split(track.scored, track.yo, diving, options.max_fit_samples);
  const HeadingResiduals yaw_error = against([&](const HeadingValues& v, std::span<const std::size_t> w,
                                                 std::vector<double>& o) { predict_yaw_rate(track, nominal, v, w, o); },
                                             track.yaw_rate_rad_s);
  // The vehicle link's fin leaves each reading behind the servo's dead time
  // as its link found it (heading_models.cpp fin_between_rows).
  HeadingValues vehicle_base = base;
  at(vehicle_base, HeadingEffect::kFinDelay) = at(d.servo.values, HeadingEffect::kFinDelay);
  d.yaw = run_link(HeadingLink::kVehicle, vehicle_base, yaw_error, yaw_samples, options);
  // Not on a decimated file's log (an .sbd: its heading interpolated
  // between readings every few seconds, which the innovations' compass-noise
  // model cannot take).
  if (options.yaw_noise_model && options.fit_only.empty() && !options.track.fin_stored_on_change) {
    measure_fin_then_reselect(track, nominal, vehicle_base, yaw_error, yaw_samples, d, options);
    // The models from here on carry the pole read beside the lag.
    track.yaw_fast_pole_with_lag_s = d.yaw_lag_pole_s;
  }
  // A lag the fast dynamics the first-order yaw lacks account for is not
  // named (heading_select_resolution.hpp); not where the caller fixed the
  // set to fit.
  if (options.fit_only.empty())
    drop_lag_within_resolution(d.yaw, vehicle_base,
                               carried_fast_pole(track.yaw_fast_pole_s, at(d.yaw.values, HeadingEffect::kYawDelay)));
  // A pole read beside a lag no longer named is not carried.
  if (std::none_of(d.yaw.findings.begin(), d.yaw.findings.end(),
                   [](const HeadingFinding& f) { return f.effect == HeadingEffect::kYawTimeConstant; })) {
    track.yaw_fast_pole_with_lag_s = d.yaw_lag_pole_s = d.yaw_lag_pole_low_s = d.yaw_lag_pole_high_s = 0.0;
  }
  // A yaw delay the servo's rows cannot see as its dead time is fitted on
  // that side too (heading_select_delay_side.hpp).
  if (options.fit_only.empty()) {
    HeadingSelectOptions yaw_select;
    yaw_select.margins.absolute = min_absolute_improvement(HeadingLink::kVehicle);
    yaw_select.intervals = options.intervals;
    const DelaySides sides{servo_error, servo_samples, {.absolute = min_absolute_improvement(HeadingLink::kServo)},
                           yaw_error,   yaw_samples,   yaw_select};
    choose_delay_side(d.yaw, d.servo, sides);
    bound_delay_split(d.yaw, d.servo, sides);
  }
  widen_for_fast_pole(d.yaw, track);

  // The current's shear, on what the vehicle link leaves (every glide
  // sample once the pitch-over is done: the scored ones alone never see
  // the top of the dives or the bottom of the climbs).
  {
    std::vector<std::size_t> samples;
    for (std::size_t run = 0; run < track.run_first.size(); ++run) {
      for (std::size_t i = track.run_first[run]; i < track.run_end(run); ++i) {
        if (track.time_s[i] - track.time_s[track.run_first[run]] >= kShearSettleS) samples.push_back(i);
      }
    }
    std::vector<double> predicted, residual(track.size(), kNaN);
    predict_yaw_rate(track, nominal, d.yaw.values, samples, predicted);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      residual[samples[k]] = track.yaw_rate_rad_s[samples[k]] - predicted[k];
    }
    d.current_shear = fit_current_shear(track, residual, samples);
  }
  if (options.closed_loop && options.fit_only.empty()) {
    d.closed_loop = check_closed_loop(track, nominal, base, d,
                                      fit_autopilot_on(per_glide ? per_glide_residuals : replayed_residuals));
    // The per-glide integrator takes a gain on an error the loop holds
    // steady through a glide (a constant per glide too): on a real log
    // whose stated law is far from the flown one that left the set no
    // better than the stated law when flown closed-loop (comet-2019-154:
    // score 2.11 -> 10.21, amadeus 1.71 -> 13.36). The replayed
    // integrator's set stands where its closed loop predicts the held-out
    // glides better by the check's margins (docs/science.md "The
    // autopilot's integrator at each glide's start").
    if (per_glide) {
      HeadingDiagnosis replayed = d;
      replayed.autopilot = run_link(HeadingLink::kAutopilot, base, replayed_residuals, autopilot_samples, options);
      const ClosedLoopCheck check =
          check_closed_loop(track, nominal, base, replayed, fit_autopilot_on(replayed_residuals));
      fitting_core::Margins margins;
      margins.absolute = kClosedLoopMargin;
      if (fitting_core::improves_heldout(check.open_loop_set.score, d.closed_loop.open_loop_set.score, margins)) {
        d.autopilot = std::move(replayed.autopilot);
        d.closed_loop = check;
        d.autopilot_integrator_per_glide = false;
      }
    }
  }
  // The autopilot link again under the log's median cycle, the two fits one
  // reading (heading_autopilot_clock.hpp); the closed-loop check flew the
  // measured clock's.
  const bool merge =
      options.autopilot_clock == AutopilotClockRule::kBoth || options.autopilot_clock == AutopilotClockRule::kHeldOut;
  if (merge && options.fit_only.empty()) {
    AutopilotReplay nominal_replay(track, d.configured, AutopilotClock::kNominal);
    const HeadingResiduals nominal_residuals = against([&](const HeadingValues& v, std::span<const std::size_t> w,
                                                           std::vector<double>& o) { nominal_replay.predict(v, w, o); },
                                                       track.row_fin_command_rad);
    const LinkFit nominal_clock = run_link(
        HeadingLink::kAutopilot, base,
        d.autopilot_integrator_per_glide ? integrator_per_glide(nominal_residuals, track, track.row_fin_command_rad)
                                         : nominal_residuals,
        autopilot_samples, options);
    d.autopilot = merge_autopilot_clocks(d.autopilot, nominal_clock, base, options.autopilot_clock,
                                         min_absolute_improvement(HeadingLink::kAutopilot), d.autopilot_clock);
  }
  const UnexplainedYaw left = unexplained_yaw(track, nominal, d.yaw.values, &d.current_shear);
  d.unexplained_yaw_rate_rad_s = left.rms_rad_s;
  d.unexplained_correlation_s = left.correlation_s;
  d.values = base;
  double best_gain = 0.0;
  for (const LinkFit* link : {&d.servo, &d.yaw, &d.autopilot}) {
    for (const HeadingFinding& f : link->findings) at(d.values, f.effect) = f.value;
    if (!link->findings.empty() && link->gain > best_gain) {
      best_gain = link->gain;
      d.cause = info(link->findings.front().effect).id;
    }
  }
  d.delay_autopilot_s = at(d.values, HeadingEffect::kAutopilotDelay);
  d.delay_servo_s = at(d.values, HeadingEffect::kFinDelay);
  d.delay_after_fin_s = at(d.values, HeadingEffect::kYawDelay);
  d.yaw_fast_pole_s = yaw_fast_pole(track, d.delay_after_fin_s);  // what the models carried
  return d;
}

model::VehicleParams apply(model::VehicleParams v, const HeadingDiagnosis& d) {
  v.heading.fin_delay_s = d.delay_servo_s + d.delay_after_fin_s;
  v.heading.fin_deadband_rad = at(d.values, HeadingEffect::kFinDeadband);
  v.heading.fin_max_rad = d.fin_max_rad;  // the log's f_fin_safety_max where it states one
  v.heading.fin_yaw_gain_per_m *= at(d.values, HeadingEffect::kFinEffectiveness);
  v.heading.yaw_time_constant_s = at(d.values, HeadingEffect::kYawTimeConstant);
  v.heading.roll_offset_rad =
      (d.roll_logged ? d.logged_roll_rad : v.heading.roll_offset_rad) + at(d.values, HeadingEffect::kRollOffset);
  return v;
}

}  // namespace glider::diagnose
