// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/diagnosis_json.hpp"

#include <cmath>

namespace glider::diagnose {
namespace {

using nlohmann::ordered_json;

ordered_json number_or_null(double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr); }

ordered_json rms_json(const Rms& r) {
  return {{"rms_depth_rate_m_s", number_or_null(r.depth_rate_m_s)}, {"samples", r.samples}};
}

}  // namespace

ordered_json diagnosis_json(const Diagnosis& d, const std::string& vehicle_source, double wall_s) {
  ordered_json j;
  j["vehicle"] = d.vehicle;
  j["vehicle_source"] = vehicle_source;
  j["flight_model"] = to_string(d.model);
  if (d.retrimmed_to_kg_m3) {
    j["trim_density_kg_m3"] = {{"vehicle", *d.retrimmed_from_kg_m3},
                               {"used", *d.retrimmed_to_kg_m3},
                               {"note",
                                "the log's water is far from the vehicle's trim density: the vehicle is taken "
                                "as ballasted for the log's median measured density"}};
  }
  j["drag_reynolds"] = {{"exponent", d.drag_reynolds_exponent},
                        {"reference_speed_m_s", d.drag_reference_speed_m_s},
                        {"exponent_sigma_in_intervals", d.drag_reynolds_exponent_sigma},
                        {"note", "the model's zero-lift drag is cd0 (V / reference_speed)^-exponent"}};
  j["samples_used"] = d.samples_used;
  j["train_samples"] = d.train_samples;
  j["heldout_samples"] = d.heldout_samples;
  ordered_json base;
  base["rms_depth_rate_m_s"] = number_or_null(d.baseline.all.depth_rate_m_s);
  base["rms_pitch_deg"] = d.baseline.rms_pitch_deg ? ordered_json(*d.baseline.rms_pitch_deg) : ordered_json(nullptr);
  base["heldout_rms_depth_rate_m_s"] = number_or_null(d.baseline.heldout_rms_m_s);
  base["rms_battpos_in"] = d.baseline.rms_battpos_in ? ordered_json(*d.baseline.rms_battpos_in) : ordered_json(nullptr);
  base["by_phase"] = {{"dive", rms_json(d.baseline.dives)},
                      {"climb", rms_json(d.baseline.climbs)},
                      {"inflection", d.model == FlightModelKind::kDynamic
                                         ? rms_json(d.baseline.inflections)
                                         : ordered_json{{"rms_depth_rate_m_s", nullptr},
                                                        {"samples", d.baseline.inflection_samples},
                                                        {"note", "turns are not scored by the steady model"}}}};
  ordered_json depth = ordered_json::array();
  for (const auto& bin : d.baseline.by_depth) {
    depth.push_back({{"from_m", bin.from_m},
                     {"to_m", bin.to_m},
                     {"rms_depth_rate_m_s", number_or_null(bin.rms.depth_rate_m_s)},
                     {"samples", bin.rms.samples}});
  }
  base["by_depth"] = depth;
  j["baseline"] = base;
  ordered_json findings = ordered_json::array();
  for (const auto& f : d.findings) {
    findings.push_back({{"effect", info(f.effect).id},
                        {"value", f.value},
                        {"unit", info(f.effect).unit},
                        {"ci95", {f.ci95_low, f.ci95_high}},
                        {"heldout_rms_depth_rate_m_s", f.heldout_rms_m_s},
                        {"gain", f.gain},
                        {"fitted", f.fitted}});
    if (f.heldout_rms_battpos_in) findings.back()["heldout_rms_battpos_in"] = *f.heldout_rms_battpos_in;
    if (!f.interval_holds_with.empty()) {
      ordered_json with = ordered_json::array();
      for (Effect e : f.interval_holds_with) with.push_back(info(e).id);
      findings.back()["ci95_holds_with"] = with;
      findings.back()["ci95_conditional"] = {f.ci95_conditional_low, f.ci95_conditional_high};
    }
    if (f.effect == Effect::kThermalExpansion) findings.back()["reference_temperature_c"] = d.thermal_reference_c;
    if (f.effect == Effect::kDepthLag && d.depth_lag_form) {
      const DepthLagFormChoice& c = *d.depth_lag_form;
      findings.back()["form"] = to_string(c.form);
      findings.back()["form_identifiability"] = {
          {"verdict", c.told_apart ? "told apart by the held-out yos" : "ambiguous"},
          {"delay_s", c.delay_s},
          {"first_order_s", c.first_order_s},
          {"delay_heldout_block_rms_depth_rate_m_s", c.delay_heldout_score_m_s},
          {"first_order_heldout_block_rms_depth_rate_m_s", c.first_order_heldout_score_m_s},
          {"delay_heldout_rms_depth_rate_m_s", c.delay_heldout_rms_m_s},
          {"first_order_heldout_rms_depth_rate_m_s", c.first_order_heldout_rms_m_s}};
      if (!c.told_apart) findings.back()["ci95_conditional"] = {f.ci95_conditional_low, f.ci95_conditional_high};
    }
  }
  j["findings"] = findings;
  ordered_json ambiguous = ordered_json::array(), identifiability = ordered_json::array();
  for (const auto& a : d.ambiguities) {
    identifiability.push_back({{"effect", info(a.chosen).id},
                               {"alternative", info(a.alternative).id},
                               {"verdict", a.ambiguous ? "ambiguous" : "told apart by the held-out yos"},
                               {"signature_correlation", a.correlation},
                               {"heldout_rms_depth_rate_m_s", a.chosen_heldout_rms_m_s},
                               {"alternative_heldout_rms_depth_rate_m_s", a.alternative_heldout_rms_m_s}});
    if (a.score_block_s > 0.0) {  // the selection's score, which the verdict also takes
      identifiability.back()["score_block_s"] = a.score_block_s;
      identifiability.back()["heldout_block_rms_depth_rate_m_s"] = a.chosen_heldout_score_m_s;
      identifiability.back()["alternative_heldout_block_rms_depth_rate_m_s"] = a.alternative_heldout_score_m_s;
    }
    if (!a.ambiguous) continue;
    ambiguous.push_back({{"effect", info(a.chosen).id},
                         {"alternative", info(a.alternative).id},
                         {"reading", "in its place"},
                         {"alternative_value", a.alternative_value},
                         {"alternative_unit", info(a.alternative).unit},
                         {"alternative_ci95", {a.alternative_ci95_low, a.alternative_ci95_high}},
                         {"heldout_rms_depth_rate_m_s", a.chosen_heldout_rms_m_s},
                         {"alternative_heldout_rms_depth_rate_m_s", a.alternative_heldout_rms_m_s},
                         {"signature_correlation", a.correlation},
                         {"ruled_out_by_prior", a.ruled_out_by_prior},
                         {"what_would_separate_them", a.separate}});
  }
  // The second kind of ambiguity: the finding with a partner beside it, a
  // partner the held-out yos prefer and this log cannot size.
  for (const auto& b : d.beside) {
    if (!b.ambiguous) continue;
    ambiguous.push_back({{"effect", info(b.finding).id},
                         {"alternative", info(b.partner).id},
                         {"reading", "beside it"},
                         {"value_beside", b.finding_value},
                         {"ci95_beside", {b.finding_ci95_low, b.finding_ci95_high}},
                         {"alternative_value", b.partner_value},
                         {"alternative_unit", info(b.partner).unit},
                         {"alternative_ci95", {b.partner_ci95_low, b.partner_ci95_high}},
                         {"heldout_rms_depth_rate_m_s", b.chosen_heldout_rms_m_s},
                         {"alternative_heldout_rms_depth_rate_m_s", b.heldout_rms_m_s},
                         {"signature_correlation", b.correlation},
                         {"ruled_out_by_prior", false},
                         {"what_would_separate_them", b.separate}});
  }
  j["ambiguous"] = ambiguous;
  ordered_json beside = ordered_json::array();
  for (const auto& b : d.beside) {
    beside.push_back({{"effect", info(b.finding).id},
                      {"partner", info(b.partner).id},
                      {"signature_correlation", b.correlation},
                      {"value", b.finding_value},
                      {"ci95", {b.finding_ci95_low, b.finding_ci95_high}},
                      {"partner_value", b.partner_value},
                      {"partner_unit", info(b.partner).unit},
                      {"partner_ci95", {b.partner_ci95_low, b.partner_ci95_high}},
                      {"heldout_rms_depth_rate_m_s", b.heldout_rms_m_s},
                      {"heldout_block_rms_depth_rate_m_s", b.heldout_score_m_s},
                      {"selected_heldout_rms_depth_rate_m_s", b.chosen_heldout_rms_m_s},
                      {"selected_heldout_block_rms_depth_rate_m_s", b.chosen_heldout_score_m_s},
                      {"partner_seen", b.seen},
                      {"ambiguous", b.ambiguous},
                      {"lags_traded", b.lags_traded}});
  }
  j["read_beside"] = beside;
  // The hull's volume terms not named, each read beside the findings (a statement, not a finding).
  ordered_json unnamed = ordered_json::array();
  for (const auto& u : d.unnamed) {
    unnamed.push_back({{"effect", info(u.effect).id},
                       {"value", u.value},
                       {"unit", info(u.effect).unit},
                       {"ci95", {number_or_null(u.ci95_low), number_or_null(u.ci95_high)}},  // none if implausible
                       {"seen", u.seen},
                       {"ruled_out_by_prior", u.ruled_out_by_prior},
                       {"heldout_rms_depth_rate_m_s", u.heldout_rms_m_s},
                       {"heldout_block_rms_depth_rate_m_s", u.heldout_score_m_s},
                       {"selected_heldout_rms_depth_rate_m_s", u.chosen_heldout_rms_m_s},
                       {"selected_heldout_block_rms_depth_rate_m_s", u.chosen_heldout_score_m_s},
                       {"what_would_size_it", u.separate}});
  }
  j["read_unnamed"] = unnamed;
  j["identifiability"] = identifiability;
  ordered_json screen = ordered_json::array();
  for (const auto& c : d.screen) {
    screen.push_back({{"effect", info(c.chosen).id},
                      {"alternative", info(c.alternative).id},
                      {"signature_correlation", number_or_null(c.correlation)},
                      {"judged", c.correlation >= d.screen_correlation}});
  }
  j["identifiability_screen"] = {{"screen_correlation", d.screen_correlation}, {"pairs", screen}};
  j["cause"] = d.cause;
  j["extended"] = {{"rms_depth_rate_m_s", number_or_null(d.extended_all.depth_rate_m_s)},
                   {"heldout_rms_depth_rate_m_s", number_or_null(d.extended_heldout_rms_m_s)}};
  j["gain"] = d.gain;
  ordered_json parameters;
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    parameters[info(static_cast<Effect>(i)).id] = d.extended[i];
  }
  j["parameters"] = parameters;
  if (d.extended_profile) {
    j["vertical_velocity_profile"] = {{"first_m", d.extended_profile->first_m},
                                      {"bin_m", d.extended_profile->bin_m},
                                      {"w_m_s", d.extended_profile->w_m_s}};
  }
  j["candidates"] = d.candidates_tried;
  if (d.speed_through_water) {
    const auto& u = *d.speed_through_water;
    j["speed_through_water"] = {
        {"samples", u.samples},
        {"measured_mean_m_s", u.measured_mean_m_s},
        {"rms_nominal_m_s", number_or_null(u.nominal_rms_m_s)},
        {"rms_extended_m_s", number_or_null(u.extended_rms_m_s)},
        {"heldout_samples", u.heldout_samples},
        {"heldout_rms_nominal_m_s", number_or_null(u.heldout_nominal_rms_m_s)},
        {"heldout_rms_extended_m_s", number_or_null(u.heldout_extended_rms_m_s)},
        {"implied_water_w_median_m_s", number_or_null(u.implied_water_w_median_m_s)},
        {"consistent_rms_nominal_m_s", number_or_null(u.consistent_nominal_rms_m_s)},
        {"consistent_rms_extended_m_s", number_or_null(u.consistent_extended_rms_m_s)},
        {"heldout_consistent_rms_nominal_m_s", number_or_null(u.heldout_consistent_nominal_rms_m_s)},
        {"heldout_consistent_rms_extended_m_s", number_or_null(u.heldout_consistent_extended_rms_m_s)}};
    ordered_json by_yo = ordered_json::array();
    for (const SpeedOfYo& y : u.by_yo) {
      by_yo.push_back({{"yo", y.yo},
                       {"heldout", y.heldout},
                       {"samples", y.samples},
                       {"measured_mean_m_s", y.measured_mean_m_s},
                       {"nominal_mean_m_s", y.nominal_mean_m_s},
                       {"rms_nominal_m_s", y.nominal_rms_m_s},
                       {"extended_mean_m_s", y.extended_mean_m_s},
                       {"rms_extended_m_s", y.extended_rms_m_s},
                       {"implied_water_w_m_s", number_or_null(y.implied_water_w_m_s)},
                       {"reference_consistent", y.reference_consistent}});
    }
    j["speed_through_water"]["by_yo"] = by_yo;
  }
  j["wall_s"] = wall_s;
  return j;
}

}  // namespace glider::diagnose
