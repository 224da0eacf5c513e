// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/speed_term.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "glider/firmware/geo.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/forecast/course_straightness.hpp"
#include "glider/forecast/depth_rate_calibration.hpp"
#include "glider/forecast/from_glider.hpp"
#include "glider/forecast/surface_touches.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

namespace {

constexpr int kMinGlideSamples = 20;             // per direction, to read a scale from
constexpr double kSamplesPerIndependent = 15.0;  // 4 s samples of one glide: about one independent a minute
constexpr double kMaxSampleGapS = 30.0;
constexpr int kSpeedPasses = 6;
constexpr double kSpeedStepMax = 1.3;     // per pass: the slope is the comet polar's only near the last flight
constexpr double kSpeedTolerance = 0.01;  // of the ratio: below the DR's own spread
// A dive whose course's straightness is below this went round: its net track
// divided by it would multiply the fixes' and current's errors.
constexpr double kMinStraightness = 0.5;

// One direction's scale (model / glider mean |pitch|) and its sampling sigma.
bool direction_scale(double glider_mean, double glider_sd, int glider_n, double model_mean, int model_n, double& scale,
                     double& sigma) {
  if (glider_n < kMinGlideSamples || model_n < kMinGlideSamples) return false;
  if (!(glider_mean > 0.0) || !(model_mean > 0.0)) return false;
  scale = model_mean / glider_mean;
  const double independent = std::max(1.0, glider_n / kSamplesPerIndependent);
  sigma = scale * (std::isfinite(glider_sd) ? glider_sd / glider_mean : 0.0) / std::sqrt(independent);
  return std::isfinite(scale);
}

// The glider's calibrated (true) over its counted dead-reckoned speed at one logged pitch.
double true_over_counted(const fw::DeadReckoning& dr, double logged_pitch_rad, double scale) {
  const double w = logged_pitch_rad < 0.0 ? 0.1 : -0.1;  // the ratio does not depend on the depth rate
  const double counted = dr.horizontal_speed(logged_pitch_rad, w);
  const double calibrated = dr.horizontal_speed(scale * logged_pitch_rad, w);
  return counted > 0.0 && calibrated > 0.0 ? calibrated / counted : std::nan("");
}

double speed_factor(const fw::DeadReckoning& dr, const GlidePitch& g, double dive_scale, double climb_scale) {
  double sum = 0.0, weight = 0.0;
  if (g.dive_n > 0) {
    const double k = true_over_counted(dr, -g.dive_rad(), dive_scale);
    if (std::isfinite(k)) {
      sum += g.dive_n * k;
      weight += g.dive_n;
    }
  }
  if (g.climb_n > 0) {
    const double k = true_over_counted(dr, g.climb_rad(), climb_scale);
    if (std::isfinite(k)) {
      sum += g.climb_n * k;
      weight += g.climb_n;
    }
  }
  return weight > 0.0 ? sum / weight : std::nan("");
}

// One still-water flight of the coming dive straight toward the active
// waypoint, not through it: a flight that reaches it and turns back covers
// less ground than it glides. Its steady glides' pitch into `pitch`.
SpeedFlight still_water_flight(const FlightSetup& setup, const ForecastOptions& options, GlidePitch* pitch) {
  FlightSetup still = setup;
  still.current = CurrentEstimate{};
  still.firmware_current.reset();
  fw::MissionPlan& plan = still.config.plan;
  if (plan.waypoint_count > 0) {
    const fw::EastNorth w = fw::LocalFrame(still.fix).to_local(plan.waypoints[0]);
    plan.heading_rad = std::atan2(w.east_m, w.north_m);
    plan.waypoint_count = 0;
  }
  const RunOutcome r = fly_runs(still, options, 1, false).at(0);
  if (pitch != nullptr) *pitch = r.glide_pitch;
  SpeedFlight out;
  out.average_m_s = r.average_speed_m_s;
  out.speed_m_s = r.surfaced && !r.aborted && r.time_s > 600.0 ? std::hypot(r.dr_east_m, r.dr_north_m) / r.time_s : 0.0;
  return out;
}

// The depth-rate calibration (depth_rate_calibration.hpp): read, said, and
// applied to the runs' vehicle and mission when the options say so. The
// polar's steady glides are not the SIL's flight to the last per cent (a
// flight 5 deg steeper read 2 % off), so once applied the model flies again
// and the rule is applied to that flight, which composes (the pitch scale is
// the hull's over the glider's logged pitch, the drag and buoyancy relative
// to the vehicle flown), up to kDepthRatePasses times. True when applied.
constexpr int kDepthRatePasses = 3;
bool calibrate_to_depth_rates(const GlidePitch& logged, const GlidePitch& model_pitch, bool dr_restarts,
                              FlightSetup& setup, const ForecastOptions& options, Forecast& f) {
  fw::YoMissionConfig& mission = setup.config.mission;
  // Slocum's d_/c_use_pitch 3: the battery servoed on the pitch sensor.
  const bool servo = std::isnan(mission.dive_battpos_in) && std::isnan(mission.climb_battpos_in);
  const bool apply = options.depth_rate_calibration && (servo || options.depth_rate_drag);
  const DepthRateCalibration first =
      calibrate_depth_rates(setup.vehicle.hydro, setup.vehicle.trim_density_kg_m3, logged, model_pitch, servo);
  char text[560];
  if (!first.have) {
    std::snprintf(text, sizeof text, "depth rates: not calibrated (%s)", first.why_not.c_str());
    f.notes.push_back(text);
    return false;
  }
  f.depth_rate_have = true;
  f.depth_rate_servo = servo;
  f.depth_rate_glider_dive_m_s = first.glider_dive_m_s;
  f.depth_rate_glider_climb_m_s = first.glider_climb_m_s;
  f.depth_rate_model_dive_m_s = first.model_dive_m_s;
  f.depth_rate_model_climb_m_s = first.model_climb_m_s;
  const model::VehicleParams nominal_vehicle = setup.vehicle;
  const fw::YoMissionConfig nominal_mission = mission;
  DepthRateCalibration c = first;
  double drag = 1.0, buoyancy = 0.0, scale = 1.0, dive_factor = 1.0, climb_factor = 1.0;
  GlidePitch flown;
  int passes = 0;
  for (; passes < kDepthRatePasses && c.have; ++passes) {
    if (servo) {
      mission.dive_pitch_rad *= c.dive_pitch_factor;
      mission.climb_pitch_rad *= c.climb_pitch_factor;
      dive_factor *= c.dive_pitch_factor;
      climb_factor *= c.climb_pitch_factor;
      scale = c.pitch_scale;
    } else {
      model::scale_drag(setup.vehicle.hydro, c.drag_factor);
      drag *= c.drag_factor;
    }
    setup.vehicle.buoyancy_offset_kg += c.buoyancy_kg;
    buoyancy += c.buoyancy_kg;
    still_water_flight(setup, options, &flown);
    c = calibrate_depth_rates(setup.vehicle.hydro, setup.vehicle.trim_density_kg_m3, logged, flown, servo);
    const bool settled = c.have && std::fabs(c.dive_pitch_factor - 1.0) < 0.002 &&
                         std::fabs(c.climb_pitch_factor - 1.0) < 0.002 && std::fabs(c.drag_factor - 1.0) < 0.002 &&
                         std::fabs(c.buoyancy_kg) < 0.0005;
    if (settled) {
      ++passes;
      break;
    }
  }
  f.depth_rate_pitch_scale = scale;
  f.depth_rate_drag_factor = drag;
  f.depth_rate_buoyancy_kg = buoyancy;
  char cause[160];
  if (servo) {
    std::snprintf(cause, sizeof cause, "pitch servo: hull pitch = %.3f x m_pitch (the mission's pitch x%.3f / x%.3f)",
                  scale, dive_factor, climb_factor);
  } else {
    std::snprintf(cause, sizeof cause, "battery fixed: drag x%.3f", drag);
  }
  std::snprintf(text, sizeof text,
                "depth rates: the glider's steady dives / climbs %.3f / %.3f m/s, the model's %.3f / %.3f: %s, "
                "buoyancy %+.0f g; so calibrated (%d flights) the model glides %.3f / %.3f (%s%s)",
                first.glider_dive_m_s, first.glider_climb_m_s, first.model_dive_m_s, first.model_climb_m_s, cause,
                1000.0 * buoyancy, passes, flown.dive_rate_m_s(), flown.climb_rate_m_s(),
                apply                            ? "flown"
                : options.depth_rate_calibration ? "said, not applied: the battery fixed (--depth-rate-drag flies it)"
                                                 : "said, not applied",
                apply && servo && options.glider_dead_reckoning
                    ? (dr_restarts ? "; the model's DR the file's: the glider's restarted inside its dives"
                                   : "; the model dead-reckons through the glider's sensor")
                    : "");
  f.notes.push_back(text);
  if (!apply) {
    setup.vehicle = nominal_vehicle;
    mission = nominal_mission;
    return false;
  }
  // Its firmware dead-reckons through the sensor the servo holds (reading
  // 1 / scale of the hull's pitch): the model's the same, so the waypoint
  // arrivals and the current it carries count as the glider's. Not when
  // the glider's DR restarted at fixes inside its dives (surface_touches.hpp):
  // its current estimates then hold its DR's error over the last leg only,
  // not over the dive the model's DR would count it over.
  if (servo && options.glider_dead_reckoning && !dr_restarts) {
    setup.config.dead_reckoning = biased_pitch_dead_reckoning(setup.config.dead_reckoning, 1.0 / scale);
  }
  f.depth_rate_applied = true;
  return true;
}

}  // namespace

