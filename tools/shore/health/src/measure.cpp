// SPDX-License-Identifier: Apache-2.0
#include "glider/health/measure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "glider/circular_statistics/circular_statistics.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/heading_report.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/trend.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/flightlog/gaps.hpp"
#include "glider/health/fin_instrument.hpp"
#include "glider/health/fin_iv.hpp"

namespace glider::health {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The dynamic model's RK4 step, at most (the core's default is 1 s). The
// update's cost is the vertical fit's flights, and on the decimated .sbd
// (4 s apart) 2 s steps halve the RK4 work: on 12 SIL surfacings the
// segments' drag moved by a median 0.017 of its own 95 % half-width (max
// 0.79, on the one segment where 1 s itself is the outlier: 1 s against
// 0.5 s moves it by a median 0.61) and every other effect by less; 4 s moved
// the drag by 3 half-widths (docs/health.md, "Cost"). Data sampled 1 s
// apart or closer are flown as before (ceil(gap / step) steps a gap).
constexpr double kVerticalMaxStep_s = 2.0;

EffectValue not_judged(std::string why) {
  EffectValue v;
  v.why = std::move(why);
  return v;
}

EffectValue& at(EffectValues& values, HealthEffect e) { return values[static_cast<std::size_t>(e)]; }

// The vertical plane: drag and offset fitted jointly (+ the pump lag where
// the dynamic model can run: it needs the turns sampled densely).
// Returns the vehicle the heading plane flies on this segment: the vertical
// findings applied as glider-diagnose applies them (heading_vehicle: the
// file's vehicle, not diagnosed_nominal's Reynolds prior; docs/health.md,
// "The heading fit flies diagnose's heading vehicle").
model::VehicleParams measure_vertical(const model::VehicleParams& nominal, const flightlog::FlightLog& log,
                                      SegmentMeasurement& m) {
  const diagnose::Observations obs = diagnose::prepare_observations(log);
  diagnose::DiagnoseOptions options;
  options.fit_only = {diagnose::Effect::kBuoyancyOffset, diagnose::Effect::kDragChange};
  options.max_step_s = kVerticalMaxStep_s;
  const bool dynamic = !obs.track.scored.empty();
  if (dynamic) options.fit_only.push_back(diagnose::Effect::kPumpLag);
  const diagnose::Diagnosis d = diagnose::diagnose(nominal, obs, options);
  for (const diagnose::Finding& f : d.findings) {
    HealthEffect e{};
    if (f.effect == diagnose::Effect::kBuoyancyOffset) {
      e = HealthEffect::kBuoyancyOffset;
    } else if (f.effect == diagnose::Effect::kDragChange) {
      e = HealthEffect::kDragChange;
    } else if (f.effect == diagnose::Effect::kPumpLag) {
      e = HealthEffect::kPumpLag;
    } else {
      continue;
    }
    at(m.effects, e) = {f.value, f.ci95_low, f.ci95_high, {}, f.reynolds_prior_shift};
  }
  if (dynamic) {
    EffectValue& lag = at(m.effects, HealthEffect::kPumpLag);
    lag = lag_at_sampling_resolution(lag, depth_sample_spacing_s(log));
  } else {
    at(m.effects, HealthEffect::kPumpLag) = not_judged(
        "needs the dynamic model (turns sampled every few seconds at least); these data are too sparse in "
        "the inflections: steady glides only");
  }
  m.judged = at(m.effects, HealthEffect::kDragChange).judged();
  return diagnose::heading_vehicle(nominal, d);
}

