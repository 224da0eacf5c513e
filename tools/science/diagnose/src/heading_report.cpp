// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "glider/diagnose/heading_select_resolution.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

// The roll offset against the wings' lift (docs/science.md "A roll offset or
// the wings' lift"): what the log would need to tell them apart.
bool is_roll_or_lift(const HeadingAmbiguity& a) {
  return a.chosen == HeadingEffect::kLiftFactor || a.alternative == HeadingEffect::kLiftFactor;
}
constexpr const char* kRollOrLiftSeparate =
    "glides at a different roll (a bank the fin holds, turns), or a lift change named by the vertical plane: where "
    "the roll hardly varies, a roll offset and the wings' lift turn the glider alike (lift_factor x: the roll's turn "
    "scaled by 1/x, the glide's angle of attack at a lift slope x times the vehicle file's)";

using nlohmann::ordered_json;

ordered_json number_or_null(double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr); }

// What each link's residual measures.
const char* measured_of(HeadingLink link) {
  switch (link) {
    case HeadingLink::kServo:
      return "m_fin (rad) from the logged c_fin";
    case HeadingLink::kVehicle:
      return "yaw rate (rad/s, slope of m_heading) from the logged m_fin";
    case HeadingLink::kAutopilot:
      return "c_fin (rad) from the logged m_heading and c_heading";
  }
  return "?";
}

ordered_json link_json(const LinkFit& f) {
  ordered_json j;
  j["measured"] = measured_of(f.link);
  j["samples"] = f.samples;
  j["train_samples"] = f.train_samples;
  j["heldout_samples"] = f.heldout_samples;
  j["baseline"] = {{"rms", number_or_null(f.baseline_rms)},
                   {"rms_dive", number_or_null(f.baseline_rms_dive)},
                   {"rms_climb", number_or_null(f.baseline_rms_climb)},
                   {"heldout_rms", number_or_null(f.baseline_heldout_rms)}};
  ordered_json findings = ordered_json::array();
  for (const HeadingFinding& x : f.findings) {
    findings.push_back({{"effect", info(x.effect).id},
                        {"value", x.value},
                        {"nominal", x.nominal},
                        {"unit", info(x.effect).unit},
                        {"ci95", {x.ci95_low, x.ci95_high}},
                        {"heldout_rms", x.heldout_rms},
                        {"gain", x.gain}});
  }
  j["findings"] = findings;
  // Chosen by the rate error, then refuted by the fin's measurement on the
  // innovations (heading_diagnose.hpp yaw_noise_model): that measurement; or
  // not selected again with the fin held at it: the rate error's value.
  ordered_json refuted = ordered_json::array();
  for (const HeadingFinding& x : f.dropped) {
    const bool fin = x.effect == HeadingEffect::kFinEffectiveness;
    refuted.push_back(
        {{"effect", info(x.effect).id},
         {"value", x.value},
         {"nominal", x.nominal},
         {"ci95", {x.ci95_low, x.ci95_high}},
         {"why", fin ? "the heading's innovations (compass noise and random yaw modelled) hold the nominal"
                     : "not selected again with the fin held at its measurement on the heading's innovations"}});
  }
  j["refuted"] = refuted;
  // Named, then left at the nominal: the yaw's lag within the dynamics a
  // first-order yaw lumps into it (heading_select_resolution.hpp).
  ordered_json within = ordered_json::array();
  for (const HeadingFinding& x : f.within_resolution) {
    within.push_back({{"effect", info(x.effect).id},
                      {"value", x.value},
                      {"nominal", x.nominal},
                      {"ci95", {x.ci95_low, x.ci95_high}},
                      {"resolution", kYawLagResolutionS}});
  }
  j["within_resolution"] = within;
  if (f.link == HeadingLink::kVehicle) j["delay_split_s"] = f.delay_split_s;
  ordered_json pairs = ordered_json::array();
  for (const HeadingAmbiguity& a : f.identifiability) {
    pairs.push_back({{"chosen", info(a.chosen).id},
                     {"alternative", info(a.alternative).id},
                     {"correlation", number_or_null(a.correlation)},
                     {"judged_on", a.on_innovations ? "heading innovations" : "rate error"},
                     {"alternative_value", a.alternative_value},
                     {"chosen_heldout_rms", a.chosen_heldout_rms},
                     {"alternative_heldout_rms", a.alternative_heldout_rms},
                     {"verdict", a.ambiguous ? "ambiguous" : "told apart by the held-out yos"}});
    if (a.ambiguous && is_roll_or_lift(a)) pairs.back()["separate"] = kRollOrLiftSeparate;
  }
  j["identifiability"] = pairs;
  ordered_json screen = ordered_json::array();
  // Judged: fitted in the finding's place (over the screen, or a dead time
  // whatever its correlation: heading_fit.cpp judge_pairs).
  auto judged = [&](const LinkFit::ScreenedCorrelation& c) {
    return std::any_of(f.identifiability.begin(), f.identifiability.end(), [&](const HeadingAmbiguity& a) {
      return a.chosen == c.chosen && a.alternative == c.alternative;
    });
  };
  for (const auto& c : f.screen) {
    screen.push_back({{"chosen", info(c.chosen).id},
                      {"alternative", info(c.alternative).id},
                      {"correlation", number_or_null(c.correlation)},
                      {"judged", judged(c)}});
  }
  j["identifiability_screen"] = {{"screen_correlation", f.screen_correlation}, {"pairs", screen}};
  j["extended"] = {{"rms", number_or_null(f.extended_rms)}, {"heldout_rms", number_or_null(f.extended_heldout_rms)}};
  j["gain"] = number_or_null(f.gain);
  ordered_json candidates = ordered_json::array();
  for (HeadingEffect e : f.candidates) candidates.push_back(info(e).id);
  j["candidates"] = candidates;
  return j;
}

}  // namespace

