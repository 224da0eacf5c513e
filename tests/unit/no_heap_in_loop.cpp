// The firmware allocates nothing after start-up: every global operator new in
// this program is counted, and the flight software flies a whole scripted
// mission (dive, climbs, yos, surfacing) and an abort with the count
// unchanged. A plain program (not CppUTest, whose library replaces the
// allocation operators itself); exit status 0 = pass.
#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "fake_hal.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"

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
  fw::FlightSoftware flight(fake.hal(), config);
  const std::array<fw::TaskSlot, 1> table{{{"flight", &flight, 1, 500'000}}};
  fw::Executive executive(fake, table, 1'000'000);
  flight.attach_executive(&executive);
  fw::FlightSoftware aborting(fake.hal(), config);

  const unsigned long before = g_allocations.load();
  double depth = 0.5;
  int cycles = 0;
  for (; cycles < 5000 && !flight.complete(); ++cycles) {
    const bool diving = flight.phase() != fw::Phase::kClimb;
    depth += diving ? 0.5 : -0.5;
    fake.pump_cc = diving ? config.mission.dive_ballast_cc : config.mission.climb_ballast_cc;
    fake.sense(depth, diving ? -0.45 : 0.45);
    executive.step();
    fake.now += 1'000'000;
  }
  fake.sense(5.0, -0.4);
  aborting.run(fake.now);
  fake.pump_fault = true;
  aborting.run(fake.now + 1'000'000);
  const unsigned long during = g_allocations.load() - before;

  const bool flew = flight.complete() && flight.yos_completed() == config.mission.yos;
  const bool aborted = aborting.phase() == fw::Phase::kAbort;
  std::printf("cycles %d, mission complete %d, abort %d, heap allocations in the loop: %lu\n", cycles, flew,
              aborted, during);
  return flew && aborted && during == 0 ? 0 : 1;
}
