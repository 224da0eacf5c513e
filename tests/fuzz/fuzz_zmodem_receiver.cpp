// SPDX-License-Identifier: Apache-2.0
// The Zmodem receiver as the shore (or line noise) can drive it: any byte
// stream into its header/subpacket parser and state machine, over an
// in-memory link and file store. Whatever the bytes: no crash, nothing
// written outside the store, and a file published under its real name only
// if it is whole (its length the one the ZFILE announced).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "glider/firmware/comms/zmodem_parser.hpp"
#include "glider/firmware/comms/zmodem_receiver.hpp"

namespace {

namespace zm = glider::fw::comms::zmodem;
using glider::fw::comms::ByteStream;
using glider::fw::comms::FileAccess;

class FeedStream : public ByteStream {
 public:
  FeedStream(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t read(std::span<std::uint8_t> out) override {
    // Small, varying reads: the parser must resume mid-header.
    std::size_t n = std::min<std::size_t>({out.size(), size_ - pos_, 1 + pos_ % 61});
    for (std::size_t i = 0; i < n; ++i) out[i] = data_[pos_ + i];
    pos_ += n;
    return n;
  }
  std::size_t write(std::span<const std::uint8_t> data) override { return data.size(); }
  bool done() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

class Files : public FileAccess {
 public:
  std::map<std::string, std::vector<std::uint8_t>> files;
  std::int64_t size(std::string_view name) override {
    const auto it = files.find(std::string(name));
    return it == files.end() ? -1 : static_cast<std::int64_t>(it->second.size());
  }
  std::int64_t mtime(std::string_view) override { return 0; }
  bool open(std::string_view name, Mode mode) override {
    open_ = std::string(name);
    if (mode == Mode::create) files[open_].clear();
    files[open_];
    return true;
  }
  bool seek(std::int64_t) override { return true; }
  std::size_t read(std::span<std::uint8_t>) override { return 0; }
  bool write(std::span<const std::uint8_t> data) override {
    auto& f = files[open_];
    if (f.size() + data.size() > (1u << 20)) return false;
    f.insert(f.end(), data.begin(), data.end());
    return true;
  }
  bool close() override { return true; }
  bool rename(std::string_view from, std::string_view to) override {
    files[std::string(to)] = files[std::string(from)];
    files.erase(std::string(from));
    return true;
  }
  bool remove(std::string_view name) override { return files.erase(std::string(name)) != 0; }

 private:
  std::string open_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The bare parser first: every event's data within bounds.
  zm::Parser parser;
  for (std::size_t i = 0; i < size; ++i) {
    if (parser.feed(data[i]) == zm::Parser::Event::subpacket && parser.data().size() > zm::kMaxSubpacket) std::abort();
  }
  FeedStream stream(data, size);
  Files files;
  zm::Options options;
  options.timeout_us = 1000;
  zm::Receiver receiver(stream, files, options);
  glider::hal::Micros now = 0;
  receiver.start(now);
  for (int i = 0; i < 100000 && receiver.status() == zm::Status::running && !stream.done(); ++i) {
    now += 100;
    receiver.step(now, 64);
  }
  // The last publication of each name is what the store holds: whole.
  std::map<std::string, std::int64_t> published;
  for (std::size_t i = 0; i < receiver.result_count(); ++i) {
    const auto& result = receiver.result(i);
    if (!result.published) continue;
    if (!zm::is_safe_name(result.info.name_view())) std::abort();
    published[std::string(result.info.name_view())] = result.info.length;
  }
  for (const auto& [name, length] : published) {
    const auto it = files.files.find(name);
    if (it == files.files.end()) std::abort();
    if (length >= 0 && static_cast<std::int64_t>(it->second.size()) != length) std::abort();
  }
  return 0;
}
