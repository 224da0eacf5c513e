// SPDX-License-Identifier: Apache-2.0
#pragma once
// A serial line of the plant: a pseudo-terminal whose slave side the
// firmware opens as its device (a symlink at a path of our choosing, as
// udev would give it), and whose master side the plant reads and writes.
#include <cstddef>
#include <string>

namespace glider::plant {

class PtyDevice {
 public:
  // Creates the pty and the symlink `link` to its slave (replacing a stale
  // one). Throws std::runtime_error naming `link` on failure.
  explicit PtyDevice(const std::string& link);
  ~PtyDevice();
  PtyDevice(const PtyDevice&) = delete;
  PtyDevice& operator=(const PtyDevice&) = delete;

  int master_fd() const { return master_; }
  const std::string& link() const { return link_; }
  const std::string& slave_path() const { return slave_path_; }

  // Writes a whole sentence or nothing: a line nobody reads fills up and
  // drops what the sensor sends, as a UART with no listener would.
  bool write_all_or_drop(const std::string& bytes);
  unsigned long long dropped_bytes() const { return dropped_; }
  // A sensor read for its current value (the compass): when the line's
  // buffer has no room, the backlog nobody read is discarded first, so the
  // reader's next read ends with this sentence, not with one from before it
  // stopped reading (a firmware stalled longer than the buffer holds: 3 KiB
  // is 7.7 simulated s of $PTNTHPR at 10 Hz, 0.4 s of wall at time scale 20).
  bool write_newest(const std::string& bytes);
  unsigned long long discarded_bytes() const { return discarded_; }
  // A byte stream (the modem's data): as much as the line's buffer has room
  // for now (the same 3 KiB as write_all_or_drop); the caller keeps the rest.
  std::size_t write_some(const char* data, std::size_t size);

 private:
  int master_ = -1;
  // The plant keeps the slave open too: without it the master reports a
  // hang-up (and poll() spins) whenever the firmware has it closed.
  int slave_keepalive_ = -1;
  std::string link_;
  std::string slave_path_;
  unsigned long long dropped_ = 0;
  unsigned long long discarded_ = 0;
};

}  // namespace glider::plant
