// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/deployment_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double middle_time_s(const Observations& obs) {
  const std::vector<double>& t = obs.time_s.empty() ? obs.track.time_s : obs.time_s;
  if (t.empty()) return kNaN;
  return 0.5 * (t.front() + t.back());
}

// The effects the segments' own selections keep finding, most often first
// (ties: the order of the vocabulary).
std::vector<Effect> recurring_effects(const std::vector<SegmentResult>& segments, std::size_t diagnosed,
                                      const DeploymentOptions& options, std::vector<std::size_t>& count) {
  count.assign(kEffectCount, 0);
  for (const SegmentResult& s : segments) {
    if (!s.selected) continue;
    for (const Finding& f : s.selected->findings) ++count[static_cast<std::size_t>(f.effect)];
  }
  const double needed =
      std::max(static_cast<double>(options.min_segments), options.min_fraction * static_cast<double>(diagnosed));
  std::vector<Effect> effects;
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    if (static_cast<double>(count[e]) >= needed) effects.push_back(effect_from_index(e));
  }
  std::stable_sort(effects.begin(), effects.end(), [&](Effect a, Effect b) {
    return count[static_cast<std::size_t>(a)] > count[static_cast<std::size_t>(b)];
  });
  return effects;
}

}  // namespace

DeploymentDiagnosis diagnose_deployment(const model::VehicleParams& nominal, const std::vector<SegmentInput>& inputs,
                                        const DeploymentOptions& options) {
  DeploymentDiagnosis result;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const SegmentInput& in = inputs[i];
    SegmentResult& s = result.segments.emplace_back();
    s.name = in.name;
    s.problem = in.problem;
    if (!in.observations) {
      if (s.problem.empty()) s.problem = "no observations";
      s.time_s = kNaN;
      continue;
    }
    s.time_s = in.time_offset_s + middle_time_s(*in.observations);
    if (options.effects.empty()) {
      if (options.progress) options.progress(1, i, in.name);
      try {
        s.selected = diagnose(nominal, *in.observations, options.diagnose);
      } catch (const std::exception& error) {
        s.problem = error.what();
        continue;
      }
    }
    ++result.diagnosed;
  }

  std::vector<std::size_t> found(kEffectCount, 0);
  const std::vector<Effect> effects =
      options.effects.empty() ? recurring_effects(result.segments, result.diagnosed, options, found) : options.effects;

  // Every segment fits the deployment's effects jointly (the pitch trim is
  // judged after them in any diagnosis), so each has a value and an interval
  // in every segment, not only where its own selection kept it.
  DiagnoseOptions fixed = options.diagnose;
  fixed.fit_only.clear();
  for (Effect e : effects) {
    if (e != Effect::kPitchTrimOffset) fixed.fit_only.push_back(e);
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    SegmentResult& s = result.segments[i];
    if (!s.problem.empty() || !inputs[i].observations) continue;
    if (fixed.fit_only.empty()) {
      s.fixed = s.selected;  // nothing to fit but the pitch trim, which the selection judged
      continue;
    }
    if (options.progress) options.progress(2, i, s.name);
    try {
      s.fixed = diagnose(nominal, *inputs[i].observations, fixed);
    } catch (const std::exception& error) {
      s.problem = error.what();
    }
  }

  std::vector<double> times;
  for (const SegmentResult& s : result.segments) times.push_back(s.fixed ? s.time_s : kNaN);
  for (Effect e : effects) {
    EffectHistory& h = result.effects.emplace_back();
    h.effect = e;
    h.selected_in = found[static_cast<std::size_t>(e)];
    for (const SegmentResult& s : result.segments) {
      double value = kNaN, low = kNaN, high = kNaN, shift = kNaN;  // NaN: no value (the trend leaves it out)
      if (s.fixed) {
        for (const Finding& f : s.fixed->findings) {
          if (f.effect != e) continue;
          value = f.value;
          low = f.ci95_low;
          high = f.ci95_high;
          shift = f.reynolds_prior_shift;
        }
      }
      h.value.push_back(value);
      h.ci95_low.push_back(low);
      h.ci95_high.push_back(high);
      h.reynolds_prior_shift.push_back(shift);
    }
    // The segments' scatter holds what differs between them; the Reynolds
    // prior's shift is one bias for the whole glider: the levels' intervals
    // carry it as a common-mode term, the slopes and steps do not.
    h.trend = fit_trend(times, h.value, options.trend, h.reynolds_prior_shift);
  }
  return result;
}

}  // namespace glider::diagnose
