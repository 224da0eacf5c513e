// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_receiver.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <string_view>

namespace glider::fw::comms::zmodem {
namespace {

// The partial's name carries the length and mtime announced by the sender,
// so a resume only ever continues the same version of a file.
std::size_t make_temp_name(const FileInfo& info, std::span<char> out) {
  std::size_t pos = info.name_length;
  std::memcpy(out.data(), info.name.data(), pos);
  const auto put_number = [&](char separator, std::int64_t value) {
    out[pos++] = separator;
    const auto [end, error] = std::to_chars(out.data() + pos, out.data() + out.size() - 8, value);
    pos = error == std::errc() ? static_cast<std::size_t>(end - out.data()) : pos;
  };
  put_number('.', info.length);
  put_number('-', info.mtime);
  std::memcpy(out.data() + pos, ".zpart", 6);
  pos += 6;
  out[pos] = '\0';
  return pos;
}

}  // namespace

Header Receiver::rinit() const {
  // Full duplex, overlapped I/O, CRC-32; buffer size 0: the sender may stream.
  return Header::flags(
      Frame::rinit, static_cast<std::uint8_t>(kCanFdx | kCanOvio | kCanFc32 | (options_.escape_control ? kEscCtl : 0)));
}

void Receiver::send(const Header& header) {
  if (encoder_.room() < Encoder::kHeaderCost) return;
  encoder_.hex_header(header);
  const bool question = header.type == Frame::rpos || header.type == Frame::rinit || header.type == Frame::nak;
  if (question && asked_us_ == kNotAsked) asked_us_ = now_;
  // A ZRPOS, or a ZNAK for the file header, is repeated if it goes unobeyed
  // (a header whose ZPAD/ZDLE lead-in is garbled vanishes: the peer waits).
  const bool repeated = header.type == Frame::rpos || (header.type == Frame::nak && between_files());
  if (repeated && resync_at_us_ < 0) {
    resync_interval_us_ = std::min(options_.timeout_us, std::max(kMinResyncUs, 4 * round_trip_us_));
    resync_at_us_ = now_ + resync_interval_us_;
  }
}

void Receiver::resync(hal::Micros now) {
  // Our ZRPOS (or, waiting for a whole ZFILE, our ZNAK) went unobeyed for 4
  // round trips: lost or garbled. Again, XON first (a garbled byte may have
  // been an XOFF to the peer's tty). Without this a lost ZNAK cost the whole
  // 10 s timeout: sz waits for an answer to its ZFILE as long (lrzsz at 1 %
  // corruption stalled so in its file-header stage, ZNAK after ZNAK).
  error();
  asked_us_ = kRepeated;
  static constexpr std::array<std::uint8_t, 1> kXonByte = {kXon};
  encoder_.raw(kXonByte);
  resync_interval_us_ = std::min(options_.timeout_us, 2 * resync_interval_us_);
  resync_at_us_ = now + resync_interval_us_;
  if (encoder_.room() >= Encoder::kHeaderCost) {
    encoder_.hex_header(between_files() ? Header::flags(Frame::nak, 0)
                                        : Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
  }
}

void Receiver::send_fin() {
  // XON first, every time: a garbled byte of our previous ZFIN may have been
  // an XOFF to the sender's tty (lrzsz's has IXON). sz was then stopped in
  // write() of its repeated ZFIN or its "OO", for good: the repeats below
  // (a ZFIN has no trailing XON) never restarted it, and sz never exited
  // (comms.zmodem.lrzsz.from_sz_corrupted, seed 640975; replayed by
  // comms.zmodem.lrzsz.from_sz_fin_xoff_*). A sender not stopped ignores the XON.
  static constexpr std::array<std::uint8_t, 1> kXonByte = {kXon};
  if (encoder_.room() < Encoder::kHeaderCost + kXonByte.size()) return;
  encoder_.raw(kXonByte);
  send(Header::flags(Frame::fin, 0));
}

void Receiver::start(hal::Micros now) {
  status_ = Status::running;
  failure_ = Failure::none;
  state_ = State::wait_file;
  now_ = now;
  asked_us_ = kNotAsked;
  round_trip_us_ = 0;
  resync_at_us_ = -1;
  result_count_ = 0;
  parser_.reset();
  heard_us_ = now;
  sender_seen_ = false;
  progress(now);
  send(rinit());
  arm(now);
}

Status Receiver::step(hal::Micros now, std::size_t budget) {
  if (status_ != Status::running) return status_;
  now_ = now;
  read_input(budget, [&](Parser::Event event, std::uint8_t byte) {
    heard_us_ = now;
    on_event(event, byte, now);
  });
  if (status_ == Status::running && expired(now)) on_timeout(now);
  if (status_ == Status::running && state_ == State::finishing && o_count_ == 0 && fin_repeats_left_ > 0 &&
      now >= fin_again_us_) {
    // No "OO" yet: our ZFIN may have vanished (its lead-in garbled) and the
    // sender waits for it, or a byte of it became XOFF and the sender's tty
    // holds its answer; said again (XON first) kFinRepeats times, a third
    // of the wait apart, before the "OO" is given up on.
    send_fin();
    --fin_repeats_left_;
    fin_again_us_ = now + fin_interval_us_;
  }
  const bool mid_frame = (state_ == State::receiving && accepting_) || (between_files() && resync_at_us_ < 0);
  if (status_ == Status::running && mid_frame && now - heard_us_ >= std::max(kMinResyncUs, 4 * round_trip_us_)) {
    // Silence in the middle of a frame: the end of a subpacket (data, or the
    // ZFILE's) was garbled and the sender waits for the answer it asked for
    // (lrzsz's sz: 10 s). Ask again at once, as for an unobeyed ZRPOS.
    // Between files a ZNAK: sz resends its ZFILE, or, still waiting for our
    // ZRINIT after its ZEOF, answers ZNAK, which we answer with ZRINIT.
    error();
    accepting_ = false;
    parser_.reset();
    send(between_files() ? Header::flags(Frame::nak, 0) : Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
  }
  const bool waiting = (state_ == State::receiving && !accepting_) || between_files();
  if (status_ == Status::running && !waiting) resync_at_us_ = -1;
  if (status_ == Status::running && resync_at_us_ >= 0 && now >= resync_at_us_) resync(now);
  if (status_ == Status::running && state_ != State::finishing) stalled(now);
  flush(budget);
  if (status_ == Status::failed) close_partial();
  return status_;
}

void Receiver::abort() {
  if (status_ != Status::running) return;
  cancel_link(Failure::cancelled);
  close_partial();
}

void Receiver::close_partial() {
  // The partial stays under its temporary name: the next session resumes it.
  if (file_open_) files_.close();
  file_open_ = false;
  accepting_ = false;
}

void Receiver::on_event(Parser::Event event, std::uint8_t byte, hal::Micros now) {
  switch (event) {
    case Parser::Event::cancelled:
      close_partial();
      fail(Failure::cancelled);
      return;
    case Parser::Event::header:
      on_header(parser_.header(), now);
      return;
    case Parser::Event::subpacket:
      on_subpacket(now);
      return;
    case Parser::Event::bad_header:
      // Answered at once, so a noisy link costs a round trip, not a timeout:
      // ZNAK makes the sender repeat its header; while resynchronising, the
      // garbled header may have been the ZDATA we wait for.
      error();
      if (state_ == State::receiving && !accepting_) {
        send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
      } else if (state_ == State::wait_file || state_ == State::file_info) {
        send(Header::flags(Frame::nak, 0));
      } else if (state_ == State::finishing) {
        // The sender's repeat of its ZFIN (all it says now): our answer was
        // garbled and lrzsz's sz waits for a ZFIN, tens of seconds, before it exits.
        send_fin();
      }
      return;
    case Parser::Event::bad_subpacket:
      error();
      if (state_ == State::receiving && accepting_) {
        // Everything before offset_ is on file: ask for the rest again.
        accepting_ = false;
        send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
      } else if (state_ == State::file_info) {
        send(Header::flags(Frame::nak, 0));
      }
      return;
    case Parser::Event::none:
      if (state_ == State::finishing && byte == 'O' && ++o_count_ >= 2) status_ = Status::done;
      return;
  }
}

void Receiver::on_header(const Header& header, hal::Micros now) {
  data_for_ = header.type;
  // Smoothed (TCP's 1/8 gain), not the largest seen: one slow answer (a busy
  // peer) made every later repeat wait 4 x that for the rest of the session.
  if (asked_us_ >= 0) {
    const hal::Micros sample = now - asked_us_;
    round_trip_us_ = round_trip_us_ == 0 ? sample : (7 * round_trip_us_ + sample) / 8;
  }
  asked_us_ = kNotAsked;
  switch (header.type) {
    case Frame::rqinit:
      close_partial();
      state_ = State::wait_file;
      sender_seen_ = true;
      send(rinit());
      arm(now);
      return;
    case Frame::sinit:
      // The sender wants control characters escaped on our side too.
      if (header.f0() & kTEscCtl) encoder_.set_escape_control(true);
      return;
    case Frame::file:
      // A ZFILE while a file is open may be a late copy of that file's (we
      // answered an earlier copy with ZRPOS): its subpacket decides
      // (on_subpacket). Dropping the file here sent lrzsz's sz, already
      // streaming it, into a ZNAK ping-pong with us.
      if (state_ == State::receiving) {
        accepting_ = false;
        arm(now);
        return;
      }
      close_partial();
      state_ = State::file_info;
      // Its subpacket follows: a repeat pending from before waits a full interval again.
      if (resync_at_us_ >= 0) resync_at_us_ = now + resync_interval_us_;
      arm(now);
      return;
    case Frame::data:
      if (state_ != State::receiving) return;
      accepting_ = header.position() == static_cast<std::uint32_t>(offset_);
      if (accepting_) resync_at_us_ = -1;  // obeyed
      if (!accepting_) {
        error();
        send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
      }
      arm(now);
      return;
    case Frame::eof:
      if (state_ == State::receiving) {
        // A ZEOF short of what we hold went out before our ZRPOS: ask again.
        if (header.position() == static_cast<std::uint32_t>(offset_)) {
          finish_file(now);
        } else {
          send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
        }
      } else if (state_ == State::wait_file) {
        // Our ZRINIT after the last file was lost: repeat it.
        send(rinit());
      }
      arm(now);
      return;
    case Frame::fin:
      close_partial();
      state_ = State::finishing;
      o_count_ = 0;
      send_fin();
      // Every file is settled: the sender's "OO" (which lrzsz's sz may not
      // get out before it hangs up) is waited for a tenth of the timeout, or
      // three of the link's round trips if longer (Iridium: seconds; a stray
      // "OO" would reach the console glued to the shore's next command),
      // a repeated ZFIN answered meanwhile. Our timed repeats split that
      // wait evenly (each at least a round trip after the one before), so
      // the wait is no longer: 1.5 s instead of 1 s made every session whose
      // "OO" is lost (the pty's hang-up can drop it) 0.5 s longer.
      deadline_ = now + std::min(options_.timeout_us, std::max(options_.timeout_us / 10, 3 * round_trip_us_));
      fin_interval_us_ = (deadline_ - now) / (kFinRepeats + 1);
      fin_again_us_ = now + fin_interval_us_;
      fin_repeats_left_ = kFinRepeats;
      return;
    case Frame::nak:
      // The sender saw our last header garbled (lrzsz's sz answers so, then
      // waits): say it again.
      if (state_ == State::receiving) {
        accepting_ = false;
        send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
      } else if (state_ == State::wait_file) {
        send(rinit());
      }
      return;
    case Frame::freecnt:
      send(Header::at(Frame::ack, 0));  // 0: free space unknown
      return;
    case Frame::abort:
    case Frame::ferr:
    case Frame::can:
      close_partial();
      send(Header::flags(Frame::fin, 0));
      fail(Failure::cancelled);
      return;
    default:
      return;  // ZCOMMAND and the rest: never executed, ignored
  }
}

void Receiver::on_subpacket(hal::Micros now) {
  const auto data = parser_.data();
  if (data_for_ == Frame::sinit) {
    send(Header::at(Frame::ack, 1));
    return;
  }
  if (data_for_ == Frame::file && state_ == State::receiving) {
    FileInfo again;
    if (parse_file_info(data, again) && again.name_view() == info_.name_view() && again.length == info_.length &&
        again.mtime == info_.mtime) {
      send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));  // the same file: go on from here
      return;
    }
    close_partial();  // another file: the one open stays a partial
    state_ = State::file_info;
  }
  if (data_for_ == Frame::file && state_ == State::file_info) {
    open_file(now);
    return;
  }
  if (data_for_ != Frame::data || state_ != State::receiving || !accepting_) return;
  if (!data.empty() && !files_.write(data)) {
    close_partial();
    cancel_link(Failure::file_error);
    return;
  }
  offset_ += static_cast<std::int64_t>(data.size());
  progress(now);
  arm(now);
  if (parser_.end() == kCrcQ || parser_.end() == kCrcW)
    send(Header::at(Frame::ack, static_cast<std::uint32_t>(offset_)));
  if (parser_.end() == kCrcW) {
    // The frame ends here and the sender waits for our ZACK before its next
    // ZDATA. A garbled ZACK left lrzsz's sz waiting 10 s; now, as for an
    // unobeyed ZRPOS, a ZRPOS at offset_ follows unless that ZDATA comes.
    accepting_ = false;
    if (resync_at_us_ < 0) {
      resync_interval_us_ = std::min(options_.timeout_us, std::max(kMinResyncUs, 4 * round_trip_us_));
      resync_at_us_ = now + resync_interval_us_;
    }
  }
}

void Receiver::open_file(hal::Micros now) {
  if (!parse_file_info(parser_.data(), info_)) {
    // Not a plain file name (a path, a dot file, junk): refused.
    state_ = State::wait_file;
    send(Header::flags(Frame::skip, 0));
    return;
  }
  make_temp_name(info_, temp_name_);
  const std::string_view temp(temp_name_.data());
  const std::int64_t have = files_.size(temp);
  // Resume only a partial of this very version, never past its end.
  const bool resume = info_.length >= 0 && have > 0 && have <= info_.length;
  if (!files_.open(temp, resume ? FileAccess::Mode::append : FileAccess::Mode::create)) {
    cancel_link(Failure::file_error);
    return;
  }
  file_open_ = true;
  offset_ = resume ? have : 0;
  state_ = State::receiving;
  accepting_ = false;
  progress(now);
  arm(now);
  send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
}

void Receiver::finish_file(hal::Micros now) {
  file_open_ = false;
  accepting_ = false;
  const bool closed = files_.close();
  const std::string_view temp(temp_name_.data());
  // A file that ends short of (or past) its announced length is not the
  // file the sender announced: it is dropped, never published.
  const bool whole = info_.length < 0 || offset_ == info_.length;
  const bool published = closed && whole && files_.rename(temp, info_.name_view());
  if (!published) files_.remove(temp);
  record(published);
  progress(now);
  state_ = State::wait_file;
  sender_seen_ = true;
  send(rinit());
}

void Receiver::record(bool published) {
  if (result_count_ >= kMaxResults) return;
  results_[result_count_].info = info_;
  results_[result_count_].published = published;
  ++result_count_;
}

void Receiver::on_timeout(hal::Micros now) {
  if (state_ == State::finishing) {
    status_ = Status::done;
    return;
  }
  if (!retry(now)) return;
  asked_us_ = kRepeated;
  parser_.reset();
  // A byte garbled into XOFF stops a peer tty with IXON (lrzsz's): XON first.
  static constexpr std::array<std::uint8_t, 1> kXonByte = {kXon};
  encoder_.raw(kXonByte);  // a frame whose end was garbled is void: hunt for the next header
  if (state_ == State::receiving) {
    accepting_ = false;
    send(Header::at(Frame::rpos, static_cast<std::uint32_t>(offset_)));
  } else if (state_ == State::file_info) {
    // The ZFILE's subpacket never ended: ZNAK has it sent again (a ZRINIT
    // here makes lrzsz's sz wait for 5 s of silence first).
    send(Header::flags(Frame::nak, 0));
  } else {
    send(rinit());
  }
}

}  // namespace glider::fw::comms::zmodem
