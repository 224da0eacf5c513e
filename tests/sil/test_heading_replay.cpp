// SPDX-License-Identifier: Apache-2.0
// The heading plane's loop closed with SIL (docs/heading-control.md, "The
// identified loops in SIL"): the loop glider-diagnose identifies on a real
// comet log, flown on the heading-hold mission, against the real heading by
// the same metric; and the compensated law on the same vehicle.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "heading_replay.hpp"

using namespace glider;

namespace {

heading_study::Replay replay(const char* log) {
  return heading_study::replay_log(GLIDER_SOURCE_DIR, std::string(GLIDER_SOURCE_DIR "/tests/data/real/") + log,
                                   GLIDER_SOURCE_DIR "/boards/vehicles/slocum_comet.toml", GLIDER_TEST_OUTPUT_DIR);
}

void print(const char* log, const heading_study::Replay& r) {
  const std::string text = std::string(log) + "\n  real        " + heading_study::format(r.real) + "\n  identified  " +
                           heading_study::format(r.sil_identified) + "\n  compensated " +
                           heading_study::format(r.sil_compensated);
  UT_PRINT(text.c_str());
}

}  // namespace

TEST_GROUP(SilHeadingReplay){};

// comet 2019 holds +17 / -12 deg under its -10 deg roll: the identified loop
// (no integral, gain ~0.4) holds the same to within a degree; the
// compensated law's per-direction integrator removes it.
TEST(SilHeadingReplay, Comet2019SteadyErrorWithinADegree) {
  const auto r = replay("comet-2019-222-02-154.csv");
  print("comet-2019-222-02-154", r);
  CHECK(std::abs(r.sil_identified.dive_error_deg - r.real.dive_error_deg) < 1.0);
  CHECK(std::abs(r.sil_identified.climb_error_deg - r.real.climb_error_deg) < 1.0);
  CHECK(std::abs(r.sil_compensated.dive_error_deg) < 1.0 && std::abs(r.sil_compensated.climb_error_deg) < 1.0);
  CHECK(r.sil_compensated.rms_error_deg < 0.3 * r.sil_identified.rms_error_deg);
}

// comet 2016 swings +-13 deg with a 109 s period: the identified loop swings
// with the period within 20 % and at least half the amplitude (57 % when
// this was written: part of the swing is still missing).
TEST(SilHeadingReplay, Comet2016SwingPeriodWithin20Percent) {
  const auto r = replay("comet-2016-174-05.csv");
  print("comet-2016-174-05", r);
  CHECK(std::abs(r.sil_identified.oscillation_period_s - r.real.oscillation_period_s) <
        0.2 * r.real.oscillation_period_s);
  CHECK(r.sil_identified.oscillation_amplitude_deg > 0.5 * r.real.oscillation_amplitude_deg);
  CHECK(r.sil_identified.oscillation_amplitude_deg < r.real.oscillation_amplitude_deg);
  CHECK(r.sil_compensated.rms_error_deg < r.sil_identified.rms_error_deg);
}
