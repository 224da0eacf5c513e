// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>

#include "glider/firmware/abort_monitor.hpp"
#include "glider/firmware/actuator_guard.hpp"
#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/heading_controller.hpp"
#include "glider/firmware/mission_plan.hpp"
#include "glider/firmware/navigator.hpp"
#include "glider/firmware/pi_controller.hpp"
#include "glider/firmware/yo_mission.hpp"
#include "glider/hal/hal.hpp"

namespace glider::fw {

struct ActuatorLimits {
  double ballast_min_cc = -250.0;
  double ballast_max_cc = 250.0;
  double battery_min_in = -1.0;  // full aft
  double battery_max_in = 1.0;   // full forward
  // The pump counts as "there" within this band; until then the pitch servo
  // holds the battery (pitch is dominated by the moving ballast mid-inflection).
  double ballast_settled_cc = 10.0;
};

struct FlightSoftwareConfig {
  YoMissionConfig mission;
  MissionPlan plan;    // waypoints and segments (none: a yo-only mission)
  AbortLimits aborts;  // abend limits beyond the yo's envelope
  HeadingControlConfig heading;
  DeadReckoningConfig dead_reckoning;
  ActuatorLimits limits;
  // Battery-slide pitch servo, error in rad, output in inches. Tuned on the
  // SLOCUM model: ~0.6 rad of pitch per inch of battery and a pitch pendulum
  // of ~0.4 rad/s give an integral crossover of ~0.12 rad/s, well below the
  // pendulum; the slide's 0.05 in/s rate limit bounds the rest.
  double pitch_kp_in_per_rad = 1.0;
  double pitch_ki_in_per_rad_s = 0.2;
  // First battery position of each glide (the servo starts from there and
  // then remembers where each direction settled: the vehicle's trim).
  double dive_battpos_in = 0.2;
  double climb_battpos_in = -0.2;
  // Slide moves smaller than this are not made (energy): 0.01 in is ~0.35
  // deg of pitch on a SLOCUM, inside the pitch noise of a glide.
  double battery_deadband_in = 0.01;
  double sensor_timeout_s = 10.0;    // older than this = stale -> abort
  double depth_rate_filter_s = 4.0;  // first-order filter of d(depth)/dt
};

const char* validate(const FlightSoftwareConfig& config);

// The flight software's one periodic task: read sensors, check them, run the
// mission and the pitch servo, command the actuators, log a row. Runs in
// constant time, allocates nothing, never throws.
class FlightSoftware final : public PeriodicTask {
 public:
  FlightSoftware(const hal::Hal& hal, const FlightSoftwareConfig& config);

  void run(hal::Micros now_us) override;

  // The executive's overrun count goes into the log rows.
  void attach_executive(const Executive* executive) { executive_ = executive; }

  // Mission over: navigation ended it at the surface, or an abort has
  // brought the vehicle up (it stays there).
  bool complete() const { return mission_over_ || (last_.phase == Phase::kAbort && last_.complete); }
  Phase phase() const { return last_.phase; }
  AbortCause abort_cause() const { return last_.abort_cause; }
  std::int32_t yos_completed() const { return last_.yos_completed; }
  const Navigator& navigator() const { return navigator_; }
  std::uint64_t log_rows_lost() const { return log_rows_lost_; }
  // The abort sequence commanded the burn wire and the output took it.
  bool drop_weight_released() const { return drop_weight_released_; }

