// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_sender.hpp"

#include <algorithm>
#include <cstring>

namespace glider::fw::comms::zmodem {

std::uint32_t Sender::max_block() const { return std::clamp<std::uint32_t>(options_.max_block, 1, kMaxBlock); }

bool Sender::add_file(std::string_view name) {
  if (file_count_ >= kMaxFiles || !is_safe_name(name)) return false;
  std::memcpy(names_[file_count_].data(), name.data(), name.size());
  names_[file_count_][name.size()] = '\0';
  name_lengths_[file_count_] = name.size();
  outcomes_[file_count_] = Outcome::pending;
  start_offsets_[file_count_] = 0;
  ++file_count_;
  return true;
}

void Sender::start(hal::Micros now) {
  status_ = Status::running;
  failure_ = Failure::none;
  state_ = State::wait_rinit;
  current_ = 0;
  parser_.reset();
  progress(now);
  // "rz\r" starts a receiver on a shell that auto-starts one; ZRQINIT asks
  // a running receiver for its ZRINIT.
  static constexpr std::array<std::uint8_t, 3> kRz = {'r', 'z', '\r'};
  encoder_.raw(kRz);
  encoder_.hex_header(Header::at(Frame::rqinit, 0));
  arm(now);
}

void Sender::abort() {
  if (status_ != Status::running) return;
  cancel_link(Failure::cancelled);
  if (file_open_) files_.close();
  file_open_ = false;
}

Status Sender::step(hal::Micros now, std::size_t budget) {
  if (status_ != Status::running) return status_;
  read_input(budget, [&](Parser::Event event, std::uint8_t) { on_event(event, now); });
  // Fill and drain the output in turns until the budget or the link is spent.
  std::size_t left = budget;
  while (status_ == Status::running && left > 0) {
    pump(now);
    const std::size_t written = flush(left);
    if (written == 0) break;
    if (state_ == State::sending) arm_answer(now);  // the link takes our data: not a silence
    left -= std::min(written, left);
  }
  if (status_ == Status::running && expired(now)) on_timeout(now);
  if (status_ == Status::running && state_ != State::finished && state_ != State::wait_fin && stalled(now))
    cancel_link(Failure::too_many_errors);
  if (status_ == Status::running && state_ == State::finished && encoder_.pending() == 0) status_ = Status::done;
  if (status_ == Status::failed && file_open_) {
    files_.close();
    file_open_ = false;
  }
  return status_;
}

void Sender::on_event(Parser::Event event, hal::Micros now) {
  switch (event) {
    case Parser::Event::cancelled:
      fail(Failure::cancelled);
      return;
    case Parser::Event::header:
      on_header(parser_.header(), now);
      return;
    case Parser::Event::bad_header:
    case Parser::Event::bad_subpacket:
      // A garbled answer to our last header: repeat it rather than wait for
      // the timeout (a repeat is harmless: the receiver answers it again).
      error();
      if (state_ == State::wait_file_pos || state_ == State::wait_eof_ack) repeat_last(now);
      return;
    default:
      return;
  }
}

void Sender::ask(hal::Micros now) {
  if (sample_pending_) return;
  sample_pending_ = true;
  asked_at_ = now;
}

void Sender::arm_answer(hal::Micros now) {
  // Until a round trip is measured, the configured timeout; then four round
  // trips (at least kMinWait), doubled for each repeat in a row, never
  // beyond the timeout: a lost answer costs about a round trip, not 10 s.
  hal::Micros wait = options_.timeout_us;
  // ZFIN is repeated only after the whole timeout: lrzsz's rz answers a
  // second ZFIN by purging its input, the "OO" with it, and then waits 10 s
  // for an "OO" that never comes (and the call may end meanwhile).
  if (smoothed_rtt_us_ > 0 && state_ != State::wait_fin) {
    wait = std::max<hal::Micros>(4 * smoothed_rtt_us_, kMinWait);
    for (int i = 0; i < retries_ && wait < options_.timeout_us; ++i) wait *= 2;
    wait = std::min(wait, options_.timeout_us);
  }
  deadline_ = now + wait;
}

void Sender::on_header(const Header& header, hal::Micros now) {
  if (sample_pending_) {
    const hal::Micros sample = now - asked_at_;
    smoothed_rtt_us_ = smoothed_rtt_us_ == 0 ? sample : (7 * smoothed_rtt_us_ + sample) / 8;
    sample_pending_ = false;
  }
  switch (header.type) {
    case Frame::rinit:
      if (state_ == State::wait_rinit) {
        crc32_ = (header.f0() & kCanFc32) != 0;
        if (header.f0() & kEscCtl) encoder_.set_escape_control(true);
        receiver_buffer_ =
            static_cast<std::uint32_t>(header.bytes[0]) | (static_cast<std::uint32_t>(header.bytes[1]) << 8);
        full_window_ = std::max(options_.window_bytes, max_block());
        if (receiver_buffer_ != 0) full_window_ = std::min(full_window_, receiver_buffer_);
        // Block and window learn the link's noise for the whole session.
        window_ = full_window_;
        block_ = max_block();
        good_since_error_ = 0;
        progress(now);
        next_file(now);
      } else if (state_ == State::wait_eof_ack) {
        end_file(Outcome::sent, now);
      }
      // In wait_file_pos a ZRINIT is not an answer to our ZFILE: lrzsz's rz
      // sends one at start and another for our ZRQINIT, and a ZFILE sent
      // again for it made rz start the file twice (every byte crossed the
      // link twice, 11425 bytes for a 4296-byte file). A ZFILE really lost
      // is sent again by the answer timer (repeat_last), as sz waits for
      // quiet before it does.
      return;
    case Frame::rpos:
      if (state_ == State::wait_file_pos || state_ == State::sending || state_ == State::wait_eof_ack)
        on_rpos(header.position(), now);
      return;
    case Frame::ack:
      if (state_ == State::sending || state_ == State::wait_eof_ack) {
        const auto position = static_cast<std::int64_t>(header.position());
        if (position > acked_ && position <= tx_pos_) {
          good_since_error_ += position - acked_;
          acked_ = position;
          progress(now);
          arm_answer(now);
          // Data gets through: grow the subpacket back, a step at a time.
          if (good_since_error_ >= 8 * static_cast<std::int64_t>(block_)) {
            block_ = std::min(block_ * 2, max_block());
            window_ = std::min(window_ * 2, full_window_);
            good_since_error_ = 0;
          }
        }
      }
      return;
    case Frame::skip:
      if (state_ == State::wait_file_pos || state_ == State::sending || state_ == State::wait_eof_ack)
        end_file(Outcome::skipped, now);
      return;
    case Frame::nak:
      // The receiver saw our last header garbled: repeat it now.
      if (state_ == State::wait_file_pos || state_ == State::wait_eof_ack || state_ == State::wait_rinit ||
          state_ == State::wait_fin)
        repeat_last(now);
      return;
    case Frame::fin:
      if (state_ == State::wait_fin) {
        static constexpr std::array<std::uint8_t, 2> kOverAndOut = {'O', 'O'};
        encoder_.raw(kOverAndOut);
        state_ = State::finished;
      }
      return;
    case Frame::abort:
    case Frame::ferr:
    case Frame::can:
      fail(Failure::cancelled);
      return;
    default:
      return;
  }
}

void Sender::on_rpos(std::uint32_t position, hal::Micros now) {
  const auto target = static_cast<std::int64_t>(position);
  if (target > info_.length || !files_.seek(target)) {
    cancel_link(Failure::file_error);
    return;
  }
  const bool advanced = target > acked_ || state_ == State::wait_file_pos;
  if (state_ == State::wait_file_pos) {
    start_offsets_[current_] = target;
  } else if (target <= acked_) {
    // A resend request without progress: smaller subpackets get through a
    // noisy link more often.
    error();
    // and a shorter window wastes less of the link on each rewind.
    block_ = std::max(block_ / 2, std::clamp<std::uint32_t>(options_.min_block, 1, max_block()));
    window_ = std::max(window_ / 2, std::min(full_window_, kMinWindow));
    good_since_error_ = 0;
  }
  encoder_.discard();
  tx_pos_ = target;
  acked_ = target;
  last_query_ = target;
  frame_open_ = false;
  state_ = State::sending;
  if (advanced) progress(now);
  arm_answer(now);
}

void Sender::next_file(hal::Micros now) {
  while (current_ < file_count_) {
    const std::string_view name = file_name(current_);
    info_ = FileInfo{};
    std::memcpy(info_.name.data(), name.data(), name.size());
    info_.name_length = name.size();
    info_.length = files_.size(name);
    info_.mtime = files_.mtime(name);
    if (info_.length >= 0 && files_.open(name, FileAccess::Mode::read)) {
      file_open_ = true;
      acked_ = 0;
      tx_pos_ = 0;
      send_file_header();
      state_ = State::wait_file_pos;
      ask(now);
      arm_answer(now);
      return;
    }
    outcomes_[current_++] = Outcome::failed;  // missing or unreadable: the others still go
  }
  encoder_.hex_header(Header::at(Frame::fin, 0));
  state_ = State::wait_fin;
  arm_answer(now);
}

void Sender::send_file_header() {
  int files_left = 0;
  std::int64_t bytes_left = 0;
  for (std::size_t i = current_; i < file_count_; ++i) {
    const std::int64_t size = files_.size(file_name(i));
    if (size < 0) continue;
    ++files_left;
    bytes_left += size;
  }
  const std::size_t length = format_file_info(info_, files_left, bytes_left, block_buffer_);
  encoder_.discard();
  encoder_.subpacket({}, kCrcE, crc32_);  // ends a garbled ZFILE subpacket still being read
  encoder_.binary_header(Header::flags(Frame::file, kConvBinary), crc32_);
  encoder_.subpacket(std::span<const std::uint8_t>(block_buffer_.data(), length), kCrcW, crc32_);
}

void Sender::end_file(Outcome outcome, hal::Micros now) {
  if (file_open_) files_.close();
  file_open_ = false;
  outcomes_[current_++] = outcome;
  progress(now);
  next_file(now);
}

void Sender::pump(hal::Micros now) {
  if (state_ != State::sending) return;
  const std::size_t need = Encoder::subpacket_cost(block_) + 2 * Encoder::kHeaderCost;
  while (state_ == State::sending && encoder_.room() >= need) {
    if (tx_pos_ - acked_ >= static_cast<std::int64_t>(window_)) return;  // wait for a ZACK
    if (!frame_open_) {
      encoder_.binary_header(Header::at(Frame::data, static_cast<std::uint32_t>(tx_pos_)), crc32_);
      frame_open_ = true;
    }
    const auto want = static_cast<std::size_t>(std::min<std::int64_t>(block_, info_.length - tx_pos_));
    const std::size_t got = want == 0 ? 0 : files_.read(std::span<std::uint8_t>(block_buffer_.data(), want));
    if (got != want) {
      cancel_link(Failure::file_error);
      return;
    }
    tx_pos_ += static_cast<std::int64_t>(got);
    const std::span<const std::uint8_t> data(block_buffer_.data(), got);
    if (tx_pos_ >= info_.length) {
      encoder_.subpacket(data, kCrcE, crc32_);
      encoder_.binary_header(Header::at(Frame::eof, static_cast<std::uint32_t>(tx_pos_)), crc32_);
      frame_open_ = false;
      state_ = State::wait_eof_ack;
      ask(now);
      arm_answer(now);
      return;
    }
    // A ZCRCQ every quarter window: the receiver's ZACKs open the window.
    std::uint8_t end = kCrcG;
    if (receiver_buffer_ != 0 && tx_pos_ - acked_ >= static_cast<std::int64_t>(window_)) {
      end = kCrcW;  // a receiver with a buffer: the frame ends, its ZACK lets us go on
      frame_open_ = false;
      last_query_ = tx_pos_;
      ask(now);
    } else if (tx_pos_ - last_query_ >= static_cast<std::int64_t>(window_ / 4)) {
      end = kCrcQ;
      last_query_ = tx_pos_;
      ask(now);
    }
    encoder_.subpacket(data, end, crc32_);
    arm_answer(now);
  }
}

void Sender::repeat_last(hal::Micros now) {
  sample_pending_ = false;  // an answer to a repeat says nothing of the round trip (Karn)
  arm_answer(now);
  // A byte garbled into XOFF stops a peer tty with IXON (lrzsz's): XON first.
  static constexpr std::array<std::uint8_t, 1> kXonByte = {kXon};
  encoder_.raw(kXonByte);
  switch (state_) {
    case State::wait_rinit:
      encoder_.hex_header(Header::at(Frame::rqinit, 0));
      return;
    case State::wait_file_pos:
      send_file_header();
      return;
    case State::sending:
      // Blocked on a lost ZACK or ZRPOS: the frame is closed (an empty
      // ZCRCW, in step with a receiver that is) and the last block goes
      // again under its own ZDATA with ZCRCW: a receiver in step answers
      // ZACK or ZRPOS at our position, one that lost sync ZRPOS at its own.
      if (frame_open_) encoder_.subpacket({}, kCrcW, crc32_);
      resend_last_block(kCrcW);
      return;
    case State::wait_eof_ack:
      // A receiver whose subpacket end was garbled still reads data: an
      // empty ZCRCE ends that subpacket (a CRC error: it asks ZRPOS); one
      // that hunts ignores it. lrzsz's rz ignores a ZEOF it is short of
      // (and waits 10 s of silence); the last block again under its ZDATA
      // makes it ask at once, or completes it.
      encoder_.subpacket({}, kCrcE, crc32_);
      resend_last_block(kCrcE);
      encoder_.binary_header(Header::at(Frame::eof, static_cast<std::uint32_t>(tx_pos_)), crc32_);
      return;
    case State::wait_fin:
      encoder_.hex_header(Header::at(Frame::fin, 0));
      return;
    case State::finished:
      status_ = Status::done;
      return;
  }
}

void Sender::resend_last_block(std::uint8_t end) {
  // Never an empty subpacket under a ZDATA that may be ahead of the
  // receiver: lrzsz's rz keeps such "out of sync blocks" and loops forever
  // on one of length 0 once it reaches its position (lrz.c, SAVE_OOSB).
  // A link that has not taken what is queued gains nothing from more.
  if (encoder_.room() < Encoder::subpacket_cost(block_) + 3 * Encoder::kHeaderCost) return;
  const std::int64_t from = std::max(acked_, tx_pos_ - static_cast<std::int64_t>(block_));
  const auto length = static_cast<std::size_t>(tx_pos_ - from);
  if (!files_.seek(from) || files_.read(std::span<std::uint8_t>(block_buffer_.data(), length)) != length) {
    cancel_link(Failure::file_error);
    return;
  }
  encoder_.binary_header(Header::at(Frame::data, static_cast<std::uint32_t>(from)), crc32_);
  encoder_.subpacket(std::span<const std::uint8_t>(block_buffer_.data(), length), end, crc32_);
  frame_open_ = false;
}

void Sender::on_timeout(hal::Micros now) {
  // Every file's outcome is known once ZFIN is out: a ZFIN still
  // unanswered after the repeats (the receiver already left) ends the
  // session as done, not failed.
  if (state_ == State::finished || (state_ == State::wait_fin && retries_ >= options_.max_retries)) {
    state_ = State::finished;
    status_ = Status::done;
    return;
  }
  parser_.reset();
  if (retry(now)) repeat_last(now);
}
}  // namespace glider::fw::comms::zmodem
