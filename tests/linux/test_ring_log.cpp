// SPDX-License-Identifier: Apache-2.0
// The target's flight log: rows handed over by the loop come out in the CSV
// file in order, with the one schema's header and text (the SIL's), UTC
// times, whole rows only, a trailer at the end; a full disk loses rows
// (counted, said once) and the log carries on when space returns.
#include <CppUTest/TestHarness.h>

#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "glider/firmware/log/log_text.hpp"
#include "glider/target/ring_log.hpp"

using namespace glider;

namespace {

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t fields(const std::string& line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

// Hands `count` rows over, retrying while the ring is full (the loop would drop them).
void write_rows(target::RingBufferLog& log, int first, int count) {
  for (int i = first; i < first + count; ++i) {
    hal::FlightLogRecord r;
    r.time_us = static_cast<hal::Micros>(i) * 1'000'000;
    r.m_depth = i % 2 == 0 ? 0.25 * i : std::nan("");
    r.m_depth_state = 1;
    r.x_yo_count = i;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!log.write(r) && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
  }
}

// Waits (at most 10 s) until the writer has dealt with `rows` rows.
bool drained(const target::RingBufferLog& log, std::uint64_t rows) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (log.rows_written() + log.rows_lost_disk() < rows) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

std::atomic<bool> g_disk_full{false};

ssize_t write_unless_full(int fd, const void* data, std::size_t size) {
  if (g_disk_full.load()) {
    errno = ENOSPC;
    return -1;
  }
  return ::write(fd, data, size);
}

}  // namespace

TEST_GROUP(RingBufferLog){};

TEST(RingBufferLog, RowsReachTheFileInOrder) {
  const std::string path = GLIDER_TEST_OUTPUT_DIR "/ring_log.csv";
  const double now_s = static_cast<double>(std::time(nullptr));
  target::RingLogOptions options;
  options.metadata = {{"source", "test"}};
  target::RingBufferLog log(path, options);
  write_rows(log, 0, 3000);  // more than the ring holds: the writer drains while we write
  CHECK_TRUE(log.close("complete"));
  CHECK_EQUAL(3000u, log.rows_written());
  CHECK_TRUE(log.fsyncs() >= 3000u / 60u - 1u);
  const std::vector<std::string> lines = read_lines(path);
  CHECK_EQUAL(3004u, lines.size());  // writer, metadata, header, rows, trailer
  // Our writer says so first: a log of it without the trailer was cut short.
  STRCMP_EQUAL("# writer: glider-firmware", lines[0].c_str());
  STRCMP_EQUAL("# source: test", lines[1].c_str());
  STRCMP_EQUAL(fw::log_header().c_str(), lines[2].c_str());
  for (std::size_t i = 3; i < 3003; ++i) CHECK_EQUAL(fields(lines[2]), fields(lines[i]));
  // m_present_time is UTC (the system clock), the rest the firmware's fields.
  const double t0 = std::stod(lines[3].substr(0, lines[3].find(',')));
  CHECK_TRUE(std::fabs(t0 - now_s) < 60.0);
  STRCMP_CONTAINS(",0.5,", lines[5].c_str());
  STRCMP_CONTAINS(",,", lines[3003 - 1].c_str());  // NaN depth: an empty field
  // The test retries a row the full ring refused; each refusal counts as lost
  // (in flight the loop does not retry: the row is gone).
  STRCMP_EQUAL(("# end: complete rows=3000 lost=" + std::to_string(log.rows_refused())).c_str(), lines.back().c_str());
}

TEST(RingBufferLog, DiskFullLosesRowsCountedAndRecovers) {
  const std::string path = GLIDER_TEST_OUTPUT_DIR "/ring_log_disk_full.csv";
  const std::string messages_path = GLIDER_TEST_OUTPUT_DIR "/ring_log_disk_full.messages";
  std::FILE* messages = std::fopen(messages_path.c_str(), "w");
  CHECK_TRUE(messages != nullptr);
  target::RingLogOptions options;
  options.messages = messages;
  options.write_fn = write_unless_full;
  target::RingBufferLog log(path, options);
  write_rows(log, 0, 10);
  CHECK_TRUE(drained(log, 10));
  g_disk_full = true;
  write_rows(log, 10, 25);
  CHECK_TRUE(drained(log, 35));
  write_rows(log, 35, 5);  // still full: the same episode, not said again
  CHECK_TRUE(drained(log, 40));
  g_disk_full = false;
  write_rows(log, 40, 10);
  CHECK_FALSE(log.close("aborted leak"));  // rows were lost: not a clean log
  std::fclose(messages);
  CHECK_EQUAL(20u, log.rows_written());
  CHECK_EQUAL(30u, log.rows_lost_disk());
  const std::vector<std::string> lines = read_lines(path);
  CHECK_EQUAL(2u + 20u + 1u, lines.size());
  STRCMP_EQUAL("# end: aborted leak rows=20 lost=30", lines.back().c_str());
  STRCMP_CONTAINS(",9,", lines[11].c_str());   // x_yo_count 9: the last row before the disk filled
  STRCMP_CONTAINS(",40,", lines[12].c_str());  // then the first after it recovered
  const std::vector<std::string> said = read_lines(messages_path);
  CHECK_EQUAL(2u, said.size());
  STRCMP_CONTAINS("No space left on device: rows are lost (counted)", said[0].c_str());
  STRCMP_CONTAINS("writing again (30 rows were lost)", said[1].c_str());
}

// A real full filesystem: a 64 KiB tmpfs. It needs CAP_SYS_ADMIN (./glider
// test runs as root); where mounting is refused it cannot run, so it says
// GLIDER-SKIP and CTest reports linux.RingBufferLogTmpfs skipped, not passed
// (its own group: the skip marks the whole group's CTest entry).
TEST_GROUP(RingBufferLogTmpfs){};

TEST(RingBufferLogTmpfs, FullTmpfsKeepsWholeRowsAndRecovers) {
  const std::filesystem::path dir = GLIDER_TEST_OUTPUT_DIR "/ring_log_tmpfs";
  std::filesystem::create_directories(dir);
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") != 0) {
    std::printf("\nGLIDER-SKIP: no tmpfs mount here (%s): the real full disk is not tested\n", std::strerror(errno));
    return;
  }
  const std::string path = (dir / "flight.csv").string();
  const std::filesystem::path filler = dir / "filler";
  std::FILE* messages = std::tmpfile();
  target::RingLogOptions options;
  options.messages = messages;
  {
    target::RingBufferLog log(path, options);
    { std::ofstream(filler) << std::string(40 * 1024, 'x'); }
    write_rows(log, 0, 400);  // ~100 KB of rows: the disk fills part way
    CHECK_TRUE(drained(log, 400));
    CHECK_TRUE(log.rows_lost_disk() > 0);
    std::filesystem::remove(filler);  // space returns
    write_rows(log, 400, 20);
    CHECK_TRUE(log.close("complete") == false);
    CHECK_TRUE(log.rows_written() >= 20u);
  }
  const std::vector<std::string> lines = read_lines(path);
  const std::size_t width = fields(lines[1]);
  for (std::size_t i = 2; i + 1 < lines.size(); ++i) CHECK_EQUAL(width, fields(lines[i]));
  STRCMP_CONTAINS("# end: complete rows=", lines.back().c_str());
  STRCMP_CONTAINS(",419,", lines[lines.size() - 2].c_str());  // the last row, written after recovery
  std::fclose(messages);
  ::umount(dir.c_str());
}
