// SPDX-License-Identifier: Apache-2.0
#include "glider/health/output.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glider/model/vehicle_file.hpp"
#include "glider/report/report.hpp"

namespace glider::health {
namespace {

using nlohmann::json;
constexpr double kDay = 86400.0;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

const EffectAssessment& of(const HealthRun& run, HealthEffect e) {
  return run.assessment.effects[static_cast<std::size_t>(e)];
}

std::string test_text(const HealthEffectInfo& e, double significance) {
  std::string text = "a step (p < " + num(0.5 * significance) + ", Bonferroni over the places searched) of at least " +
                     num(e.rule.step_size) + (e.rule.relative ? " of the level before" : std::string(" ") + e.unit);
  if (e.rule.rate_per_day > 0.0) {
    text += "; or a line over the last days (p < " + num(0.5 * significance) + ") of at least " +
            num(e.rule.rate_per_day) + " " + e.unit + "/day";
  }
  return text;
}

json alert_json(const Alert& a) {
  return {{"id", a.id},
          {"effect", info(a.effect).id},
          {"kind", a.kind},
          {"size", a.size},
          {"unit", std::string(a.relative ? "fraction of the level before" : info(a.effect).unit) +
                       (a.kind == "line" ? "/day" : "")},
          {"ci95", {a.low, a.high}},
          {"since_utc", utc_iso(a.since_s)},
          {"message", a.message},
          {"check", a.check}};
}

}  // namespace

std::string health_json(const HealthRun& run) {
  json segments = json::array();
  for (const SegmentMeasurement& m : run.segments) {
    // Each effect this segment gives no value for, and why (a fin that
    // turned too little: docs/health.md, "The fin is judged only on
    // segments that turn").
    json not_judged = json::object();
    for (std::size_t i = 0; i < kHealthEffectCount; ++i) {
      if (!m.effects[i].judged()) not_judged[info(health_effect(i)).id] = m.effects[i].why;
    }
    segments.push_back({{"name", m.name},
                        {"files", m.files},
                        {"start_utc", utc_iso(m.start_s)},
                        {"end_utc", utc_iso(m.end_s)},
                        {"judged", m.judged},
                        {"why", m.why.empty() ? json(nullptr) : json(m.why)},
                        {"fin_spread_deg", number_or_null(m.fin_spread_deg)},
                        {"heading_spread_deg", number_or_null(m.heading_spread_deg)},
                        {"not_judged", not_judged}});
  }
  json effects = json::array();
  for (const EffectAssessment& a : run.assessment.effects) {
    const HealthEffectInfo& e = info(a.effect);
    json series = json::array();
    for (std::size_t k : a.segments) {
      const EffectValue& v = run.segments[k].effects[static_cast<std::size_t>(a.effect)];
      series.push_back({{"t_utc", utc_iso(run.segments[k].time_s)},
                        {"segment", run.segments[k].name},
                        {"value", v.value},
                        {"lo", number_or_null(v.low)},
                        {"hi", number_or_null(v.high)}});
    }
    // The contract's names (CONTRACTS.md: constant | line | step).
    json shape = nullptr;
    if (a.trend.shape == diagnose::TrendShape::kConstant) shape = "constant";
    if (a.trend.shape == diagnose::TrendShape::kLinear) shape = "line";
    if (a.trend.shape == diagnose::TrendShape::kStep) shape = "step";
    if (a.trend.shape == diagnose::TrendShape::kHinge) shape = "hinge";
    json entry = {{"name", e.id},
                  {"unit", e.unit},
                  {"what", e.what},
                  {"shape", shape},
                  {"shape_text", a.trend.shape == diagnose::TrendShape::kNone ? "" : a.trend.describe(e.unit)},
                  {"value", number_or_null(a.value)},
                  {"ci95", {number_or_null(a.low), number_or_null(a.high)}},
                  {"shared_sigma", number_or_null(a.shared_sigma)},
                  {"since_utc", a.since_s ? json(utc_iso(*a.since_s)) : json(nullptr)},
                  {"judged", a.judged},
                  {"why", a.why.empty() ? json(nullptr) : json(a.why)},
                  {"threshold",
                   {{"size", e.rule.step_size},
                    {"relative", e.rule.relative},
                    {"rate_per_day", e.rule.rate_per_day},
                    {"test", test_text(e, diagnose::TrendOptions{}.significance)}}},
                  {"series", series}};
    effects.push_back(entry);
  }
  json alerts = json::array();
  for (const Alert& a : run.assessment.alerts) alerts.push_back(alert_json(a));
  const double updated = run.segments.empty() ? 0.0 : run.segments.back().end_s;
  const json j = {{"schema", "glider-health/1"},
                  {"glider", run.glider},
                  {"updated_utc", utc_iso(updated)},
                  {"vehicle", run.vehicle_source},
                  {"state", run.assessment.state},
                  {"segments", segments},
                  {"effects", effects},
                  {"alerts", alerts},
                  {"notes", run.notes},
                  {"update", {{"measured", run.measured}, {"reused", run.reused}, {"cost_s", run.cost_s}}}};
  return j.dump(1) + "\n";
}

std::string health_text(const HealthRun& run) {
  std::ostringstream out;
  std::size_t judged = 0;
  for (const SegmentMeasurement& m : run.segments) judged += m.judged ? 1 : 0;
  out << "Flight health of " << (run.glider.empty() ? "(unnamed glider)" : run.glider) << ": " << run.assessment.state
      << "  (" << run.segments.size() << " segments, " << judged << " judged; " << run.measured << " measured now, "
      << run.reused << " from the state; " << num(run.cost_s) << " s)\n";
  out << "  vehicle: " << run.vehicle_source << "\n";
  for (const Alert& a : run.assessment.alerts) {
    out << "  ALERT " << a.id << ": " << a.message << "\n        check: " << a.check << "\n";
  }
  out << "  effects (current level [95 % interval], shape over the deployment):\n";
  for (const EffectAssessment& a : run.assessment.effects) {
    const HealthEffectInfo& e = info(a.effect);
    char line[160];
    std::snprintf(line, sizeof line, "    %-18s ", e.id);
    out << line;
    if (!std::isfinite(a.value)) {
      out << "cannot judge: " << a.why << "\n";
      continue;
    }
    out << num(a.value) << " " << e.unit;
    if (std::isfinite(a.low)) out << " [" << num(a.low) << ", " << num(a.high) << "]";
    if (a.judged) {
      out << "; " << a.trend.describe(e.unit);
    } else {
      out << "; cannot judge: " << a.why;
    }
    out << "\n";
  }
  for (const SegmentMeasurement& m : run.segments) {
    const EffectValue& fin = m.effects[static_cast<std::size_t>(HealthEffect::kFinEffectiveness)];
    if (m.judged && !fin.judged()) out << "  fin_effectiveness not judged on " << m.name << ": " << fin.why << "\n";
  }
  for (const std::string& note : run.notes) out << "  note: " << note << "\n";
  return out.str();
}

model::VehicleParams estimated_vehicle(const model::VehicleParams& nominal, const HealthRun& run) {
  model::VehicleParams v = nominal;
  auto level = [&](HealthEffect e) -> std::optional<double> {
    const EffectAssessment& a = of(run, e);
    if (!std::isfinite(a.value)) return std::nullopt;
    return a.value;
  };
  if (auto d = level(HealthEffect::kDragChange)) v.hydro.cd0 *= *d;
  if (auto b = level(HealthEffect::kBuoyancyOffset)) v.buoyancy_offset_kg = *b * 1e-3;
  if (auto r = level(HealthEffect::kPumpRate)) v.ballast.rate_m3_s = *r * 1e-6;
  if (auto l = level(HealthEffect::kPumpLag)) v.ballast.lag_s = std::max(0.0, *l);
  if (auto f = level(HealthEffect::kFinEffectiveness)) v.heading.fin_yaw_gain_per_m *= *f;
  if (auto r = level(HealthEffect::kRollOffset)) v.heading.roll_offset_rad = *r * M_PI / 180.0;
  v.description = "health's current estimates applied to " + nominal.name;
  return v;
}

bool write_outputs(const std::filesystem::path& dir, const HealthRun& run, const model::VehicleParams& nominal) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  report::write_file(dir / "health.json", health_json(run));
  report::write_file(dir / "vehicle.toml", "# Written by glider-health: " + nominal.name +
                                               " with the deployment's current estimates (docs/health.md)\n" +
                                               model::vehicle_file_text(estimated_vehicle(nominal, run)));
  // The plots are drawn in a scratch folder and renamed into plots/ one by
  // one: a reader never sees a half-written PNG.
  const fs::path scratch = dir / ".plots.tmp";
  fs::remove_all(scratch);
  report::Report plots(scratch);
  plots.text() << "# Flight health of " << run.glider << "\n";
  std::vector<std::string> names;
  const double t0 = run.segments.empty() ? 0.0 : run.segments.front().start_s;
  for (const EffectAssessment& a : run.assessment.effects) {
    if (a.segments.empty()) continue;
    const HealthEffectInfo& e = info(a.effect);
    std::vector<double> day, value, low, high, shape, upper, lower;
    for (std::size_t k : a.segments) {
      const EffectValue& v = run.segments[k].effects[static_cast<std::size_t>(a.effect)];
      day.push_back((run.segments[k].time_s - t0) / kDay);
      value.push_back(v.value);
      low.push_back(std::isfinite(v.low) ? v.low : v.value);
      high.push_back(std::isfinite(v.high) ? v.high : v.value);
      shape.push_back(a.trend.shape == diagnose::TrendShape::kNone ? v.value : a.trend.at(run.segments[k].time_s));
      // The alert threshold: a step of this size from the first level.
      const double base =
          a.trend.shape == diagnose::TrendShape::kNone ? value.front() : a.trend.at(a.trend.first_time_s);
      const double size = e.rule.step_size * (e.rule.relative ? std::abs(base) : 1.0);
      upper.push_back(base + size);
      lower.push_back(base - size);
    }
    const std::string name = e.id;
    plots.data(name + ".dat", {"day", "value", "low", "high", "shape", "upper", "lower"},
               {day, value, low, high, shape, upper, lower});
    plots.plot(name,
               std::string(e.id) + " (" + e.unit +
                   ") per segment with its 95 % interval, the shape, and the "
                   "alert threshold (a change of this size from the start)",
               "set xlabel 'day of the deployment'\nset ylabel '" + std::string(e.id) + " (" + e.unit +
                   ")' noenhanced\nset key outside bottom\nplot '" + name +
                   ".dat' u 1:2:3:4 w yerrorbars pt 7 ps 0.6 t 'segment', '' u 1:5 w l lw 2 t '" +
                   (a.trend.shape == diagnose::TrendShape::kNone ? "none" : diagnose::to_string(a.trend.shape)) +
                   "', '' u 1:6 w l dt 2 lc rgb 'red' t 'alert threshold', '' u 1:7 w l dt 2 lc rgb 'red' notitle");
    names.push_back(name);
  }
  const bool ok = plots.finish();
  fs::create_directories(dir / "plots");
  for (const std::string& name : names) {
    std::error_code error;
    fs::rename(scratch / (name + ".png"), dir / "plots" / (name + ".png"), error);
  }
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  return ok;
}

}  // namespace glider::health