// Why a segment's fin is too thin to judge (empty: it can be judged). NaN
// spreads (too few values under water: a decimated file stores m_fin on
// change, so a fin that hardly moved leaves few) are no evidence of turns.
std::string fin_too_thin(double fin_spread, double heading_spread) {
  char why[256];
  if (std::isnan(fin_spread)) return "too thin to judge: fewer than 10 fin values under water, no measure of its turns";
  if (!(fin_spread >= kMinFinSpreadDeg)) {
    std::snprintf(why, sizeof why,
                  "too thin to judge: the fin moved %.2f deg (sd under water, at least %.1f needed), too little "
                  "turning to tell its effect",
                  fin_spread, kMinFinSpreadDeg);
    return why;
  }
  if (!(heading_spread >= kMinHeadingSpreadDeg)) {
    std::snprintf(why, sizeof why,
                  "too thin to judge: the heading turned %.2f deg (circular sd under water, at least %.0f needed) "
                  "while the fin moved %.2f deg: a fin holding against a random yaw or compass noise, not turning",
                  heading_spread, kMinHeadingSpreadDeg, fin_spread);
    return why;
  }
  return {};
}

// The segment with m_fin as the file stored it: the heading plane knows
// where a file that stores the fin on change found it unchanged and where it
// moved (diagnose/stored_on_change.hpp); the held column would put every
// move at the next reading, ~2 s late on a 4 s .sbd (the fin read 0.85-0.92
// for 1, and a halved fin's interval missed -50 %: docs/science.md).
flightlog::FlightLog with_fin_as_stored(const flightlog::FlightLog& held, const flightlog::FlightLog& raw) {
  const flightlog::Column* stored = raw.find("m_fin");
  if (stored == nullptr || stored->size() != held.rows()) return held;
  std::vector<flightlog::Column> columns;
  std::size_t time_index = 0;
  const auto& names = held.column_names();
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (&held.column(names[c]) == &held.time()) time_index = c;
    columns.push_back(names[c] == "m_fin" ? *stored : held.column(names[c]));
  }
  return flightlog::FlightLog(held.source(), held.metadata(), names, std::move(columns), time_index);
}

// The fin and the roll offset by instrumental variables (fin_iv.hpp): the
// yaw rate's error with the fin as logged, the fin projected on the command
// and the lagged heading (fin_instrument.hpp) its instrument.
void measure_heading(const model::VehicleParams& nominal, const flightlog::FlightLog& held,
                     const flightlog::FlightLog& raw, bool decimated, SegmentMeasurement& m) {
  try {
    const flightlog::FlightLog projected = with_fin_on_lagged_heading(held);
    const FinByInstruments iv = fin_by_instruments(nominal, with_fin_as_stored(held, raw), decimated, projected);
    at(m.effects, HealthEffect::kFinEffectiveness) = iv.fin;
    at(m.effects, HealthEffect::kRollOffset) = iv.roll_deg;
    for (HealthEffect e : {HealthEffect::kFinEffectiveness, HealthEffect::kRollOffset}) {
      if (!at(m.effects, e).judged()) at(m.effects, e) = not_judged("the heading fit gave no value");
    }
    const EffectValue& fin = at(m.effects, HealthEffect::kFinEffectiveness);
    const std::string too_thin = fin_too_thin(m.fin_spread_deg, m.heading_spread_deg);
    if (fin.judged() && !too_thin.empty()) {
      char read[96];
      std::snprintf(read, sizeof read, " (it read %.3f [%.3f, %.3f])", fin.value, fin.low, fin.high);
      at(m.effects, HealthEffect::kFinEffectiveness) = not_judged(too_thin + read);
    }
  } catch (const std::exception& error) {
    for (HealthEffect e : {HealthEffect::kFinEffectiveness, HealthEffect::kRollOffset}) {
      at(m.effects, e) = not_judged(error.what());
    }
  }
}

}  // namespace

double fin_spread_deg(const flightlog::FlightLog& log) {
  const flightlog::Column* fin = log.find("m_fin");
  const flightlog::Column* depth = log.find("m_depth");
  if (fin == nullptr || depth == nullptr) return std::nan("");
  std::vector<double> under;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    if (std::isfinite((*fin)[i]) && (*depth)[i] > 2.0) under.push_back((*fin)[i] * kDeg);
  }
  if (under.size() < 10) return std::nan("");
  double mean = 0.0;
  for (double f : under) mean += f;
  mean /= static_cast<double>(under.size());
  double sum2 = 0.0;
  for (double f : under) sum2 += (f - mean) * (f - mean);
  return std::sqrt(sum2 / static_cast<double>(under.size() - 1));
}