PitchCalibrationEstimate estimate_pitch_calibration(const GlidePitch& glider, const GlidePitch& model) {
  PitchCalibrationEstimate e;
  double ds = 1.0, dsig = 0.0, cs = 1.0, csig = 0.0;
  const bool dive =
      direction_scale(glider.dive_rad(), glider.dive_sd_rad(), glider.dive_n, model.dive_rad(), model.dive_n, ds, dsig);
  const bool climb = direction_scale(glider.climb_rad(), glider.climb_sd_rad(), glider.climb_n, model.climb_rad(),
                                     model.climb_n, cs, csig);
  if (!dive && !climb) return e;
  const int nd = dive ? glider.dive_n : 0, nc = climb ? glider.climb_n : 0;
  e.glider_samples = nd + nc;
  // One direction alone stands for both.
  e.dive_scale = dive ? ds : cs;
  e.climb_scale = climb ? cs : ds;
  e.scale = (nd * (dive ? ds : 0.0) + nc * (climb ? cs : 0.0)) / (nd + nc);
  if (!(e.scale >= kPitchScaleMin && e.scale <= kPitchScaleMax)) return PitchCalibrationEstimate{};
  const double sampling = (nd * dsig + nc * csig) / (nd + nc);
  const double disagreement = dive && climb ? 0.5 * std::fabs(ds - cs) : 0.0;
  e.scale_sigma =
      std::sqrt(sampling * sampling + disagreement * disagreement + kPitchScaleSigmaFloor * kPitchScaleSigmaFloor);
  e.have = true;
  return e;
}

