// SPDX-License-Identifier: Apache-2.0
// The project's GPIO driver against a real kernel: run inside the qemu guest
// of run_gpio_kernel_test.sh, on a gpio-sim bank whose lines are named like
// boards/gpio/gpio_sim.toml says. The simulated chip shows what the driver
// did (sim_gpioN/value) and takes the outside world's level (sim_gpioN/pull),
// so every check below goes through the kernel's GPIO character device.
// A plain static program (no CppUTest: it counts operator new itself, and
// must link statically for the initramfs); prints the pass marker last.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <sstream>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/gpio_board.hpp"
#include "glider/hal_linux/gpio_lines.hpp"

namespace {

std::atomic<unsigned long> g_allocations{0};
int g_failures = 0;
int g_checks = 0;

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

namespace {

using namespace glider;
using hal_linux::LineRole;

#define EXPECT(condition, what)                                                    \
  do {                                                                             \
    ++g_checks;                                                                    \
    if (!(condition)) {                                                            \
      ++g_failures;                                                                \
      std::printf("FAIL %s:%d: %s  [%s]\n", __FILE__, __LINE__, what, #condition); \
    }                                                                              \
  } while (0)

class GuestClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override { return ++now_; }

 private:
  mutable hal::Micros now_ = 0;
};

// Offsets of the named lines in the bank the guest's init script creates.
constexpr int kLeak = 0, kDropWeight = 1, kPumpEnable = 2, kValve = 3, kSlideFwd = 4;

struct Sim {
  std::string sysfs;  // /sys/devices/platform/gpio-sim.N/gpiochipM
  std::string attribute(int offset, const char* name) const {
    return sysfs + "/sim_gpio" + std::to_string(offset) + "/" + name;
  }
  std::string read(int offset, const char* name) const {
    std::ifstream in(attribute(offset, name));
    std::string value;
    in >> value;
    return value;
  }
  void pull(int offset, const char* direction) const {
    std::ofstream out(attribute(offset, "pull"));
    out << direction;
  }
};

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string substituted(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

std::string write_board(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/" + name;
  std::ofstream(path) << text;
  return path;
}

// The start-up error opening `board_text` gives (empty if it opens).
std::string open_error(const std::string& file_name, const std::string& board_text, const hal::Clock& clock) {
  try {
    const auto board = hal_linux::load_gpio_board(write_board(file_name, board_text));
    auto lines = hal_linux::GpioLines::open(board, clock);
  } catch (const config::ConfigError& error) {
    return error.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void outputs_drive_the_lines(hal_linux::GpioLines& lines, const Sim& sim) {
  EXPECT(sim.read(kDropWeight, "value") == "0", "drop weight starts off");
  EXPECT(sim.read(kValve, "value") == "1", "valve starts at its initial_active level");
  EXPECT(sim.read(kPumpEnable, "value") == "1", "active-low pump enable starts inactive = high");
  hal_linux::GpioOutput* drop = lines.output(LineRole::kDropWeight);
  hal_linux::GpioOutput* pump = lines.output(LineRole::kPumpEnable);
  EXPECT(drop != nullptr && pump != nullptr, "outputs exist");
  if (drop == nullptr || pump == nullptr) return;
  EXPECT(drop->set(true), "set drop weight");
  EXPECT(sim.read(kDropWeight, "value") == "1", "drop weight line high when active");
  EXPECT(pump->set(true), "set pump enable");
  EXPECT(sim.read(kPumpEnable, "value") == "0", "active-low pump enable line low when active");
  EXPECT(drop->set(false) && pump->set(false), "clear outputs");
  EXPECT(sim.read(kDropWeight, "value") == "0", "drop weight line low when inactive");
  EXPECT(sim.read(kPumpEnable, "value") == "1", "pump enable line high when inactive");
  EXPECT(drop->stats().writes == 2 && drop->stats().errors == 0, "output statistics");
}

void inputs_follow_the_pull(hal_linux::GpioLines& lines, const Sim& sim) {
  hal_linux::GpioInput* leak = lines.input(LineRole::kLeak);
  hal_linux::GpioInput* limit = lines.input(LineRole::kSlideLimitFwd);
  EXPECT(leak != nullptr && limit != nullptr, "inputs exist");
  if (leak == nullptr || limit == nullptr) return;
  // The board's bias reaches the (simulated) pin: the requests set the pulls.
  EXPECT(sim.read(kLeak, "pull") == "pull-up", "leak bias pull-up from the board file");
  EXPECT(sim.read(kSlideFwd, "pull") == "pull-down", "limit bias pull-down from the board file");
  hal::DigitalSample sample = leak->read();
  EXPECT(sample.valid && !sample.active, "dry: active-low leak line pulled up reads inactive");
  EXPECT(!limit->read().active, "limit switch open");
  sim.pull(kSlideFwd, "pull-up");
  sample = limit->read();
  EXPECT(sample.valid && sample.active, "limit switch follows its line high");
  sim.pull(kSlideFwd, "pull-down");
  EXPECT(!limit->read().active, "limit switch follows its line low");
  sim.pull(kLeak, "pull-down");
  sample = leak->read();
  EXPECT(sample.valid && sample.active, "wet: leak line low reads active");
  sim.pull(kLeak, "pull-up");
  EXPECT(!leak->read().active, "dry again");
}

void a_short_leak_pulse_is_latched_once(hal_linux::GpioLines& lines, const Sim& sim) {
  hal_linux::GpioInput* leak = lines.input(LineRole::kLeak);
  if (leak == nullptr) return;
  const auto before = leak->stats();
  sim.pull(kLeak, "pull-down");  // wet for less than a cycle ...
  sim.pull(kLeak, "pull-up");    // ... and dry again before the firmware reads
  const hal::DigitalSample sample = leak->read();
  EXPECT(sample.valid && sample.active, "the pulse is reported although the line is back");
  EXPECT(leak->stats().edge_events - before.edge_events == 2, "both edges delivered by the kernel");
  EXPECT(leak->stats().latched_activations - before.latched_activations == 1, "counted as latched");
  EXPECT(!leak->read().active, "reported once, then the level again");
}

void the_loop_path_does_not_allocate(hal_linux::GpioLines& lines, const Sim& sim) {
  hal_linux::GpioInput* leak = lines.input(LineRole::kLeak);
  hal_linux::GpioOutput* drop = lines.output(LineRole::kDropWeight);
  if (leak == nullptr || drop == nullptr) return;
  sim.pull(kLeak, "pull-down");  // an event pending, so the drain path runs too
  sim.pull(kLeak, "pull-up");
  const unsigned long before = g_allocations.load();
  for (int cycle = 0; cycle < 100; ++cycle) leak->read();
  const unsigned long reads = g_allocations.load() - before;
  for (int cycle = 0; cycle < 100; ++cycle) drop->set(cycle % 2 == 0);
  const unsigned long sets = g_allocations.load() - before - reads;
  drop->set(false);
  std::printf("operator new calls: %lu in 100 read(), %lu in 100 set()\n", reads, sets);
  EXPECT(reads == 0, "read() allocates nothing");
  EXPECT(sets == 0, "set() allocates nothing");
}

void start_up_errors_name_the_board_file_and_line(const std::string& board_text, const std::string& chip,
                                                  const hal::Clock& clock) {
  std::string error = open_error("missing_line.toml", substituted(board_text, "\"VALVE\"", "\"NO_SUCH_LINE\""), clock);
  std::printf("missing line -> %s\n", error.c_str());
  EXPECT(contains(error, "/tmp/missing_line.toml:") && contains(error, "lines.valve") &&
             contains(error, "has no line named \"NO_SUCH_LINE\""),
         "a missing line names the file, its [lines.valve] table and the line");
  error = open_error("missing_chip.toml", substituted(board_text, "\"" + chip + "\"", "\"gpiochip99\""), clock);
  std::printf("missing chip -> %s\n", error.c_str());
  EXPECT(contains(error, "/tmp/missing_chip.toml:") && contains(error, "no GPIO chip \"gpiochip99\""),
         "a missing chip names the file and the chip");
}

void a_line_in_use_is_refused(const std::string& board_text, const hal::Clock& clock) {
  const std::string error = open_error("second_user.toml", board_text, clock);  // the first set is still open
  std::printf("line in use -> %s\n", error.c_str());
  EXPECT(contains(error, "/tmp/second_user.toml:") && contains(error, "in use by \"glider\""),
         "a second request of a held line is refused at start-up, naming the holder");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s BOARD_TEMPLATE.toml SIM_CHIP_NAME SIM_SYSFS_DIR\n", argv[0]);
    return 2;
  }
  const std::string chip = argv[2];
  const Sim sim{argv[3]};
  const std::string board_text = substituted(read_text(argv[1]), "@SIM_CHIP@", chip);
  GuestClock clock;
  try {
    const auto board = hal_linux::load_gpio_board(write_board("gpio_sim.toml", board_text));
    {
      auto lines = hal_linux::GpioLines::open(board, clock);
      outputs_drive_the_lines(*lines, sim);
      inputs_follow_the_pull(*lines, sim);
      a_short_leak_pulse_is_latched_once(*lines, sim);
      the_loop_path_does_not_allocate(*lines, sim);
      a_line_in_use_is_refused(board_text, clock);
    }  // released: the error cases below open the board's lines again
    start_up_errors_name_the_board_file_and_line(board_text, chip, clock);
  } catch (const std::exception& error) {
    std::printf("FAIL: unexpected exception: %s\n", error.what());
    ++g_failures;
  }
  std::printf("%d checks, %d failed\n", g_checks, g_failures);
  if (g_failures == 0) std::printf("GPIO-KERNEL-TESTS PASS\n");
  return g_failures == 0 ? 0 : 1;
}