  // The comms task's hooks (surface dialog; firmware/src/comms). Each takes
  // effect in the next run().
  // Up and ready for a call: between segments, at the end, or after an abort.
  bool at_surface() const {
    return (last_.segment_complete && navigator_.at_surface()) || (last_.phase == Phase::kAbort && last_.complete);
  }
  void set_surface_hold(bool hold) { surface_hold_ = hold; }
  // A call connected now: the "no comms for when_secs" clock (start_when 12) restarts.
  void note_comms(hal::Micros now_us) { navigator_.note_comms(now_us); }
  void request_resume() { resume_requested_ = true; }  // Control-R: dive without the keystroke wait
  void end_mission() {                                 // Control-C: the mission ends at the surface
    mission_over_ = true;
    ended_by_operator_ = true;
  }
  // `run`/`sequence` after Control-C: fly on. False if the mission was over anyway.
  bool restart_mission();
  bool ended_by_operator() const { return ended_by_operator_ && mission_over_; }
  // Control-F: a validated plan replaces the flown one (waypoints from the first).
  void replace_plan(const MissionPlan& plan) {
    config_.plan = plan;
    navigator_.replace_plan(plan);
  }
  const MissionPlan& plan() const { return config_.plan; }
  // Before the first run(): the current estimate the mission resumes with.
  void seed_current(EastNorth current) { navigator_.seed_current(current); }
  bool seed_average_speed(double speed_m_s, double glided_s) {
    return navigator_.seed_average_speed(speed_m_s, glided_s);
  }
  void seed_clocks(double since_surfacing_s, double since_comms_s) {
    navigator_.seed_clocks(since_surfacing_s, since_comms_s);
  }
  // Commands clamped to the vehicle's range (or non-finite) before they were sent.
  const GuardCounts& actuator_guard_counts() const { return guard_.counts(); }

 private:
  // One cycle's sensor readings, each with its check.
  struct CycleReadings {
    hal::DepthSample depth{};
    bool depth_valid = false;
    hal::AttitudeSample attitude{};
    bool attitude_valid = false;
    hal::ActuatorReading pump{}, battery{}, fin{};
    bool pump_ok = false, battery_ok = false, fin_ok = false;
    hal::GpsFix fix{};
    hal::DigitalSample leak{};
    bool leak_ok = false;
    hal::PowerSample power{};
    bool power_ok = false;
    bool depth_ok = false;     // a valid depth fresher than the sensor timeout
    bool attitude_ok = false;  // likewise the attitude
  };
  struct CycleCommands {
    double ballast_cc = 0.0;
    double battery_in = 0.0;
    double fin_rad = 0.0;
  };

  // The steps of run(), in order.
  CycleReadings read_sensors(hal::Micros now_us);
  NavigatorOutputs navigate(hal::Micros now_us, const CycleReadings& in);
  AbortCause check_aborts(hal::Micros now_us, const CycleReadings& in);
  void run_mission(hal::Micros now_us, const CycleReadings& in, const NavigatorOutputs& nav, AbortCause monitored);
  CycleCommands command_actuators(const CycleReadings& in, const NavigatorOutputs& nav, double dt_s);
  void log_record(hal::Micros now_us, const CycleReadings& in, const NavigatorOutputs& nav,
                  const CycleCommands& commands);

  void update_depth_rate(const hal::DepthSample& depth);
  double fin_command(const NavigatorOutputs& nav, double dt_s);
  double battery_command(const MissionOutputs& mission, double pitch_rad, double ballast_cc, double dt_s);

  hal::Hal hal_;
  FlightSoftwareConfig config_;
  YoMission mission_;
  Navigator navigator_;
  AbortMonitor abort_monitor_;
  ActuatorGuard guard_;
  HeadingController heading_;
  PiController pitch_servo_;
  bool mission_over_ = false;  // the navigator's end of mission
  bool ended_by_operator_ = false;
  bool surface_hold_ = false;
  bool resume_requested_ = false;
  bool drop_weight_released_ = false;
  const Executive* executive_ = nullptr;

  MissionOutputs last_{};
  hal::Micros last_run_us_ = 0;
  bool has_run_ = false;

  // Last valid sensor values and when they were measured.
  double depth_m_ = 0.0;
  hal::Micros depth_time_us_ = 0;
  bool have_depth_ = false;
  hal::AttitudeSample attitude_{};
  bool have_attitude_ = false;

  double depth_rate_m_s_ = 0.0;
  bool have_depth_rate_ = false;
  double prev_depth_m_ = 0.0;
  hal::Micros prev_depth_time_us_ = 0;

  Phase servo_phase_ = Phase::kSurface;  // glide the servo last ran in
  double dive_trim_in_;
  double climb_trim_in_;
  double battery_cmd_in_ = 0.0;
  double ballast_cmd_cc_ = 0.0;
  double fin_cmd_rad_ = 0.0;
  bool commanded_ = false;
  std::uint64_t log_rows_lost_ = 0;
};

}  // namespace glider::fw
