// SPDX-License-Identifier: Apache-2.0
// The in-flight mission re-read (Control-F) and an uploaded mission file's
// install (zr) take nothing from the heap: every malloc, calloc, realloc and
// aligned allocation of the process is counted around each phase (with its
// bytes, the peak of live bytes and the wall time). The mission parser
// allocates; inside reload_arena::Scope its operator new is served from the
// arena reserved at start-up (docs/comms.md, "Control-F and the heap"). The
// parser's own appetite is printed too (the "heap:" rows, no Scope). Fails
// on the old code (385 mallocs per Control-F, 559 per install). A plain
// program (not CppUTest); exit 0 = pass, 77 = skipped (AddressSanitizer).
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>

#include "fake_hal.hpp"
#include "glider/firmware/app/mission_reload.hpp"
#include "glider/firmware/app/reload_arena.hpp"
#include "glider/firmware/mission_file/mi_document.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"

// Under AddressSanitizer the allocator is the sanitizer's: nothing to replace (skipped, 77).
#if !defined(__SANITIZE_ADDRESS__)
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* p);
}

namespace {

// Counted only while `on` (the phase being measured); the counters are plain
// (one thread).
struct Heap {
  bool on = false;
  unsigned long calls = 0;
  unsigned long long bytes = 0;
  long long live = 0;
  long long peak = 0;
  void took(void* p) {
    if (!on || p == nullptr) return;
    ++calls;
    const auto n = static_cast<long long>(malloc_usable_size(p));
    bytes += static_cast<unsigned long long>(n);
    live += n;
    peak = std::max(peak, live);
  }
  void gave(void* p) {
    if (on && p != nullptr) live -= static_cast<long long>(malloc_usable_size(p));
  }
};
Heap g_heap;

}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  void* p = __libc_malloc(size);
  g_heap.took(p);
  return p;
}
void* calloc(std::size_t n, std::size_t size) {
  void* p = __libc_calloc(n, size);
  g_heap.took(p);
  return p;
}
void* realloc(void* old, std::size_t size) {
  g_heap.gave(old);
  void* p = __libc_realloc(old, size);
  g_heap.took(p);
  return p;
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  void* p = __libc_memalign(alignment, size);
  g_heap.took(p);
  return p;
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  *out = __libc_memalign(alignment, size);
  g_heap.took(*out);
  return *out == nullptr ? 12 /* ENOMEM */ : 0;
}
void free(void* p) {
  g_heap.gave(p);
  __libc_free(p);
}
}
#endif

using namespace glider;
namespace fs = std::filesystem;