DrSpeedCalibration dr_speed_calibration(const fw::DeadReckoningConfig& config, const GlidePitch& glider,
                                        const PitchCalibrationEstimate& c) {
  DrSpeedCalibration out;
  if (!c.have) return out;
  const fw::DeadReckoning dr(config);
  const double k = speed_factor(dr, glider, c.dive_scale, c.climb_scale);
  if (!std::isfinite(k) || !(k > 0.0)) return out;
  // The sigma: the scale moved by its sigma in both directions at once.
  const double up = speed_factor(dr, glider, c.dive_scale + c.scale_sigma, c.climb_scale + c.scale_sigma);
  const double down = speed_factor(dr, glider, c.dive_scale - c.scale_sigma, c.climb_scale - c.scale_sigma);
  out.factor = k;
  out.sigma = std::isfinite(up) && std::isfinite(down) ? 0.5 * std::fabs(up - down) : 0.0;
  return out;
}

fw::DeadReckoningConfig biased_pitch_dead_reckoning(const fw::DeadReckoningConfig& config, double sensor_scale) {
  if (sensor_scale == 1.0) return config;
  const fw::DeadReckoning given(config);
  fw::DeadReckoningConfig out = config;
  out.method = fw::DrMethod::kFlightModel;
  // The assumed-alpha method infers no speed through an inflection: coast
  // over no time there too.
  if (config.method == fw::DrMethod::kAssumedAlpha) out.coast_time_constant_s = 1e-3;
  out.min_pitch_rad = config.min_pitch_rad / sensor_scale;
  for (std::size_t i = 0; i < fw::DeadReckoningConfig::kTableSize; ++i) {
    const double p = out.table_first_pitch_rad + static_cast<double>(i) * out.table_step_rad;
    // glide path' (p) = p + alpha'(p) = sensor_scale p + alpha(sensor_scale p)
    out.dive_alpha_rad[i] = (sensor_scale - 1.0) * p + given.alpha_for(-sensor_scale * p);
    out.climb_alpha_rad[i] = (sensor_scale - 1.0) * p + given.alpha_for(sensor_scale * p);
  }
  return out;
}

