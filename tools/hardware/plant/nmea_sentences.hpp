// SPDX-License-Identifier: Apache-2.0
#pragma once
// The sentences the plant's GPS receiver and compass send, in the form the
// firmware's decoders read (hal/linux/src/sentence_decoders.cpp): GGA with a
// fix or with quality 0 (no fix: antenna under water), RMC, and the
// TCM-class compass' $PTNTHPR (heading, pitch, roll in degrees, 0.1 deg
// resolution, status N = normal).
#include <string>

#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/gps.hpp"

namespace glider::plant {

// "$BODY*HH\r\n"
std::string nmea_sentence(const std::string& body);

// UTC time of day of the sentence, seconds.
std::string gga_fix(const hal::GpsFix& fix, double utc_s);
std::string gga_no_fix(double utc_s);
std::string rmc_fix(const hal::GpsFix& fix, double utc_s);
std::string ptnthpr(const hal::AttitudeSample& sample);

}  // namespace glider::plant
