// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <cstring>

#include "glider/firmware/yo_mission.hpp"

using glider::fw::AbortCause;
using glider::fw::MissionInputs;
using glider::fw::MissionOutputs;
using glider::fw::Phase;
using glider::fw::YoMission;
using glider::fw::YoMissionConfig;

namespace {

MissionInputs at(double t_s, double depth_m) {
  MissionInputs in;
  in.now_us = static_cast<glider::hal::Micros>(t_s * 1e6);
  in.depth_m = depth_m;
  in.depth_ok = true;
  in.attitude_ok = true;
  return in;
}

}  // namespace

TEST_GROUP(YoMission) {
  YoMissionConfig config;
  void setup() override {
    config.dive_to_m = 50.0;
    config.climb_to_m = 5.0;
    config.yos = 2;
  }
};

TEST(YoMission, FliesTheYosThenSurfaces) {
  YoMission mission(config);
  double t = 0.0;
  MissionOutputs out = mission.update(at(t, 0.2));
  CHECK(out.phase == Phase::kDive);
  CHECK_TRUE(out.phase_changed);
  DOUBLES_EQUAL(config.dive_ballast_cc, out.ballast_cc, 0.0);
  DOUBLES_EQUAL(config.dive_pitch_rad, out.pitch_target_rad, 0.0);
  CHECK_TRUE(out.pitch_control);

  out = mission.update(at(t += 1, 49.9));
  CHECK(out.phase == Phase::kDive);
  CHECK_FALSE(out.phase_changed);
  out = mission.update(at(t += 1, 50.0));
  CHECK(out.phase == Phase::kClimb);
  CHECK_TRUE(out.phase_changed);
  DOUBLES_EQUAL(config.climb_ballast_cc, out.ballast_cc, 0.0);
  DOUBLES_EQUAL(config.climb_pitch_rad, out.pitch_target_rad, 0.0);

  out = mission.update(at(t += 1, 5.0));  // first yo done
  CHECK(out.phase == Phase::kDive);
  LONGS_EQUAL(1, out.yos_completed);
  out = mission.update(at(t += 1, 51.0));
  CHECK(out.phase == Phase::kClimb);
  out = mission.update(at(t += 1, 4.0));  // second (last) yo: keep climbing
  CHECK(out.phase == Phase::kClimb);
  LONGS_EQUAL(2, out.yos_completed);
  CHECK_FALSE(out.complete);
  out = mission.update(at(t += 1, 1.5));
  CHECK(out.phase == Phase::kClimb);
  out = mission.update(at(t += 1, 0.9));
  CHECK(out.phase == Phase::kSurface);
  CHECK_TRUE(out.complete);
  CHECK(out.ballast_cc > 0.0);
  CHECK_FALSE(out.pitch_control);
  CHECK(out.abort_cause == AbortCause::kNone);
}

TEST(YoMission, OverdepthAbortsAndLatches) {
  YoMission mission(config);
  mission.update(at(0, 0.0));
  MissionOutputs out = mission.update(at(1, config.max_depth_m + 0.1));
  CHECK(out.phase == Phase::kAbort);
  CHECK(out.abort_cause == AbortCause::kOverdepth);
  CHECK_TRUE(out.phase_changed);
  CHECK(out.ballast_cc > 0.0);
  CHECK_FALSE(out.pitch_control);
  out = mission.update(at(2, 30.0));  // back inside the envelope: still abort
  CHECK(out.phase == Phase::kAbort);
  CHECK_FALSE(out.complete);
  out = mission.update(at(3, 0.5));  // up: the abort is complete
  CHECK(out.phase == Phase::kAbort);
  CHECK_TRUE(out.complete);
  CHECK(out.abort_cause == AbortCause::kOverdepth);
}

TEST(YoMission, EachSensorOrActuatorFaultAborts) {
  struct Case {
    void (*break_it)(MissionInputs&);
    AbortCause expected;
  };
  const Case cases[] = {
      {[](MissionInputs& in) { in.depth_ok = false; }, AbortCause::kDepthSensor},
      {[](MissionInputs& in) { in.attitude_ok = false; }, AbortCause::kAttitudeSensor},
      {[](MissionInputs& in) { in.actuator_fault = true; }, AbortCause::kActuatorFault},
  };
  for (const Case& c : cases) {
    YoMission mission(config);
    mission.update(at(0, 0.0));
    MissionInputs in = at(1, 20.0);
    c.break_it(in);
    const MissionOutputs out = mission.update(in);
    CHECK(out.phase == Phase::kAbort);
    CHECK(out.abort_cause == c.expected);
  }
}

TEST(YoMission, OvertimeAborts) {
  config.max_duration_s = 100.0;
  YoMission mission(config);
  mission.update(at(10, 0.0));  // the clock need not start at zero
  CHECK(mission.update(at(110, 20.0)).phase == Phase::kDive);
  const MissionOutputs out = mission.update(at(110.5, 20.0));
  CHECK(out.phase == Phase::kAbort);
  CHECK(out.abort_cause == AbortCause::kOvertime);
}

TEST(YoMission, InvalidDepthAbortNeverCompletes) {
  YoMission mission(config);
  mission.update(at(0, 0.0));
  MissionInputs in = at(1, 0.5);  // shallow, but the depth is not trusted
  in.depth_ok = false;
  const MissionOutputs out = mission.update(in);
  CHECK(out.phase == Phase::kAbort);
  CHECK_FALSE(out.complete);
}

TEST(YoMission, ValidationNamesTheProblem) {
  STRCMP_EQUAL("", glider::fw::validate(config));
  YoMissionConfig bad = config;
  bad.dive_to_m = 4.0;
  STRCMP_EQUAL("dive_to_m must be deeper than climb_to_m", glider::fw::validate(bad));
  bad = config;
  bad.yos = 0;
  STRCMP_EQUAL("yos must be at least 1", glider::fw::validate(bad));
  bad = config;
  bad.max_depth_m = 40.0;
  STRCMP_EQUAL("max_depth_m must be deeper than dive_to_m", glider::fw::validate(bad));
  bad = config;
  bad.dive_ballast_cc = 10.0;
  CHECK(std::strlen(glider::fw::validate(bad)) > 0);
}
