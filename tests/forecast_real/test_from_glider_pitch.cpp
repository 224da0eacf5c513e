// SPDX-License-Identifier: Apache-2.0
// The forecast's from-glider pitch reader (speed_term.cpp, logged_glide_pitch) on a pitch outside
// +-90 deg (or in degrees): the file is named with its line, the value and the allowed range, and it
// is not used; the other files are. A `nan` is an empty field in the flight-log contract
// (docs/flight-log.md): a missing sample, skipped, not an error.
#include <CppUTest/TestHarness.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "glider/forecast/speed_term.hpp"

namespace fc = glider::forecast;
namespace fs = std::filesystem;

namespace {

// 400 rows of yos 3-50 m, 4 s apart, pitch -0.44 / +0.44 rad; row `bad_row` (0-based) gets `bad_pitch`.
// Line 1 is the header, so row r is on line r + 2.
void write_glides(const fs::path& path, int bad_row, const std::string& bad_pitch) {
  std::ofstream out(path);
  out << "m_present_time,m_depth,m_pitch\n";
  double t = 1000.0, z = 3.5;
  int sign = 1;
  for (int i = 0; i < 400; ++i) {
    out << t << "," << z << ",";
    if (i == bad_row) {
      out << bad_pitch;
    } else {
      out << (sign > 0 ? "-0.44" : "0.44");
    }
    out << "\n";
    t += 4.0;
    z += sign * 0.48;
    if (z > 50.0 || z < 3.5) sign = -sign;
  }
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_GROUP(ForecastFromGliderPitch){};

TEST(ForecastFromGliderPitch, APitchBeyondNinetyDegreesNamesTheFileAndLine) {
  const fs::path dir = fs::path(GLIDER_TEST_OUTPUT_DIR) / "forecast_from_glider_pitch";
  fs::remove_all(dir);
  fs::create_directories(dir / "from-glider");
  write_glides(dir / "from-glider" / "a_good.sbd.csv", -1, "");
  write_glides(dir / "from-glider" / "b_somersault.sbd.csv", 47, "1.9");  // 109 deg, line 49
  write_glides(dir / "from-glider" / "c_degrees.sbd.csv", 10, "-25.2");   // a pitch in degrees, line 12
  write_glides(dir / "from-glider" / "d_nan.sbd.csv", 3, "nan");          // empty: read
  std::vector<std::string> notes;
  int files = 0;
  const fc::GlidePitch g = fc::logged_glide_pitch(dir, 0.0, notes, files);
  for (const std::string& n : notes) UT_PRINT(n.c_str());
  LONGS_EQUAL(2, files);  // the good file and the one with a missing sample
  LONGS_EQUAL(2, static_cast<long>(notes.size()));
  CHECK(has(notes[0], "b_somersault.sbd.csv:49:m_pitch"));
  CHECK(has(notes[0], "1.9"));
  CHECK(has(notes[0], "[-1.5708, 1.5708]"));
  CHECK(has(notes[1], "c_degrees.sbd.csv:12:m_pitch"));
  CHECK(has(notes[1], "-25.2"));
  // The two read files' glides, none of the refused files' rows.
  CHECK(g.dive_n + g.climb_n > 600 && g.dive_n + g.climb_n < 800);
  DOUBLES_EQUAL(0.44, g.dive_rad(), 1e-9);
  DOUBLES_EQUAL(0.44, g.climb_rad(), 1e-9);
}
