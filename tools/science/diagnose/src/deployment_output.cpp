// SPDX-License-Identifier: Apache-2.0
#include "deployment_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "glider/diagnose/diagnosis_json.hpp"
#include "glider/report/report.hpp"

namespace glider::diagnose {
namespace {

constexpr double kSecondsPerDay = 86400.0;

// Day 0: the first diagnosed segment.
double day_zero_s(const DeploymentDiagnosis& d) {
  for (const SegmentResult& s : d.segments) {
    if (s.fixed) return s.time_s;
  }
  return 0.0;
}

double day_of(const DeploymentDiagnosis& d, double time_s) { return (time_s - day_zero_s(d)) / kSecondsPerDay; }

nlohmann::ordered_json interval_json(const Interval& i) {
  return {{"value", i.value}, {"low", i.low}, {"high", i.high}};
}

// JSON has no NaN: a segment without a value is null.
nlohmann::ordered_json number_or_null(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nullptr; }

// A level's interval with the bias all segments share in it: its sigma and
// the segments' scatter's half-width alone (the slopes and steps carry none).
nlohmann::ordered_json level_json(const Interval& i, const SharedBias& shared) {
  nlohmann::ordered_json j = interval_json(i);
  j["shared_sigma"] = shared.sigma;
  j["between_segments_half_width"] = shared.sigma > 0.0 ? shared.between_half_width : 0.5 * (i.high - i.low);
  return j;
}

nlohmann::ordered_json trend_json(const Trend& t, const DeploymentDiagnosis& d) {
  nlohmann::ordered_json j{{"shape", to_string(t.shape)}, {"segments", t.segments}};
  switch (t.shape) {
    case TrendShape::kNone:
      break;
    case TrendShape::kConstant:
      j["mean"] = level_json(t.mean, t.mean_shared);
      break;
    case TrendShape::kLinear:
      j["per_day"] = interval_json(t.slope_per_day);
      j["at_day_0"] = level_json(t.at_start, t.at_start_shared);
      j["p"] = t.p_slope;
      break;
    case TrendShape::kStep:
      j["change"] = interval_json(t.step_change);
      j["after_day"] = day_of(d, t.step_before_s);
      j["before_day"] = day_of(d, t.step_after_s);
      j["level_before"] = t.level_before;
      j["level_after"] = t.level_after;
      j["p"] = t.p_step;
      break;
    case TrendShape::kHinge:
      j["level"] = level_json(t.hinge_level, t.hinge_level_shared);
      j["at_last_segment"] = level_json(t.hinge_end, t.hinge_end_shared);
      j["from_day"] = day_of(d, t.hinge_s);
      j["per_day"] = interval_json(t.hinge_slope_per_day);
      j["p"] = t.p_hinge;
      break;
  }
  j["bic"] = {{"constant", t.bic_constant}, {"linear", t.bic_linear}, {"step", t.bic_step}, {"hinge", t.bic_hinge}};
  return j;
}

std::string cell(const EffectHistory& h, std::size_t i) {
  if (!std::isfinite(h.value[i])) return "-";
  char text[96];
  std::snprintf(text, sizeof text, "%.4g [%.4g, %.4g]", h.value[i], h.ci95_low[i], h.ci95_high[i]);
  return text;
}

}  // namespace

void print_deployment(const DeploymentDiagnosis& d, const std::string& vehicle_source) {
  std::printf("Deployment diagnosis: %zu segments, %zu diagnosed (day 0 = the first diagnosed segment)\n",
              d.segments.size(), d.diagnosed);
  std::printf("  vehicle: %s\n", vehicle_source.c_str());
  std::printf("  effects of the deployment (found by the segments' own selection in n of them), over time:\n");
  if (d.effects.empty()) std::printf("    none: no effect recurs across the segments\n");
  for (const EffectHistory& h : d.effects) {
    std::printf("    %-24s (%zu of %zu) %s\n", info(h.effect).id, h.selected_in, d.diagnosed,
                h.trend.describe(info(h.effect).unit).c_str());
  }
  std::printf("  per segment (value [95 %% interval] of each effect, all fitted jointly):\n");
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    const SegmentResult& s = d.segments[i];
    if (!s.problem.empty()) {
      std::printf("    %s: not diagnosed: %s\n", s.name.c_str(), s.problem.c_str());
      continue;
    }
    std::printf("    %s (day %.2f, own cause %s):", s.name.c_str(), day_of(d, s.time_s),
                s.selected ? s.selected->cause.c_str() : "-");
    for (const EffectHistory& h : d.effects) std::printf("  %s %s", info(h.effect).id, cell(h, i).c_str());
    std::printf("\n");
  }
}

