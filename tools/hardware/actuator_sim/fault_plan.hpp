// SPDX-License-Identifier: Apache-2.0
#pragma once
// The faults the simulator injects (--fault SPEC, repeatable), and what it
// does with each request because of them. Deterministic (counts, not dice),
// so the tests that use them are reproducible.
#include <string>

namespace glider::sim_tools {

enum class ReplyAction { kReply, kSilent, kGarbled, kException };

struct FaultPlan {
  double stall_after_s = -1.0;  // stall:S      every axis jams after S s of motion
  long silent_after = -1;       // silent:N     no answer at all after N requests (dead mid-move)
  long garble_every = 0;        // noise:N      every Nth reply garbled (RTU: bad CRC; TCP: bad header)
  long exception_every = 0;     // exception:N  every Nth request answered with exception 4 (device failure)
  int slow_ms = 0;              // slow:MS      every reply delayed MS ms

  // Throws std::invalid_argument naming the bad spec.
  void add(const std::string& spec);
  std::string describe() const;
};

// Counts the requests and decides each one's fate.
class FaultInjector {
 public:
  explicit FaultInjector(const FaultPlan& plan) : plan_(plan) {}
  ReplyAction next();
  int delay_ms() const { return plan_.slow_ms; }

 private:
  FaultPlan plan_;
  long requests_ = 0;
};

}  // namespace glider::sim_tools
