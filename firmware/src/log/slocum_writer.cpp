// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_writer.hpp"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace glider::fw {
namespace {

constexpr std::size_t kMaxNameChars = 32;  // vehicle and mission names
constexpr std::size_t kHeaderBytes = 1024;

// 2-bit states, first sensor in the most significant pair of each byte.
constexpr unsigned kNotUpdated = 0;
constexpr unsigned kSameValue = 1;
constexpr unsigned kNewValue = 2;

// Little-endian (the known bytes say 0x34 0x12, as a G3S writes).
template <typename Unsigned>
void put_le(std::uint8_t* out, Unsigned value) {
  for (std::size_t i = 0; i < sizeof(Unsigned); ++i) out[i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFFU);
}

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > kMaxNameChars) return false;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_' && c != '.') return false;
  }
  return true;
}

}  // namespace

// --- one file --------------------------------------------------------------

void SlocumFileEncoder::configure(const SlocumSelection& selection, int slot, const char* extension, bool skip_empty) {
  selection_ = selection;
  slot_ = slot;
  extension_ = extension;
  skip_empty_ = skip_empty;
  count_ = 0;
  for (std::size_t i = 0; i < kSlocumFlightSensorCount; ++i) {
    if (selection.logged[i]) sensors_[count_++] = static_cast<std::uint16_t>(i);
  }
  state_bytes_ = (count_ + 3) / 4;
  list_ = slocum_sensor_list(selection);
  crc_ = slocum_list_crc(list_);
}

bool SlocumFileEncoder::store(std::size_t i, double value, std::uint8_t* out, std::uint64_t& bits) {
  if (!std::isfinite(value)) return false;
  switch (kSlocumFlightSensors[i].bytes) {
    case 1:
      if (value != std::trunc(value) || value < -128.0 || value > 127.0) return false;
      out[0] = static_cast<std::uint8_t>(static_cast<std::int8_t>(value));
      bits = out[0];
      return true;
    case 2: {
      if (value != std::trunc(value) || value < -32768.0 || value > 32767.0) return false;
      const auto raw = static_cast<std::uint16_t>(static_cast<std::int16_t>(value));
      put_le(out, raw);
      bits = raw;
      return true;
    }
    case 4: {
      const auto f = static_cast<float>(value);
      // A counter past 2^24 would read back as another number: not stored (counted).
      const bool integer = hal::kLogColumns[i].kind == hal::LogColumnKind::kInteger;
      if (!std::isfinite(f) || (integer && static_cast<double>(f) != value)) return false;
      const auto raw = std::bit_cast<std::uint32_t>(f);
      put_le(out, raw);
      bits = raw;
      return true;
    }
    default: {
      const auto raw = std::bit_cast<std::uint64_t>(value);
      put_le(out, raw);
      bits = raw;
      return true;
    }
  }
}

void SlocumFileEncoder::forget_held() {
  held_valid_.fill(false);
  stored_once_.fill(false);
}

