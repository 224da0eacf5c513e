// SPDX-License-Identifier: Apache-2.0
#pragma once
// The plant's own lateness, written as it happens, so that a flight that
// aborted on an actuator fault can be told apart from a plant that answered
// late (tests/hil/overload_verdict.py): each step of the model that woke
// `floor` or more after its deadline, and each Modbus read whose answer left
// `floor` or more after its request arrived, or that held more than one
// request (the firmware sends a request only after the previous one was
// answered or given up: a second one waiting means the first timed out).
//
// CSV, one row a flushed line (a killed plant keeps what it wrote):
//   kind,t_s,late_ms,requests
// kind "step" or "answer"; t_s simulated seconds after launch (0 before);
// late_ms wall milliseconds; requests the requests answered by that read
// (steps: 0). An answer whose arrival time the kernel did not give is not
// timed: late_ms is empty.
#include <cstdint>
#include <cstdio>
#include <string>

namespace glider::plant {

struct LatenessStats {
  std::uint64_t late_steps = 0;       // woke >= floor after the deadline
  double max_step_late_ms = 0.0;      // over every step
  std::uint64_t answers = 0;          // reads that carried requests
  std::uint64_t untimed_answers = 0;  // no kernel arrival time
  std::uint64_t late_answers = 0;     // >= floor, or more than one request
  double max_answer_late_ms = 0.0;    // over every timed answer
  std::uint64_t max_requests = 0;     // the most requests one read held
};

class LatenessRecord {
 public:
  // Opens (truncates) `path` and writes the header; throws
  // std::runtime_error naming the path when it cannot. An empty path
  // keeps the statistics only.
  LatenessRecord(const std::string& path, double floor_ms);
  ~LatenessRecord();
  LatenessRecord(const LatenessRecord&) = delete;
  LatenessRecord& operator=(const LatenessRecord&) = delete;

  void step(double t_s, double late_ms);
  // late_ms < 0: the arrival time is unknown.
  void answer(double t_s, double late_ms, int requests);

  double floor_ms() const { return floor_ms_; }
  const LatenessStats& stats() const { return stats_; }
  // "N steps >= F ms late (max X ms); N Modbus reads, max answer X ms after
  // the request, K of several requests"
  std::string summary() const;

 private:
  void write(const char* kind, double t_s, double late_ms, int requests);

  std::FILE* file_ = nullptr;
  double floor_ms_;
  LatenessStats stats_;
};

}  // namespace glider::plant