nlohmann::ordered_json deployment_json(const DeploymentDiagnosis& d, const std::string& vehicle_source) {
  nlohmann::ordered_json j;
  j["vehicle_source"] = vehicle_source;
  j["segments_diagnosed"] = d.diagnosed;
  j["day_0_time_s"] = day_zero_s(d);
  nlohmann::ordered_json effects = nlohmann::ordered_json::array();
  for (const EffectHistory& h : d.effects) {
    nlohmann::ordered_json e{{"id", info(h.effect).id}, {"unit", info(h.effect).unit}, {"selected_in", h.selected_in}};
    nlohmann::ordered_json values = nlohmann::ordered_json::array(), low = values, high = values;
    for (std::size_t i = 0; i < h.value.size(); ++i) {
      values.push_back(number_or_null(h.value[i]));
      low.push_back(number_or_null(h.ci95_low[i]));
      high.push_back(number_or_null(h.ci95_high[i]));
    }
    e["values"] = values;
    e["ci95_low"] = low;
    e["ci95_high"] = high;
    nlohmann::ordered_json shift = nlohmann::ordered_json::array();
    for (double x : h.reynolds_prior_shift) shift.push_back(number_or_null(x));
    e["reynolds_prior_shift"] = shift;  // per segment, 1 sigma: the shared part of ci95
    e["trend"] = trend_json(h.trend, d);
    effects.push_back(e);
  }
  j["effects"] = effects;
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (const SegmentResult& s : d.segments) {
    nlohmann::ordered_json seg{{"name", s.name}, {"time_s", number_or_null(s.time_s)}};
    if (!s.problem.empty()) seg["problem"] = s.problem;
    if (s.fixed) seg["day"] = day_of(d, s.time_s);
    if (s.selected) seg["own_cause"] = s.selected->cause;
    if (s.fixed) seg["diagnosis"] = diagnosis_json(*s.fixed, vehicle_source, 0.0);
    segments.push_back(seg);
  }
  j["segments"] = segments;
  return j;
}

void write_deployment_report(const std::string& dir, const DeploymentDiagnosis& d, const std::string& vehicle_source) {
  std::filesystem::create_directories(dir);
  report::Report r(dir);
  r.text() << "# Deployment diagnosis\n\n"
           << d.segments.size() << " segments, " << d.diagnosed << " diagnosed; vehicle: " << vehicle_source
           << ". Each effect that the segments' own diagnoses keep finding is fitted jointly in every segment; "
              "its values over time are a constant, a line or one step, whichever the segments' scatter "
              "supports (numbers: deployment.json).\n\n";
  std::vector<std::vector<std::string>> rows;
  for (const EffectHistory& h : d.effects) {
    rows.push_back({info(h.effect).id, std::to_string(h.selected_in) + " of " + std::to_string(d.diagnosed),
                    h.trend.describe(info(h.effect).unit)});
  }
  r.table({"effect", "found in", "over the deployment (95 % intervals)"}, rows);
  for (const EffectHistory& h : d.effects) {
    std::vector<double> day, value, low, high;
    for (std::size_t i = 0; i < d.segments.size(); ++i) {
      if (!std::isfinite(h.value[i])) continue;
      day.push_back(day_of(d, d.segments[i].time_s));
      value.push_back(h.value[i]);
      low.push_back(h.ci95_low[i]);
      high.push_back(h.ci95_high[i]);
    }
    if (day.empty()) continue;
    // The fitted shape drawn finely, so a step is a step.
    std::vector<double> fine_day, fine_value;
    const double first = day.front(), last = day.back();
    for (int k = 0; k <= 400; ++k) {
      const double t = first + (last - first) * k / 400.0;
      fine_day.push_back(t);
      fine_value.push_back(h.trend.at(day_zero_s(d) + t * kSecondsPerDay));
    }
    const std::string id = info(h.effect).id;
    r.data(id + ".dat", {"day", "value", "ci95_low", "ci95_high"}, {day, value, low, high});
    r.data(id + "_shape.dat", {"day", "value"}, {fine_day, fine_value});
    r.plot(
        id,
        id + " per segment (95 % interval) and its shape over the deployment: " + h.trend.describe(info(h.effect).unit),
        "set termoption noenhanced\nset xlabel 'day of the deployment'\nset ylabel '" + id + " (" +
            info(h.effect).unit + ")'\nset key top left\nplot '" + id +
            ".dat' u 1:2:3:4 w yerrorbars pt 7 ps 0.6 t 'segments', '" + id + "_shape.dat' u 1:2 w l lw 2 t '" +
            to_string(h.trend.shape) + "'");
  }
  if (!r.finish()) throw std::runtime_error("the plots could not be rendered (gnuplot)");
  glider::report::write_file(std::filesystem::path(dir) / "deployment.json",
                             deployment_json(d, vehicle_source).dump(2) + '\n');
}

}  // namespace glider::diagnose
