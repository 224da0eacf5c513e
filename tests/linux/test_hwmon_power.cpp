// SPDX-License-Identifier: Apache-2.0
// The hwmon power monitor on a directory shaped like /sys/class/hwmon (the
// ina2xx driver's files): found by name, voltage and current read, charge
// integrated, bad values rejected and counted.
#include <CppUTest/TestHarness.h>

#include <filesystem>
#include <fstream>

#include "glider/hal_linux/hwmon_power.hpp"

using namespace glider;

namespace {

class ManualClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override { return now; }
  hal::Micros now = 0;
};

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_GROUP(HwmonPower) {
  std::filesystem::path root = std::filesystem::path(GLIDER_TEST_OUTPUT_DIR) / "hwmon";
  ManualClock clock;
  hal_linux::PowerMonitorConfig config;

  void setup() override {
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root / "hwmon0");
    std::filesystem::create_directories(root / "hwmon3");
    write(root / "hwmon0" / "name", "cpu_thermal\n");
    write(root / "hwmon3" / "name", "ina219\n");
    write(root / "hwmon3" / "in1_input", "14800\n");
    write(root / "hwmon3" / "curr1_input", "2000\n");
    config.hwmon_root = root;
    config.charge_used_at_start_amphr = 10.0;
  }
};

TEST(HwmonPower, FoundByNameAndChargeIntegrated) {
  auto power = hal_linux::HwmonPowerMonitor::open(config, clock);
  STRCMP_EQUAL((root / "hwmon3").c_str(), power->device().c_str());
  hal::PowerSample sample = power->read();
  CHECK_TRUE(sample.valid);
  DOUBLES_EQUAL(14.8, sample.battery_voltage_v, 1e-12);
  DOUBLES_EQUAL(10.0, sample.charge_used_amphr, 1e-12);
  clock.now += 1800 * hal::kMicrosPerSecond;  // half an hour at 2 A, then 4 A
  write(root / "hwmon3" / "curr1_input", "4000\n");
  sample = power->read();
  DOUBLES_EQUAL(10.0 + 0.5 * (2.0 + 4.0) * 0.5, sample.charge_used_amphr, 1e-12);
}

TEST(HwmonPower, BadValuesAreRejectedAndCounted) {
  auto power = hal_linux::HwmonPowerMonitor::open(config, clock);
  write(root / "hwmon3" / "in1_input", "garbage\n");
  CHECK_FALSE(power->read().valid);
  write(root / "hwmon3" / "in1_input", "900\n");  // 0.9 V: not this battery
  CHECK_FALSE(power->read().valid);
  CHECK_EQUAL(1u, power->stats().errors);
  CHECK_EQUAL(1u, power->stats().out_of_range);
}

TEST(HwmonPower, AMissingDeviceIsAStartUpError) {
  config.hwmon_name = "ina226";
  try {
    hal_linux::HwmonPowerMonitor::open(config, clock);
    FAIL("opened a device that is not there");
  } catch (const std::runtime_error& error) {
    STRCMP_CONTAINS("no hwmon device named \"ina226\" in", error.what());
  }
}