GlidePitch logged_glide_pitch(const fs::path& glider_dir, double since_utc_s, std::vector<std::string>& notes,
                              int& files) {
  GlidePitch g;
  files = 0;
  for_each_from_glider_log(glider_dir, {"m_depth", "m_pitch"}, "pitch", notes, [&](const flightlog::FlightLog& log) {
    const flightlog::Column& t = log.time();
    const flightlog::Column& depth = log.column("m_depth");
    const flightlog::Column& pitch = log.column("m_pitch");
    ++files;
    std::size_t last = t.size();
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (!std::isfinite(depth[i]) || !std::isfinite(pitch[i]) || !(t[i] >= since_utc_s)) continue;
      if (last < t.size() && t[i] - t[last] <= kMaxSampleGapS) {
        const double dt = t[i] - t[last];
        g.add(0.5 * (depth[i] + depth[last]), (depth[i] - depth[last]) / dt, 0.5 * (pitch[i] + pitch[last]),
              (pitch[i] - pitch[last]) / dt);
      }
      last = i;
    }
  });
  return g;
}

SpeedMatch match_speed(double target_m_s, const SpeedFlight& at_one, const std::function<SpeedFlight(double)>& fly) {
  SpeedMatch best;
  best.flight = at_one;
  best.ratio = target_m_s / at_one.speed_m_s;
  double factor = 1.0, slope = -0.5, last_log_factor = 0.0, last_log_speed = std::log(at_one.speed_m_s);
  for (int pass = 0; pass < kSpeedPasses && std::abs(best.ratio - 1.0) > kSpeedTolerance; ++pass) {
    // Secant steps on log speed against log drag, the first at drag^-1/2
    // (the horizontal speed falls faster, ~drag^-0.7..-1, as the angle of
    // attack grows).
    const double step = std::clamp(std::exp(std::log(best.ratio) / slope), 1.0 / kSpeedStepMax, kSpeedStepMax);
    const double next = std::clamp(best.factor * step, kSpeedDragMin, kSpeedDragMax);
    if (next == factor) break;  // at a limit
    factor = next;
    const SpeedFlight flight = fly(factor);
    ++best.flights;
    if (!(flight.speed_m_s > 0.02)) break;  // no glide there: keep the best so far
    const double ratio = target_m_s / flight.speed_m_s;
    if (std::abs(ratio - 1.0) < std::abs(best.ratio - 1.0)) {
      best.factor = factor;
      best.ratio = ratio;
      best.flight = flight;
    }
    const double log_factor = std::log(factor), log_speed = std::log(flight.speed_m_s);
    const double secant = (log_speed - last_log_speed) / (log_factor - last_log_factor);
    if (std::isfinite(secant) && secant < -0.1 && secant > -3.0) slope = secant;  // else keep the last
    last_log_factor = log_factor;
    last_log_speed = log_speed;
  }
  best.slope = slope;
  return best;
}

