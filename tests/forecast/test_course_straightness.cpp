// SPDX-License-Identifier: Apache-2.0
// A dive's course straightness (course_straightness.hpp): the speed term
// divides a dive's net dead-reckoned track by it. Synthetic headings whose
// mean resultant is known, and from-glider files read as the shore has them.
#include <CppUTest/TestHarness.h>

#include <unistd.h>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

#include "glider/forecast/course_straightness.hpp"

namespace fc = glider::forecast;
namespace fs = std::filesystem;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Legs of (duration s, heading deg) sampled every `step_s` from t = 0.
std::vector<fc::HeadingSample> legs(const std::vector<std::pair<double, double>>& l, double step_s) {
  std::vector<fc::HeadingSample> out;
  double start = 0.0;
  for (const auto& [duration, heading] : l) {
    for (double t = start; t < start + duration; t += step_s) out.push_back({t, heading * kDeg});
    start += duration;
  }
  return out;
}

fs::path scratch(const char* name) {
  const fs::path d = fs::temp_directory_path() / ("glider_course_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d / "from-glider");
  return d;
}

}  // namespace

TEST_GROUP(CourseStraightness){};

TEST(CourseStraightness, AStraightCourseIsOne) {
  const auto s = legs({{9000.0, 242.0}}, 4.0);
  DOUBLES_EQUAL(1.0, fc::course_straightness(s, 0.0, 9000.0), 1e-12);
}

// The comet's dive 154: 1.9 h at 242 deg, then 0.82 h at 305 deg.
TEST(CourseStraightness, TwoLegsGiveTheirMeanResultant) {
  const double a = 1.9 * 3600.0, b = 0.82 * 3600.0;
  const auto s = legs({{a, 242.0}, {b, 305.0}}, 4.0);
  const std::complex<double> sum = a * std::polar(1.0, 242.0 * kDeg) + b * std::polar(1.0, 305.0 * kDeg);
  DOUBLES_EQUAL(std::abs(sum) / (a + b), fc::course_straightness(s, 0.0, a + b), 2e-3);
  // Two equal legs d apart: cos(d / 2).
  const auto even = legs({{3600.0, 10.0}, {3600.0, 100.0}}, 4.0);
  DOUBLES_EQUAL(std::cos(45.0 * kDeg), fc::course_straightness(even, 0.0, 7200.0), 2e-3);
  // Across north: 350 and 10 deg are 20 deg apart, not 340.
  const auto north = legs({{3600.0, 350.0}, {3600.0, 10.0}}, 4.0);
  DOUBLES_EQUAL(std::cos(10.0 * kDeg), fc::course_straightness(north, 0.0, 7200.0), 2e-3);
}

TEST(CourseStraightness, TooFewOrTooSparseSamplesSayNothing) {
  CHECK(std::isnan(fc::course_straightness(legs({{60.0, 10.0}}, 4.0), 0.0, 60.0)));  // 15 samples
  // 4 s samples over the first hour of a 3 h span: a third covered.
  CHECK(std::isnan(fc::course_straightness(legs({{3600.0, 10.0}}, 4.0), 0.0, 10800.0)));
  // Samples 120 s apart weigh nothing: the gaps are not the course.
  CHECK(std::isnan(fc::course_straightness(legs({{10800.0, 10.0}}, 120.0), 0.0, 10800.0)));
  CHECK(std::isnan(fc::course_straightness(legs({{3600.0, 10.0}}, 4.0), 100.0, 100.0)));
}

TEST(CourseStraightness, OnlyTheSpanCounts) {
  const auto s = legs({{3600.0, 0.0}, {3600.0, 180.0}}, 4.0);
  DOUBLES_EQUAL(1.0, fc::course_straightness(s, 0.0, 3596.0), 1e-12);
  DOUBLES_EQUAL(0.0, fc::course_straightness(s, 0.0, 7200.0), 2e-3);
}

TEST(CourseStraightness, HeadingsAreReadUnderWayFromWhatTheGliderSent) {
  const fs::path dir = scratch("read");
  {
    std::ofstream f(dir / "from-glider" / "a.sbd.csv");
    f << "m_present_time,m_depth,m_heading\n";
    f << "50.0,10.0,2.3\n";  // before `since`
    f << "100.0,0.5,1.0\n";  // at the surface: drifting, not the course
    f << "104.0,2.5,2.0\n";
    f << "108.0,,2.1\n";  // no depth that row
    f << "112.0,10.0,2.2\n";
  }
  {
    std::ofstream f(dir / "from-glider" / "b.tbd.csv");  // science: no heading, passed over
    f << "m_present_time,sci_water_temp\n1,2\n";
  }
  {
    std::ofstream f(dir / "from-glider" / "c.sbd.csv");  // names the columns, not a log
    f << "m_present_time,m_depth,m_heading\n3,2,x\n2,3,1\n";
  }
  std::vector<std::string> notes;
  const auto s = fc::logged_headings(dir, 60.0, notes);
  LONGS_EQUAL(2, s.size());
  DOUBLES_EQUAL(104.0, s[0].time_utc_s, 0.0);
  DOUBLES_EQUAL(2.2, s[1].heading_rad, 0.0);
  LONGS_EQUAL(1, notes.size());
  CHECK(notes[0].find("c.sbd.csv") != std::string::npos);
  fs::remove_all(dir.parent_path());
}
