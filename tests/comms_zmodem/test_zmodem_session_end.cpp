// SPDX-License-Identifier: Apache-2.0
// The end of a session, receiver side, against a scripted sender: the
// sender's ZFIN and our answer. lrzsz's sz (saybibi) sends ZFIN, and on
// anything but a ZFIN back (our answer garbled) sends ZFIN again and waits
// for an answer up to its own timeout (tens of seconds); only our ZFIN makes
// it send "OO" and exit. Found in comms.zmodem.lrzsz.from_sz_corrupted
// (seed 581279 at 1 %): every file byte-exact at 1.5 s, our ZFIN answer
// garbled, sz's second ZFIN garbled too, we never answered it, and sz had not
// exited 17 s later.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include "glider/firmware/comms/zmodem_encoder.hpp"
#include "glider/firmware/comms/zmodem_parser.hpp"
#include "glider/firmware/comms/zmodem_receiver.hpp"
#include "memory_link.hpp"

using namespace glider::fw::comms;
using namespace glider::fw::comms::zmodem;
using glider::test::MemoryFiles;
using glider::test::Pipe;
using glider::test::PipeEnd;

namespace {

// The sender's end, written by hand: headers go in, the receiver's headers
// come out decoded.
struct ScriptedSender {
  Pipe up;    // to the receiver
  Pipe down;  // from the receiver
  PipeEnd receiver_end{up, down};
  MemoryFiles files;
  Receiver receiver{receiver_end, files};
  Parser parser;
  std::vector<std::uint8_t> raw;  // every byte the receiver sent, in order
  glider::hal::Micros now = 0;

  // The hex header as sz sends it; `garble` flips one of its CRC digits,
  // so the receiver sees a header arrive but cannot trust it.
  void send_hex(Frame type, bool garble = false) {
    Encoder encoder;
    encoder.hex_header(Header::flags(type, 0));
    Pipe sink;
    PipeEnd capture{sink, sink};
    encoder.flush(capture, Encoder::kCapacity);
    std::vector<std::uint8_t> bytes(sink.bytes.begin(), sink.bytes.end());
    if (garble) bytes[bytes.size() - 4] = bytes[bytes.size() - 4] == '0' ? '1' : '0';  // a CRC hex digit
    up.bytes.insert(up.bytes.end(), bytes.begin(), bytes.end());
  }
  void send_raw(const char* text) {
    for (const char* c = text; *c != '\0'; ++c) up.bytes.push_back(static_cast<std::uint8_t>(*c));
  }
  // Steps the receiver every 10 ms for `ms`; the headers it sent, in order.
  std::vector<Frame> run_ms(int ms) {
    std::vector<Frame> seen;
    for (int t = 0; t < ms; t += 10) {
      receiver.step(now, 4096);
      now += 10'000;
      while (!down.bytes.empty()) {
        const std::uint8_t byte = down.bytes.front();
        down.bytes.pop_front();
        raw.push_back(byte);
        if (parser.feed(byte) == Parser::Event::header) seen.push_back(parser.header().type);
      }
    }
    return seen;
  }
  // How many of the receiver's hex ZFIN headers came right after an XON.
  int fins_after_xon() const {
    static constexpr std::uint8_t kFin[] = {kPad, kPad, kDle, kHex, '0', '8'};
    int n = 0;
    for (std::size_t i = 1; i + sizeof kFin <= raw.size(); ++i) {
      n += std::equal(std::begin(kFin), std::end(kFin), raw.begin() + static_cast<std::ptrdiff_t>(i)) &&
                   raw[i - 1] == kXon
               ? 1
               : 0;
    }
    return n;
  }
  static int count(const std::vector<Frame>& frames, Frame type) {
    int n = 0;
    for (Frame f : frames) n += f == type ? 1 : 0;
    return n;
  }
};

}  // namespace

TEST_GROUP(ZmodemSessionEnd){};

TEST(ZmodemSessionEnd, ZfinIsAnsweredAndOoEndsTheSession) {
  ScriptedSender s;
  s.receiver.start(s.now);
  CHECK_EQUAL(1, ScriptedSender::count(s.run_ms(20), Frame::rinit));
  s.send_hex(Frame::fin);
  CHECK_EQUAL(1, ScriptedSender::count(s.run_ms(20), Frame::fin));
  s.send_raw("OO");
  // Done at once: no timed repeat after it (a stray ZFIN would reach the shore's next reader).
  CHECK_EQUAL(0, ScriptedSender::count(s.run_ms(3000), Frame::fin));
  CHECK(s.receiver.status() == Status::done);
}

