// SPDX-License-Identifier: Apache-2.0
// The Linux serial modem driver on a pseudo-terminal: the AT driver's
// commands go out on the line, a "modem" on the other side answers, nothing
// blocks when the line is silent.
#include <CppUTest/TestHarness.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "glider/firmware/comms/at_driver.hpp"
#include "glider/hal_linux/serial_modem.hpp"

using namespace glider;

TEST_GROUP(CommsSerialModem) {
  int master = -1;
  std::string slave;
  void setup() override {
    master = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    CHECK(master >= 0);
    CHECK(grantpt(master) == 0 && unlockpt(master) == 0);
    slave = ptsname(master);
  }
  void teardown() override { ::close(master); }
  std::string from_glider() {
    std::string text;
    char buffer[256];
    for (int i = 0; i < 50; ++i) {
      const ssize_t n = ::read(master, buffer, sizeof buffer);
      if (n > 0) text.append(buffer, static_cast<std::size_t>(n));
      if (!text.empty() && text.back() == '\r') break;
      ::usleep(2000);
    }
    return text;
  }
};

TEST(CommsSerialModem, AtCommandOverAPty) {
  hal_linux::SerialModem modem({slave, 19200, false});
  CHECK(modem.carrier() == hal::Carrier::kUnknown);  // no DCD wire configured
  fw::comms::AtDriver at(modem);
  CHECK_TRUE(at.start("AT+CSQ", 0, 3'000'000));
  STRCMP_EQUAL("AT+CSQ\r", from_glider().c_str());
  CHECK(at.poll(500'000) == fw::comms::AtResult::kPending);  // silent line: returns at once
  const std::string reply = "\r\n+CSQ:3\r\n\r\nOK\r\n";
  CHECK(::write(master, reply.data(), reply.size()) == static_cast<ssize_t>(reply.size()));
  fw::comms::AtResult r = fw::comms::AtResult::kPending;
  for (int i = 0; i < 100 && r == fw::comms::AtResult::kPending; ++i) {
    r = at.poll(1'000'000);
    if (r == fw::comms::AtResult::kPending) ::usleep(2000);
  }
  CHECK(r == fw::comms::AtResult::kOk);
  LONGS_EQUAL(3, at.signal_quality());
}

TEST(CommsSerialModem, MissingDeviceNamed) {
  try {
    hal_linux::SerialModem modem({"/dev/no-such-modem", 19200, false});
    FAIL("opened a missing device");
  } catch (const std::runtime_error& e) {
    STRCMP_CONTAINS("/dev/no-such-modem", e.what());
  }
}
