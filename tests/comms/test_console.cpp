// SPDX-License-Identifier: Apache-2.0
// The GliderDOS console subset: echo, control keys, put/get with refusals
// from the value-limits table, send with globs and -num=, bad input.
#include <CppUTest/TestHarness.h>

#include <string>
#include <vector>

#include "glider/firmware/comms/console.hpp"

using namespace glider;
using namespace glider::fw::comms;

namespace {

struct FakeActions final : ConsoleActions {
  bool running = true;
  int ended = 0, resumed = 0, reread = 0, reports = 0, resets = 0, transfers = 0, runs = 0;
  double callback_min = 0.0;
  const char* vehicle_name() const override { return "unit_345"; }
  bool mission_running() const override { return running; }
  void end_mission() override {
    ++ended;
    running = false;
  }
  void resume_mission() override { ++resumed; }
  void reread_mafiles() override { ++reread; }
  void device_report() override { ++reports; }
  void callback(double minutes) override { callback_min = minutes; }
  bool run_mission() override {
    ++runs;
    running = true;
    return true;
  }
  void exit_reset() override { ++resets; }
  void transfer_started() override { ++transfers; }
};

// The engine's side as the tests see it: which files were asked for.
struct FakeTransfer final : FileTransfer {
  std::vector<std::string> files{"unit_345-2026-100-0-0.sbd", "unit_345-2026-100-0-0.tbd", "unit_345-2026-100-0-1.sbd",
                                 "unit_345-2026-100-0-2.sbd", "unit_345-2026-100-0-2.tbd"};
  std::vector<std::string> sent;
  int receives = 0;
  std::size_t file_count() const override { return files.size(); }
  const char* file_name(std::size_t i) const override { return files[i].c_str(); }
  bool begin_send(std::span<const FileName> names) override {
    for (const FileName& f : names) sent.emplace_back(f.text);
    return true;
  }
  bool begin_receive() override { return ++receives > 0; }
  TransferProgress poll(hal::Micros, ByteStream&) override { return {TransferState::kDone, 1, 0, 10}; }
  void cancel() override {}
};

std::string drain(DialogQueue& q) {
  std::string text;
  while (!q.empty()) {
    const auto f = q.front();
    text.append(reinterpret_cast<const char*>(f.data()), f.size());
    q.consume(f.size());
  }
  return text;
}

}  // namespace

TEST_GROUP(CommsConsole) {
  FakeActions actions;
  FakeTransfer transfer;
  ParameterTable parameters;
  DialogQueue out;
  double wait_s = 300.0;
  Console* console = nullptr;
  void setup() override {
    static constexpr config::Range kWait{0.0, 86400.0, "s"};
    CHECK_TRUE(parameters.add("u_keystroke_wait_time", kWait, &wait_s));
    console = new Console(actions, parameters, &transfer, out);
  }
  void teardown() override { delete console; }
  std::string type(const std::string& text) {
    console->feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    return drain(out);
  }
};

TEST(CommsConsole, WhoruEchoesAndAnswers) {
  STRCMP_EQUAL("whoru\r\nVehicle Name: unit_345\r\n", type("whoru\r").c_str());
}

TEST(CommsConsole, ControlKeysShownAtTheHeadOfTheNextLine) {
  STRCMP_EQUAL("ab\r\n^C\r\n", type("ab\x03").c_str());
  LONGS_EQUAL(1, actions.ended);
  STRCMP_EQUAL("^R\r\n", type("\x12").c_str());
  STRCMP_EQUAL("^F\r\n^W\r\n", type("\x06\x17").c_str());
  LONGS_EQUAL(1, actions.resumed);
  LONGS_EQUAL(1, actions.reread);
  LONGS_EQUAL(1, actions.reports);
}

TEST(CommsConsole, PutNeedsBangWhileTheMissionRuns) {
  const std::string reply = type("put u_keystroke_wait_time 60\r");
  CHECK(reply.find("ERROR: a mission is running: type !put") != std::string::npos);
  DOUBLES_EQUAL(300.0, wait_s, 0.0);
  STRCMP_CONTAINS("u_keystroke_wait_time(s)=60", type("!put u_keystroke_wait_time 60\r").c_str());
  DOUBLES_EQUAL(60.0, wait_s, 0.0);
  STRCMP_CONTAINS("u_keystroke_wait_time(s)=60", type("!get u_keystroke_wait_time\r").c_str());
}

