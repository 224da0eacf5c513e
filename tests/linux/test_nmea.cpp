// SPDX-License-Identifier: Apache-2.0
// NMEA framing, checksums and the GPS and compass sentences: every kind of
// bad input is rejected and counted, never used.
#include <CppUTest/TestHarness.h>

#include <string>
#include <vector>

#include "glider/hal_linux/nmea.hpp"
#include "glider/hal_linux/sentence_decoders.hpp"
#include "glider/units.hpp"
#include "nmea_text.hpp"

using namespace glider;
using hal_linux::NmeaCheck;
using test::nmea;

namespace {

// The example GGA of the NMEA literature: 48 07.038' N, 11 31.000' E.
const std::string kGga = "GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,";
const std::string kRmc = "GPRMC,123520,A,4807.040,N,01131.010,E,022.4,084.4,230394,003.1,W";

std::vector<std::string> frame(const std::string& bytes, hal_linux::NmeaFramer& framer) {
  std::vector<std::string> lines;
  framer.feed(bytes, [&](std::string_view line) { lines.emplace_back(line); });
  return lines;
}

std::string without_line_end(std::string sentence) { return sentence.substr(0, sentence.size() - 2); }

}  // namespace

TEST_GROUP(Nmea){};

TEST(Nmea, ChecksumAndFields) {
  hal_linux::NmeaSentence s;
  const std::string line = without_line_end(nmea(kGga));  // the fields point into it
  CHECK(check_nmea(line, s) == NmeaCheck::kOk);
  CHECK_EQUAL(15u, s.count);
  STRCMP_EQUAL("GGA", std::string(s.formatter()).c_str());
  STRCMP_EQUAL("4807.038", std::string(s.field(2)).c_str());
  STRCMP_EQUAL("", std::string(s.field(14)).c_str());
  CHECK(check_nmea(without_line_end(nmea(kGga, true)), s) == NmeaCheck::kBadChecksum);
  CHECK(check_nmea("$" + kGga, s) == NmeaCheck::kNoChecksum);
  CHECK(check_nmea("$" + kGga + "*4", s) == NmeaCheck::kMalformed);
  CHECK(check_nmea("$" + kGga + "*ZZ", s) == NmeaCheck::kMalformed);
  CHECK(check_nmea(kGga, s) == NmeaCheck::kMalformed);  // no '$'
  std::string binary = without_line_end(nmea(kGga));
  binary[10] = '\x01';
  CHECK(check_nmea(binary, s) == NmeaCheck::kMalformed);
}

TEST(Nmea, FramerCutsAStreamInAnyPieces) {
  hal_linux::NmeaFramer framer;
  const std::string stream = "noise" + nmea(kGga) + nmea(kRmc);
  std::vector<std::string> lines;
  for (const char c : stream) {  // one byte at a time, as a slow port gives them
    for (auto& line : frame(std::string(1, c), framer)) lines.push_back(line);
  }
  CHECK_EQUAL(2u, lines.size());
  STRCMP_EQUAL(without_line_end(nmea(kRmc)).c_str(), lines[1].c_str());
  CHECK_EQUAL(5u, framer.stats().garbage_bytes);
}

TEST(Nmea, PartialAndOverlongSentencesAreDropped) {
  hal_linux::NmeaFramer framer;
  // A sentence cut short by the next '$' (a receiver reset mid-line) is not a line.
  const auto lines = frame("$GPGGA,1235" + nmea(kRmc) + "$" + std::string(100, 'A') + "\r\n", framer);
  CHECK_EQUAL(1u, lines.size());
  CHECK_EQUAL(1u, framer.stats().overlong);
  CHECK(framer.stats().garbage_bytes > 0);
}

TEST(Nmea, NumbersAndCoordinates) {
  DOUBLES_EQUAL(48.1173, *hal_linux::nmea_coordinate("4807.038", "N", 90.0), 1e-9);
  DOUBLES_EQUAL(-11.516666667, *hal_linux::nmea_coordinate("01131.000", "W", 180.0), 1e-9);
  CHECK_FALSE(hal_linux::nmea_coordinate("4861.000", "N", 90.0));  // 61 minutes
  CHECK_FALSE(hal_linux::nmea_coordinate("9107.038", "N", 90.0));  // beyond the pole
  CHECK_FALSE(hal_linux::nmea_coordinate("4807.038", "E", 90.0));  // a latitude is N or S
  CHECK_FALSE(hal_linux::nmea_coordinate("", "N", 90.0));
  CHECK_FALSE(hal_linux::nmea_number("1.2.3"));
  CHECK_FALSE(hal_linux::nmea_number("nan"));
  CHECK_FALSE(hal_linux::nmea_integer("08x"));
}

TEST_GROUP(NmeaGps) {
  hal_linux::NmeaGpsDecoder gps;
  void feed(const std::string& sentence, hal::Micros at) { gps.decode(without_line_end(sentence), at); }
};

TEST(NmeaGps, GgaGivesTheFixAndRmcRefreshesIt) {
  CHECK_FALSE(gps.latest().valid);
  feed(nmea(kGga), 100);
  const hal::GpsFix fix = gps.latest();
  CHECK_TRUE(fix.valid);
  DOUBLES_EQUAL(48.1173, fix.latitude_deg, 1e-9);
  DOUBLES_EQUAL(11.516666667, fix.longitude_deg, 1e-9);
  CHECK_EQUAL(1, fix.quality);
  CHECK_EQUAL(8, fix.satellites);
  DOUBLES_EQUAL(0.9, fix.hdop, 0.0);
  CHECK_EQUAL(100, fix.time_us);
  feed(nmea(kRmc), 200);
  DOUBLES_EQUAL(48.0 + 7.040 / 60.0, gps.latest().latitude_deg, 1e-9);
  CHECK_EQUAL(200, gps.latest().time_us);
  CHECK_EQUAL(2u, gps.stats().accepted);
}

