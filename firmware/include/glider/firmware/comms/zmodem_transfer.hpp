// SPDX-License-Identifier: Apache-2.0
#pragma once
// FileTransfer (what the console's send/s/zs/zr hand over) done by the
// Zmodem engine: `send` runs a zmodem::Sender over the call's stream from
// the vehicle's data directory (the shore's `rz` receives), `zr` runs a
// zmodem::Receiver into the from-shore directory (the shore's `sz` sends).
// The sender and receiver live in fixed storage (std::optional, emplaced
// per transfer): no heap. Listing the data directory reads it with
// getdents64 into a fixed buffer: no heap either (opendir would malloc).
#include <array>
#include <optional>

#include "glider/firmware/comms/file_access.hpp"
#include "glider/firmware/comms/file_transfer.hpp"
#include "glider/firmware/comms/zmodem_receiver.hpp"
#include "glider/firmware/comms/zmodem_sender.hpp"

namespace glider::fw::comms {

// Files still being written (the open log segment): not offered to a send.
class OpenFiles {
 public:
  virtual ~OpenFiles() = default;
  virtual bool is_open(const char* name) const = 0;
};

// What was sent is not sent again (as a Slocum moves its sent logs to
// SENTLOGS): a file the shore's receiver took whole (or skipped: it has it)
// is moved into `<data_dir>/sentlogs/` when the send ends, so the next call's
// `send *.sbd` offers only what is new; a file cut by a lost carrier stays
// and is offered (and resumed) again.
class ZmodemTransfer final : public FileTransfer {
 public:
  static constexpr const char* kSentFolder = "sentlogs";
  static constexpr std::size_t kMaxListed = 512;
  static constexpr std::size_t kMaxPath = 256;
  // Bytes read and written per control cycle (the modem's buffer takes what fits).
  static constexpr std::size_t kBudgetPerCycle = 1024;

  // data_dir/outgoing: the files a send picks from (regular files only);
  // incoming_dir/incoming: where zr publishes complete files.
  ZmodemTransfer(const char* data_dir, FileAccess& outgoing, const char* incoming_dir, FileAccess& incoming,
                 const OpenFiles* open_files = nullptr, const zmodem::Options& options = {});

  std::size_t file_count() const override { return listed_; }
  const char* file_name(std::size_t index) const override { return names_[index].text; }
  void list_files() override;
  bool begin_send(std::span<const FileName> files) override;
  bool begin_receive() override;
  TransferProgress poll(hal::Micros now_us, ByteStream& stream) override;
  void cancel() override;
  std::size_t received_count() const override { return received_; }
  const char* received_path(std::size_t index) const override { return received_paths_[index].data(); }
  // Why the last transfer failed ("none" if it did not).
  const char* last_failure() const { return zmodem::failure_name(failure_); }
  // Files sent and moved to sentlogs/ so far; moves that failed (the file stays, offered again).
  std::uint32_t files_moved_to_sent() const { return moved_; }
  std::uint32_t sent_moves_failed() const { return move_failures_; }

 private:
  // The engine keeps one stream for its life; the call's stream is handed
  // over at each poll, so this forwards to it.
  class Link final : public ByteStream {
   public:
    std::size_t read(std::span<std::uint8_t> out) override { return target_ ? target_->read(out) : 0; }
    std::size_t write(std::span<const std::uint8_t> data) override { return target_ ? target_->write(data) : 0; }
    ByteStream* target_ = nullptr;
  };
  enum class Mode : std::uint8_t { kIdle, kSend, kReceive };
  TransferProgress finish(zmodem::Status status);
  void move_to_sent(std::string_view name);

  std::array<char, kMaxPath> data_dir_{};
  std::array<char, kMaxPath> incoming_dir_{};
  FileAccess& outgoing_;
  FileAccess& incoming_;
  const OpenFiles* open_files_;
  zmodem::Options options_;
  Link link_;
  std::optional<zmodem::Sender> sender_;
  std::optional<zmodem::Receiver> receiver_;
  Mode mode_ = Mode::kIdle;
  bool started_ = false;
  zmodem::Failure failure_ = zmodem::Failure::none;
  std::array<FileName, kMaxListed> names_{};
  std::size_t listed_ = 0;
  std::array<std::array<char, kMaxPath>, zmodem::Receiver::kMaxResults> received_paths_{};
  std::size_t received_ = 0;
  std::uint32_t moved_ = 0;
  std::uint32_t move_failures_ = 0;
};

}  // namespace glider::fw::comms