// The glider's own speed through the water, as its dead reckoning counts
// it, against the model's: over each recent dive of the last day the DR's
// track less the current it carried ((DR position on surfacing - the fix it
// dived from) / time - its m_water_vx/vy then, over its course's
// straightness where the glider sent its heading home), against one still-water
// flight of the model (whose DR is its track through the water). Both count
// speed from the depth rate and pitch; the glider's pitch through its
// sensor, whose scale the steady glides it sent home give against the
// model's (estimate_pitch_calibration): the glider's speed is calibrated by
// it before the two are compared (options.pitch_calibration). Said (notes,
// JSON); applied when calibrated (options.speed_correction_calibrated, the
// default) or always (options.speed_correction): the vehicle's drag
// (cd0 and cd_alpha2, as the runs' draws scale it) is scaled until the
// model's speed is the glider's. The speed falls smoothly with drag, about
// as drag^-1/2, since slocum_comet.toml flies the comet's own polar
// (model.comet_drag_sweep), so secant steps settle it in a few flights.
// Also the mean glide speed the runs start with (the model's).
void measure_speed(const std::vector<Surfacing>& history, const fs::path& glider_dir, FlightSetup& setup,
                   const ForecastOptions& options, Forecast& f) {
  std::vector<double> glider_speeds;
  // The glider's headings under way, to read each dive's net track as the
  // distance it glided (course_straightness.hpp).
  const std::vector<HeadingSample> headings = logged_headings(glider_dir, f.fix_utc_s - 2.0 * 86400.0, f.notes);
  int straightened = 0;
  double least_straight = 1.0, most_straight = 0.0;
  // The glider's depths, to find the dives whose yo tops came to the surface
  // (surface_touches.hpp): its DR restarted there, not measured.
  const std::vector<DepthSample> depths = logged_depths(glider_dir, f.fix_utc_s - 2.0 * 86400.0, f.notes);
  int reset_dives = 0, touches = 0, measurable_dives = 0;
  for (std::size_t i = 1; i < history.size(); ++i) {
    const Surfacing& s = history[i];
    const Surfacing& before = history[i - 1];
    if (s.call_start_utc_s <= f.fix_utc_s - 86400.0) continue;  // the last day's dives: today's trim
    if (!before.has_fix() || !s.dr_lat_deg || !s.dr_lon_deg) continue;
    const int touched =
        surface_touches(depths, before.call_end_utc_s, s.call_start_utc_s, setup.config.mission.surfaced_depth_m);
    ++measurable_dives;
    if (touched > 0) {
      ++reset_dives;
      touches += touched;
      continue;
    }
    const double under_s = s.call_start_utc_s - before.call_end_utc_s;
    if (!(under_s >= 1800.0)) continue;  // a short dive's speed is mostly its turns
    const fw::EastNorth dr =
        fw::LocalFrame({*before.lat_deg, *before.lon_deg}).to_local({*s.dr_lat_deg, *s.dr_lon_deg});
    const double ce = before.water_vx_m_s.value_or(0.0), cn = before.water_vy_m_s.value_or(0.0);
    const double net = std::hypot(dr.east_m / under_s - ce, dr.north_m / under_s - cn);
    const double straight = course_straightness(headings, before.call_end_utc_s, s.call_start_utc_s);
    if (std::isfinite(straight) && straight < kMinStraightness) continue;  // it circled: its net track says nothing
    const double speed = std::isfinite(straight) ? net / straight : net;
    if (!(std::isfinite(speed) && speed > 0.02)) continue;
    glider_speeds.push_back(speed);
    if (std::isfinite(straight)) {
      ++straightened;
      least_straight = std::min(least_straight, straight);
      most_straight = std::max(most_straight, straight);
    }
  }
  GlidePitch model_pitch;
  SpeedFlight nominal = still_water_flight(setup, options, &model_pitch);

  // The pitch sensor's scale, from the steady glides sent home in the last day.
  int files = 0;
  const GlidePitch logged = logged_glide_pitch(glider_dir, f.fix_utc_s - 86400.0, f.notes, files);
  char text[400];
  f.nominal_average_speed_m_s = nominal.average_m_s;  // the baseline's: the vehicle file's flight
  if (files > 0 && calibrate_to_depth_rates(logged, model_pitch, reset_dives > 0, setup, options, f)) {
    nominal = still_water_flight(setup, options, nullptr);
  }
  double average = nominal.average_m_s;
  const double model = nominal.speed_m_s;
  const PitchCalibrationEstimate calibration = estimate_pitch_calibration(logged, model_pitch);
  const DrSpeedCalibration dr_calibration = dr_speed_calibration(setup.config.dead_reckoning, logged, calibration);
  if (calibration.have) {
    f.pitch_scale = calibration.scale;
    f.pitch_scale_sigma = calibration.scale_sigma;
    f.pitch_samples = calibration.glider_samples;
    f.pitch_dr_speed_factor = dr_calibration.factor;
    std::snprintf(text, sizeof text,
                  "pitch sensor: the glider's steady glides (%d samples in %d file(s) of from-glider/) over the "
                  "model's give hull pitch = %.3f +- %.3f x m_pitch (dives %.3f, climbs %.3f): its dead-reckoned "
                  "speed is x%.3f +- %.3f of the true (%s)",
                  calibration.glider_samples, files, calibration.scale, calibration.scale_sigma, calibration.dive_scale,
                  calibration.climb_scale, 1.0 / dr_calibration.factor,
                  dr_calibration.sigma / (dr_calibration.factor * dr_calibration.factor),
                  options.pitch_calibration ? "calibrated below" : "said, not applied");
    f.notes.push_back(text);
  } else if (files > 0) {
    f.notes.push_back("pitch sensor: too few steady glides in from-glider/ over the last day to read its scale");
  }
  const bool calibrate = options.pitch_calibration && calibration.have;
  const double k = calibrate ? dr_calibration.factor : 1.0;
  // Uncalibrated, a sensor's scale would be read as drag (the comet's ~15 %
  // low DR speed as drag x1.41): by default the drag follows only a
  // calibrated speed.
  const bool correct = options.speed_correction || (options.speed_correction_calibrated && calibrate);

  if (reset_dives > 0) {
    std::snprintf(text, sizeof text,
                  "speed through the water by dead reckoning: %d of the last day's %d dive(s) not measured: the "
                  "glider came up shallower than %.1f m %d time(s) inside them (from-glider/ m_depth), where a "
                  "Slocum takes GPS positions and restarts its dead reckoning, so its DR at the call is not its "
                  "track from the fix it dived from",
                  reset_dives, measurable_dives, setup.config.mission.surfaced_depth_m, touches);
    f.notes.push_back(text);
  }
  if (!glider_speeds.empty() && model > 0.02) {
    std::sort(glider_speeds.begin(), glider_speeds.end());
    const double counted = glider_speeds[glider_speeds.size() / 2];
    const double glider = counted * k;
    f.glider_speed_ratio = glider / model;
    f.speed_dives = static_cast<int>(glider_speeds.size());
    char course[160];
    if (straightened == static_cast<int>(glider_speeds.size())) {
      std::snprintf(course, sizeof course, ", each net track over its course's straightness %.2f-%.2f", least_straight,
                    most_straight);
    } else {
      std::snprintf(course, sizeof course,
                    ", %d of them net tracks without the heading (a dive that turned counts short there)",
                    static_cast<int>(glider_speeds.size()) - straightened);
    }
    std::snprintf(text, sizeof text,
                  "speed through the water by dead reckoning: the glider's %.3f m/s over %zu recent dives%s%s, the "
                  "model's %.3f (%s)",
                  glider, glider_speeds.size(), course, calibrate ? " (pitch calibrated)" : "", model,
                  correct                                             ? "corrected below"
                  : options.speed_correction_calibrated && !calibrate ? "not corrected: no pitch calibration"
                                                                      : "said, not applied");
    f.notes.push_back(text);
    if (correct) {
      const model::Hydrodynamics nominal_hydro = setup.vehicle.hydro;
      const SpeedMatch m = match_speed(glider, nominal, [&](double factor) {
        setup.vehicle.hydro = nominal_hydro;
        model::scale_drag(setup.vehicle.hydro, factor);
        return still_water_flight(setup, options, nullptr);
      });
      setup.vehicle.hydro = nominal_hydro;
      model::scale_drag(setup.vehicle.hydro, m.factor);
      f.speed_drag_factor = m.factor;
      if (m.factor != 1.0) {
        average = m.flight.average_m_s;
        // The drag's own uncertainty from the calibration's: d log drag =
        // d log speed / slope (the runs draw it on top of their own).
        const double relative = calibrate ? dr_calibration.sigma / dr_calibration.factor : 0.0;
        f.speed_drag_sigma = relative / std::fabs(m.slope);
        std::snprintf(text, sizeof text,
                      "the model's drag x%.3f (+- %.1f %% from the pitch calibration): its dead-reckoned speed %.3f "
                      "m/s (ratio %.3f)",
                      m.factor, 100.0 * f.speed_drag_sigma, m.flight.speed_m_s, m.ratio);
      } else {
        std::snprintf(text, sizeof text, "the model's drag not corrected: no factor in [%.1f, %.1f] brought it nearer",
                      kSpeedDragMin, kSpeedDragMax);
      }
      f.notes.push_back(text);
    }
  }
  if (std::isfinite(average) && average > 0.0) {
    setup.average_speed_m_s = average;
    setup.average_weight_s = 3600.0;
  }
}

}  // namespace glider::forecast
