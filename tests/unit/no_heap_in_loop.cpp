// SPDX-License-Identifier: Apache-2.0
// The firmware allocates nothing after start-up: every global operator new in
// this program is counted, and the flight software flies a whole scripted
// mission (dive, climbs, yos, surfacing), a navigated mission (GPS fixes,
// segments, waypoints) and an abort with the count unchanged, through the
// flight application both mains share, with the log rows' text formatted. A plain program (not CppUTest, whose library
// replaces the allocation operators itself); exit status 0 = pass.
#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "fake_hal.hpp"
#include "glider/firmware/app/flight_application.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/firmware/log/log_text.hpp"
#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_lz4_sink.hpp"
#include "glider/firmware/log/slocum_writer.hpp"

namespace {

std::atomic<unsigned long> g_allocations{0};

void* allocate(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

int main() {
  using namespace glider;
  test::FakeHal fake;
  fw::FlightSoftwareConfig config;
  // The flight application both mains fly (its task table and executive).
  fw::app::FlightApplication application(fake.hal(), config);
  const fw::FlightSoftware& flight = application.flight();
  fw::Executive& executive = application.executive();
  fw::FlightSoftware aborting(fake.hal(), config);
  // A navigated mission: two waypoints, segments of 2 yos, GPS at the surface.
  test::FakeHal nav_fake;
  fw::FlightSoftwareConfig nav_config;
  nav_config.mission.start_at_launch = false;
  nav_config.mission.yos = 2;
  nav_config.plan.waypoint_count = 2;
  nav_config.plan.waypoints[0] = {54.02, 7.0};
  nav_config.plan.waypoints[1] = {54.04, 7.0};  // both north: the fake only moves north
  nav_config.plan.legs_to_run = 2;
  nav_config.plan.waypoint_radius_m = 500.0;
  nav_config.plan.gps_wait_s = 60.0;
  fw::FlightSoftware navigated(nav_fake.hal(), nav_config);

  // The Slocum writer (.dbd/.sbd per segment, into a real directory) takes
  // the navigated mission's rows: file closes and opens at every surfacing.
  fw::SlocumDirectorySink slocum_dir(GLIDER_TEST_OUTPUT_DIR "/no_heap_slocum");
  fw::SlocumLogOptions slocum_options;
  slocum_options.sbd = fw::parse_slocum_list(fw::kDefaultSbdList, "built-in").selection;
  fw::SlocumLogger slocum(slocum_dir, slocum_options);
  // and their LZ4 forms (liblz4's block API, its state on the stack)
  fw::SlocumDirectorySink slocum_lz4_dir(GLIDER_TEST_OUTPUT_DIR "/no_heap_slocum_lz4");
  fw::SlocumLz4Sink slocum_lz4_sink(slocum_lz4_dir);
  fw::SlocumLogger slocum_lz4(slocum_lz4_sink, slocum_options);
  const bool slocum_started = slocum_dir.ok() && slocum.start() && slocum_lz4_dir.ok() && slocum_lz4.start();

  const unsigned long before = g_allocations.load();
  double depth = 0.5;
  int cycles = 0;
  std::size_t row_chars = 0;
  for (; cycles < 5000 && !flight.complete(); ++cycles) {
    const bool diving = flight.phase() != fw::Phase::kClimb;
    depth += diving ? 0.5 : -0.5;
    fake.pump_cc = diving ? config.mission.dive_ballast_cc : config.mission.climb_ballast_cc;
    fake.sense(depth, diving ? -0.45 : 0.45);
    executive.step();
    // The writers' row text (SIL CSV, target ring log) of this cycle's row.
    char row[fw::kLogFieldsMaxChars];
    row_chars += fw::format_log_fields(fake.last_row, fake.now, row, sizeof row);
    fake.now += 1'000'000;
  }
  // The navigated mission: the fake glider moves north at 0.3 m/s under
  // water and gets a fix where it is at the surface.
  double north_m = 0.0;
  double nav_depth = 0.5;
  int nav_cycles = 0;
  for (; nav_cycles < 100000 && !navigated.complete(); ++nav_cycles) {
    const fw::Phase phase = navigated.phase();
    const bool under_way = phase == fw::Phase::kDive || phase == fw::Phase::kClimb;
    if (under_way) {
      nav_depth += phase == fw::Phase::kDive ? 0.3 : -0.3;
      north_m += 0.3;
    } else {
      nav_depth = 0.2;
    }
    nav_fake.pump_cc =
        phase == fw::Phase::kDive ? nav_config.mission.dive_ballast_cc : nav_config.mission.climb_ballast_cc;
    nav_fake.depth = {nav_depth, nav_fake.now, true};
    nav_fake.attitude.sample = {phase == fw::Phase::kClimb ? 0.45 : -0.45, 0.0, 0.0, nav_fake.now, true};
    nav_fake.leak.sample.time_us = nav_fake.now;
    nav_fake.power.sample.time_us = nav_fake.now;
    nav_fake.gps.fix = {54.0 + north_m / 111195.0, 7.0, 1, 8, 1.0, nav_fake.now, !under_way};
    navigated.run(nav_fake.now);
    slocum.write(nav_fake.last_row, nav_fake.now);
    slocum_lz4.write(nav_fake.last_row, nav_fake.now);
    nav_fake.now += 1'000'000;
  }
  fake.sense(5.0, -0.4);
  aborting.run(fake.now);
  fake.pump_fault = true;
  aborting.run(fake.now + 1'000'000);
  const bool slocum_ok = slocum_started && slocum.finish() && slocum.segments() >= 2 &&
                         slocum.dbd().cycles_written == static_cast<std::uint64_t>(nav_cycles);
  const unsigned long during = g_allocations.load() - before;

  const bool flew = flight.complete() && flight.yos_completed() == config.mission.yos;
  const bool aborted = aborting.phase() == fw::Phase::kAbort;
  const bool navigated_ok = navigated.complete() && navigated.navigator().waypoints_reached() == 2;
  std::printf(
      "cycles %d, mission complete %d, abort %d, navigated mission complete %d (%d cycles, %d segments), "
      "heap allocations in the loop: %lu\n",
      cycles, flew, aborted, navigated_ok, nav_cycles, navigated.navigator().segments(), during);
  std::printf("log row text formatted: %zu characters\n", row_chars);
  std::printf("slocum files written: %d segments, %llu .dbd cycles, ok %d\n", slocum.segments(),
              static_cast<unsigned long long>(slocum.dbd().cycles_written), slocum_ok);
  return flew && aborted && navigated_ok && slocum_ok && during == 0 && row_chars > 0 ? 0 : 1;
}