ordered_json heading_json(const HeadingDiagnosis& d) {
  ordered_json j;
  j["available"] = true;
  j["runs"] = d.runs;
  j["roll_logged"] = d.roll_logged;
  j["autopilot_integrator"] = d.autopilot_integrator_per_glide ? "per-glide" : "replayed";
  if (d.autopilot_clock.fitted) {
    ordered_json one = ordered_json::array();
    for (const HeadingFinding& x : d.autopilot_clock.one_clock_only) {
      one.push_back({{"effect", info(x.effect).id}, {"value", x.value}, {"ci95", {x.ci95_low, x.ci95_high}}});
    }
    j["autopilot_clock"] = {{"kept", d.autopilot_clock.kept},
                            {"measured_heldout_rms", d.autopilot_clock.measured_heldout_rms},
                            {"nominal_heldout_rms", d.autopilot_clock.nominal_heldout_rms},
                            {"named_under_one_clock_only", one}};
  }
  j["logged_roll_rad"] = d.logged_roll_rad;
  j["fin_max_rad"] = d.fin_max_rad;
  j["heading_noise_rad"] = d.heading_noise_rad;
  j["unexplained_yaw_rate"] = {{"rms_rad_s", d.unexplained_yaw_rate_rad_s},
                               {"correlation_s", d.unexplained_correlation_s}};
  j["yaw_noise"] = {{"compass_rad", d.yaw_noise.heading_rad},
                    {"random_yaw_rad_s", d.yaw_noise.disturbance_rad_s},
                    {"random_yaw_correlation_s", d.yaw_noise.correlation_s}};
  ordered_json shear = ordered_json::array();
  for (const ShearBin& b : d.current_shear.bins) {
    if (!b.fitted) continue;
    shear.push_back({{"depth_from_m", b.from_m},
                     {"depth_to_m", b.to_m},
                     {"shear_per_s", b.shear_per_s},
                     {"ci95", {b.ci95_low, b.ci95_high}},
                     {"glides", b.runs}});
  }
  j["current_shear"] = {
      {"bins", shear},
      {"heldout_yaw_rms_rad_s", {d.current_shear.heldout_rms_before, d.current_shear.heldout_rms_after}},
      {"dive_climb_correlation", d.current_shear.dive_climb_correlation}};
  ordered_json holds = ordered_json::array();
  for (const HoldBin& b : d.holds) {
    holds.push_back(
        {{"error_from_rad", b.from_rad}, {"error_to_rad", b.to_rad}, {"held", b.held}, {"changed", b.changed}});
  }
  j["fin_holds"] = holds;
  j["configured_autopilot"] = {{"gain", d.configured.gain},
                               {"igain", d.configured.igain},
                               {"dgain", d.configured.dgain},
                               {"rate_deadband_rad_s", d.configured.rate_deadband_rad_s},
                               {"stated_by_log", d.configured.stated}};
  j["flown_autopilot"] = {{"gain", at(d.values, HeadingEffect::kAutopilotGain)},
                          {"igain", at(d.values, HeadingEffect::kAutopilotIntegral)},
                          {"dgain", at(d.values, HeadingEffect::kAutopilotDgain)},
                          {"delay_s", at(d.values, HeadingEffect::kAutopilotDelay)}};
  j["delay_s"] = {{"autopilot", d.delay_autopilot_s},
                  {"servo", d.delay_servo_s},
                  {"after_fin", d.delay_after_fin_s},
                  {"total", d.delay_autopilot_s + d.delay_servo_s + d.delay_after_fin_s}};
  j["yaw_fast_pole_s"] = {{"carried", d.yaw_fast_pole_s},
                          {"prior_max", d.yaw_fast_pole_max_s},
                          {"beside_lag", d.yaw_lag_pole_s},
                          {"beside_lag_span", {d.yaw_lag_pole_low_s, d.yaw_lag_pole_high_s}}};
  j["links"] = {{"servo", link_json(d.servo)}, {"vehicle", link_json(d.yaw)}, {"autopilot", link_json(d.autopilot)}};
  {
    const ClosedLoopCheck& c = d.closed_loop;
    auto score = [](const ClosedLoopScore& x) {
      return ordered_json{
          {"score", x.score}, {"error_rms_rad", x.error_rms_rad}, {"fin_travel_rms_rad_s", x.travel_rms_rad_s}};
    };
    ordered_json candidates = ordered_json::array();
    for (const ClosedLoopCandidate& x : c.candidates) {
      ordered_json one = score(x.score);
      one["effect"] = info(x.effect).id;
      one["value"] = x.value;
      one["beats_open_loop_set"] = x.beats;
      candidates.push_back(one);
    }
    j["closed_loop"] = {{"measured",
                         "per glide, model against log: mean heading error and fin travel, in units of the log's "
                         "glide-to-glide scatter"},
                        {"train_glides", c.train_glides},
                        {"heldout_glides", c.heldout_glides},
                        {"error_scatter_rad", c.error_scatter_rad},
                        {"fin_travel_scatter_rad_s", c.travel_scatter_rad_s},
                        {"configured", score(c.configured)},
                        {"open_loop_set", score(c.open_loop_set)},
                        {"candidates", candidates}};
  }
  j["cause"] = d.cause;
  ordered_json parameters;
  for (std::size_t i = 0; i < kHeadingEffectCount; ++i)
    parameters[info(static_cast<HeadingEffect>(i)).id] = d.values[i];
  j["parameters"] = parameters;
  return j;
}