// The cycle of `values` into the buffer (which has room for kMaxCycleBytes).
// The file-open cycle stores every value as new and does not count for the
// decimation: readers drop it, the first data cycle after it is the row.
void SlocumFileEncoder::encode(const double* values, bool file_open_cycle) {
  std::array<std::uint8_t, kSlocumFlightSensorCount> states{};
  std::array<std::uint64_t, kSlocumFlightSensorCount> bits{};
  std::array<std::array<std::uint8_t, 8>, kSlocumFlightSensorCount> bytes{};
  const double now_s = values[0];
  bool anything_but_time = false;
  for (std::size_t k = 0; k < count_; ++k) {
    const std::size_t i = sensors_[k];
    const double interval = selection_.interval_s[i];
    if (!file_open_cycle && interval > 0.0 && stored_once_[k] && now_s - stored_at_s_[k] < interval) continue;
    if (!store(i, values[i], bytes[k].data(), bits[k])) {
      if (std::isfinite(values[i])) ++unrepresentable_;
      continue;
    }
    const bool same = !file_open_cycle && held_valid_[k] && held_[k] == bits[k];
    // A decimated file stores changes only: an unchanged value costs its
    // 2 bits in every cycle of a .dbd, nothing in an .sbd.
    if (same && skip_empty_) continue;
    states[k] = same ? kSameValue : kNewValue;
    if (i != 0) anything_but_time = true;
  }
  if (skip_empty_ && !file_open_cycle && !anything_but_time) return;

  char* out = buffer_.data() + used_;
  std::size_t at = 0;
  out[at++] = 'd';
  std::memset(out + at, 0, state_bytes_);
  for (std::size_t k = 0; k < count_; ++k) {
    out[at + k / 4] = static_cast<char>(static_cast<unsigned char>(out[at + k / 4]) | (states[k] << (6 - 2 * (k % 4))));
  }
  at += state_bytes_;
  for (std::size_t k = 0; k < count_; ++k) {
    if (states[k] == kNotUpdated) continue;
    // A decimated file's first data cycle stores every value again (readers
    // drop the file-open cycle, and it never says "same").
    if (!(file_open_cycle && skip_empty_)) {
      held_[k] = bits[k];
      held_valid_[k] = true;
    }
    if (!file_open_cycle) {
      stored_at_s_[k] = now_s;
      stored_once_[k] = true;
    }
    if (states[k] != kNewValue) continue;
    const std::size_t size = kSlocumFlightSensors[sensors_[k]].bytes;
    std::memcpy(out + at, bytes[k].data(), size);
    at += size;
  }
  used_ += at;
  if (!file_open_cycle) ++buffered_cycles_;
}

void SlocumFileEncoder::flush(SlocumSink& sink) {
  if (used_ == 0) return;
  // A file whose open or header the sink refused is tried again with every
  // flush, its header still at the buffer's start.
  if (!opened_) opened_ = sink.open(slot_, name_.data());
  if (opened_ && sink.write(slot_, buffer_.data(), used_)) {
    counters_.cycles_written += buffered_cycles_;
    counters_.bytes += used_;
    header_bytes_ = 0;
    used_ = 0;
  } else {
    // The file ends at its last whole cycle (the sink's promise); what the
    // reader holds is that cycle's values: store everything anew (after a
    // new file-open cycle if the header has not reached the file yet).
    counters_.cycles_lost += buffered_cycles_;
    forget_held();
    used_ = header_bytes_;
    needs_open_cycle_ = header_bytes_ > 0;
  }
  buffered_cycles_ = 0;
}

bool SlocumFileEncoder::open(SlocumSink& sink, const char* name, const char* header, std::size_t size,
                             bool list_in_file, const double* values) {
  open_ = true;
  buffered_cycles_ = 0;
  forget_held();
  ++counters_.files;
  // The header, the list and the known-bytes cycle reach the file at once:
  // from then on it reads (with no cycle yet) whatever happens to the power.
  // Known bytes: 's' 'a', int16 0x1234, float 123.456, double 123456789.12345.
  std::array<std::uint8_t, 16> known{};
  known[0] = 's';
  known[1] = 'a';
  put_le(known.data() + 2, std::uint16_t{0x1234});
  put_le(known.data() + 4, std::bit_cast<std::uint32_t>(123.456F));
  put_le(known.data() + 8, std::bit_cast<std::uint64_t>(123456789.12345));
  const std::size_t list_size = list_in_file ? list_.size() : 0;
  const std::size_t name_size = std::strlen(name);
  // What cannot happen with this sensor table (a header over 1 KiB, a list
  // over 6 KiB): the segment's rows are lost, counted.
  broken_ =
      size == 0 || name_size >= name_.size() || size + list_size + known.size() + kMaxCycleBytes + 1 > buffer_.size();
  used_ = 0;
  header_bytes_ = 0;
  opened_ = false;
  needs_open_cycle_ = false;
  if (broken_) return false;
  std::memcpy(name_.data(), name, name_size + 1);
  std::memcpy(buffer_.data(), header, size);
  if (list_size > 0) std::memcpy(buffer_.data() + size, list_.data(), list_size);
  std::memcpy(buffer_.data() + size + list_size, known.data(), known.size());
  used_ = size + list_size + known.size();
  opened_ = sink.open(slot_, name_.data());
  if (opened_ && sink.write(slot_, buffer_.data(), used_)) {
    counters_.bytes += used_;
    used_ = 0;
  }
  header_bytes_ = used_;  // 0 once written; else tried again at the next flush
  encode(values, true);
  return header_bytes_ == 0;
}

