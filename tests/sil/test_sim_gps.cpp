// SPDX-License-Identifier: Apache-2.0
// The simulated GPS receiver (sil/sim_peripherals.hpp).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "glider/model/environment.hpp"
#include "glider/model/simulator.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/fault_injection.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/sim_clock.hpp"
#include "glider/sil/sim_peripherals.hpp"

using namespace glider;

namespace {

constexpr std::uint64_t kSeed = 11;

// Reads a receiver every `read_period_s` through three surfacings (80 s at
// the surface, then 20 s at depth, for each); returns the time of the first
// fix of each surfacing, in seconds.
std::vector<double> first_fix_times(double read_period_s) {
  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  model::GliderSimulator sim(vehicle, model::Environment{});
  sil::SimClock clock;
  const sil::FaultInjection faults{};
  sil::SimGps gps(sim, clock, faults, sil::GpsModel{}, sil::derived_seed(kSeed, sil::kGpsNoiseStream),
                  sil::derived_seed(kSeed, sil::kGpsAcquisitionStream));
  const auto period_us = static_cast<hal::Micros>(std::llround(read_period_s * 1e6));
  std::vector<double> firsts;
  for (int surfacing = 0; surfacing < 3; ++surfacing) {
    sim.reset_at_surface(0.0, 0.0);
    const hal::Micros surfaced_us = clock.now_us();
    bool have_first = false;
    for (; clock.now_us() < surfaced_us + 80'000'000; clock.advance(period_us)) {
      const hal::GpsFix fix = gps.read();
      if (!have_first && fix.valid && fix.time_us >= surfaced_us) {
        firsts.push_back(hal::to_seconds(fix.time_us - surfaced_us));
        have_first = true;
      }
    }
    sim.reset_at_depth(10.0, 0.0, 0.0);
    for (const hal::Micros dived_us = clock.now_us(); clock.now_us() < dived_us + 20'000'000;
         clock.advance(period_us)) {
      gps.read();
    }
  }
  return firsts;
}

}  // namespace

TEST_GROUP(SimGps){};

// A HIL plant reads the receiver at other instants than SIL, so a surfacing
// may produce one fix more or less; the next surfacing's wait must not
// change with it (hil.waypoint compares the mission's end, which waits for a
// fix, between the two).
TEST(SimGps, TimeToFirstFixDoesNotDependOnHowOftenTheReceiverIsRead) {
  const std::vector<double> often = first_fix_times(0.5);
  const std::vector<double> seldom = first_fix_times(2.5);
  LONGS_EQUAL(3, often.size());
  LONGS_EQUAL(3, seldom.size());
  for (std::size_t i = 0; i < often.size(); ++i) {
    // Within the model's range, and the same wait to one read of the slower reader.
    CHECK(often[i] >= sil::GpsModel{}.time_to_first_fix_min_s &&
          often[i] <= sil::GpsModel{}.time_to_first_fix_max_s + 0.5);
    DOUBLES_EQUAL(often[i], seldom[i], 2.5);
  }
  // The draws differ between surfacings (a fixed wait would pass the above too).
  CHECK(std::fabs(often[0] - often[1]) > 1.0 || std::fabs(often[1] - often[2]) > 1.0);
}