namespace {

int g_failures = 0;

void expect(bool ok, const char* what) {
  if (ok) return;
  std::printf("FAIL: %s\n", what);
  ++g_failures;
}

// Runs `phase` `runs` times and reports the last run (the first ones warm up
// what a process keeps: locale facets, stdio buffers). `no_malloc`: the
// phase must not call malloc at all (the firmware rule: no heap after init).
template <typename Phase>
void measure(const char* name, int runs, bool no_malloc, Phase phase) {
  bool ok = true;
  double wall_us = 0.0;
  for (int i = 0; i < runs; ++i) {
    const bool last = i == runs - 1;
    g_heap = Heap{};
    g_heap.on = last;
    const auto t0 = std::chrono::steady_clock::now();
    ok = phase();
    const auto t1 = std::chrono::steady_clock::now();
    g_heap.on = false;
    if (last) wall_us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    expect(fw::app::reload_arena::in_use() == 0 && fw::app::reload_arena::live_blocks() == 0,
           "the arena is empty after each phase");
  }
  std::printf("| %-46s | %6lu | %9llu | %8lld | %6lld | %9zu | %7.0f |\n", name, g_heap.calls, g_heap.bytes,
              g_heap.peak, g_heap.live, fw::app::reload_arena::high_water(), wall_us);
  expect(ok, name);
  // Every byte taken is given back (a re-read per surfacing for a month must not grow the heap).
  if (g_heap.live != 0) std::printf("FAIL: %s keeps %lld bytes\n", name, g_heap.live);
  g_failures += g_heap.live != 0 ? 1 : 0;
  if (no_malloc && g_heap.calls != 0) std::printf("FAIL: %s called malloc %lu times\n", name, g_heap.calls);
  g_failures += no_malloc && g_heap.calls != 0 ? 1 : 0;
}

// The allocator itself: alignment of every new form, the block freed last
// given back at once, a block still live at the Scope's end keeping the
// arena from being emptied (never overwritten), and outside a Scope the heap.
void check_arena_mechanics() {
  namespace arena = fw::app::reload_arena;
  expect(arena::reserve(64 * 1024), "a 64 KiB arena is reserved");
  {
    const arena::Scope scope;
    auto* plain = new char[3];
    auto* aligned = new (std::align_val_t{64}) double[5];
    expect(arena::detail::owns(plain) && arena::detail::owns(aligned), "a Scope's blocks are the arena's");
    expect(reinterpret_cast<std::uintptr_t>(plain) % __STDCPP_DEFAULT_NEW_ALIGNMENT__ == 0, "default alignment");
    expect(reinterpret_cast<std::uintptr_t>(aligned) % 64 == 0, "64-byte alignment");
    const std::size_t with_both = arena::in_use();
    operator delete[](aligned, std::align_val_t{64});
    expect(arena::in_use() < with_both, "the block freed last is given back at once");
    delete[] plain;
    expect(arena::in_use() == 0 && arena::live_blocks() == 0, "both freed: nothing in use");
  }
  int* kept = nullptr;
  {
    const arena::Scope scope;
    kept = new int(42);
  }
  expect(arena::live_blocks() == 1 && arena::in_use() > 0, "a block kept past its Scope keeps the arena");
  {
    const arena::Scope scope;
    int* other = new int(7);
    expect(other != kept && *kept == 42, "a kept block is not handed out again");
    delete other;
  }
  delete kept;
  expect(arena::live_blocks() == 0, "the kept block freed");
  {
    const arena::Scope scope;  // emptied at its end now that nothing is live
  }
  expect(arena::in_use() == 0, "the arena is emptied once nothing is live");
  auto* heap = new char[16];
  expect(!arena::detail::owns(heap), "outside a Scope: the heap");
  delete[] heap;
}

}  // namespace

