// SPDX-License-Identifier: Apache-2.0
// The AT driver against a scripted modem: good replies, malformed ones, a
// modem that never answers, no signal, a busy or absent far end.
#include <CppUTest/TestHarness.h>

#include <string>

#include "glider/firmware/comms/at_driver.hpp"
#include "scripted_modem.hpp"

using namespace glider;
using fw::comms::AtDriver;
using fw::comms::AtResult;

namespace {

constexpr hal::Micros kSecond = 1'000'000;

// Polls once a second (the control cycle) until a result or `max_s`.
AtResult poll_until_result(AtDriver& at, hal::Micros& now, int max_s = 100) {
  for (int i = 0; i < max_s; ++i) {
    const AtResult r = at.poll(now);
    if (r != AtResult::kPending) return r;
    now += kSecond;
  }
  return AtResult::kPending;
}

}  // namespace

TEST_GROUP(CommsAtDriver) {
  test::ScriptedModem modem;
  AtDriver at{modem};
  hal::Micros now = 0;
};

TEST(CommsAtDriver, OkAndEchoedCommand) {
  modem.replies["AT"] = "AT\r\r\nOK\r\n";  // echo on (E1), then OK
  CHECK_TRUE(at.start("AT", now, 3 * kSecond));
  STRCMP_EQUAL("AT\r", modem.written.c_str());
  CHECK(poll_until_result(at, now) == AtResult::kOk);
  LONGS_EQUAL(0, at.malformed_lines());
}

TEST(CommsAtDriver, SignalQualityParsed) {
  modem.replies["AT+CSQ"] = "\r\n+CSQ:4\r\n\r\nOK\r\n";
  CHECK_TRUE(at.start("AT+CSQ", now, 3 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kOk);
  LONGS_EQUAL(4, at.signal_quality());
}

TEST(CommsAtDriver, NoSignalIsCsqZero) {
  modem.replies["AT+CSQ"] = "\r\n+CSQ:0\r\n\r\nOK\r\n";
  CHECK_TRUE(at.start("AT+CSQ", now, 3 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kOk);
  LONGS_EQUAL(0, at.signal_quality());
}

TEST(CommsAtDriver, MalformedRepliesAreCountedAndSkipped) {
  // Garbage, an impossible CSQ, a CSQ without digits, then the final code.
  modem.replies["AT+CSQ"] = "\r\n\x01\x7fGARBAGE\r\n+CSQ:9\r\n+CSQ:x\r\nCONNECT fast\r\nOK\r\n";
  CHECK_TRUE(at.start("AT+CSQ", now, 3 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kOk);
  LONGS_EQUAL(-1, at.signal_quality());
  LONGS_EQUAL(4, at.malformed_lines());
}

TEST(CommsAtDriver, OverlongLineIsCutAndCounted) {
  modem.replies["AT"] = "\r\n" + std::string(5000, 'X') + "\r\nOK\r\n";
  CHECK_TRUE(at.start("AT", now, 30 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kOk);  // 256 bytes a poll: it takes several cycles, then OK
  LONGS_EQUAL(1, at.overlong_lines());
}

TEST(CommsAtDriver, ModemThatNeverAnswersTimesOut) {
  CHECK_TRUE(at.start("AT", now, 3 * kSecond));
  CHECK(at.poll(now + 2 * kSecond) == AtResult::kPending);
  CHECK(at.poll(now + 3 * kSecond) == AtResult::kTimeout);
  LONGS_EQUAL(1, at.timeouts());
  CHECK_FALSE(at.busy());
}

TEST(CommsAtDriver, GarbageForeverStillTimesOut) {
  modem.replies["AT"] = std::string(200, '#');  // no line end ever
  CHECK_TRUE(at.start("AT", now, 3 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kTimeout);
}

TEST(CommsAtDriver, DialBusyAndNoCarrier) {
  modem.replies["ATD0088160000519"] = "\r\nBUSY\r\n";
  CHECK_TRUE(at.start("ATD0088160000519", now, 60 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kBusy);
  modem.replies["ATD0088160000520"] = "\r\nNO CARRIER\r\n";
  CHECK_TRUE(at.start("ATD0088160000520", now, 60 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kNoCarrier);
}

TEST(CommsAtDriver, ConnectKeepsTheCallsFirstBytes) {
  modem.replies["ATD1"] = "\r\nCONNECT 19200\r\nwhoru\r";
  CHECK_TRUE(at.start("ATD1", now, 60 * kSecond));
  CHECK(poll_until_result(at, now) == AtResult::kConnect);
  LONGS_EQUAL(19200, at.connect_rate());
  const auto data = at.data_after_connect();
  STRCMP_EQUAL("whoru\r", std::string(data.begin(), data.end()).c_str());
}

TEST(CommsAtDriver, EscapeIsSentRaw) {
  CHECK_TRUE(at.start("+++", now, 3 * kSecond, true));
  STRCMP_EQUAL("+++", modem.written.c_str());
}

TEST(CommsAtDriver, OverlongCommandRefused) {
  CHECK_FALSE(at.start(std::string(100, '9').c_str(), now, kSecond));
  CHECK_FALSE(at.busy());
}