ordered_json heading_unavailable_json(const std::string& reason) { return {{"available", false}, {"reason", reason}}; }

HeadingPlane heading_plane(const model::VehicleParams& nominal, const flightlog::FlightLog& log,
                           const HeadingDiagnoseOptions& options) {
  HeadingPlane plane;
  try {
    plane.diagnosis = diagnose_heading(nominal, log, options);
    plane.json = heading_json(*plane.diagnosis);
  } catch (const HeadingUnavailable& why) {
    plane.json = heading_unavailable_json(why.what());
  }
  return plane;
}

std::string heading_text(const HeadingDiagnosis& d) {
  std::string out;
  char line[512];
  auto add = [&](const char* fmt, auto... args) {
    std::snprintf(line, sizeof line, fmt, args...);
    out += line;
  };
  add("Heading plane: %zu glides under a heading command; roll %s %.1f deg; fin limit %.3f rad\n", d.runs,
      d.roll_logged ? "logged, median" : "not logged, the vehicle's", rad_to_deg(d.logged_roll_rad), d.fin_max_rad);
  add("  configured autopilot%s: gain %.3g, igain %.3g, dgain %.3g\n",
      d.configured.stated ? "" : " (not stated: defaults)", d.configured.gain, d.configured.igain, d.configured.dgain);
  for (const LinkFit* f : {&d.servo, &d.yaw, &d.autopilot}) {
    add("  %-9s %s: baseline RMS %.4g (dives %.4g, climbs %.4g), held-out %.4g over %zu samples\n", to_string(f->link),
        measured_of(f->link), f->baseline_rms, f->baseline_rms_dive, f->baseline_rms_climb, f->baseline_heldout_rms,
        f->samples);
    if (f->findings.empty()) add("            findings: none\n");
    for (const HeadingFinding& x : f->findings) {
      add("            %-20s %+.4g %s (nominal %.4g; 95%% CI %.4g .. %.4g) held-out %.4g, gain %.0f %%\n",
          info(x.effect).id, x.value, info(x.effect).unit, x.nominal, x.ci95_low, x.ci95_high, x.heldout_rms,
          100.0 * x.gain);
    }
    for (const HeadingAmbiguity& a : f->identifiability) {
      if (!a.ambiguous || !is_roll_or_lift(a)) continue;
      add("            ambiguous: %s as read, or %s %.4g %s in its place (held-out %.4g vs %.4g; signatures "
          "correlate %.3f)\n",
          info(a.chosen).id, info(a.alternative).id, a.alternative_value, info(a.alternative).unit,
          a.chosen_heldout_rms, a.alternative_heldout_rms, a.correlation);
      out += "              separate them by ";
      out += kRollOrLiftSeparate;
      out += "\n";
    }
    for (const HeadingFinding& x : f->dropped) {
      add("            not %-16s %+.4g %s (95%% CI %.4g .. %.4g on the heading's innovations, noise modelled: holds "
          "%.4g)\n",
          info(x.effect).id, x.value, info(x.effect).unit, x.ci95_low, x.ci95_high, x.nominal);
    }
    for (const HeadingFinding& x : f->within_resolution) {
      add("            not %-16s %+.4g %s (95%% CI %.4g .. %.4g): within %.3g %s of the nominal %.4g, the fast "
          "dynamics a first-order yaw lumps into its lag\n",
          info(x.effect).id, x.value, info(x.effect).unit, x.ci95_low, x.ci95_high, kYawLagResolutionS,
          info(x.effect).unit, x.nominal);
    }
    if (f->delay_split_s > 0.0) {
      add("            %.2f s of the yaw delay the servo's rows cannot place on either side of the fin (both "
          "intervals span it)\n",
          f->delay_split_s);
    }
  }
  if (d.closed_loop.heldout_glides > 0) {
    const ClosedLoopCheck& c = d.closed_loop;
    add("  closed loop, %zu held-out glides, model - log (mean heading error RMS, fin travel RMS; score in the log's "
        "scatter %.2f deg, %.2f rad/h): configured %.2f deg %.2f rad/h (%.2f), identified %.2f deg %.2f rad/h "
        "(%.2f)\n",
        c.heldout_glides, rad_to_deg(c.error_scatter_rad), 3600.0 * c.travel_scatter_rad_s,
        rad_to_deg(c.configured.error_rms_rad), 3600.0 * c.configured.travel_rms_rad_s, c.configured.score,
        rad_to_deg(c.open_loop_set.error_rms_rad), 3600.0 * c.open_loop_set.travel_rms_rad_s, c.open_loop_set.score);
    for (const ClosedLoopCandidate& x : c.candidates) {
      add("            with %-20s %+.4g: %.2f deg %.2f rad/h (%.2f)%s\n", info(x.effect).id, x.value,
          rad_to_deg(x.score.error_rms_rad), 3600.0 * x.score.travel_rms_rad_s, x.score.score,
          x.beats ? ", beats it" : "");
    }
  }
  const ShearProfile& shear = d.current_shear;
  add("  current shear across the heading (1/s, fitted glides' 95 %% CI), held-out yaw rate RMS %.3f -> %.3f deg/s, "
      "dives vs climbs correlation %.2f:\n   ",
      rad_to_deg(shear.heldout_rms_before), rad_to_deg(shear.heldout_rms_after), shear.dive_climb_correlation);
  for (const ShearBin& b : shear.bins) {
    if (b.fitted) add(" %.0f-%.0f m %+.4f [%+.4f, %+.4f];", b.from_m, b.to_m, b.shear_per_s, b.ci95_low, b.ci95_high);
  }
  add("\n");
  add("  heading jitter (cycle to cycle, as white noise): %.2f deg; yaw rate left unexplained: RMS %.2f deg/s, "
      "correlated over %.0f s\n",
      rad_to_deg(d.heading_noise_rad), rad_to_deg(d.unexplained_yaw_rate_rad_s), d.unexplained_correlation_s);
  add("  c_fin held / changed by the previous cycle's error (rate inside its deadband):");
  for (const HoldBin& b : d.holds) {
    add(" %.0f-%.0f deg %zu/%zu;", rad_to_deg(b.from_rad), rad_to_deg(b.to_rad), b.held, b.changed);
  }
  if (d.yaw_noise.heading_rad > 0.0) {
    add("\n  the fin measured on the heading's innovations with compass noise %.2f deg and a random yaw %.3f deg/s "
        "over %.0f s (likeliest)",
        rad_to_deg(d.yaw_noise.heading_rad), rad_to_deg(d.yaw_noise.disturbance_rad_s), d.yaw_noise.correlation_s);
  }
  add("\n  loop dead time: autopilot %.1f s + servo %.1f s + after the fin %.1f s (beside a fast yaw pole of %.2f s, "
      "prior 0-%.2f s)\n",
      d.delay_autopilot_s, d.delay_servo_s, d.delay_after_fin_s, d.yaw_fast_pole_s, d.yaw_fast_pole_max_s);
  add("  heading cause: %s\n", d.cause.c_str());
  return out;
}

model::VehicleParams heading_vehicle(const model::VehicleParams& vehicle, const Diagnosis& vertical) {
  return apply(vehicle, vertical.extended, vertical.thermal_reference_c);
}

}  // namespace glider::diagnose
