// SPDX-License-Identifier: Apache-2.0
// CRC-16/XMODEM and CRC-32 against published check values, and the frame
// layer: every header and subpacket the encoder writes is read back by the
// parser, and one flipped byte is caught.
#include <CppUTest/TestHarness.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <random>
#include <string_view>
#include <vector>

#include "glider/firmware/comms/zmodem_crc.hpp"
#include "glider/firmware/comms/zmodem_encoder.hpp"
#include "glider/firmware/comms/zmodem_file_info.hpp"
#include "glider/firmware/comms/zmodem_parser.hpp"

using namespace glider::fw::comms;
using namespace glider::fw::comms::zmodem;

namespace {

std::span<const std::uint8_t> bytes_of(std::string_view text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

// Collects what an encoder writes.
class Capture : public ByteStream {
 public:
  std::vector<std::uint8_t> bytes;
  std::size_t read(std::span<std::uint8_t>) override { return 0; }
  std::size_t write(std::span<const std::uint8_t> data) override {
    bytes.insert(bytes.end(), data.begin(), data.end());
    return data.size();
  }
};

}  // namespace

TEST_GROUP(ZmodemCrc){};

TEST(ZmodemCrc, Crc16XmodemCheckValue) {
  // The catalogue's check value of CRC-16/XMODEM over "123456789".
  CHECK_EQUAL(0x31C3, crc16(bytes_of("123456789")));
  CHECK_EQUAL(0x0000, crc16(bytes_of("")));
  // Appending the CRC high byte first leaves a zero register (the receiver's test).
  std::vector<std::uint8_t> data = {'1', '2', '3', '4', '5', '6', '7', '8', '9', 0x31, 0xC3};
  CHECK_EQUAL(0, crc16(data));
}

TEST(ZmodemCrc, Crc32CheckValues) {
  CHECK_EQUAL(0xCBF43926u, crc32(bytes_of("123456789")));
  CHECK_EQUAL(0x00000000u, crc32(bytes_of("")));
  CHECK_EQUAL(0x414FA339u, crc32(bytes_of("The quick brown fox jumps over the lazy dog")));
  // Data plus its complemented CRC, little-endian, runs to the residue.
  std::uint32_t reg = kCrc32Init;
  for (const std::uint8_t b : bytes_of("123456789")) reg = crc32_update(reg, b);
  for (const std::uint8_t b : {0x26, 0x39, 0xF4, 0xCB}) reg = crc32_update(reg, static_cast<std::uint8_t>(b));
  CHECK_EQUAL(kCrc32Residue, reg);
}

TEST_GROUP(ZmodemFrames){};

TEST(ZmodemFrames, HexHeaderIsTheSpecificationsText) {
  // ZRINIT with ZF0 = CANFDX|CANOVIO|CANFC32 (0x23), as lrzsz's rz sends it.
  Encoder encoder;
  Capture capture;
  encoder.hex_header(Header::flags(Frame::rinit, 0x23));
  encoder.flush(capture, 1000);
  const std::string text(capture.bytes.begin(), capture.bytes.end());
  STRCMP_EQUAL(
      "**\x18"
      "B0100000023be50\r\x8a\x11",
      text.c_str());
}

TEST(ZmodemFrames, HeadersAndSubpacketsRoundTripWithEscapes) {
  std::mt19937_64 rng(7);
  for (const bool crc32 : {false, true}) {
    for (const bool escape_all : {false, true}) {
      Encoder encoder;
      encoder.set_escape_control(escape_all);
      Capture capture;
      std::vector<std::uint8_t> payload(1024);
      for (auto& b : payload) b = static_cast<std::uint8_t>(rng());
      // Every byte value, including ZDLE, XON/XOFF, CR after '@', 0x7f, 0xff.
      for (int i = 0; i < 256; ++i) payload[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
      payload[300] = '@';
      payload[301] = 0x0d;
      encoder.binary_header(Header::at(Frame::data, 0x12345678u), crc32);
      encoder.subpacket(payload, kCrcG, crc32);
      encoder.subpacket({}, kCrcQ, crc32);
      encoder.subpacket(std::span(payload).first(10), kCrcE, crc32);
      encoder.hex_header(Header::at(Frame::rpos, 4096));
      encoder.flush(capture, 100000);
      // No raw flow-control byte ever goes out inside binary data.
      Parser parser;
      parser.set_drop_control(escape_all);
      std::vector<Parser::Event> events;
      std::vector<std::vector<std::uint8_t>> packets;
      for (const std::uint8_t b : capture.bytes) {
        const auto e = parser.feed(b);
        if (e == Parser::Event::none) continue;
        events.push_back(e);
        if (e == Parser::Event::header) {
          if (events.size() == 1) {
            CHECK(parser.header().type == Frame::data);
            CHECK_EQUAL(0x12345678u, parser.header().position());
            CHECK_EQUAL(crc32, parser.header_crc32());
          } else {
            CHECK(parser.header().type == Frame::rpos);
            CHECK_EQUAL(4096u, parser.header().position());
          }
        }
        if (e == Parser::Event::subpacket) packets.emplace_back(parser.data().begin(), parser.data().end());
      }
      const std::vector<Parser::Event> expected = {Parser::Event::header, Parser::Event::subpacket,
                                                   Parser::Event::subpacket, Parser::Event::subpacket,
                                                   Parser::Event::header};
      CHECK(events == expected);
      CHECK(packets.at(0) == payload);
      CHECK(packets.at(1).empty());
      CHECK(packets.at(2) == std::vector<std::uint8_t>(payload.begin(), payload.begin() + 10));
    }
  }
}

TEST(ZmodemFrames, FlippedByteIsCaught) {
  Encoder encoder;
  Capture capture;
  std::vector<std::uint8_t> payload(200, 0x41);
  encoder.binary_header(Header::at(Frame::data, 0), true);
  encoder.subpacket(payload, kCrcE, true);
  encoder.flush(capture, 100000);
  for (std::size_t at = 0; at < capture.bytes.size(); ++at) {
    auto damaged = capture.bytes;
    damaged[at] ^= 0x04;
    Parser parser;
    int good_subpackets = 0;
    for (const std::uint8_t b : damaged) {
      const auto e = parser.feed(b);
      if (e == Parser::Event::subpacket && parser.data().size() == payload.size()) ++good_subpackets;
    }
    CHECK_EQUAL(0, good_subpackets);  // a damaged frame never yields the data
  }
}

TEST(ZmodemFrames, FiveCansCancel) {
  Parser parser;
  int cancels = 0;
  for (int i = 0; i < 4; ++i) cancels += parser.feed(kCan) == Parser::Event::cancelled;
  CHECK_EQUAL(0, cancels);
  CHECK(parser.feed(kCan) == Parser::Event::cancelled);
}

TEST(ZmodemFrames, FileInfoRoundTripAndUnsafeNamesRefused) {
  FileInfo info;
  const std::string_view name = "unit_123-2026-331-0-1.sbd";
  std::memcpy(info.name.data(), name.data(), name.size());
  info.name_length = name.size();
  info.length = 307200;
  info.mtime = 01234567;
  std::array<std::uint8_t, 256> out{};
  const std::size_t n = format_file_info(info, 2, 400000, out);
  CHECK(n > 0);
  FileInfo back;
  CHECK(parse_file_info(std::span(out).first(n), back));
  CHECK(back.name_view() == name);
  CHECK_EQUAL(307200, back.length);
  CHECK_EQUAL(01234567, back.mtime);
  for (const std::string_view bad :
       {std::string_view("../etc/passwd\0", 14), std::string_view("a/b\0", 4), std::string_view(".hidden\0", 8),
        std::string_view("\0", 1), std::string_view("noterminator")}) {
    FileInfo refused;
    CHECK_FALSE(parse_file_info(bytes_of(bad), refused));
  }
}