TEST(CommsConsole, PutRefusesNanAndOutOfRangeNamingKeyValueAndRange) {
  STRCMP_CONTAINS("ERROR: put refused: u_keystroke_wait_time value nan is outside the allowed range [0, 86400] s",
                  type("!put u_keystroke_wait_time nan\r").c_str());
  STRCMP_CONTAINS("ERROR: put refused: u_keystroke_wait_time value -5 is outside the allowed range [0, 86400] s",
                  type("!put u_keystroke_wait_time -5\r").c_str());
  STRCMP_CONTAINS("value 1e999 is outside", type("!put u_keystroke_wait_time 1e999\r").c_str());
  STRCMP_CONTAINS("value 12abc is outside", type("!put u_keystroke_wait_time 12abc\r").c_str());
  STRCMP_CONTAINS("u_nothing is not a u_ parameter", type("!put u_nothing 1\r").c_str());
  DOUBLES_EQUAL(300.0, wait_s, 0.0);
  actions.running = false;  // at GliderDOS no ! is needed
  STRCMP_CONTAINS("=10", type("put u_keystroke_wait_time 10\r").c_str());
}

TEST(CommsConsole, UnknownCommandRefused) {
  STRCMP_CONTAINS("ERROR: unknown command: format", type("format c:\r").c_str());
  LONGS_EQUAL(1, console->stats().refused);
}

TEST(CommsConsole, OverlongLineAndGarbageNeverExecute) {
  const std::string reply = type(std::string(5000, 'w') + "\r");
  STRCMP_CONTAINS("ERROR: line too long (5000 characters, at most 128): ignored", reply.c_str());
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 131 + 7) % 256));
  type(garbage);
  type("\r");
  CHECK(console->stats().ignored_bytes > 0);
  STRCMP_EQUAL("whoru\r\nVehicle Name: unit_345\r\n", type("whoru\r").c_str());  // still works
}

TEST(CommsConsole, SendPicksTheNewestMatchesOldestFirst) {
  STRCMP_CONTAINS("Sending 2 file(s)", type("s -num=2 *.sbd\r").c_str());
  LONGS_EQUAL(2, transfer.sent.size());
  STRCMP_EQUAL("unit_345-2026-100-0-1.sbd", transfer.sent[0].c_str());
  STRCMP_EQUAL("unit_345-2026-100-0-2.sbd", transfer.sent[1].c_str());
  transfer.sent.clear();
  type("send *-0-2.* *-0-0.tbd\r");
  LONGS_EQUAL(3, transfer.sent.size());
  STRCMP_EQUAL("unit_345-2026-100-0-0.tbd", transfer.sent[0].c_str());
  STRCMP_CONTAINS("-num value 0 is outside the allowed range [1, 32]", type("send -num=0 *.sbd\r").c_str());
  STRCMP_CONTAINS("no file matches", type("send *.dbd\r").c_str());
  type("zr\r");
  LONGS_EQUAL(1, transfer.receives);
  LONGS_EQUAL(3, actions.transfers);  // s, send, zr (the refused ones started none)
}

TEST(CommsConsole, CallbackRangeAndGliderDosCommands) {
  STRCMP_CONTAINS("callback minutes value nan is outside the allowed range [1, 1440] min",
                  type("callback nan\r").c_str());
  type("callback 30\r");
  DOUBLES_EQUAL(30.0, actions.callback_min, 0.0);
  STRCMP_CONTAINS("a mission is already running", type("run\r").c_str());
  type("\x03");
  type("sequence\r");
  LONGS_EQUAL(1, actions.runs);
  STRCMP_CONTAINS("only `exit reset`", type("exit now\r").c_str());
  type("exit reset\r");
  LONGS_EQUAL(1, actions.resets);
}

TEST(CommsConsole, BackspaceEditsTheLine) {
  STRCMP_EQUAL("whox\b \bru\r\nVehicle Name: unit_345\r\n", type("whox\bru\r").c_str());
}