double heading_spread_deg(const flightlog::FlightLog& log) {
  const flightlog::Column* heading = log.find("m_heading");
  const flightlog::Column* depth = log.find("m_depth");
  if (heading == nullptr || depth == nullptr) return std::nan("");
  circular_statistics::MeanResultant headings;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    if (!std::isfinite((*heading)[i]) || !((*depth)[i] > 2.0)) continue;
    headings.add((*heading)[i]);
  }
  if (headings.total_weight() < 10.0) return std::nan("");
  // The circular standard deviation (the ordinary one for a small spread).
  return circular_statistics::circular_sd_rad(headings.length()) * kDeg;
}

EffectValue pump_rate(const flightlog::FlightLog& raw) {
  const flightlog::Column* pumped = raw.find("m_ballast_pumped");
  if (pumped == nullptr) return not_judged("the data have no m_ballast_pumped");
  const flightlog::Column& time = raw.time();
  std::vector<double> t, v;
  for (std::size_t i = 0; i < pumped->size(); ++i) {
    if (std::isfinite((*pumped)[i])) {
      t.push_back(time[i]);
      v.push_back((*pumped)[i]);
    }
  }
  // An interval is "running" when the reading moved by more than a reading's
  // resolution in it; a rate counts when its neighbours ran too (the pump
  // started before it and stopped after it) and all three are short (a long
  // one hides a stop).
  constexpr double kMovedCc = 2.0, kMaxIntervalS = 15.0;
  auto running = [&](std::size_t k) {  // interval k: samples k, k+1
    const double dt = t[k + 1] - t[k];
    return dt > 0.0 && dt <= kMaxIntervalS && std::abs(v[k + 1] - v[k]) > kMovedCc;
  };
  std::vector<double> rates;
  std::vector<long> run_of;  // the pump run (one stroke between stops) each rate is from
  long run = 0;
  bool in_run = false;
  for (std::size_t k = 1; k + 2 < t.size(); ++k) {
    if (!running(k - 1) || !running(k) || !running(k + 1) || (v[k + 1] - v[k]) * (v[k] - v[k - 1]) <= 0.0) {
      in_run = false;
      continue;
    }
    if (!in_run) ++run;
    in_run = true;
    rates.push_back(std::abs(v[k + 1] - v[k]) / (t[k + 1] - t[k]));
    run_of.push_back(run);
  }
  if (rates.size() < 3) {
    return not_judged("only " + std::to_string(rates.size()) +
                      " interval(s) with the pump running throughout (3 needed): the pump's travel is too short "
                      "against the sampling of m_ballast_pumped");
  }
  // The fitting core's rule: consecutive rates share a stroke's pressure and
  // oil temperature (serially correlated: counted over the effective sample
  // count), and with two strokes or more each stroke is a cluster (the wider
  // of the two, Student-t on strokes - 1).
  const fitting_core::IntervalRule rule =
      run >= 2 ? fitting_core::IntervalRule::kGlides : fitting_core::IntervalRule::kLag1;
  const fitting_core::Estimate i = fitting_core::mean_with_rule(rates, run_of, rule);
  return {i.value, i.low, i.high, {}};
}

double depth_sample_spacing_s(const flightlog::FlightLog& log) {
  const flightlog::Column* depth = log.find("m_depth");
  if (depth == nullptr) return std::nan("");
  const flightlog::Column& time = log.time();
  std::vector<double> gaps;
  double last = std::nan("");
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (!std::isfinite((*depth)[i]) || !std::isfinite(time[i])) continue;
    if (std::isfinite(last) && time[i] > last) gaps.push_back(time[i] - last);
    last = time[i];
  }
  if (gaps.empty()) return std::nan("");
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

EffectValue lag_at_sampling_resolution(EffectValue lag, double spacing_s) {
  if (!lag.judged() || !(spacing_s > 0.0) || !std::isfinite(lag.low) || !std::isfinite(lag.high)) return lag;
  const double half = 0.5 * spacing_s;
  lag.low = std::max(0.0, std::min(lag.low, lag.value - half));
  lag.high = std::max(lag.high, lag.value + half);
  return lag;
}

