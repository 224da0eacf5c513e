// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/flight.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "glider/truth/dormand_prince.hpp"
#include "glider/truth/dynamics.hpp"
#include "glider/truth/sensors.hpp"
#include "glider/units.hpp"

namespace glider::truth {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;
constexpr double kCometMeasuredSpeedMS = 0.35;  // m/s, through the water (see draw())
constexpr double kWe01MeasuredSpeedMS = 0.46;   // m/s, hypot(0.20, 0.42): Graver et al. 2003 Fig. 13
double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
double wrap(double a) { return std::remainder(a, 2.0 * kPi); }
double effect_or(const Effects& e, const char* id, double fallback) {
  const auto it = e.find(id);
  return it == e.end() ? fallback : it->second;
}

// Everything a flight draws from its seed, in a fixed order (so that a
// given option does not shift the other draws).
struct Draws {
  PitchControl control;
  double cycle_s, dive_to_m, climb_to_m, pitch_deg, sensor_lag_s;
  Unmodelled unmodelled;
  Water water;
  double layer_from, layer_to, trim_error_kg_m3;
  std::uint64_t noise_seed;
};

Draws draw(const FlightRequest& r, const Vehicle& v) {
  std::mt19937_64 rng(r.seed);
  Draws d;
  d.control = uniform(rng, 0.0, 1.0) < 0.5 ? PitchControl::kBangBang : PitchControl::kPi;
  d.cycle_s = uniform(rng, 1.0, 8.0);
  d.dive_to_m = r.deep ? uniform(rng, 80.0, 180.0) : uniform(rng, 40.0, 90.0);
  d.climb_to_m = uniform(rng, 4.0, 8.0);
  d.pitch_deg = uniform(rng, 20.0, 28.0);
  d.sensor_lag_s = uniform(rng, 0.1, 0.5);
  Unmodelled& u = d.unmodelled;
  u.lift_lag_chords = uniform(rng, 1.0, 4.0);
  u.chord_m = std::sqrt(v.hydro.area_m2 / 7.0);  // mean chord of wings of aspect ratio ~7 on the reference area
  u.cl_q = uniform(rng, 0.0, 2.0);
  u.drag_reynolds_exponent = uniform(rng, 0.05, 0.2);
  // The speed at which the vehicle file's published C_D0 was measured: the
  // skin friction's Reynolds-number term is 1 there. comet (shallow): the
  // DVL of gliderflight-adcp reads 0.27-0.35 m/s; WE01 (deep): Graver et al.
  // 2003 Fig. 13 glides 0.20 m/s down and 0.42 m/s across, 0.46 m/s along
  // the path. (Both variants used 0.35 before: WE01's own drag, flown at its
  // own speed, then read 3-7 % low against its own file.)
  u.drag_reference_speed_m_s = r.deep ? kWe01MeasuredSpeedMS : kCometMeasuredSpeedMS;
  u.yaw_second_pole_s = uniform(rng, 0.2, 1.0);
  u.fin_roll_per_rad = uniform(rng, 0.0, 0.2);
  u.roll_time_constant_s = uniform(rng, 2.0, 5.0);
  // This first water is discarded; the draw stays so that the seeds of the runs in
  // docs/science.md replay the same flights.
  d.water = draw_water(rng, 0.0);
  d.water = draw_water(rng, d.dive_to_m);
  d.layer_from = uniform(rng, 0.15, 0.5);
  d.layer_to = d.layer_from + uniform(rng, 0.3, 0.5);
  d.trim_error_kg_m3 = uniform(rng, -0.3, 0.3);
  d.noise_seed = rng();
  if (r.control) d.control = *r.control;
  if (r.cycle_s) d.cycle_s = *r.cycle_s;
  if (r.dive_to_m) d.dive_to_m = *r.dive_to_m;
  return d;
}

struct FinCommand {
  double arrives_s, fin_rad;
};

FlightResult fly_once(const FlightRequest& request, double reference_temperature_c) {
  Vehicle v = load_vehicle(request.vehicle_path);
  const Draws dr = draw(request, v);
  FlightResult out;
  const Effects& e = request.effects;
  v.unmodelled = dr.unmodelled;
  // Hidden effects (effects.hpp).
  v.buoyancy_offset_kg += effect_or(e, "buoyancy_offset", 0.0) * 1e-3;
  v.hydro.cd0 *= effect_or(e, "drag_change", 1.0);
  v.hull_compressibility_per_pa += effect_or(e, "hull_compressibility", 0.0);
  if (e.contains("thermal_expansion")) {
    v.thermal_expansion_per_k += e.at("thermal_expansion");
    v.reference_temperature_c = reference_temperature_c;
  }
  v.battery_x_at_zero_m += in_to_m(effect_or(e, "pitch_trim_offset", 0.0));
  v.pump_lag_s += effect_or(e, "pump_lag", 0.0);
  const double lift = effect_or(e, "lift_change", 1.0);
  v.hydro.cl0 *= lift;
  v.hydro.cl_alpha *= lift;
  v.hydro.cl_alpha_abs_alpha *= lift;
  v.hydro.cd_alpha2 += (lift - 1.0) * v.hydro.wing_induced_cd_alpha2;
  HeadingParams& hd = v.heading;
  hd.fin_delay_s = effect_or(e, "fin_delay", hd.fin_delay_s);
  hd.fin_deadband_rad = effect_or(e, "fin_deadband", hd.fin_deadband_rad);
  hd.yaw_time_constant_s = effect_or(e, "yaw_time_constant", hd.yaw_time_constant_s);
  out.yaw_delay_s = effect_or(e, "yaw_delay", 0.0);
  out.fin_effectiveness = effect_or(e, "fin_effectiveness", 1.0);
  out.roll_offset_rad = effect_or(e, "roll_offset", 0.0);
  hd.roll_rad += out.roll_offset_rad;  // the true roll; the log shows it less the offset
  out.flown_gain = effect_or(e, "autopilot_gain", out.stated_gain);
  out.flown_igain = effect_or(e, "autopilot_integral", out.stated_igain);
  out.flown_dgain = effect_or(e, "autopilot_dgain", out.stated_dgain);
  out.autopilot_delay_s = effect_or(e, "autopilot_delay", 0.0);
  out.flown_deadband_rad = effect_or(e, "autopilot_deadband", 0.0);

  // A pilot ballasts the glider for the water it will fly in: the density
  // half-way between the surface's and the dive depth's is the vehicle's
  // trim density (within +-0.3 kg/m^3), so the pump can dive and climb through it.
  Water water = dr.water;
  water.density_offset_kg_m3 = v.trim_density_kg_m3 -
                               0.5 * (water.density_kg_m3(0.0, 0.0) + water.density_kg_m3(dr.dive_to_m, 0.0)) +
                               dr.trim_error_kg_m3;
  if (e.contains("vertical_water_velocity")) {
    water.hidden_w_m_s = e.at("vertical_water_velocity");
    water.hidden_w_from_m = dr.layer_from * dr.dive_to_m;
    water.hidden_w_to_m = dr.layer_to * dr.dive_to_m;
  }
  out.control = dr.control;
  out.cycle_s = dr.cycle_s;
  out.dive_to_m = dr.dive_to_m;
  out.climb_to_m = dr.climb_to_m;
  out.pitch_target_rad = deg_to_rad(dr.pitch_deg);
  out.depth_sensor_lag_s = dr.sensor_lag_s + effect_or(e, "depth_lag", 0.0);

  std::mt19937_64 rng(dr.noise_seed);
  SensorNoise noise = SensorNoise::slocum();
  Ar1 yaw_disturbance(0.002, 30.0);
  FinHistory fin_history;
  Dynamics dyn{v, water, {}, out.yaw_delay_s, out.fin_effectiveness, out.depth_sensor_lag_s, &fin_history};

  State y{};
  y[kDepth] = 0.5;
  y[kSensedDepth] = 0.5;
  y[kSurge] = 0.05;
  y[kHeading] = uniform(rng, -kPi, kPi);
  y[kRoll] = hd.roll_rad;
  y[kPiston] = 0.0;
  y[kDisplaced] = 0.0;
  double t = 0.0, h = 0.1;
  StepControl control;
  IntegrationStats stats;

  // Controllers' state.
  int state = 1, yo = 0;
  double c_heading = y[kHeading];
  double battery_trim[2] = {0.0, 0.0};  // dive, climb (m): remembered as the firmware does
  double c_battery = 0.0, integral = 0.0, last_correction_s = -1e9;
  double ap_integrator = 0.0, ap_output = 0.0, last_heading = kNaN;
  std::deque<FinCommand> fin_queue;
  std::deque<std::pair<double, double>> heading_readings;  // (time, measured heading) for the autopilot's delay
  double servo_target = 0.0;
  // The pitch a battery move buys (rad per m), for the bang-bang's correction and the PI's gains.
  const double slope = v.battery_kg / (v.offset_kg * v.offset_z_m + v.battery_kg * v.battery_z_m);
  const double max_time_s = request.yos * 2.0 * (dr.dive_to_m + 20.0) / 0.05 + 600.0;

  while (true) {
    const Dynamics::Forces f = dyn.forces(t, y);
    // Sensors.
    Sample s{};
    s.time_s = t;
    s.depth_m = quantize(y[kSensedDepth] + noise.depth_m.next(out.cycle_s, rng), noise.depth_step_m);
    s.pitch_rad = quantize(y[kPitch] + noise.pitch_rad.next(out.cycle_s, rng), noise.angle_step_rad);
    s.roll_rad = quantize(y[kRoll] - out.roll_offset_rad + noise.roll_rad.next(out.cycle_s, rng), noise.angle_step_rad);
    const double heading_meas = wrap(y[kHeading] + noise.heading_rad.next(out.cycle_s, rng));
    s.heading_rad = quantize(heading_meas < 0.0 ? heading_meas + 2.0 * kPi : heading_meas, noise.angle_step_rad);
    s.fin_rad = quantize(y[kFin], noise.angle_step_rad);
    s.ballast_cc = quantize(m3_to_cc(y[kPiston]), noise.ballast_step_cc);
    s.battpos_in = quantize(m_to_in(y[kBattery]), noise.battpos_step_in);
    s.temperature_c = water.temperature_c(y[kDepth], t) + 0.002 * std::normal_distribution<double>()(rng);
    s.pressure_bar = std::max(0.0, y[kDepth]) * f.density_kg_m3 * kGravity / 1e5;
    s.density_kg_m3 = f.density_kg_m3 + 0.003 * std::normal_distribution<double>()(rng);
    s.true_depth_m = y[kDepth];
    s.water_w_m_s = water.vertical_velocity_m_s(y[kDepth], t);
    s.speed_m_s = f.speed_m_s;
    s.alpha_rad = f.alpha_rad;
    s.lat_m = y[kNorth];
    s.lon_m = y[kEast];

    // The yo: a bang-bang pump, the depth state from the measured depth.
    const double depth = s.depth_m;
    bool inflection = false;
    if (state == 1 && depth >= dr.dive_to_m) {
      state = 2;
      inflection = true;
    } else if (state == 2 && depth <= dr.climb_to_m && yo + 1 < request.yos) {
      state = 1;
      ++yo;
      inflection = true;
      c_heading = wrap(c_heading + (uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0) * deg_to_rad(uniform(rng, 20.0, 90.0)));
    } else if (state == 2 && depth <= 1.0 && yo + 1 >= request.yos) {
      state = 0;
    }
    const int direction = state == 2 ? 1 : 0;
    const double pitch_target = state == 2 ? out.pitch_target_rad : -out.pitch_target_rad;
    dyn.targets.piston_m3 = state == 1 ? v.ballast_min_m3 : v.ballast_max_m3;
    // Pitch: the battery (+ forward = nose down).
    const double error = pitch_target - s.pitch_rad;
    if (inflection) {
      battery_trim[1 - direction] = c_battery;  // remember the trim the glide ended with
      c_battery = battery_trim[direction];
      integral = 0.0;
      last_correction_s = t;
    }
    if (state != 0) {
      if (out.control == PitchControl::kPi) {
        const double kp = 0.5 / slope, ki = kp / 60.0;
        integral = std::clamp(integral + error * out.cycle_s, -0.5 / (ki * slope), 0.5 / (ki * slope));
        c_battery = battery_trim[direction] - (kp * error + ki * integral);
      } else if (std::abs(error) > deg_to_rad(2.0) && t - last_correction_s > 30.0 &&
                 std::abs(y[kBattery] - c_battery) < 1e-4) {
        c_battery -= error / slope;  // the whole correction at once, then wait for the glide to settle
        battery_trim[direction] = c_battery;
        last_correction_s = t;
      }
      c_battery = std::clamp(c_battery, v.battery_min_m, v.battery_max_m);
    }
    dyn.targets.battery_m = c_battery;
    // Heading autopilot (Slocum's law) on the heading read a delay ago.
    heading_readings.emplace_back(t, heading_meas);
    while (heading_readings.size() > 2 && heading_readings[1].first <= t - out.autopilot_delay_s) {
      heading_readings.pop_front();
    }
    double fin_command = 0.0;
    if (state == 1 || state == 2) {
      double read = heading_readings.front().second;
      if (heading_readings.size() > 1 && heading_readings.front().first < t - out.autopilot_delay_s) {
        const auto& a = heading_readings[0];
        const auto& b = heading_readings[1];
        const double w = (t - out.autopilot_delay_s - a.first) / (b.first - a.first);
        read = a.second + w * wrap(b.second - a.second);
      }
      const double err = wrap(c_heading - read);
      double rate = std::isfinite(last_heading) ? wrap(read - last_heading) / out.cycle_s : 0.0;
      last_heading = read;
      bool hold = false;
      if (std::abs(rate) < out.rate_deadband_rad_s) {
        rate = 0.0;
        hold = std::abs(err) < out.flown_deadband_rad;
      }
      if (!hold) {
        ap_integrator += out.flown_igain * err * out.cycle_s;
        ap_output =
            std::clamp(out.flown_gain * err + ap_integrator + out.flown_dgain * rate, -hd.fin_max_rad, hd.fin_max_rad);
      }
      fin_command = ap_output;
    } else {
      last_heading = kNaN;
      ap_output = 0.0;
    }
    fin_queue.push_back({t + hd.fin_delay_s, fin_command});

    s.c_heading_rad = state != 0 ? (c_heading < 0.0 ? c_heading + 2.0 * kPi : c_heading) : kNaN;
    s.c_fin_rad = fin_command;
    s.c_ballast_cc = m3_to_cc(dyn.targets.piston_m3);
    s.c_battpos_in = m_to_in(c_battery);
    s.c_pitch_rad = state != 0 ? pitch_target : kNaN;
    s.depth_state = state;
    s.yo_count = yo + (state == 0 ? 1 : 0);
    out.samples.push_back(s);
    if (state == 0) break;
    if (t > max_time_s) {
      throw std::runtime_error("truth flight did not complete: at " + std::to_string(t) + " s depth " +
                               std::to_string(y[kDepth]) + " m after " + std::to_string(yo) +
                               " yos (the vehicle cannot glide at these settings)");
    }
    if (y[kDepth] < -0.5) throw std::runtime_error("truth flight: the vehicle left the water");

    // Integrate one cycle (jittered +-5 %, as a Slocum cycle is), in
    // pieces of at most 0.5 s (the yaw's dead time reads the fin's
    // history) split where a fin command reaches the servo.
    const double next_t = t + out.cycle_s * uniform(rng, 0.95, 1.05);
    dyn.targets.yaw_disturbance_rad_s = yaw_disturbance.next(out.cycle_s, rng);
    while (t < next_t) {
      double until = std::min(next_t, t + 0.5);
      if (!fin_queue.empty() && fin_queue.front().arrives_s <= until) until = std::max(t, fin_queue.front().arrives_s);
      if (until > t) integrate(dyn, t, y, until, h, control, stats);
      while (!fin_queue.empty() && fin_queue.front().arrives_s <= t) {
        const double wanted = fin_queue.front().fin_rad;
        if (std::abs(wanted - y[kFin]) > hd.fin_deadband_rad) servo_target = wanted;
        fin_queue.pop_front();
      }
      dyn.targets.fin_rad = servo_target;
      fin_history.add(t, y[kFin]);
    }
  }
  out.steps_accepted = stats.accepted;
  out.steps_rejected = stats.rejected;
  out.vehicle = v;
  out.water = water;
  out.truth = request.effects;
  return out;
}

double median_glide_temperature(const FlightResult& r) {
  std::vector<double> t;
  for (const Sample& s : r.samples) {
    if ((s.depth_state == 1 || s.depth_state == 2) && s.depth_m > 2.0) t.push_back(s.temperature_c);
  }
  if (t.empty()) return 10.0;
  std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

}  // namespace

const char* to_string(PitchControl c) { return c == PitchControl::kPi ? "pi" : "bang-bang"; }

FlightResult fly(const FlightRequest& request) {
  const Vehicle nominal = load_vehicle(request.vehicle_path);
  FlightResult r = fly_once(request, nominal.reference_temperature_c);
  if (request.effects.contains("thermal_expansion")) {
    // Trimmed where it flies, as a pilot ballasts: the hull's reference
    // temperature is the log's median; the same seed flies the same water.
    r = fly_once(request, median_glide_temperature(r));
  }
  if (request.effects.contains("vertical_water_velocity")) {
    // What a mean vertical velocity can be on this log: the water's (waves
    // included) mean over the glides' samples.
    double sum = 0.0;
    int n = 0;
    for (const Sample& s : r.samples) {
      if ((s.depth_state == 1 || s.depth_state == 2) && s.depth_m > 2.0) {
        sum += s.water_w_m_s;
        ++n;
      }
    }
    r.truth["vertical_water_velocity"] = n > 0 ? sum / n : 0.0;
  }
  return r;
}

}  // namespace glider::truth
