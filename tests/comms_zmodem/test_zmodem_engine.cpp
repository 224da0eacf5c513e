// SPDX-License-Identifier: Apache-2.0
// Engine to engine in memory (virtual time, seeded noise: fast and
// deterministic): files of several sizes, 1 % and 5 % byte corruption,
// a carrier lost mid-file then a second session that resumes, aborts.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "glider/firmware/comms/zmodem_receiver.hpp"
#include "glider/firmware/comms/zmodem_sender.hpp"
#include "memory_link.hpp"

using namespace glider::fw::comms;
using namespace glider::fw::comms::zmodem;
using glider::test::MemoryFiles;
using glider::test::Pipe;
using glider::test::PipeEnd;

namespace {

std::vector<std::uint8_t> random_bytes(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> data(n);
  for (auto& b : data) b = static_cast<std::uint8_t>(rng());
  return data;
}

struct Run {
  Status sender = Status::idle;
  Status receiver = Status::idle;
  glider::hal::Micros elapsed_us = 0;
  std::vector<double> step_us;  // wall time of each step() (information, not checked)
  double quantile(double q) {
    if (step_us.empty()) return 0.0;
    std::sort(step_us.begin(), step_us.end());
    return step_us[static_cast<std::size_t>(q * static_cast<double>(step_us.size() - 1))];
  }
};

// Steps both ends every 1 ms of virtual time with `budget` bytes each (a
// link of budget kB/s) until both have finished or `limit_us` has passed.
Run run_session(Sender& sender, Receiver& receiver, glider::hal::Micros limit_us, std::size_t budget = 64) {
  glider::hal::Micros now = 0;
  receiver.start(now);
  sender.start(now);
  Run run;
  while (now < limit_us) {
    const auto t0 = std::chrono::steady_clock::now();
    run.sender = sender.step(now, budget);
    const auto t1 = std::chrono::steady_clock::now();
    run.receiver = receiver.step(now, budget);
    const auto t2 = std::chrono::steady_clock::now();
    run.step_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    run.step_us.push_back(std::chrono::duration<double, std::micro>(t2 - t1).count());
    const bool sender_running = run.sender == Status::running;
    const bool receiver_running = run.receiver == Status::running;
    if (!sender_running && !receiver_running) break;
    now += 1000;
  }
  run.elapsed_us = now;
  return run;
}

Options fast_options(int max_retries = 10) {
  Options options;
  options.timeout_us = 200'000;  // virtual time, a link of 1 ms latency: keeps noisy runs short
  options.max_retries = max_retries;
  return options;
}

struct Link {
  std::mt19937_64 rng;
  Pipe up;    // sender -> receiver
  Pipe down;  // receiver -> sender
  PipeEnd sender_end{down, up};
  PipeEnd receiver_end{up, down};
  explicit Link(std::uint64_t seed, double corruption = 0.0) : rng(seed) {
    up.rng = down.rng = &rng;
    up.corruption = down.corruption = corruption;
  }
};

void check_transfer(const std::vector<std::size_t>& sizes, double corruption, std::uint64_t seed,
                    glider::hal::Micros limit_us, int max_retries = 10) {
  std::printf("\n  seed %llu, corruption %.0f %%\n", static_cast<unsigned long long>(seed), corruption * 100);
  Link link(seed, corruption);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  Sender sender(link.sender_end, glider_files, fast_options(max_retries));
  Receiver receiver(link.receiver_end, shore_files, fast_options(max_retries));
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::string name = "file" + std::to_string(i) + ".sbd";
    glider_files.files[name] = random_bytes(sizes[i], seed + i);
    glider_files.mtimes[name] = 1764201600 + static_cast<std::int64_t>(i);
    CHECK(sender.add_file(name));
  }
  Run run = run_session(sender, receiver, limit_us);
  std::printf("  %.1f s virtual, %d errors seen by the sender, %d by the receiver, %llu + %llu bytes corrupted\n",
              static_cast<double>(run.elapsed_us) / 1e6, sender.errors(), receiver.errors(),
              static_cast<unsigned long long>(link.up.corrupted), static_cast<unsigned long long>(link.down.corrupted));
  std::printf("  sender %s, receiver %s; step() wall time (64-byte budget): median %.1f us, p99 %.1f us, max %.0f us\n",
              failure_name(sender.failure()), failure_name(receiver.failure()), run.quantile(0.5), run.quantile(0.99),
              run.quantile(1.0));
  CHECK(run.sender == Status::done);
  CHECK(run.receiver == Status::done);
  CHECK_EQUAL(sizes.size(), receiver.result_count());
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::string name = "file" + std::to_string(i) + ".sbd";
    CHECK(sender.outcome(i) == Sender::Outcome::sent);
    CHECK(receiver.result(i).published);
    CHECK(shore_files.files.count(name) == 1);
    CHECK(shore_files.files[name] == glider_files.files[name]);
  }
  CHECK_EQUAL(sizes.size(), shore_files.files.size());  // no partial left behind
  if (corruption > 0.0) CHECK(link.up.corrupted > 0 && link.down.corrupted > 0);
}

}  // namespace

TEST_GROUP(ZmodemEngine){};

TEST(ZmodemEngine, CleanLinkSeveralSizes) { check_transfer({0, 1, 1024, 300 * 1024}, 0.0, 1, 60'000'000); }

TEST(ZmodemEngine, OnePercentCorruption) { check_transfer({0, 1, 1024, 100 * 1024}, 0.01, 20261127, 600'000'000); }

// At 5 % a ZFILE frame (~75 bytes) gets through about once in 50 tries:
// the no-progress limit (2 x max_retries timeouts, here 40 s) is set for
// that link; with the default 10 repeats the session gives up (measured).
TEST(ZmodemEngine, FivePercentCorruption) { check_transfer({1, 1024, 16 * 1024}, 0.05, 5, 3000'000'000, 100); }