EffectValue battery_per_km(const flightlog::FlightLog& log) {
  const flightlog::Column* charge = log.find("m_coulomb_amphr_total");
  if (charge == nullptr) return not_judged("the data have no m_coulomb_amphr_total (coulomb counter)");
  const flightlog::Column* depth = log.find("m_depth");
  const flightlog::Column* pitch = log.find("m_pitch");
  if (depth == nullptr || pitch == nullptr) return not_judged("the data have no m_depth or m_pitch");
  const flightlog::Column& time = log.time();
  double first = std::nan(""), last = std::nan("");
  for (double c : *charge) {
    if (!std::isfinite(c)) continue;
    if (!std::isfinite(first)) first = c;
    last = c;
  }
  // The pitch at each depth reading: a decimated file stores m_depth and
  // m_pitch on their own timers, so after a skipped cycle the two stay in
  // different rows (an .sbd of the health SIL lost 42 % of a segment's glide
  // distance that way, reading 0.210 Ah/km against 0.121: a false step).
  // Pitch is continuous: the straight line between its readings
  // (flightlog/gaps.hpp), never across more than the 30 s allowed a step.
  const flightlog::Column pitch_at = flightlog::interpolate_linear(time, *pitch, 30.0);
  double distance_m = 0.0, last_t = std::nan(""), last_z = std::nan("");
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double z = (*depth)[i], p = pitch_at[i];
    if (!std::isfinite(z)) continue;
    if (std::isfinite(last_z) && std::isfinite(p) && time[i] - last_t <= 30.0 && z > 2.0 && std::abs(p) > 0.1745) {
      distance_m += std::abs(z - last_z) / std::tan(std::abs(p));
    }
    last_z = z;
    last_t = time[i];
  }
  if (!std::isfinite(first) || last <= first) return not_judged("the coulomb counter did not advance");
  if (distance_m < 500.0) return not_judged("less than 0.5 km flown in glides");
  const double value = (last - first) / (distance_m / 1000.0);
  return {value, std::nan(""), std::nan(""), {}};
}

SegmentMeasurement measure_segment(const model::VehicleParams& nominal, const LoadedSegment& segment,
                                   double time_offset_s) {
  const auto start = std::chrono::steady_clock::now();
  SegmentMeasurement m;
  m.name = segment.files.name;
  m.files = segment.files.files;
  m.fingerprint = segment.files.fingerprint;
  if (const auto g = glider_of_file(m.files.front())) m.glider = *g;
  m.time_offset_s = time_offset_s;
  m.start_s = segment.start_s + time_offset_s;
  m.end_s = segment.end_s + time_offset_s;
  m.time_s = 0.5 * (m.start_s + m.end_s);
  const std::string file = m.files.front();
  if (!segment.log) {
    m.why = file + ": cannot be read: " + segment.problem;
    for (EffectValue& v : m.effects) v = not_judged(m.why);
  } else {
    const flightlog::FlightLog& log = *segment.log;
    model::VehicleParams flown = nominal;
    try {
      flown = measure_vertical(nominal, log, m);
    } catch (const std::exception& error) {
      const std::string what = error.what();
      m.why = what.find(file) == std::string::npos ? file + ": " + what : what;
      for (HealthEffect e : {HealthEffect::kDragChange, HealthEffect::kBuoyancyOffset, HealthEffect::kPumpLag}) {
        at(m.effects, e) = not_judged(m.why);
      }
    }
    m.fin_spread_deg = fin_spread_deg(log);
    m.heading_spread_deg = heading_spread_deg(log);
    measure_heading(flown, log, *segment.raw, segment.files.decimated, m);
    at(m.effects, HealthEffect::kPumpRate) = pump_rate(*segment.raw);
    at(m.effects, HealthEffect::kBatteryPerKm) = battery_per_km(log);
  }
  m.cost_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

}  // namespace glider::health