int main() {
#if defined(__SANITIZE_ADDRESS__)
  std::printf("SKIPPED: malloc is AddressSanitizer's in this build\n");
  return 77;
#endif
  const fs::path dir = fs::path(GLIDER_TEST_OUTPUT_DIR) / "comms_reload_heap";
  fs::remove_all(dir);
  fs::copy(GLIDER_SOURCE_DIR "/boards/missions/box_current", dir, fs::copy_options::recursive);
  const fs::path mi = dir / "missions" / "box.mi";
  const fs::path goto_ma = dir / "mafiles" / "goto_l10.ma";
  std::ifstream shipped(goto_ma);
  const std::string good{std::istreambuf_iterator<char>(shipped), {}};
  std::string bad = good;
  bad.replace(bad.find("726.4381 5420.0452"), 18, "nan 5420.0452");
  const fs::path bad_ma = dir / "bad" / "goto_l10.ma";
  const fs::path upload = dir / "incoming" / "goto_l10.ma";
  fs::create_directories(bad_ma.parent_path());
  fs::create_directories(upload.parent_path());
  std::ofstream(upload) << good;

  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  const fw::app::FittedDevices fitted{
      .drop_weight = false, .leak_detector = true, .rudder = true, .power_monitor = true};
  const fw::app::VehicleSetup setup = sil::vehicle_setup(vehicle, fitted, 200.0, false, 1025.0);
  const fw::app::PreparedMission launch = fw::app::prepare_mission(mi, setup, {});
  expect(launch.config.has_value(), "the shipped mission loads at launch");
  if (!launch.config) return 1;
  test::FakeHal fake;
  fw::FlightSoftware flight(fake.hal(), *launch.config);
  fw::app::MissionFileReloader reloader(mi, setup, {});
  char refusal[512];
  constexpr int kRuns = 3;
  namespace arena = fw::app::reload_arena;
  expect(arena::serving(), "operator new is the arena's (glider_reload_arena_new linked)");

  std::printf(
      "box_current (box.mi + 3 .ma files), the last of %d runs of each; allocs, bytes, peak and kept are\n"
      "malloc's (every malloc of the process), arena: the reload arena's high water so far\n\n",
      kRuns);
  std::printf("| %-46s | %6s | %9s | %8s | %6s | %9s | %7s |\n", "phase", "allocs", "bytes", "peak", "kept", "arena",
              "wall us");
  std::printf("|%s|%s|%s|%s|%s|%s|%s|\n", std::string(48, '-').c_str(), std::string(8, '-').c_str(),
              std::string(11, '-').c_str(), std::string(10, '-').c_str(), std::string(8, '-').c_str(),
              std::string(11, '-').c_str(), std::string(9, '-').c_str());
  // The parser's own appetite, on the heap (no arena scope): what the arena has to hold.
  measure("heap: read_mi_file (.mi + .ma -> MiDocument)", kRuns, false, [&] {
    const fw::mission_file::MiDocument doc = fw::mission_file::read_mi_file(mi);
    return !doc.has_errors();
  });
  const fw::mission_file::MiDocument doc = fw::mission_file::read_mi_file(mi);
  measure("heap: load_mission (MiDocument -> config)", kRuns, false,
          [&] { return fw::mission_file::load_mission(doc, setup.vehicle, *launch.config).config.has_value(); });
  measure("heap: prepare_mission (both + checks)", kRuns, false,
          [&] { return fw::app::prepare_mission(mi, setup, {}).config.has_value(); });

  // Reserved at init, as glider-firmware does.
  expect(arena::reserve(fw::app::kReloadArenaBytes), "the arena is reserved");
  measure("Control-F: reread, taken", kRuns, true, [&] { return reloader.reread(flight, refusal, sizeof refusal); });
  const std::size_t reread_high_water = arena::high_water();
  std::ofstream(goto_ma) << bad;
  measure("Control-F: reread, refused (NaN waypoint)", kRuns, true, [&] {
    const bool taken = reloader.reread(flight, refusal, sizeof refusal);
    return !taken && std::strstr(refusal, "nan") != nullptr;  // no std::string: the test's own malloc
  });
  std::ofstream(goto_ma) << good;
  measure("zr: install of an uploaded goto_l10.ma", kRuns, true,
          [&] { return reloader.install(flight, upload.c_str(), refusal, sizeof refusal); });
  const std::size_t install_high_water = arena::high_water();
  // A month of surfacings, each with a Control-F: no malloc, the arena emptied every time.
  measure("Control-F x 200 (a month of surfacings)", 1, true, [&] {
    bool all = true;
    for (int i = 0; i < 200; ++i) all = reloader.reread(flight, refusal, sizeof refusal) && all;
    return all;
  });
  // An arena too small: a changed waypoint (a valid file) refused with the
  // reason, the plan untouched, the arena empty again; with room, taken.
  std::string moved = good;
  moved.replace(moved.find("726.4381 5420.0452"), 18, "726.9000 5420.0452");
  std::ofstream(goto_ma) << moved;
  const double lon_before = flight.plan().waypoints[1].lon_deg;
  expect(arena::reserve(4096), "a small arena is reserved");
  // Not malloc-free: the std::bad_alloc thrown is C++'s exception object (glibc's malloc).
  measure("Control-F in a 4 KiB arena: refused", 1, false, [&] {
    const bool taken = reloader.reread(flight, refusal, sizeof refusal);
    return !taken && std::strstr(refusal, "needs more than the reload arena's 4096 bytes") != nullptr;
  });
  std::printf("\nrefusal: %s\n", refusal);
  expect(flight.plan().waypoints[1].lon_deg == lon_before, "the plan is untouched by a refused re-read");
  expect(arena::reserve(fw::app::kReloadArenaBytes), "the arena is reserved again");
  expect(reloader.reread(flight, refusal, sizeof refusal), "the moved waypoint is taken with room");
  expect(flight.plan().waypoints[1].lon_deg != lon_before, "the moved waypoint is flown");
  std::printf("arena high water: re-read %zu bytes, install %zu bytes (of %zu reserved)\n", reread_high_water,
              install_high_water, fw::app::kReloadArenaBytes);
  check_arena_mechanics();
  std::printf("\n%s\n", g_failures == 0 ? "PASS" : "FAIL");
  return g_failures == 0 ? 0 : 1;
}