// sz's repeat of its ZFIN arrives garbled: it is the only header a sender
// says now, so it is answered with ZFIN again (old code: ignored, sz waited).
TEST(ZmodemSessionEnd, GarbledRepeatOfZfinIsAnsweredAgain) {
  ScriptedSender s;
  s.receiver.start(s.now);
  s.run_ms(20);
  s.send_hex(Frame::fin);
  CHECK_EQUAL(1, ScriptedSender::count(s.run_ms(20), Frame::fin));
  // Our answer was garbled on its way: sz sends ZFIN again; that one is garbled too.
  s.send_hex(Frame::fin, true);
  CHECK_EQUAL(1, ScriptedSender::count(s.run_ms(20), Frame::fin));
  CHECK(s.receiver.status() == Status::running);
  s.send_raw("OO");
  s.run_ms(20);
  CHECK(s.receiver.status() == Status::done);
}

// A byte of our ZFIN answer garbled into XOFF stops lrzsz's tty (IXON): sz is
// held in write() of its repeat or its "OO", and a ZFIN has no trailing XON.
// So every ZFIN we say, the timed repeats included, goes out after an XON
// (old code: none; sz never exited, comms.zmodem.lrzsz.from_sz_corrupted,
// seed 640975; against the real sz: comms.zmodem.lrzsz.from_sz_fin_xoff_*).
TEST(ZmodemSessionEnd, EveryZfinGoesOutAfterAnXon) {
  ScriptedSender s;
  s.receiver.start(s.now);
  s.run_ms(20);
  s.send_hex(Frame::fin);
  s.run_ms(20);
  CHECK_EQUAL(1, s.fins_after_xon());
  s.send_hex(Frame::fin, true);  // sz's repeat, garbled: answered
  s.run_ms(20);
  CHECK_EQUAL(2, s.fins_after_xon());
  s.run_ms(3000);  // no "OO": the timed repeats, then the session ends
  CHECK_EQUAL(4, s.fins_after_xon());
  CHECK(s.receiver.status() == Status::done);
}

// Our answer lost whole (its ZPAD ZDLE lead-in garbled: sz sees no header
// and waits for one), and our timed repeats too (lead-ins garbled at 1 %):
// sz waits for a ZFIN in silence (saybibi, tens of seconds), and the
// old receiver, done 1 s after the ZFIN, left it so (sz never exited,
// comms.zmodem.lrzsz.from_sz_corrupted, seed 296357; against the real sz:
// comms.zmodem.lrzsz.from_sz_fin_lost). Like lrzsz's rz (ackbibi: ZFIN up to
// 3 times), the answer is repeated twice, a third of the "OO" wait (1 s
// here) apart, and the wait is not longer. Old code: 2 ZFINs (0 and 0.5 s).
TEST(ZmodemSessionEnd, ZfinIsSaidThreeTimesWithinTheOoWait) {
  ScriptedSender s;
  s.receiver.start(s.now);
  s.run_ms(20);
  s.send_hex(Frame::fin);
  const glider::hal::Micros fin_at = s.now;
  std::vector<glider::hal::Micros> said;  // when each of our ZFINs came out
  while (s.receiver.status() == Status::running && s.now - fin_at < 5'000'000) {
    const glider::hal::Micros t = s.now;
    for (std::size_t i = 0, n = ScriptedSender::count(s.run_ms(10), Frame::fin); i < n; ++i) said.push_back(t - fin_at);
  }
  CHECK(s.receiver.status() == Status::done);
  CHECK_EQUAL(3U, said.size());
  CHECK(said[0] < 20'000);
  CHECK(said[1] >= 330'000 && said[1] < 350'000);
  CHECK(said[2] >= 660'000 && said[2] <= 690'000);  // steps are 10 ms apart
  // The "OO" wait stays a tenth of the 10 s timeout.
  CHECK(s.now - fin_at >= 1'000'000 && s.now - fin_at < 1'030'000);
}
