// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight software's log sink is fixed when it is built, and the comms
// task (the log tap the dialog reads) needs the flight software first: the
// mains hand the flight application this forwarder, then point it at the
// comms task once that exists.
#include "glider/hal/log_record.hpp"

namespace glider::fw::comms {

class LogForward final : public hal::LogSink {
 public:
  explicit LogForward(hal::LogSink& first) : target_(&first) {}
  bool write(const hal::FlightLogRecord& record) override { return target_->write(record); }
  void retarget(hal::LogSink& target) { target_ = &target; }

 private:
  hal::LogSink* target_;
};

}  // namespace glider::fw::comms
