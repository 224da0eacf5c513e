// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "glider/firmware/comms/file_access.hpp"
#include "glider/firmware/comms/zmodem_file_info.hpp"
#include "glider/firmware/comms/zmodem_session.hpp"

namespace glider::fw::comms::zmodem {

// Zmodem sender (glider -> shore: data files). Streams ZDATA subpackets
// (CRC-32 when the receiver offers it) with a ZCRCQ every quarter window, at
// most options.window_bytes (or the receiver's buffer) ahead of its last
// ZACK; a lost answer is asked again after about four measured round trips; a ZRPOS
// rewinds to the receiver's offset (its last good byte, or the size of a
// partial it already holds: resume) and halves the subpacket, which grows
// back as data gets through. Non-blocking: step() reads and writes at most
// `budget` bytes each and reads the file one subpacket at a time.
class Sender : public Session {
 public:
  static constexpr std::size_t kMaxFiles = 16;
  enum class Outcome : std::uint8_t { pending, sent, skipped, failed };

  Sender(ByteStream& stream, FileAccess& files, const Options& options = {})
      : Session(stream, options), files_(files) {}

  // Queues a file before start(); false if the list is full or the name unsafe.
  bool add_file(std::string_view name);
  void start(hal::Micros now);
  Status step(hal::Micros now, std::size_t budget);
  void abort();

  std::size_t file_count() const { return file_count_; }
  std::string_view file_name(std::size_t i) const { return {names_[i].data(), name_lengths_[i]}; }
  Outcome outcome(std::size_t i) const { return outcomes_[i]; }
  // Offset the receiver asked for last (ZRPOS): where a resumed file started.
  std::int64_t start_offset(std::size_t i) const { return start_offsets_[i]; }

 private:
  enum class State : std::uint8_t { wait_rinit, wait_file_pos, sending, wait_eof_ack, wait_fin, finished };
  void on_event(Parser::Event event, hal::Micros now);
  void on_header(const Header& header, hal::Micros now);
  void on_rpos(std::uint32_t position, hal::Micros now);
  void on_timeout(hal::Micros now);
  void repeat_last(hal::Micros now);
  void resend_last_block(std::uint8_t end);
  void ask(hal::Micros now);
  void arm_answer(hal::Micros now);
  void next_file(hal::Micros now);
  void send_file_header();
  void pump(hal::Micros now);
  void end_file(Outcome outcome, hal::Micros now);
  std::uint32_t max_block() const;

  FileAccess& files_;
  std::array<std::array<char, kMaxName + 1>, kMaxFiles> names_{};
  std::array<std::size_t, kMaxFiles> name_lengths_{};
  std::array<Outcome, kMaxFiles> outcomes_{};
  std::array<std::int64_t, kMaxFiles> start_offsets_{};
  std::size_t file_count_ = 0;
  std::size_t current_ = 0;

  State state_ = State::wait_rinit;
  bool crc32_ = false;
  std::uint32_t receiver_buffer_ = 0;  // ZRINIT's buffer size; 0 = may stream
  std::uint32_t full_window_ = 0;
  std::uint32_t window_ = 0;  // shrinks on errors, grows back with the block
  static constexpr std::uint32_t kMinWindow = 1024;
  std::uint32_t block_ = 0;
  FileInfo info_;
  bool file_open_ = false;
  bool frame_open_ = false;  // a ZDATA frame is going: subpackets may follow
  std::int64_t tx_pos_ = 0;
  std::int64_t acked_ = 0;
  std::int64_t last_query_ = 0;  // position of the last ZCRCQ/ZCRCW
  std::int64_t good_since_error_ = 0;
  // Round trip, measured from a question (ZFILE, ZEOF, ZCRCQ) to the next
  // header back; it sets how long a lost answer is waited for.
  static constexpr hal::Micros kMinWait = 50'000;
  hal::Micros smoothed_rtt_us_ = 0;
  hal::Micros asked_at_ = 0;
  bool sample_pending_ = false;
  std::array<std::uint8_t, kMaxBlock> block_buffer_{};
};

}  // namespace glider::fw::comms::zmodem