TEST(ZmodemEngine, CarrierLostThenResumed) {
  const std::uint64_t seed = 3;
  Link link(seed);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  const std::vector<std::uint8_t> data = random_bytes(200 * 1024, seed);
  glider_files.files["long.sbd"] = data;
  glider_files.mtimes["long.sbd"] = 1764201600;
  link.up.cut_after = 120 * 1024;  // the carrier drops a bit past half way
  {
    Sender sender(link.sender_end, glider_files, fast_options());
    Receiver receiver(link.receiver_end, shore_files, fast_options());
    CHECK(sender.add_file("long.sbd"));
    const Run run = run_session(sender, receiver, 60'000'000);
    CHECK(run.sender == Status::failed);
    CHECK(run.receiver == Status::failed);
    CHECK(receiver.failure() == Failure::timeout);
    // Nothing under the real name; a partial under the temporary one.
    CHECK_EQUAL(0, shore_files.files.count("long.sbd"));
    CHECK_EQUAL(1, shore_files.files.size());
    const auto& partial = shore_files.files.begin()->second;
    CHECK(partial.size() > 64 * 1024 && partial.size() < data.size());
    CHECK(std::equal(partial.begin(), partial.end(), data.begin()));
  }
  // Next call: the link is back; the receiver resumes from the partial's size.
  Link second(seed + 1);
  Sender sender(second.sender_end, glider_files, fast_options());
  Receiver receiver(second.receiver_end, shore_files, fast_options());
  CHECK(sender.add_file("long.sbd"));
  const std::size_t partial_size = shore_files.files.begin()->second.size();
  const Run run = run_session(sender, receiver, 60'000'000);
  CHECK(run.sender == Status::done);
  CHECK(run.receiver == Status::done);
  CHECK_EQUAL(static_cast<std::int64_t>(partial_size), sender.start_offset(0));
  CHECK(shore_files.files["long.sbd"] == data);
  CHECK_EQUAL(1, shore_files.files.size());
  // Only the rest crossed the link the second time (plus framing).
  CHECK(sender.bytes_out() < (data.size() - partial_size) * 11 / 10 + 2048);
}

TEST(ZmodemEngine, PartialOfAnotherVersionIsNotResumed) {
  Link link(11);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  glider_files.files["goto_l10.ma"] = random_bytes(3000, 11);
  glider_files.mtimes["goto_l10.ma"] = 1000;
  // A stale partial of an older, different-length version.
  shore_files.files["goto_l10.ma.2500-1750.zpart"] = random_bytes(1000, 99);
  Sender sender(link.sender_end, glider_files, fast_options());
  Receiver receiver(link.receiver_end, shore_files, fast_options());
  CHECK(sender.add_file("goto_l10.ma"));
  const Run run = run_session(sender, receiver, 10'000'000);
  CHECK(run.receiver == Status::done);
  CHECK_EQUAL(0, sender.start_offset(0));
  CHECK(shore_files.files["goto_l10.ma"] == glider_files.files["goto_l10.ma"]);
}

TEST(ZmodemEngine, AbortByCancelStopsBothEnds) {
  Link link(12);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  glider_files.files["big.dbd"] = random_bytes(100 * 1024, 12);
  Sender sender(link.sender_end, glider_files, fast_options());
  Receiver receiver(link.receiver_end, shore_files, fast_options());
  CHECK(sender.add_file("big.dbd"));
  receiver.start(0);
  sender.start(0);
  glider::hal::Micros now = 0;
  for (int i = 0; i < 300; ++i, now += 1000) {
    sender.step(now, 64);
    receiver.step(now, 64);
  }
  CHECK(receiver.offset() > 0);
  receiver.abort();
  CHECK(receiver.status() == Status::failed);
  for (int i = 0; i < 100 && sender.status() == Status::running; ++i, now += 1000) sender.step(now, 64);
  CHECK(sender.status() == Status::failed);
  CHECK(sender.failure() == Failure::cancelled);
  CHECK_EQUAL(0, shore_files.files.count("big.dbd"));
}

TEST(ZmodemEngine, MissingFileIsReportedAndTheOthersStillGo) {
  Link link(13);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  glider_files.files["a.sbd"] = random_bytes(500, 13);
  Sender sender(link.sender_end, glider_files, fast_options());
  Receiver receiver(link.receiver_end, shore_files, fast_options());
  CHECK(sender.add_file("missing.sbd"));
  CHECK(sender.add_file("a.sbd"));
  CHECK_FALSE(sender.add_file("../escape"));
  const Run run = run_session(sender, receiver, 10'000'000);
  CHECK(run.sender == Status::done);
  CHECK(sender.outcome(0) == Sender::Outcome::failed);
  CHECK(sender.outcome(1) == Sender::Outcome::sent);
  CHECK(shore_files.files["a.sbd"] == glider_files.files["a.sbd"]);
}

TEST(ZmodemEngine, WriteFailureCancelsAndPublishesNothing) {
  Link link(14);
  MemoryFiles glider_files;
  MemoryFiles shore_files;
  shore_files.fail_writes = true;
  glider_files.files["a.sbd"] = random_bytes(5000, 14);
  Sender sender(link.sender_end, glider_files, fast_options());
  Receiver receiver(link.receiver_end, shore_files, fast_options());
  CHECK(sender.add_file("a.sbd"));
  const Run run = run_session(sender, receiver, 10'000'000);
  CHECK(run.receiver == Status::failed);
  CHECK(receiver.failure() == Failure::file_error);
  CHECK(run.sender == Status::failed);
  CHECK_EQUAL(0, shore_files.files.count("a.sbd"));
}
