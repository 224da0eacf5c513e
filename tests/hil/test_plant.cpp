// SPDX-License-Identifier: Apache-2.0
// The plant's pieces against the firmware's own readers: what the plant's
// GPS and compass send is what the target's decoders accept, to the
// resolution of the sentence; the fault names and times parse as documented.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <string>

#include "glider/hal_linux/sentence_decoders.hpp"
#include "glider/units.hpp"
#include "nmea_sentences.hpp"
#include "plant_faults.hpp"

using namespace glider;

namespace {

std::string line_of(const std::string& sentence) {
  return sentence.substr(0, sentence.find('\r'));  // the framer hands the decoder a line without CR LF
}

}  // namespace

TEST_GROUP(PlantSentences){};

TEST(PlantSentences, GgaFixReadsBackToTwoCentimetres) {
  const hal::GpsFix fix{54.3161123, -7.4098456, 1, 8, 1.0, 0, true};
  hal_linux::NmeaGpsDecoder decoder;
  decoder.decode(line_of(plant::gga_fix(fix, 45296.5)), 123);
  const hal::GpsFix& read = decoder.latest();
  CHECK(read.valid);
  CHECK_EQUAL(123, read.time_us);
  // 1e-5 minute of arc: 1.9 cm of latitude.
  DOUBLES_EQUAL(fix.latitude_deg, read.latitude_deg, 2e-7);
  DOUBLES_EQUAL(fix.longitude_deg, read.longitude_deg, 2e-7);
  CHECK_EQUAL(8, read.satellites);
}

TEST(PlantSentences, RmcRefreshesTheFixAndNoFixLosesIt) {
  const hal::GpsFix fix{54.3161, 7.4098, 1, 8, 1.0, 0, true};
  hal_linux::NmeaGpsDecoder decoder;
  decoder.decode(line_of(plant::gga_fix(fix, 100.0)), 1);
  decoder.decode(line_of(plant::rmc_fix(fix, 101.0)), 2);
  CHECK(decoder.latest().valid);
  CHECK_EQUAL(2, decoder.latest().time_us);
  decoder.decode(line_of(plant::gga_no_fix(102.0)), 3);
  CHECK_FALSE(decoder.latest().valid);
  CHECK_EQUAL(2u, decoder.stats().accepted);
  CHECK_EQUAL(1u, decoder.stats().no_fix);
}

TEST(PlantSentences, CompassHeadingNeverReads360) {
  hal_linux::CompassDecoder decoder;
  const hal::AttitudeSample sample{deg_to_rad(-25.96), deg_to_rad(1.04), deg_to_rad(359.97), 0, true};
  decoder.decode(line_of(plant::ptnthpr(sample)), 7);
  const hal::AttitudeSample& read = decoder.latest();
  CHECK(read.valid);
  DOUBLES_EQUAL(0.0, read.heading_rad, 1e-12);  // 359.97 rounds to 360.0, which is north
  DOUBLES_EQUAL(deg_to_rad(-26.0), read.pitch_rad, 1e-9);
  DOUBLES_EQUAL(deg_to_rad(1.0), read.roll_rad, 1e-9);
}

TEST_GROUP(PlantFaults){};

TEST(PlantFaults, NamesTimesAndRefusals) {
  std::string error;
  const auto stall = plant::parse_plant_fault("pump_stall@2m", error);
  CHECK(stall.has_value());
  CHECK(stall->kind == plant::PlantFaultKind::kPumpStall);
  DOUBLES_EQUAL(120.0, stall->at_s, 0.0);
  CHECK_FALSE(plant::parse_plant_fault("depth_silent@nan", error).has_value());
  CHECK_FALSE(plant::parse_plant_fault("depth_silent@1e300", error).has_value());
  CHECK_FALSE(plant::parse_plant_fault("depth_silent@-5", error).has_value());
  CHECK_FALSE(plant::parse_plant_fault("pump_jam@5", error).has_value());
  CHECK(error.find("pump_stall") != std::string::npos);  // the known names are listed
  CHECK_FALSE(plant::parse_plant_fault("leak@5", error).has_value());
  CHECK(error.find("GPIO") != std::string::npos);  // and why the leak is not a plant fault
}
