// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/flight_products.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glider/diagnose/track.hpp"
#include "glider/model/dynamics.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::netcdf {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
constexpr double kEarthRadiusM = 6371000.0;
constexpr double kMinDiveDepthM = 3.0;  // as ProfileOptions::min_depth_change_m
constexpr double kSurfaceDepthM = 1.0;  // as flightlog::PhaseOptions::surface_depth_m

bool gliding(flightlog::Phase p) { return p == flightlog::Phase::kDive || p == flightlog::Phase::kClimb; }

void steady_glides(const Trajectory& t, const model::VehicleParams& v, FlightProducts& out) {
  const model::GliderDynamics dynamics(v, model::still_water(v.trim_density_kg_m3));
  const model::PitchGlideSolver solver(v.hydro);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!gliding(t.phase[i]) || !std::isfinite(t.pitch_rad[i]) || !std::isfinite(t.ballast_cc[i]) ||
        !std::isfinite(t.depth_m[i])) {
      continue;
    }
    model::WaterSample water;
    water.density_kg_m3 = std::isfinite(t.density_kg_m3[i]) ? t.density_kg_m3[i] : v.trim_density_kg_m3;
    water.temperature_c = std::isfinite(t.temperature_c[i]) ? t.temperature_c[i] : v.hull_reference_temperature_c;
    model::MassInputs masses;
    masses.pumped_volume_m3 = cc_to_m3(t.ballast_cc[i]);
    const double m0 = dynamics.net_buoyancy_kg(t.depth_m[i], water, masses);
    const model::SteadyGlideResult glide = solver.solve(water.density_kg_m3, t.pitch_rad[i], m0);
    if (!glide.glide) continue;  // a pitch the wing cannot hold steadily (stall): no product
    out.speed_m_s[i] = glide.glide->speed_m_s;
    out.alpha_deg[i] = glide.glide->alpha_rad * kDegPerRad;
    out.glide_angle_deg[i] = glide.glide->glide_path_rad * kDegPerRad;
    out.glider_w_m_s[i] = -glide.glide->depth_rate_m_s;
    if (std::isfinite(out.measured_w_m_s[i])) out.water_w_m_s[i] = out.measured_w_m_s[i] - out.glider_w_m_s[i];
  }
}

