// SPDX-License-Identifier: Apache-2.0
// The prescribed-pitch stage's angle of attack (flow_forces_inline.hpp's
// small_angle_atan2) is glibc's atan2 to within 4 ulps where it sums its
// series (|v3| <= v1 / 4) and glibc's atan2 bit for bit everywhere else: the
// diagnosis's flights then differ from atan2's in the last bits only.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "flow_forces_inline.hpp"

namespace {

using glider::model::detail::small_angle_atan2;

// Distance in units in the last place between two finite doubles of one sign.
std::int64_t ulps_apart(double a, double b) {
  std::int64_t ia = 0, ib = 0;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  return ia > ib ? ia - ib : ib - ia;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_GROUP(SmallAngleAtan2){};

TEST(SmallAngleAtan2, WithinFourUlpsOfAtan2InsideTheSeriesRange) {
  std::int64_t worst = 0;
  int summed = 0;
  for (const double v1 : {1e-6, 0.03, 0.3, 1.0, 2.7}) {
    for (int i = -2000; i <= 2000; ++i) {
      if (i == 0) continue;  // t = 0: the sign of zero is checked below
      const double v3 = 0.25 * v1 * i / 2000.0;
      const double fast = small_angle_atan2(v3, v1);
      const double exact = std::atan2(v3, v1);
      CHECK(std::signbit(fast) == std::signbit(exact));
      const std::int64_t d = ulps_apart(fast, exact);
      worst = d > worst ? d : worst;
      ++summed;
    }
  }
  CHECK_EQUAL(20000, summed);
  CHECK(worst <= 4);
  CHECK(same_bits(small_angle_atan2(0.0, 0.5), std::atan2(0.0, 0.5)));
  CHECK(same_bits(small_angle_atan2(-0.0, 0.5), std::atan2(-0.0, 0.5)));
}

TEST(SmallAngleAtan2, Atan2BitForBitOutsideIt) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double cases[][2] = {{0.2501, 1.0}, {-0.26, 1.0}, {1.0, 1.0}, {0.1, -1.0}, {-0.1, -1.0},
                             {0.0, -1.0},   {1.0, 0.0},   {0.0, 0.0}, {3.0, 0.5},  {-0.0, -0.0}};
  for (const auto& c : cases) CHECK(same_bits(small_angle_atan2(c[0], c[1]), std::atan2(c[0], c[1])));
  CHECK(std::isnan(small_angle_atan2(nan, 1.0)));
  CHECK(std::isnan(small_angle_atan2(0.1, nan)));
}
