// SPDX-License-Identifier: Apache-2.0
// The pitch calibration (pitch_calibration.hpp): an explicit, switchable
// prior applied to the logged m_pitch before the diagnosis. The end-to-end
// effect on a real log is diagnose.real.pitch_calibration (tests/CMakeLists.txt).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "glider/diagnose/pitch_calibration.hpp"
#include "glider/flightlog/flight_log.hpp"

using glider::diagnose::calibrate_pitch;
using glider::diagnose::PitchCalibration;
using glider::flightlog::FlightLog;

namespace {

FlightLog small_log() {
  return glider::flightlog::parse_flight_log(
      "# glider: comet\n"
      "m_present_time,m_depth,m_pitch,m_ballast_pumped\n"
      "0,1.0,0.40,100\n"
      "4,2.0,,100\n"
      "8,3.0,-0.30,-100\n",
      "small.csv");
}

std::string message_of(const PitchCalibration& c) {
  try {
    calibrate_pitch(small_log(), c);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(DiagnosePitchCalibration){};

TEST(DiagnosePitchCalibration, CalibratesOnlyThePitch) {
  const FlightLog log = small_log();
  const FlightLog c = calibrate_pitch(log, {0.86, -0.004});
  DOUBLES_EQUAL(0.86 * 0.40 - 0.004, c.column("m_pitch")[0], 1e-15);
  CHECK(std::isnan(c.column("m_pitch")[1]));  // not logged stays not logged
  DOUBLES_EQUAL(0.86 * -0.30 - 0.004, c.column("m_pitch")[2], 1e-15);
  for (const char* name : {"m_present_time", "m_depth", "m_ballast_pumped"}) {
    for (std::size_t i = 0; i < log.rows(); ++i) DOUBLES_EQUAL(log.column(name)[i], c.column(name)[i], 0.0);
  }
  DOUBLES_EQUAL(8.0, c.time()[2], 0.0);
  CHECK_EQUAL(std::string("comet"), *c.metadata_value("glider"));
}

TEST(DiagnosePitchCalibration, OffByDefault) {
  const PitchCalibration none;
  CHECK_FALSE(none.active());
  CHECK_EQUAL(std::string("none (m_pitch as logged)"), none.describe());
  const FlightLog c = calibrate_pitch(small_log(), none);
  DOUBLES_EQUAL(0.40, c.column("m_pitch")[0], 0.0);
  CHECK_EQUAL(std::string("0.86 m_pitch - 0.004 rad"), (PitchCalibration{0.86, -0.004}.describe()));
}

TEST(DiagnosePitchCalibration, RefusesValuesOutsideTheirRange) {
  CHECK_EQUAL(std::string("pitch calibration scale 3 outside [0.5, 2]"), message_of({3.0, 0.0}));
  CHECK_EQUAL(std::string("pitch calibration scale nan outside [0.5, 2]"), message_of({std::nan(""), 0.0}));
  CHECK_EQUAL(std::string("pitch calibration offset 0.5 rad outside [-0.2, 0.2] rad"), message_of({1.0, 0.5}));
  CHECK_EQUAL(std::string(""), message_of({0.5, -0.2}));  // the limits are allowed
}
