// SPDX-License-Identifier: Apache-2.0
// What the plant records of its own lateness (the evidence
// tests/hil/overload_verdict.py judges an actuator-fault abort on): a
// request left waiting is timed from its arrival, several requests read at
// once are counted, the record keeps what crosses its floor; and the
// compass line hands a reader that stalled the newest sentence.
#include <CppUTest/TestHarness.h>
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lateness_record.hpp"
#include "modbus_tcp_server.hpp"
#include "pty_device.hpp"

using namespace glider;
using Clock = std::chrono::steady_clock;

namespace {

std::filesystem::path scratch(const char* name) {
  const auto dir = std::filesystem::temp_directory_path() / ("plant_lateness_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// A read of the pump block (function 3, 2 registers) with transaction id `tid`.
std::vector<std::uint8_t> read_request(std::uint8_t tid) { return {0, tid, 0, 0, 0, 6, 1, 3, 0, 0, 0, 2}; }

struct Answer {
  double late_ms = -2.0;
  int requests = 0;
  int calls = 0;
};

// A server on an ephemeral port, one raw client connected, and what the
// answer observer was told.
class Bench {
 public:
  Bench() : mapping_(modbus_mapping_new(0, 0, 64, 0)) {
    // One socket asking for receive stamps for the whole run: the kernel
    // switches them off (deferred) when the last such socket closes, which
    // would race with the next test's server (the plant's listener holds
    // them on the same way for its whole run).
    static const int keep_stamps_on = [] {
      const int fd = socket(AF_INET, SOCK_DGRAM, 0);
      const int yes = 1;
      setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &yes, sizeof yes);
      return fd;
    }();
    CHECK(keep_stamps_on >= 0);
    server_ =
        std::make_unique<plant::ModbusTcpServer>(plant::TcpServerOptions{}, mapping_, 1, [](int) { return true; });
    server_->set_answer_observer([this](double late_ms, int requests) {
      answer_.late_ms = late_ms;
      answer_.requests = requests;
      ++answer_.calls;
    });
    client_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(static_cast<std::uint16_t>(server_->port()));
    inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
    CHECK_EQUAL(0, connect(client_, reinterpret_cast<sockaddr*>(&to), sizeof to));
    serve_until([this] { return server_->clients() == 1; });
    // The kernel stamps received packets only once its receive timestamps
    // are switched on, which it does a little after the first socket asks
    // (deferred work): probe until a read is timed, then start clean.
    for (std::uint8_t probe = 100; probe < 200 && answer_.late_ms < 0.0; ++probe) {
      answer_.late_ms = -2.0;
      send_request(probe);
      serve_until([this] { return answer_.late_ms > -2.0; });
      if (answer_.late_ms < 0.0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    CHECK(answer_.late_ms >= 0.0);
    answer_ = Answer{};
  }
  ~Bench() {
    close(client_);
    server_.reset();
    modbus_mapping_free(mapping_);
  }
  Bench(const Bench&) = delete;
  Bench& operator=(const Bench&) = delete;

  void send_request(std::uint8_t tid) {
    const auto frame = read_request(tid);
    CHECK_EQUAL(static_cast<ssize_t>(frame.size()), send(client_, frame.data(), frame.size(), 0));
  }
  // Polls and serves (as the plant's loop does) until `done` or 2 s.
  template <typename Done>
  void serve_until(Done done) {
    const auto give_up = Clock::now() + std::chrono::seconds(2);
    while (!done() && Clock::now() < give_up) {
      std::vector<pollfd> fds;
      server_->append_pollfds(fds);
      if (poll(fds.data(), fds.size(), 10) > 0) server_->service(fds.data(), fds.size(), [] {});
    }
    CHECK(done());
  }
  const Answer& answer() const { return answer_; }

 private:
  modbus_mapping_t* mapping_;
  std::unique_ptr<plant::ModbusTcpServer> server_;
  int client_ = -1;
  Answer answer_;
};

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_GROUP(PlantAnswerLatency){};

// A request that waited 300 ms for a plant that did not look (as a stalled,
// unscheduled or paused plant) is answered most of that after it arrived
// (the kernel stamps a packet when it processes it, a few ms after the send
// on a loaded machine), and never more than the time since it was sent.
TEST(PlantAnswerLatency, ARequestLeftWaitingIsTimedFromItsArrival) {
  Bench bench;
  const auto sent = Clock::now();
  bench.send_request(1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  bench.serve_until([&] { return bench.answer().calls == 1; });
  const double elapsed = ms_since(sent);
  CHECK_EQUAL(1, bench.answer().requests);
  CHECK_TEXT(bench.answer().late_ms >= 200.0, std::to_string(bench.answer().late_ms).c_str());
  CHECK(bench.answer().late_ms <= elapsed + 1.0);
}

// Served at once, the answer's lateness is what passed since the send (the
// bound holds however loaded the machine is) and far below a stall's.
TEST(PlantAnswerLatency, APromptAnswerIsNotLate) {
  Bench bench;
  const auto sent = Clock::now();
  bench.send_request(2);
  bench.serve_until([&] { return bench.answer().calls == 1; });
  const double elapsed = ms_since(sent);
  CHECK(bench.answer().late_ms >= 0.0);
  CHECK(bench.answer().late_ms <= elapsed + 1.0);
}

// Two requests waiting together: the firmware sends one only after the
// previous was answered or given up, so the count is the evidence even
// where the kernel's time is the newest request's.
TEST(PlantAnswerLatency, SeveralRequestsReadTogetherAreCounted) {
  Bench bench;
  bench.send_request(3);
  std::this_thread::sleep_for(std::chrono::milliseconds(40));
  bench.send_request(4);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  bench.serve_until([&] { return bench.answer().calls >= 1; });
  CHECK_EQUAL(1, bench.answer().calls);
  CHECK_EQUAL(2, bench.answer().requests);
  CHECK(bench.answer().late_ms >= 0.0);  // timed: the newest request's wait
}

TEST_GROUP(PlantLatenessRecord){};

TEST(PlantLatenessRecord, KeepsWhatCrossesTheFloorAndSeveralRequests) {
  const auto path = scratch("record.csv");
  {
    plant::LatenessRecord record(path.string(), 20.0);
    record.step(1.0, 5.0);         // under the floor: statistics only
    record.step(2.5, 412.3);       // a stall
    record.answer(3.0, 0.2, 1);    // prompt
    record.answer(4.0, 0.3, 2);    // prompt, but the first request had been given up
    record.answer(5.0, 380.0, 1);  // late
    record.answer(6.0, -1.0, 1);   // untimed, one request: nothing to show
    const plant::LatenessStats& s = record.stats();
    CHECK_EQUAL(1u, s.late_steps);
    DOUBLES_EQUAL(412.3, s.max_step_late_ms, 1e-9);
    CHECK_EQUAL(4u, s.answers);
    CHECK_EQUAL(2u, s.late_answers);
    CHECK_EQUAL(1u, s.untimed_answers);
    DOUBLES_EQUAL(380.0, s.max_answer_late_ms, 1e-9);
    CHECK_EQUAL(2u, s.max_requests);
  }
  STRCMP_EQUAL("kind,t_s,late_ms,requests\nstep,2.50,412.3,0\nanswer,4.00,0.3,2\nanswer,5.00,380.0,1\n",
               read_text(path).c_str());
}

TEST(PlantLatenessRecord, AnUnwritablePathIsNamed) {
  try {
    plant::LatenessRecord record("/nonexistent-dir/lateness.csv", 20.0);
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("/nonexistent-dir/lateness.csv") != std::string::npos);
  }
}

TEST_GROUP(PlantCompassLine){};

namespace {

// What a reader that stalled gets when it reads again: the last sentence
// in the line.
std::string last_sentence_after_stall(bool newest) {
  const auto link = scratch(newest ? "compass_newest" : "compass_drop");
  plant::PtyDevice line(link.string());
  for (int i = 0; i < 300; ++i) {  // 30 simulated s at 10 Hz: more than the line holds
    char sentence[64];
    std::snprintf(sentence, sizeof sentence, "$PTNTHPR,%03d.0,N,-26.0,N,1.0,N*00\r\n", i);
    if (newest) {
      line.write_newest(sentence);
    } else {
      line.write_all_or_drop(sentence);
    }
    // The pty hands written bytes to the line a moment later (deferred
    // work); the plant writes a sentence a step (5 ms of wall at X = 20).
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const int fd = open(line.slave_path().c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY);
  CHECK(fd >= 0);
  std::string text;
  char chunk[512];
  for (ssize_t n; (n = read(fd, chunk, sizeof chunk)) > 0;) text.append(chunk, static_cast<std::size_t>(n));
  close(fd);
  const std::size_t start = text.rfind('$');
  return start == std::string::npos ? "" : text.substr(start, 13);
}

}  // namespace

TEST(PlantCompassLine, AStalledReaderGetsTheNewestSentence) {
  STRCMP_EQUAL("$PTNTHPR,299.", last_sentence_after_stall(true).c_str());
  // A line that drops the newest (the GPS's) keeps the backlog instead.
  CHECK(last_sentence_after_stall(false) != "$PTNTHPR,299.");
}
