// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/flight_summary.hpp"

#include <cmath>

#include "glider/units.hpp"

namespace glider::sil {
namespace {

using Json = nlohmann::ordered_json;

Json glide_json(const GlideStats& s) {
  return Json{{"settled_samples", s.samples},
              {"mean_pitch_deg", rad_to_deg(s.mean_pitch_rad())},
              {"mean_depth_rate_m_s", s.mean_depth_rate_m_s()},
              {"pitch_error_samples", s.pitch_error_samples},
              {"max_pitch_error_deg", rad_to_deg(s.max_pitch_error_rad)},
              {"rms_pitch_error_deg", rad_to_deg(s.rms_pitch_error_rad())}};
}

Json surfacings_json(const std::vector<SurfacingStats>& surfacings, Json& totals) {
  Json list = Json::array();
  double error_sum = 0.0, distance_sum = 0.0, worst = 0.0;
  for (const SurfacingStats& s : surfacings) {
    error_sum += s.dr_error_m;
    distance_sum += s.dr_distance_m;
    worst = std::max(worst, s.dr_error_m);
    list.push_back(Json{{"time_s", s.time_s},
                        {"dr_error_m", s.dr_error_m},
                        {"dr_distance_m", s.dr_distance_m},
                        {"dr_error_m_per_km", s.dr_distance_m > 0.0 ? 1000.0 * s.dr_error_m / s.dr_distance_m : 0.0},
                        {"water_vx_m_s", s.water_vx_m_s},
                        {"water_vy_m_s", s.water_vy_m_s}});
  }
  // Sum of errors over sum of DR distances (null without a surfacing).
  totals["dr_error_m_per_km"] = distance_sum > 0.0 ? Json(1000.0 * error_sum / distance_sum) : Json(nullptr);
  totals["dr_error_max_m"] = surfacings.empty() ? Json(nullptr) : Json(worst);
  return list;
}

}  // namespace

const char* result_name(const ScenarioResult& result) {
  if (result.final_phase == fw::Phase::kAbort) return "aborted";
  return result.completed ? "complete" : "stopped";
}

Json flight_summary(const ScenarioResult& result, const fw::FlightSoftwareConfig& config,
                    const SummaryContext& context) {
  const FlightStats& stats = result.stats;
  const bool aborted = result.final_phase == fw::Phase::kAbort;
  Json j;
  j["schema"] = kSummarySchema;
  j["mission_file"] = context.mission_file;
  j["vehicle_file"] = context.vehicle_file;
  j["seed"] = context.seed;
  j["result"] = result_name(result);
  j["stop_reason"] = aborted || result.completed ? Json(nullptr) : Json("max_sim_time");
  if (aborted) {
    j["abort"] =
        Json{{"cause", fw::cause_id(result.abort_cause)},
             {"cause_text", fw::to_string(result.abort_cause)},
             {"time_s", result.abort_time_s},
             {"surfaced_after_s",
              result.abort_surfaced_s >= 0.0 ? Json(result.abort_surfaced_s - result.abort_time_s) : Json(nullptr)},
             {"firmware_knows_surfaced", result.completed},
             {"drop_weight_released", result.drop_weight_released}};
  } else {
    j["abort"] = nullptr;
  }
  j["yos"] = result.yos;
  j["max_depth_m"] = stats.max_depth_m();
  j["segments"] = stats.segments();

  Json waypoints = Json::array();
  const fw::LocalFrame frame(context.launch);
  for (const WaypointEvent& w : result.waypoints) {
    Json event{{"reached", w.reached}, {"time_s", w.time_s}};
    if (config.plan.waypoint_count > 0) {
      const auto index = static_cast<std::size_t>((w.reached - 1) % config.plan.waypoint_count);
      const fw::EastNorth target = frame.to_local(config.plan.waypoints[index]);
      event["index"] = index;
      event["true_distance_m"] = std::hypot(w.east_m - target.east_m, w.north_m - target.north_m);
    }
    waypoints.push_back(std::move(event));
  }
  j["waypoint_list_length"] = config.plan.waypoint_count;
  j["waypoint_radius_m"] = config.plan.waypoint_count > 0 ? Json(config.plan.waypoint_radius_m) : Json(nullptr);
  j["waypoints_reached"] = stats.waypoints_reached();
  j["waypoints"] = std::move(waypoints);

  Json totals;
  j["surfacings"] = surfacings_json(stats.surfacings(), totals);
  j["dr_error_m_per_km"] = totals["dr_error_m_per_km"];
  j["dr_error_max_m"] = totals["dr_error_max_m"];

  j["dives"] = glide_json(stats.dives());
  j["climbs"] = glide_json(stats.climbs());
  j["energy_kj"] = result.energy_used_j / 1000.0;
  j["charge_ah"] = result.charge_used_amphr;
  j["distance_km"] = std::hypot(result.final_truth.east_m, result.final_truth.north_m) / 1000.0;
  j["sim_time_s"] = result.sim_time_s;
  j["wall_time_s"] = context.wall_time_s;
  j["cycles"] = result.executive.cycles;
  j["loop_overruns"] = result.executive.overruns;
  j["log_rows"] = result.log_rows;
  j["log_rows_lost"] = result.log_rows_lost;
  j["glide_warnings"] = context.glide_warnings;
  return j;
}

}  // namespace glider::sil