TEST(NmeaGps, RmcAloneIsNoFix) {
  feed(nmea(kRmc), 1);
  CHECK_FALSE(gps.latest().valid);
}

TEST(NmeaGps, TheReceiverSayingNoFixWithdrawsTheFix) {
  feed(nmea(kGga), 1);
  feed(nmea("GPGGA,123521,,,,,0,00,99.9,,M,,M,,"), 2);
  CHECK_FALSE(gps.latest().valid);
  feed(nmea(kGga), 3);
  feed(nmea("GPRMC,123522,V,4807.040,N,01131.010,E,0.0,0.0,230394,,"), 4);
  CHECK_FALSE(gps.latest().valid);
  feed(nmea(kGga), 5);
  feed(nmea("GNRMC,123522,A,4807.040,N,01131.010,E,0.0,0.0,230394,,,N"), 6);  // FAA mode: no fix
  CHECK_FALSE(gps.latest().valid);
  feed(nmea("GPGGA,123519,4807.038,N,01131.000,E,6,08,0.9,545.4,M,46.9,M,,"), 7);  // dead reckoning
  CHECK_FALSE(gps.latest().valid);
  CHECK_EQUAL(4u, gps.stats().no_fix);
}

TEST(NmeaGps, BadSentencesAreCountedAndNeverUsed) {
  feed(nmea(kGga), 1);
  const hal::GpsFix good = gps.latest();
  feed(nmea("GPGGA,123519,4907.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,", true), 2);  // checksum
  feed("$GPGGA,123519,4907.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,\r\n", 3);         // no checksum
  feed(nmea("GPGGA,123519,49x7.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"), 4);        // not a number
  feed(nmea("GPGGA,123519,4907.038,N"), 5);                                              // truncated
  feed(nmea("GPGGA,123519,4907.038,N,01131.000,E,1,02,0.9,545.4,M,46.9,M,,"), 6);        // 2 satellites
  feed(nmea("GPGGA,123519,4907.038,N,01131.000,E,1,08,0.0,545.4,M,46.9,M,,"), 7);        // HDOP 0
  feed(nmea("GPGSV,3,1,11,03,03,111,00,04,15,270,00,06,01,010,00,13,06,292,00"), 8);     // not ours
  CHECK_TRUE(gps.latest().valid);
  DOUBLES_EQUAL(good.latitude_deg, gps.latest().latitude_deg, 0.0);
  CHECK_EQUAL(1, gps.latest().time_us);
  CHECK_EQUAL(1u, gps.stats().bad_checksum);
  CHECK_EQUAL(1u, gps.stats().no_checksum);
  CHECK_EQUAL(2u, gps.stats().malformed);
  CHECK_EQUAL(2u, gps.stats().implausible);
  CHECK_EQUAL(1u, gps.stats().other);
  CHECK_EQUAL(6u, gps.stats().rejected());
}

TEST_GROUP(Compass) {
  hal_linux::CompassDecoder compass;
  void feed(const std::string& sentence, hal::Micros at) { compass.decode(without_line_end(sentence), at); }
};

TEST(Compass, HeadingPitchRollInRadians) {
  feed(nmea("PTNTHPR,85.9,N,-0.9,N,0.8,N"), 42);
  const hal::AttitudeSample a = compass.latest();
  CHECK_TRUE(a.valid);
  DOUBLES_EQUAL(deg_to_rad(85.9), a.heading_rad, 1e-12);
  DOUBLES_EQUAL(deg_to_rad(-0.9), a.pitch_rad, 1e-12);
  DOUBLES_EQUAL(deg_to_rad(0.8), a.roll_rad, 1e-12);
  CHECK_EQUAL(42, a.time_us);
}

TEST(Compass, FlaggedOrBadReadingsAreRejected) {
  feed(nmea("PTNTHPR,85.9,N,-0.9,N,0.8,N"), 1);
  feed(nmea("PTNTHPR,10.0,P,-0.9,N,0.8,N"), 2);   // magnetic alarm
  feed(nmea("PTNTHPR,10.0,N,-0.9,N,0.8,O"), 3);   // roll out of range warning
  feed(nmea("PTNTHPR,360.0,N,-0.9,N,0.8,N"), 4);  // heading is [0, 360)
  feed(nmea("PTNTHPR,10.0,N,95.0,N,0.8,N"), 5);   // pitch beyond vertical
  feed(nmea("PTNTHPR,10.0,N,-0.9,N"), 6);         // fields missing
  feed(nmea("PTNTHPR,10.0,N,-0.9,N,0.8,N", true), 7);
  feed(nmea("HCHDT,10.0,T"), 8);
  DOUBLES_EQUAL(deg_to_rad(85.9), compass.latest().heading_rad, 1e-12);
  CHECK_EQUAL(1, compass.latest().time_us);
  CHECK_EQUAL(2u, compass.stats().no_fix);
  CHECK_EQUAL(2u, compass.stats().implausible);
  CHECK_EQUAL(1u, compass.stats().malformed);
  CHECK_EQUAL(1u, compass.stats().bad_checksum);
  CHECK_EQUAL(1u, compass.stats().other);
}
