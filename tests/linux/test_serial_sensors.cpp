// SPDX-License-Identifier: Apache-2.0
// The GPS and compass drivers on real pseudo-terminals (a socat pty pair
// stands for the serial cable): a writer feeds good, bad and partial
// sentences in pieces; the driver reads without blocking, uses the good
// ones, counts the rest and marks a silent sensor stale.
#include <CppUTest/TestHarness.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "../modbus/child_process.hpp"
#include "glider/hal_linux/serial_sensors.hpp"
#include "glider/units.hpp"
#include "nmea_text.hpp"

using namespace glider;
using test::nmea;

namespace {

class ManualClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override { return now; }
  hal::Micros now = 1'000'000;
};

// The sensor's end of the cable.
class Writer {
 public:
  explicit Writer(const std::string& device) : fd_(::open(device.c_str(), O_WRONLY | O_NOCTTY)) {}
  ~Writer() { ::close(fd_); }
  bool write(const std::string& bytes) { return ::write(fd_, bytes.data(), bytes.size()) == ssize_t(bytes.size()); }

 private:
  int fd_;
};

constexpr hal::Micros kStaleAfterUs = 3'000'000;

// Reads once per "cycle" until `done` holds (socat forwards asynchronously).
// The 20 s bound only stops a hang: the wait ends on the event, so a loaded
// machine (socat starved for seconds under a parallel ctest) cannot fail it.
template <typename Sensor, typename Done>
auto read_until(Sensor& sensor, Done&& done) {
  auto value = sensor.read();
  for (int i = 0; i < 2000 && !done(value); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    value = sensor.read();
  }
  return value;
}

}  // namespace

TEST_GROUP(SerialSensors) { ManualClock clock; };

TEST(SerialSensors, GpsOverAPtyUsesOnlyGoodSentences) {
  test::PtyPair cable;
  hal_linux::NmeaGpsReceiver gps(hal_linux::SerialPort::open(cable.glider_end(), 9600), clock, kStaleAfterUs);
  Writer receiver(cable.device_end());

  // Nothing sent: read() returns at once with no fix (it must not wait).
  const auto start = std::chrono::steady_clock::now();
  CHECK_FALSE(gps.read().valid);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::milliseconds(100));

  const std::string good = nmea("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,");
  const std::string bad_checksum = nmea("GPGGA,123519,5807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,", true);
  const std::string partial = "$GPGGA,123520,5907.0";
  const std::string noise = "\x13\x7f garbage " + bad_checksum + partial;
  CHECK_TRUE(receiver.write(noise));
  CHECK_TRUE(receiver.write(good.substr(0, 20)));  // a sentence split across two reads
  // Wait until the driver has read every byte written so far (not a fixed time).
  const auto first =
      read_until(gps, [&](const hal::GpsFix&) { return gps.stream().port_stats().bytes >= noise.size() + 20; });
  CHECK_EQUAL(noise.size() + 20, gps.stream().port_stats().bytes);
  CHECK_FALSE(first.valid);
  CHECK_TRUE(receiver.write(good.substr(20)));
  const hal::GpsFix fix = read_until(gps, [](const hal::GpsFix& f) { return f.valid; });
  CHECK_TRUE(fix.valid);
  DOUBLES_EQUAL(48.1173, fix.latitude_deg, 1e-9);
  CHECK_EQUAL(clock.now, fix.time_us);
  CHECK_EQUAL(1u, gps.stats().bad_checksum);
  CHECK_EQUAL(1u, gps.stats().accepted);
  CHECK(gps.stream().framer_stats().garbage_bytes >= 10);  // the noise and the cut-short sentence

  // The antenna goes under: no more sentences, the fix goes stale.
  clock.now += kStaleAfterUs + 1;
  CHECK_FALSE(gps.read().valid);
  CHECK_EQUAL(1u, gps.stale_reads());
}

TEST(SerialSensors, CompassOverAPty) {
  test::PtyPair cable;
  hal_linux::SerialCompass compass(hal_linux::SerialPort::open(cable.glider_end(), 19200), clock, kStaleAfterUs);
  Writer sensor(cable.device_end());
  CHECK_TRUE(sensor.write(nmea("PTNTHPR,85.9,N,-0.9,N,0.8,N") + nmea("PTNTHPR,90.0,P,-0.9,N,0.8,N")));
  const hal::AttitudeSample a = read_until(compass, [](const hal::AttitudeSample& s) { return s.valid; });
  CHECK_TRUE(a.valid);
  DOUBLES_EQUAL(deg_to_rad(85.9), a.heading_rad, 1e-12);
  read_until(compass, [&](const hal::AttitudeSample&) { return compass.stats().no_fix == 1; });
  CHECK_EQUAL(1u, compass.stats().no_fix);  // the alarm-flagged reading was not used
  DOUBLES_EQUAL(deg_to_rad(85.9), compass.read().heading_rad, 1e-12);
  clock.now += kStaleAfterUs + 1;
  CHECK_FALSE(compass.read().valid);
}

TEST(SerialSensors, ABabblingDeviceCannotHoldTheLoop) {
  test::PtyPair cable;
  hal_linux::SerialCompass compass(hal_linux::SerialPort::open(cable.glider_end(), 115200), clock, kStaleAfterUs);
  Writer sensor(cable.device_end());
  CHECK_TRUE(sensor.write(std::string(3 * hal_linux::NmeaSerialStream::kMaxBytesPerPoll, 'x')));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // lets socat forward most of it
  // The first read that finds bytes must take no more than one poll's worth.
  read_until(compass, [&](const hal::AttitudeSample&) { return compass.stream().port_stats().bytes > 0; });
  CHECK(compass.stream().port_stats().bytes <= hal_linux::NmeaSerialStream::kMaxBytesPerPoll);
  CHECK(compass.stream().port_stats().bytes > 0);
}

TEST(SerialSensors, AMissingDeviceIsAStartUpError) {
  try {
    hal_linux::SerialPort::open("/dev/does-not-exist", 9600);
    FAIL("opened a missing device");
  } catch (const std::runtime_error& error) {
    STRCMP_CONTAINS("/dev/does-not-exist: cannot open: No such file or directory", error.what());
  }
  try {
    hal_linux::SerialPort::open("/dev/null", 9600);
    FAIL("took /dev/null for a serial port");
  } catch (const std::runtime_error& error) {
    STRCMP_CONTAINS("/dev/null: not a serial port", error.what());
  }
}