void SlocumFileEncoder::cycle(SlocumSink& sink, const double* values, std::uint32_t flush_every) {
  if (!open_) return;
  if (broken_) {
    ++counters_.cycles_lost;
    return;
  }
  if (needs_open_cycle_) {
    needs_open_cycle_ = false;
    encode(values, true);
  }
  encode(values, false);
  if (buffer_.size() - used_ < kMaxCycleBytes + 1 || buffered_cycles_ >= flush_every) flush(sink);
}

bool SlocumFileEncoder::close(SlocumSink& sink) {
  if (!open_) return true;
  open_ = false;
  if (broken_) {  // nothing of it was ever written
    broken_ = false;
    return false;
  }
  buffer_[used_++] = 'X';
  const std::uint64_t lost_before = counters_.cycles_lost;
  flush(sink);
  const bool closed = opened_ && sink.close(slot_);
  opened_ = false;
  const bool ok = !broken_ && closed && counters_.cycles_lost == lost_before;
  broken_ = false;
  return ok;
}

// --- the segments ------------------------------------------------------------

SlocumLogger::SlocumLogger(SlocumSink& sink, SlocumLogOptions options) : sink_(sink), options_(std::move(options)) {
  for (char& c : options_.mission_name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  dbd_.configure(all_slocum_sensors(), 0, "dbd", false);
  options_.sbd.logged[0] = true;  // the time is in every cycle
  options_.sbd.interval_s[0] = 0.0;
  sbd_.configure(options_.sbd, 1, "sbd", true);
}

bool SlocumLogger::write_cache(const SlocumFileEncoder& file) {
  char name[32];
  std::snprintf(name, sizeof name, "cac/%08x.cac", static_cast<unsigned>(file.crc()));
  const int slot = 2;
  const bool ok = sink_.open(slot, name) && sink_.write(slot, file.sensor_list().data(), file.sensor_list().size());
  const bool closed = sink_.close(slot);
  if (!ok || !closed) error_ = std::string("cannot write the sensor-list cache ") + name;
  return ok && closed;
}

bool SlocumLogger::start() {
  if (!valid_name(options_.vehicle)) {
    error_ = "vehicle name '" + options_.vehicle + "' must be 1 to 32 letters, digits, '_' or '.'";
    return false;
  }
  if (!valid_name(options_.mission_name)) {
    error_ = "mission name '" + options_.mission_name + "' must be 1 to 32 letters, digits, '_' or '.'";
    return false;
  }
  if (options_.mission_of_day < 0 || options_.mission_of_day > 99 || options_.mission_number < 0 ||
      options_.mission_number > 9999) {
    error_ = "mission numbers out of range (of the day 0..99, 8.3 number 0..9999)";
    return false;
  }
  if (options_.flush_every_cycles == 0) options_.flush_every_cycles = 1;
  started_ = write_cache(dbd_) && (!options_.write_sbd || write_cache(sbd_));
  return started_;
}

std::size_t SlocumLogger::format_header(const SlocumFileEncoder& file, hal::Micros time_us, bool factored, char* out,
                                        std::size_t capacity) const {
  char open_time[32];
  format_fileopen_time(utc_date(time_us), open_time);
  const std::size_t stored = file.selection().count();
  const int n = std::snprintf(out, capacity,
                              "dbd_label:    DBD(dinkum_binary_data)file\n"
                              "encoding_ver:    5\n"
                              "num_ascii_tags:    14\n"
                              "all_sensors:    %s\n"
                              "the8x3_filename:    %04d%04d\n"
                              "full_filename:    %s\n"
                              "filename_extension:    %s\n"
                              "mission_name:    %s\n"
                              "fileopen_time:    %s\n"
                              "total_num_sensors:    %d\n"
                              "sensors_per_cycle:    %d\n"
                              "state_bytes_per_cycle:    %d\n"
                              "sensor_list_crc:    %08x\n"
                              "sensor_list_factored:    %d\n",
                              stored == kSlocumFlightSensorCount ? "T" : "F", options_.mission_number, segment_ % 10000,
                              full_name_.data(), file.extension(), options_.mission_name.c_str(), open_time,
                              static_cast<int>(kSlocumFlightSensorCount), static_cast<int>(stored),
                              static_cast<int>((stored + 3) / 4), static_cast<unsigned>(file.crc()), factored ? 1 : 0);
  return n > 0 && static_cast<std::size_t>(n) < capacity ? static_cast<std::size_t>(n) : 0;
}

void SlocumLogger::start_segment(hal::Micros time_us, const double* values) {
  if (segment_ >= 0) {
    dbd_.close(sink_);
    sbd_.close(sink_);
  } else {
    mission_date_ = utc_date(time_us);
  }
  ++segment_;
  std::snprintf(full_name_.data(), full_name_.size(), "%s-%04d-%03d-%d-%d", options_.vehicle.c_str(),
                mission_date_.year, mission_date_.day_of_year, options_.mission_of_day, segment_);
  std::snprintf(file_stem_.data(), file_stem_.size(), "%s-%04d-%03d-%02d-%03d", options_.vehicle.c_str(),
                mission_date_.year, mission_date_.day_of_year, options_.mission_of_day, segment_);
  // The mission's first files carry their sensor list (a shore station
  // that never saw this glider's caches can read them); later ones refer
  // to the cache by its CRC, as a glider does once the list is known.
  const bool list_in_file = segment_ == 0;
  char name[128];
  char header[kHeaderBytes];
  std::snprintf(name, sizeof name, "%s.%s", file_stem_.data(), dbd_.extension());
  dbd_.open(sink_, name, header, format_header(dbd_, time_us, !list_in_file, header, sizeof header), list_in_file,
            values);
  if (options_.write_sbd) {
    std::snprintf(name, sizeof name, "%s.%s", file_stem_.data(), sbd_.extension());
    sbd_.open(sink_, name, header, format_header(sbd_, time_us, !list_in_file, header, sizeof header), list_in_file,
              values);
  }
}

bool SlocumLogger::write(const hal::FlightLogRecord& record, hal::Micros row_time_us) {
  if (!started_) return false;
  // The row's time as a clock's (UTC): m_present_time, the names and fileopen_time.
  const hal::Micros time_us = row_time_us + options_.utc_at_zero_us;
  std::array<double, kSlocumFlightSensorCount> values{};
  slocum_flight_values(record, time_us, values.data());
  const bool surfaced = record.m_depth_state == 0 && last_depth_state_ != 0;
  if (segment_ < 0 || surfaced) start_segment(time_us, values.data());
  last_depth_state_ = record.m_depth_state;
  const std::uint64_t lost_before = dbd_.counters().cycles_lost;
  dbd_.cycle(sink_, values.data(), options_.flush_every_cycles);
  if (options_.write_sbd) sbd_.cycle(sink_, values.data(), options_.flush_every_cycles);
  ++rows_;
  return dbd_.counters().cycles_lost == lost_before;
}

bool SlocumLogger::finish() {
  const bool dbd_ok = dbd_.close(sink_);
  const bool sbd_ok = sbd_.close(sink_);
  return started_ && dbd_ok && sbd_ok && dbd_.counters().cycles_lost == 0 && sbd_.counters().cycles_lost == 0;
}

}  // namespace glider::fw
