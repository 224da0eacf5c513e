// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/mission_file/mission_loader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include "glider/config/value_limits.hpp"
#include "glider/firmware/geo.hpp"

namespace glider::fw::mission_file {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The dive overshoots its target while the pump turns it round (~3 m at
// 0.2 m/s and 15 s of pumping): the overdepth limit must leave room for it.
constexpr double kOvershootMarginM = 5.0;

// What the loader does with an argument it meets.
enum class Use {
  kUsed,     // flown
  kIgnored,  // harmless to leave out: a warning
  kRefused,  // would change how safely the vehicle flies: an error if set
};

struct ArgRule {
  Use use;
  const char* why;      // for kIgnored / kRefused
  config::Range range;  // for kUsed: anything else is refused with its line
};

// Ranges in Slocum's units; -1 is Slocum's "off" where the range starts there.
ArgRule used(double min, double max, const char* unit) { return {Use::kUsed, "", {min, max, unit}}; }
ArgRule ignored(const char* why) { return {Use::kIgnored, why, {0.0, 0.0, ""}}; }
ArgRule refused(const char* why) { return {Use::kRefused, why, {0.0, 0.0, ""}}; }

using Rules = std::map<std::string, ArgRule>;

const Rules& abend_rules() {
  static const Rules rules{
      {"overdepth", used(-1.0, 1500.0, "m")},
      {"overtime", used(-1.0, 2.0 * 366.0 * 86400.0, "s")},
      {"samedepth_for", used(-1.0, 2.0 * 366.0 * 86400.0, "s")},
      {"stalled_for", used(-1.0, 2.0 * 366.0 * 86400.0, "s")},
      {"max_wpt_distance", used(-1.0, 2e7, "m")},
      {"remaining_charge_min", used(0.0, 100.0, "%")},
      {"overdepth_sample_time", ignored("checked every control cycle (1 s), not sampled")},
      {"samedepth_for_sample_time", ignored("checked every control cycle (1 s), not sampled")},
      {"stalled_for_sample_time", ignored("checked every control cycle (1 s), not sampled")},
      {"no_cop_tickle_for", ignored("no COP watchdog in this firmware (the executive counts overruns)")},
      {"no_cop_tickle_percent", ignored("no COP watchdog in this firmware")},
      {"reqd_spare_heap", ignored("the firmware allocates nothing after start-up")},
      {"chk_sensor_reasonableness", ignored("every sensor value is always checked (validity, finiteness, age)")},
      {"leakdetect_sample_time", ignored("the leak detector is read every control cycle")},
      {"vacuum_min", refused("no vacuum sensor in the HAL: the vacuum abort cannot be honoured")},
      {"vacuum_max", refused("no vacuum sensor in the HAL: the vacuum abort cannot be honoured")},
  };
  return rules;
}

const Rules& surface_rules() {
  static const Rules rules{
      {"start_when", used(0.0, 20.0, "")},
      {"when_secs", used(-1.0, 2.0 * 366.0 * 86400.0, "s")},
      {"end_action", used(0.0, 2.0, "")},
      {"gps_wait_time", used(0.0, 86400.0, "s")},
      {"keystroke_wait_time", used(0.0, 86400.0, "s")},
      {"c_use_bpump", ignored("surfacing climbs use the yo's climb ballast (full buoyancy at the surface)")},
      {"c_bpump_value", ignored("surfacing climbs use the yo's climb ballast (full buoyancy at the surface)")},
      {"c_use_pitch", ignored("surfacing climbs use the yo's climb pitch")},
      {"c_pitch_value", ignored("surfacing climbs use the yo's climb pitch")},
      {"strobe_on", ignored("no strobe in the HAL")},
      {"report_all", ignored("no surface dialog")},
      {"printout_cycle_time", used(10.0, 3600.0, "s")},
      {"when_wpt_dist", ignored("only used by start_when 7, which is refused")},
      {"when_utc_min", ignored("only used by start_when 13, which is refused")},
      {"when_utc_hour", ignored("only used by start_when 13, which is refused")},
      {"when_utc_day", ignored("only used by start_when 13, which is refused")},
  };
  return rules;
}

const Rules& goto_rules() {
  static const Rules rules{
      {"start_when", used(0.0, 20.0, "")},         {"list_stop_when", used(0.0, 20.0, "")},
      {"list_when_wpt_dist", used(0.0, 1e5, "m")}, {"initial_wpt", used(-2.0, 1000.0, "")},
      {"num_waypoints", used(0.0, 1000.0, "")},    {"num_legs_to_run", used(-2.0, 1e6, "")},
  };
  return rules;
}

const Rules& glide_rules() {  // yo (d_ and c_ prefixes), dive_to and climb_to (no prefix)
  static const Rules rules{
      {"start_when", used(0.0, 20.0, "")},
      {"end_action", used(0.0, 2.0, "")},
      {"num_half_cycles_to_do", used(-1.0, 1e6, "")},
      {"target_depth", used(-1.0, 1500.0, "m")},
      {"target_altitude", used(-1.0, 1500.0, "m")},
      {"use_pitch", used(1.0, 3.0, "")},
      {"pitch_value", used(-5.0, 5.0, "rad (use_pitch 3) or in (use_pitch 1)")},
      {"use_bpump", used(0.0, 2.0, "")},
      {"bpump_value", used(-1000.0, 1000.0, "cc")},
      {"stop_when_hover_for",
       ignored("not a per-glide check here: the abend samedepth_for/stalled_for aborts still apply")},
      {"stop_when_stalled_for",
       ignored("not a per-glide check here: the abend samedepth_for/stalled_for aborts still apply")},
      {"wait_for_pitch", ignored("the pitch servo runs from the start of every glide")},
      {"wait_for_ballast", ignored("the pitch servo waits for the pump by itself")},
  };
  return rules;
}

const Rules& prepare_rules() {
  static const Rules rules{
      {"start_when", used(0.0, 20.0, "")},
      {"wait_time", used(0.0, 86400.0, "s")},
  };
  return rules;
}

const Rules& heading_rules() {
  static const Rules rules{
      {"start_when", used(0.0, 20.0, "")},
      {"use_heading", used(0.0, 4.0, "")},
      {"heading_value", used(-7.0, 7.0, "rad")},
      {"end_action", ignored("a set heading holds until the mission ends")},
      {"stop_when", ignored("a set heading holds until the mission ends")},
      {"when_secs", ignored("a set heading holds until the mission ends")},
  };
  return rules;
}

// Behaviours that only concern science or logging: read and left alone.
bool harmless_behavior(const std::string& name) {
  return name == "sample" || name == "sensors_in" || name == "sensors_out" || name == "nop_cmds";
}

class Loader {
 public:
  Loader(const MissionVehicle& vehicle, const FlightSoftwareConfig& base, std::vector<Diagnostic>& out)
      : vehicle_(vehicle), config_(base), diagnostics_(out) {}

  std::optional<FlightSoftwareConfig> load(const MiDocument& doc);

 private:
  void warn(const SourceLocation& at, const std::string& message) {
    diagnostics_.push_back({Severity::kWarning, at.file, at.line, message});
  }
  void fail(const SourceLocation& at, const std::string& message) {
    diagnostics_.push_back({Severity::kError, at.file, at.line, message});
  }

  // Checks every argument of a block against its rules; the glide rules are
  // matched after the d_/c_ prefix for the yo.
  void check_args(const MiBehavior& b, const Rules& rules, bool strict, bool prefixed);
  const MiArg* find(const MiBehavior& b, const std::string& name) const;
  double value(const MiBehavior& b, const std::string& name, double fallback) const;

  void read_abend(const MiBehavior& b);
  void read_surface(const MiBehavior& b);
  void read_goto(const MiBehavior& b);
  void read_glide(const MiBehavior& b, const std::string& prefix, bool dive);
  void read_yo(const MiBehavior& b);
  void read_prepare(const MiBehavior& b);
  void read_set_heading(const MiBehavior& b);
  void read_sensors(const MiDocument& doc);
  void check_safety(const SourceLocation& mission);

  MissionVehicle vehicle_;
  FlightSoftwareConfig config_;
  std::vector<Diagnostic>& diagnostics_;
  bool have_abend_ = false;
  bool have_yo_ = false;
  bool have_dive_ = false;
  bool have_goto_ = false;
  bool have_set_heading_ = false;
  SourceLocation yo_at_{};
  std::int32_t half_cycles_ = -1;
  double overdepth_m_ = 0.0;
  std::set<const MiArg*> out_of_range_;
};

const MiArg* Loader::find(const MiBehavior& b, const std::string& name) const {
  const MiArg* found = nullptr;
  for (const MiArg& a : b.args) {
    if (a.name == name) found = &a;  // the last one counts (.ma after .mi)
  }
  return found;
}

double Loader::value(const MiBehavior& b, const std::string& name, double fallback) const {
  const MiArg* a = find(b, name);
  // A refused value (error already reported) is never flown, nor converted.
  return a != nullptr && out_of_range_.count(a) == 0 ? a->value : fallback;
}

void Loader::check_args(const MiBehavior& b, const Rules& rules, bool strict, bool prefixed) {
  for (const MiArg& a : b.args) {
    std::string key = a.name;
    if (prefixed && key.size() > 2 && (key.rfind("d_", 0) == 0 || key.rfind("c_", 0) == 0)) key = key.substr(2);
    const auto rule = rules.find(key);
    if (rule == rules.end()) {
      if (strict) {
        fail(a.where,
             b.name + ": argument " + a.name + " is not supported (an abort limit the firmware cannot honour)");
      } else {
        warn(a.where, b.name + ": argument " + a.name + " is not supported and is ignored");
      }
    } else if (rule->second.use == Use::kUsed && !config::within(a.value, rule->second.range)) {
      fail(a.where, b.name + ": " + a.name + ": " + config::range_problem(a.value, rule->second.range));
      out_of_range_.insert(&a);
    } else if (rule->second.use == Use::kIgnored) {
      warn(a.where, b.name + ": " + a.name + " ignored: " + rule->second.why);
    } else if (rule->second.use == Use::kRefused) {
      fail(a.where, b.name + ": " + a.name + " refused: " + rule->second.why);
    }
  }
}

void Loader::read_abend(const MiBehavior& b) {
  have_abend_ = true;
  check_args(b, abend_rules(), true, false);
  overdepth_m_ = value(b, "overdepth", -1.0);
  const double overtime = value(b, "overtime", -1.0);
  config_.mission.max_duration_s = overtime > 0.0 ? overtime : kInfinity;
  AbortLimits& a = config_.aborts;
  a.samedepth_for_s = value(b, "samedepth_for", -1.0);
  a.stalled_for_s = value(b, "stalled_for", -1.0);
  a.max_wpt_distance_m = value(b, "max_wpt_distance", -1.0);
  a.remaining_charge_min_pct = value(b, "remaining_charge_min", 0.0);
  if (a.remaining_charge_min_pct >= 100.0) {
    fail(b.where, "abend: remaining_charge_min must be below 100 %");
  }
}

void Loader::read_surface(const MiBehavior& b) {
  check_args(b, surface_rules(), false, false);
  const int start_when = static_cast<int>(value(b, "start_when", 1.0));
  const double when_secs = value(b, "when_secs", -1.0);
  MissionPlan& p = config_.plan;
  switch (start_when) {
    case 1:  // stack idle: when the yos (or the list) are done: a segment's end
      break;
    case 9:   // every when_secs, counted from its previous firing (navigator.cpp)
    case 12:  // no comms for when_secs, counted from the last call connected
    {
      if (!(when_secs > 0.0)) {
        fail(b.where, "surface: start_when " + std::to_string(start_when) + " needs when_secs > 0");
        return;
      }
      double& interval = start_when == 9 ? p.surface_interval_s : p.no_comms_interval_s;
      interval = interval > 0.0 ? std::min(interval, when_secs) : when_secs;
      break;
    }
    default:
      fail(b.where, "surface: start_when " + std::to_string(start_when) +
                        " is not supported (1 stack idle, 9 every when_secs, 12 no comms for when_secs are)");
      return;
  }
  const int end_action = static_cast<int>(value(b, "end_action", 1.0));
  if (end_action < 0 || end_action > 2) fail(b.where, "surface: end_action must be 0, 1 or 2");
  p.gps_wait_s = std::max(p.gps_wait_s, value(b, "gps_wait_time", 0.0));
  // end_action 1 waits for the pilot's ^C for keystroke_wait_time, then resumes.
  p.printout_cycle_s = value(b, "printout_cycle_time", p.printout_cycle_s);
  if (end_action == 1) p.surface_dwell_s = std::max(p.surface_dwell_s, value(b, "keystroke_wait_time", 0.0));
}

void Loader::read_goto(const MiBehavior& b) {
  have_goto_ = true;
  check_args(b, goto_rules(), false, false);
  MissionPlan& p = config_.plan;
  const int stop_when = static_cast<int>(value(b, "list_stop_when", 7.0));
  if (stop_when != 7) {
    fail(b.where, "goto_list: list_stop_when " + std::to_string(stop_when) +
                      " is not supported (7: a waypoint is reached within list_when_wpt_dist)");
  }
  p.waypoint_radius_m = value(b, "list_when_wpt_dist", 100.0);
  if (!(p.waypoint_radius_m > 0.0)) fail(b.where, "goto_list: list_when_wpt_dist must be positive");
  const double legs = value(b, "num_legs_to_run", -1.0);
  if (legs == -1.0 || legs == -2.0 || legs >= 1.0) {
    p.legs_to_run = static_cast<std::int32_t>(legs);
  } else {
    fail(b.where, "goto_list: num_legs_to_run must be -1 (loop), -2 (once) or a positive count");
  }
  if (!b.has_waypoint_section) {
    fail(b.where, "goto_list: no <start:waypoints> section (the waypoints come from the args_from_file .ma)");
    return;
  }
  const double declared = value(b, "num_waypoints", static_cast<double>(b.waypoints.size()));
  if (declared < 1.0 || declared > static_cast<double>(b.waypoints.size())) {
    fail(b.where, "goto_list: num_waypoints " + std::to_string(static_cast<int>(declared)) + " but " +
                      std::to_string(b.waypoints.size()) + " waypoints listed");
    return;
  }
  if (declared > static_cast<double>(kMaxWaypoints)) {
    fail(b.where, "goto_list: at most " + std::to_string(kMaxWaypoints) + " waypoints");
    return;
  }
  const auto count = static_cast<std::size_t>(declared);
  if (count < b.waypoints.size()) {
    warn(b.waypoints[count].where,
         "goto_list: waypoints after the first num_waypoints (" + std::to_string(count) + ") are not flown");
  }
  for (std::size_t i = 0; i < count; ++i) {
    const MiWaypoint& w = b.waypoints[i];
    const double lat_minutes = std::fmod(std::fabs(w.lat_nmea), 100.0);
    const double lon_minutes = std::fmod(std::fabs(w.lon_nmea), 100.0);
    const LatLon ll{nmea_to_degrees(w.lat_nmea), nmea_to_degrees(w.lon_nmea)};
    // Written so that NaN fails too (the reader already refuses non-finite numbers).
    if (!(lat_minutes < 60.0 && lon_minutes < 60.0 && std::fabs(ll.lat_deg) <= 90.0 &&
          std::fabs(ll.lon_deg) <= 180.0)) {
      fail(w.where, "waypoint is not a position in NMEA ddmm.mmm (lon lat)");
      continue;
    }
    p.waypoints[i] = ll;
  }
  p.waypoint_count = static_cast<std::int32_t>(count);
  const double initial = value(b, "initial_wpt", -1.0);
  if (initial == -2.0) {
    warn(find(b, "initial_wpt")->where, "goto_list: initial_wpt -2 (closest) starts at the first waypoint");
  } else if (initial >= 0.0) {
    if (initial >= declared) {
      fail(find(b, "initial_wpt")->where, "goto_list: initial_wpt beyond the list");
    } else {
      // Rotate the list so the firmware starts at index 0.
      std::rotate(p.waypoints.begin(), p.waypoints.begin() + static_cast<std::ptrdiff_t>(initial),
                  p.waypoints.begin() + static_cast<std::ptrdiff_t>(count));
    }
  } else if (initial != -1.0) {
    fail(find(b, "initial_wpt")->where, "goto_list: initial_wpt must be -1, -2 or an index");
  }
}

void Loader::read_glide(const MiBehavior& b, const std::string& prefix, bool dive) {
  YoMissionConfig& m = config_.mission;
  const std::string what = b.name + (prefix.empty() ? "" : " " + prefix);
  const double depth = value(b, prefix + "target_depth", -1.0);
  if (!(depth > 0.0)) {
    fail(b.where, what + "target_depth must be given and positive");
    return;
  }
  (dive ? m.dive_to_m : m.climb_to_m) = depth;
  const MiArg* altitude = find(b, prefix + "target_altitude");
  if (altitude != nullptr && altitude->value > 0.0) {
    warn(altitude->where, what + "target_altitude ignored: no altimeter in the HAL, the glide turns at " + prefix +
                              "target_depth only (keep it above the bottom)");
  }
  const int use_bpump = static_cast<int>(value(b, prefix + "use_bpump", 2.0));
  if (use_bpump != 2) fail(b.where, what + "use_bpump must be 2 (absolute cc)");
  // Slocum's +-1000 means "as far as the pump goes".
  const double bpump = value(b, prefix + "bpump_value", dive ? -1000.0 : 1000.0);
  const double limited = std::clamp(bpump, vehicle_.limits.ballast_min_cc, vehicle_.limits.ballast_max_cc);
  if (dive ? !(limited < 0.0) : !(limited > 0.0)) {
    fail(b.where, what + "bpump_value must make the glider " + (dive ? "heavy (< 0)" : "light (> 0)"));
  }
  (dive ? m.dive_ballast_cc : m.climb_ballast_cc) = limited;
  const int use_pitch = static_cast<int>(value(b, prefix + "use_pitch", 3.0));
  const double pitch_value = value(b, prefix + "pitch_value", dive ? -0.4363 : 0.4363);
  if (use_pitch == 1) {  // battery position, in
    if (!(pitch_value >= vehicle_.limits.battery_min_in && pitch_value <= vehicle_.limits.battery_max_in)) {
      fail(find(b, prefix + "pitch_value") != nullptr ? find(b, prefix + "pitch_value")->where : b.where,
           what + "pitch_value " + std::to_string(pitch_value) + " in is outside the battery's travel");
    }
    (dive ? m.dive_battpos_in : m.climb_battpos_in) = pitch_value;
  } else if (use_pitch == 3) {  // pitch servo, rad
    if (dive ? !(pitch_value < 0.0) : !(pitch_value > 0.0)) {
      fail(b.where, what + "pitch_value must be " + (dive ? "nose down (< 0 rad)" : "nose up (> 0 rad)"));
    }
    constexpr config::Range kPitchRad{-1.4, 1.4, "rad (80 deg)"};
    if (!config::within(pitch_value, kPitchRad)) {
      fail(find(b, prefix + "pitch_value") != nullptr ? find(b, prefix + "pitch_value")->where : b.where,
           what + "pitch_value: " + config::range_problem(pitch_value, kPitchRad));
    }
    (dive ? m.dive_pitch_rad : m.climb_pitch_rad) = pitch_value;
    (dive ? m.dive_battpos_in : m.climb_battpos_in) = std::numeric_limits<double>::quiet_NaN();
  } else {
    fail(b.where, what + "use_pitch " + std::to_string(use_pitch) + " is not supported (1 battpos, 3 servo)");
  }
}

void Loader::read_yo(const MiBehavior& b) {
  have_yo_ = true;
  yo_at_ = b.where;
  check_args(b, glide_rules(), false, true);
  read_glide(b, "d_", true);
  read_glide(b, "c_", false);
  const double half = value(b, "num_half_cycles_to_do", -1.0);
  if (half == -1.0) {
    half_cycles_ = -1;
    config_.mission.yos = std::numeric_limits<std::int32_t>::max();  // until the surface interval
  } else if (half >= 1.0 && half < 1e6) {
    half_cycles_ = static_cast<std::int32_t>(half);
    config_.mission.yos = (half_cycles_ + 1) / 2;
    if (half_cycles_ % 2 != 0) {
      warn(find(b, "num_half_cycles_to_do")->where,
           "yo: an odd num_half_cycles_to_do is flown as " + std::to_string(config_.mission.yos) + " whole yos");
    }
  } else {
    fail(b.where, "yo: num_half_cycles_to_do must be -1 or a positive count");
  }
}

void Loader::read_prepare(const MiBehavior& b) {
  check_args(b, prepare_rules(), false, false);
  config_.plan.gps_wait_s = std::max(config_.plan.gps_wait_s, value(b, "wait_time", 0.0));
}

void Loader::read_set_heading(const MiBehavior& b) {
  have_set_heading_ = true;
  check_args(b, heading_rules(), false, false);
  const int use = static_cast<int>(value(b, "use_heading", 2.0));
  if (use != 2) {
    fail(b.where, "set_heading: use_heading " + std::to_string(use) + " is not supported (2: heading_value in rad)");
    return;
  }
  const double heading = value(b, "heading_value", std::numeric_limits<double>::quiet_NaN());
  if (!(heading >= 0.0 && heading < 2.0 * std::numbers::pi)) {
    fail(b.where, "set_heading: heading_value must be in [0, 2 pi) rad");
    return;
  }
  config_.plan.heading_rad = heading;
}

void Loader::read_sensors(const MiDocument& doc) {
  for (const MiArg& s : doc.sensors) {
    if (s.name == "u_use_current_correction") {
      if (!(s.value == 0.0 || s.value == 1.0)) {
        fail(s.where, "sensor u_use_current_correction: value " + config::show_value(s.value) + " must be 0 or 1");
      }
      config_.plan.current_correction = s.value != 0.0;
    } else {
      warn(s.where, "sensor " + s.name + " is not used by this firmware and is ignored");
    }
  }
}

void Loader::check_safety(const SourceLocation& mission) {
  YoMissionConfig& m = config_.mission;
  if (!have_abend_) {
    fail(mission, "no abend behavior: a mission without abort limits is refused");
  }
  // Overdepth: the abend limit where given, never deeper than the rating.
  m.max_depth_m =
      overdepth_m_ > 0.0 ? std::min(overdepth_m_, vehicle_.max_working_depth_m) : vehicle_.max_working_depth_m;
  if (overdepth_m_ > vehicle_.max_working_depth_m) {
    warn(mission, "abend overdepth " + std::to_string(overdepth_m_) + " m is beyond the vehicle's rating: " +
                      std::to_string(vehicle_.max_working_depth_m) + " m applies");
  }
  if (!have_yo_ && !have_dive_) fail(mission, "nothing to fly: no yo (or dive_to) behavior");
  if (m.dive_to_m > vehicle_.max_working_depth_m) {
    fail(yo_at_, "dive target " + std::to_string(m.dive_to_m) + " m is beyond the vehicle's rating (" +
                     std::to_string(vehicle_.max_working_depth_m) + " m)");
  } else if (m.dive_to_m > m.max_depth_m - kOvershootMarginM) {
    fail(yo_at_, "dive target " + std::to_string(m.dive_to_m) + " m leaves less than " +
                     std::to_string(kOvershootMarginM) + " m to the overdepth limit (" + std::to_string(m.max_depth_m) +
                     " m)");
  }
  const bool surfaces_by_count = half_cycles_ > 0;
  const bool surfaces_by_time = config_.plan.surface_interval_s > 0.0 || config_.plan.no_comms_interval_s > 0.0;
  if (!surfaces_by_count && !surfaces_by_time) {
    fail(yo_at_,
         "the yos never end (num_half_cycles_to_do -1) and no surface behavior brings the glider up "
         "by time: it would never surface");
  }
  if (have_set_heading_ && have_goto_) {
    warn(mission, "set_heading and goto_list both given: the waypoints are flown");
    config_.plan.heading_rad = std::numeric_limits<double>::quiet_NaN();
  }
}

std::optional<FlightSoftwareConfig> Loader::load(const MiDocument& doc) {
  config_.limits = vehicle_.limits;
  config_.heading.fin_max_rad = vehicle_.fin_max_rad;
  config_.heading.fin_rate_rad_s = vehicle_.fin_rate_rad_s;
  config_.heading.yaw_gain_per_m = vehicle_.yaw_gain_per_m;
  config_.aborts.drop_weight_fitted = vehicle_.drop_weight_fitted;
  config_.mission.start_at_launch = false;  // prepare_to_dive: GPS first
  config_.plan = MissionPlan{};
  config_.plan.gps_wait_s = 0.0;
  config_.plan.surface_dwell_s = 0.0;
  read_sensors(doc);
  SourceLocation mission{doc.behaviors.empty() ? std::string("mission") : doc.behaviors.front().where.file, 0};
  for (const MiBehavior& b : doc.behaviors) {
    if (b.name == "abend") {
      read_abend(b);
    } else if (b.name == "surface") {
      read_surface(b);
    } else if (b.name == "goto_list") {
      read_goto(b);
    } else if (b.name == "yo") {
      read_yo(b);
    } else if (b.name == "dive_to" || b.name == "climb_to") {
      check_args(b, glide_rules(), false, false);
      if (have_yo_) {
        warn(b.where, b.name + " is superseded by the yo in this firmware");
      } else {
        read_glide(b, "", b.name == "dive_to");
        have_dive_ = have_dive_ || b.name == "dive_to";
        half_cycles_ = 2;
        config_.mission.yos = 1;
        yo_at_ = b.where;
      }
    } else if (b.name == "prepare_to_dive") {
      read_prepare(b);
    } else if (b.name == "set_heading") {
      read_set_heading(b);
    } else if (harmless_behavior(b.name)) {
      warn(b.where, "behavior " + b.name + " (science/logging) is not flown by this firmware and is ignored");
    } else {
      fail(b.where, "behavior " + b.name + " is not supported: a mission that needs it is refused");
    }
  }
  if (have_dive_ && !have_yo_ && config_.mission.climb_to_m >= config_.mission.dive_to_m) {
    config_.mission.climb_to_m = config_.mission.surfaced_depth_m + 1.0;
  }
  check_safety(mission);
  if (std::any_of(diagnostics_.begin(), diagnostics_.end(),
                  [](const Diagnostic& d) { return d.severity == Severity::kError; })) {
    return std::nullopt;
  }
  const char* problem = validate(config_);
  if (problem[0] != '\0') {
    fail(mission, std::string("mission refused: ") + problem);
    return std::nullopt;
  }
  return config_;
}

}  // namespace

std::vector<ArgumentRange> mission_argument_limits() {
  std::vector<ArgumentRange> out;
  auto add = [&out](const char* behavior, const Rules& rules, const char* prefix) {
    for (const auto& [name, rule] : rules) {
      if (rule.use == Use::kUsed) out.push_back({behavior, prefix + name, rule.range});
    }
  };
  add("abend", abend_rules(), "");
  add("surface", surface_rules(), "");
  add("goto_list", goto_rules(), "");
  add("yo", glide_rules(), "d_");
  add("yo", glide_rules(), "c_");
  add("dive_to", glide_rules(), "");
  add("prepare_to_dive", prepare_rules(), "");
  add("set_heading", heading_rules(), "");
  return out;
}

LoadedMission load_mission(const MiDocument& doc, const MissionVehicle& vehicle, const FlightSoftwareConfig& base) {
  LoadedMission result;
  result.diagnostics = doc.diagnostics;
  if (doc.has_errors()) return result;
  Loader loader(vehicle, base, result.diagnostics);
  result.config = loader.load(doc);
  return result;
}

LoadedMission load_mission_file(const std::filesystem::path& path, const MissionVehicle& vehicle,
                                const FlightSoftwareConfig& base) {
  return load_mission(read_mi_file(path), vehicle, base);
}

}  // namespace glider::fw::mission_file
