// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/byte_stream.hpp"
#include "glider/firmware/comms/zmodem_encoder.hpp"
#include "glider/firmware/comms/zmodem_parser.hpp"
#include "glider/firmware/comms/zmodem_protocol.hpp"

namespace glider::fw::comms::zmodem {

// What the sender and the receiver share: the link, its encoder and parser,
// the one timer (a header is repeated after options.timeout_us of silence,
// at most options.max_retries times) and the session's outcome.
class Session {
 public:
  Session(ByteStream& stream, const Options& options) : stream_(stream), options_(options) {
    encoder_.set_escape_control(options.escape_control);
  }

  Status status() const { return status_; }
  Failure failure() const { return failure_; }
  // Bytes that went through the link (both directions), for throughput figures.
  std::uint64_t bytes_in() const { return bytes_in_; }
  std::uint64_t bytes_out() const { return bytes_out_; }
  int errors() const { return errors_total_; }

 protected:
  // Reads at most `budget` bytes and hands each parser event to on_event
  // (event, byte). Stops early when the session ends.
  template <typename OnEvent>
  void read_input(std::size_t budget, OnEvent&& on_event) {
    while (budget > 0 && status_ == Status::running) {
      const std::size_t want = std::min(budget, input_.size());
      const std::size_t got = stream_.read(std::span<std::uint8_t>(input_.data(), want));
      if (got == 0) return;
      budget -= std::min(got, budget);
      bytes_in_ += got;
      for (std::size_t i = 0; i < got && status_ == Status::running; ++i) {
        const Parser::Event event = parser_.feed(input_[i]);
        if (event == Parser::Event::header) heard();
        on_event(event, input_[i]);
      }
    }
  }
  std::size_t flush(std::size_t budget) {
    const std::size_t written = encoder_.flush(stream_, budget);
    bytes_out_ += written;
    return written;
  }
  void arm(hal::Micros now) { deadline_ = now + options_.timeout_us; }
  bool expired(hal::Micros now) const { return now >= deadline_; }
  // A repeat after silence: false (and the session failed) once
  // options.max_retries silences in a row have gone unanswered.
  bool retry(hal::Micros now) {
    arm(now);
    if (++retries_ > options_.max_retries) {
      fail(Failure::timeout);
      return false;
    }
    return true;
  }
  // The peer answered (any good header): the silence count starts again.
  void heard() { retries_ = 0; }
  // Data or a file went through.
  void progress(hal::Micros now) {
    retries_ = 0;
    last_progress_ = now;
  }
  // A damaged or out-of-place frame. On a noisy link the peers keep talking
  // (every garble is answered at once), so the limit is on time: no
  // progress for 2 x max_retries timeouts ends the session (silence alone
  // ends it after max_retries: a timeout).
  void error() { ++errors_total_; }
  bool stalled(hal::Micros now) {
    if (now - last_progress_ <= 2 * options_.timeout_us * options_.max_retries) return false;
    fail(Failure::too_many_errors);
    return true;
  }
  void fail(Failure failure) {
    status_ = Status::failed;
    failure_ = failure;
  }
  void cancel_link(Failure failure) {
    encoder_.cancel_sequence();
    flush(Encoder::kCapacity);
    fail(failure);
  }

  ByteStream& stream_;
  Options options_;
  Encoder encoder_;
  Parser parser_;
  Status status_ = Status::idle;
  Failure failure_ = Failure::none;
  hal::Micros deadline_ = 0;
  int retries_ = 0;
  hal::Micros last_progress_ = 0;
  int errors_total_ = 0;
  std::uint64_t bytes_in_ = 0;
  std::uint64_t bytes_out_ = 0;
  std::array<std::uint8_t, 256> input_{};
};

}  // namespace glider::fw::comms::zmodem
