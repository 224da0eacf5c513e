// SPDX-License-Identifier: Apache-2.0
// ZmodemTransfer (what the console's `send` hands its files to) on a real
// folder against the engine's receiver in memory: what the shore took whole
// moves to sentlogs/ and is not offered again; what a lost carrier cut stays.
#include <CppUTest/TestHarness.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "glider/firmware/comms/file_access_posix.hpp"
#include "glider/firmware/comms/zmodem_receiver.hpp"
#include "glider/firmware/comms/zmodem_transfer.hpp"
#include "memory_link.hpp"

using namespace glider::fw::comms;
using glider::test::MemoryFiles;
using glider::test::Pipe;
using glider::test::PipeEnd;
namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& path, std::size_t size, char fill) {
  std::ofstream(path, std::ios::binary) << std::string(size, fill);
}

std::vector<std::uint8_t> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct OpenSegment final : OpenFiles {
  std::string name;
  bool is_open(const char* n) const override { return name == n; }
};

// Sends every listed file; the link carries `cut_after` bytes glider -> shore
// at most (then the transfer is cancelled, as at a lost carrier).
TransferState send_listed(ZmodemTransfer& transfer, MemoryFiles& shore, std::uint64_t cut_after = UINT64_MAX) {
  Pipe up, down;
  up.cut_after = cut_after;
  PipeEnd glider_end(down, up), shore_end(up, down);
  zmodem::Options options;
  options.timeout_us = 200'000;
  zmodem::Receiver receiver(shore_end, shore, options);
  std::vector<FileName> files(transfer.file_count());
  for (std::size_t i = 0; i < files.size(); ++i)
    std::snprintf(files[i].text, kMaxFileName, "%s", transfer.file_name(i));
  CHECK(transfer.begin_send(files));
  glider::hal::Micros now = 0;
  receiver.start(now);
  TransferProgress p;
  for (; now < 30'000'000; now += 1000) {
    p = transfer.poll(now, glider_end);
    receiver.step(now, 1024);
    if (p.state != TransferState::kRunning) return p.state;
    if (up.carried > cut_after) {
      transfer.cancel();
      return TransferState::kFailed;
    }
  }
  return p.state;
}

}  // namespace

TEST_GROUP(ZmodemTransferSent) {
  fs::path dir;
  void setup() override {
    char pattern[] = "/tmp/zmodem_transfer_XXXXXX";
    dir = ::mkdtemp(pattern);
  }
  void teardown() override { fs::remove_all(dir); }
};

TEST(ZmodemTransferSent, WhatTheShoreTookIsNotSentAgain) {
  write_file(dir / "unit-2026-330-00-000.sbd", 3000, 'a');
  write_file(dir / "unit-2026-330-00-001.sbd", 5000, 'b');
  write_file(dir / "unit-2026-330-00-002.sbd", 100, 'c');  // still being written
  OpenSegment open;
  open.name = "unit-2026-330-00-002.sbd";
  PosixFileAccess files(dir.string());
  MemoryFiles unused, shore;
  ZmodemTransfer transfer(dir.c_str(), files, (dir / "in").c_str(), unused, &open);
  CHECK(fs::is_directory(dir / "sentlogs"));
  transfer.list_files();
  LONGS_EQUAL(2, transfer.file_count());
  CHECK(send_listed(transfer, shore) == TransferState::kDone);
  // At the shore whole; on the vehicle moved to sentlogs/, byte for byte.
  CHECK(shore.files["unit-2026-330-00-000.sbd"] == read_file(dir / "sentlogs" / "unit-2026-330-00-000.sbd"));
  CHECK(shore.files["unit-2026-330-00-001.sbd"] == read_file(dir / "sentlogs" / "unit-2026-330-00-001.sbd"));
  CHECK_EQUAL(3000u, shore.files["unit-2026-330-00-000.sbd"].size());
  CHECK_FALSE(fs::exists(dir / "unit-2026-330-00-000.sbd"));
  LONGS_EQUAL(2, transfer.files_moved_to_sent());
  LONGS_EQUAL(0, transfer.sent_moves_failed());
  // The next call: only what is new is offered.
  transfer.list_files();
  LONGS_EQUAL(0, transfer.file_count());
  open.name.clear();  // the segment closed at the next surfacing
  transfer.list_files();
  LONGS_EQUAL(1, transfer.file_count());
  STRCMP_EQUAL("unit-2026-330-00-002.sbd", transfer.file_name(0));
}

TEST(ZmodemTransferSent, AFileCutByALostCarrierStaysToBeSentAgain) {
  write_file(dir / "unit-2026-330-00-000.sbd", 20000, 'a');
  PosixFileAccess files(dir.string());
  MemoryFiles unused, shore;
  ZmodemTransfer transfer(dir.c_str(), files, (dir / "in").c_str(), unused);
  transfer.list_files();
  LONGS_EQUAL(1, transfer.file_count());
  CHECK(send_listed(transfer, shore, 8000) == TransferState::kFailed);
  CHECK(fs::exists(dir / "unit-2026-330-00-000.sbd"));
  CHECK_FALSE(fs::exists(dir / "sentlogs" / "unit-2026-330-00-000.sbd"));
  LONGS_EQUAL(0, transfer.files_moved_to_sent());
  transfer.list_files();
  LONGS_EQUAL(1, transfer.file_count());  // offered (and resumed) at the next call
}