// Depth-averaged current of each dive: the GPS displacement from the last fix
// before it to the first fix after it, minus the displacement through the
// water (the model's horizontal speed along the logged heading), over the time
// between the fixes. Uncertainty (1 sigma): the two fixes' errors, the
// model's speed error, and the underwater time the model could not fly
// (taken as unknown at the mean horizontal speed), added in quadrature.
void depth_averaged_currents(const Trajectory& t, FlightProducts& out) {
  std::vector<std::size_t> fixes;
  for (std::size_t i = 0; i < t.size(); ++i) {
    // Only fixes at the surface: the receiver goes on reporting positions for
    // the first metres of a dive (comet-2019 logs new ones at 3.7 m).
    const bool surface = !(t.depth_m[i] > kSurfaceDepthM);
    if (surface && std::isfinite(t.gps_latitude[i]) && std::isfinite(t.gps_longitude[i])) fixes.push_back(i);
  }
  const std::vector<double> heading = forward_fill(t.time_s, t.heading_deg, 60.0);
  for (std::size_t f = 0; f + 1 < fixes.size(); ++f) {
    const std::size_t a = fixes[f], b = fixes[f + 1];
    // A dive between the two fixes: deeper than a profile's depth change (two
    // fixes seconds apart at the surface, with a climb's last samples between
    // them, are not a dive).
    double deepest = 0.0;
    for (std::size_t i = a; i <= b; ++i) {
      if (std::isfinite(t.depth_m[i])) deepest = std::max(deepest, t.depth_m[i]);
    }
    if (deepest < kMinDiveDepthM) continue;
    double east = 0.0, north = 0.0, through_water = 0.0, unflown_s = 0.0, flown_s = 0.0;
    for (std::size_t i = a; i < b; ++i) {
      const double dt = t.time_s[i + 1] - t.time_s[i];
      const double speed = out.speed_m_s[i];
      if (std::isfinite(speed) && std::isfinite(heading[i])) {
        const double horizontal = speed * std::cos(out.glide_angle_deg[i] / kDegPerRad);
        east += horizontal * std::sin(heading[i] / kDegPerRad) * dt;
        north += horizontal * std::cos(heading[i] / kDegPerRad) * dt;
        through_water += horizontal * dt;
        flown_s += dt;
      } else if (gliding(t.phase[i]) || t.phase[i] == flightlog::Phase::kInflection) {
        unflown_s += dt;
      }
    }
    const double span_s = t.time_s[b] - t.time_s[a];
    if (!(span_s > 0.0) || flown_s == 0.0) continue;
    const double mean_lat = 0.5 * (t.gps_latitude[a] + t.gps_latitude[b]);
    const double gps_east =
        (t.gps_longitude[b] - t.gps_longitude[a]) / kDegPerRad * kEarthRadiusM * std::cos(mean_lat / kDegPerRad);
    const double gps_north = (t.gps_latitude[b] - t.gps_latitude[a]) / kDegPerRad * kEarthRadiusM;
    CurrentEstimate c;
    c.first = a;
    c.last = b;
    c.start_s = t.time_s[a];
    c.end_s = t.time_s[b];
    c.latitude = mean_lat;
    c.longitude = 0.5 * (t.gps_longitude[a] + t.gps_longitude[b]);
    c.east_m_s = (gps_east - east) / span_s;
    c.north_m_s = (gps_north - north) / span_s;
    const double mean_speed = through_water / flown_s;
    const double gps_term = std::sqrt(2.0) * kGpsFixErrorM;
    const double speed_term = kSpeedRelativeError * through_water;
    const double unflown_term = mean_speed * unflown_s;
    c.uncertainty_m_s = std::sqrt(gps_term * gps_term + speed_term * speed_term + unflown_term * unflown_term) / span_s;
    for (std::size_t i = a; i <= b; ++i) {
      out.current_east_m_s[i] = c.east_m_s;
      out.current_north_m_s[i] = c.north_m_s;
      out.current_uncertainty_m_s[i] = c.uncertainty_m_s;
    }
    out.currents.push_back(c);
  }
}

}  // namespace

FlightProducts compute_flight_products(const Trajectory& t, const model::VehicleParams& v) {
  FlightProducts out;
  const std::size_t n = t.size();
  for (auto* series : {&out.speed_m_s, &out.alpha_deg, &out.glide_angle_deg, &out.glider_w_m_s, &out.water_w_m_s,
                       &out.current_east_m_s, &out.current_north_m_s, &out.current_uncertainty_m_s}) {
    series->assign(n, kNaN);
  }
  // The diagnosis's depth-rate estimator (a line over +-5 s), so that the
  // water's velocity here is the residual the diagnosis fits.
  out.measured_w_m_s = diagnose::depth_rate_estimate(t.time_s, t.depth_m, 5.0, 30.0);
  for (double& w : out.measured_w_m_s) w = -w;
  steady_glides(t, v, out);
  depth_averaged_currents(t, out);
  out.vehicle_name = v.name;
  out.parameters = {
      {"drag_coefficient_cd0", v.hydro.cd0},
      {"drag_coefficient_cd_alpha2_per_rad2", v.hydro.cd_alpha2},
      {"lift_coefficient_cl_alpha_per_rad", v.hydro.cl_alpha},
      {"reference_area_m2", v.hydro.reference_area_m2},
      {"mass_kg", model::dry_mass_kg(v)},
      {"volume_m3", model::displaced_volume_m3(v)},
      {"buoyancy_offset_kg", v.buoyancy_offset_kg},
      {"hull_compressibility_per_pa", v.hull_compressibility_per_pa},
      {"hull_thermal_expansion_per_k", v.hull_thermal_expansion_per_k},
      {"trim_density_kg_m3", v.trim_density_kg_m3},
  };
  return out;
}

}  // namespace glider::netcdf
