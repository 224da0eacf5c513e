// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_transfer.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "glider/firmware/comms/directory_entries.hpp"

namespace glider::fw::comms {

ZmodemTransfer::ZmodemTransfer(const char* data_dir, FileAccess& outgoing, const char* incoming_dir,
                               FileAccess& incoming, const OpenFiles* open_files, const zmodem::Options& options)
    : outgoing_(outgoing), incoming_(incoming), open_files_(open_files), options_(options) {
  std::snprintf(data_dir_.data(), data_dir_.size(), "%s", data_dir);
  std::snprintf(incoming_dir_.data(), incoming_dir_.size(), "%s", incoming_dir);
  // Start-up: the folder sent files move to (none: they stay and are offered again).
  std::array<char, kMaxPath + 16> sent{};
  std::snprintf(sent.data(), sent.size(), "%s/%s", data_dir_.data(), kSentFolder);
  ::mkdir(sent.data(), 0755);
}

void ZmodemTransfer::list_files() {
  // Heap-free (it runs in the control cycle a send arrives): the folder is
  // read with getdents64 into a fixed buffer, not opendir (which mallocs).
  listed_ = 0;
  for_each_directory_entry(data_dir_.data(), [this](int dir, const char* name, unsigned char /*type*/) {
    if (listed_ == kMaxListed) return false;
    // Plain names only (what Zmodem may carry): no hidden or temporary files, no folders.
    if (name[0] == '.' || std::strlen(name) >= kMaxFileName || !zmodem::is_safe_name(name)) return true;
    struct stat st {};
    if (::fstatat(dir, name, &st, 0) != 0 || !S_ISREG(st.st_mode)) return true;
    if (open_files_ != nullptr && open_files_->is_open(name)) return true;
    std::snprintf(names_[listed_++].text, kMaxFileName, "%s", name);
    return true;
  });
  // Oldest first: Slocum segment names (<vehicle>-<yyyy>-<ddd>-<mission>-<segment>,
  // zero-padded) and 8.3 numbers sort in the order they were written.
  std::sort(names_.begin(), names_.begin() + static_cast<std::ptrdiff_t>(listed_),
            [](const FileName& a, const FileName& b) { return std::strcmp(a.text, b.text) < 0; });
}

bool ZmodemTransfer::begin_send(std::span<const FileName> files) {
  if (mode_ != Mode::kIdle || files.empty()) return false;
  received_ = 0;  // what the last zr brought has been dealt with
  sender_.emplace(link_, outgoing_, options_);
  for (const FileName& f : files) {
    if (!sender_->add_file(f.text)) break;  // more than the engine's list: the rest next time
  }
  mode_ = Mode::kSend;
  started_ = false;
  failure_ = zmodem::Failure::none;
  return true;
}

bool ZmodemTransfer::begin_receive() {
  if (mode_ != Mode::kIdle) return false;
  receiver_.emplace(link_, incoming_, options_);
  mode_ = Mode::kReceive;
  started_ = false;
  received_ = 0;
  failure_ = zmodem::Failure::none;
  return true;
}

TransferProgress ZmodemTransfer::poll(hal::Micros now_us, ByteStream& stream) {
  link_.target_ = &stream;
  zmodem::Status status = zmodem::Status::failed;
  if (mode_ == Mode::kSend && sender_) {
    if (!started_) sender_->start(now_us);
    started_ = true;
    status = sender_->step(now_us, kBudgetPerCycle);
  } else if (mode_ == Mode::kReceive && receiver_) {
    if (!started_) receiver_->start(now_us);
    started_ = true;
    status = receiver_->step(now_us, kBudgetPerCycle);
  } else {
    return {};
  }
  link_.target_ = nullptr;
  if (status == zmodem::Status::running) {
    TransferProgress p;
    p.state = TransferState::kRunning;
    p.bytes = mode_ == Mode::kSend ? sender_->bytes_out() : receiver_->bytes_in();
    return p;
  }
  return finish(status);
}

TransferProgress ZmodemTransfer::finish(zmodem::Status status) {
  TransferProgress p;
  p.state = status == zmodem::Status::done ? TransferState::kDone : TransferState::kFailed;
  if (mode_ == Mode::kSend) {
    failure_ = sender_->failure();
    p.bytes = sender_->bytes_out();
    for (std::size_t i = 0; i < sender_->file_count(); ++i) {
      const zmodem::Sender::Outcome o = sender_->outcome(i);
      if (o == zmodem::Sender::Outcome::sent || o == zmodem::Sender::Outcome::skipped) {
        ++p.files_done;
        move_to_sent(sender_->file_name(i));
      } else {
        ++p.files_failed;
      }
    }
    sender_.reset();
  } else {
    failure_ = receiver_->failure();
    p.bytes = receiver_->bytes_in();
    received_ = 0;
    for (std::size_t i = 0; i < receiver_->result_count(); ++i) {
      const zmodem::Receiver::Result& r = receiver_->result(i);
      if (!r.published) {
        ++p.files_failed;
        continue;
      }
      ++p.files_done;
      // The folder, '/', then the name as received (a plain name: is_safe_name).
      std::array<char, kMaxPath>& path = received_paths_[received_];
      const int head = std::snprintf(path.data(), kMaxPath, "%s/", incoming_dir_.data());
      const std::size_t at = head > 0 ? std::min(static_cast<std::size_t>(head), kMaxPath - 1) : 0;
      const std::size_t n = std::min(r.info.name_length, kMaxPath - 1 - at);
      std::memcpy(path.data() + at, r.info.name.data(), n);
      path[at + n] = '\0';
      ++received_;
    }
    receiver_.reset();
  }
  mode_ = Mode::kIdle;
  return p;
}

void ZmodemTransfer::move_to_sent(std::string_view name) {
  // The shore has it: into sentlogs/ (a rename in one folder tree: atomic,
  // bounded; a name is at most kMaxFileName characters).
  std::array<char, kMaxFileName + 16> to{};
  const int n = std::snprintf(to.data(), to.size(), "%s/%.*s", kSentFolder, static_cast<int>(name.size()), name.data());
  if (n > 0 && static_cast<std::size_t>(n) < to.size() && outgoing_.rename(name, std::string_view(to.data()))) {
    ++moved_;
  } else {
    ++move_failures_;
  }
}

void ZmodemTransfer::cancel() {
  if (mode_ == Mode::kSend && sender_) {
    sender_->abort();
    sender_.reset();
  } else if (mode_ == Mode::kReceive && receiver_) {
    receiver_->abort();  // the partial stays for resume, never under its real name
    receiver_.reset();
  }
  mode_ = Mode::kIdle;
}

}  // namespace glider::fw::comms
