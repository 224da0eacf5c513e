// SPDX-License-Identifier: Apache-2.0
#pragma once
// The firmware's own Slocum data files (docs/slocum-binary.md, "Writing"):
// every log row becomes a cycle of the segment's full-resolution .dbd (every
// sensor) and, chosen by an sbdlist.dat, of its decimated .sbd; a new segment
// (a new pair of files) starts at every arrival at the surface, as a Slocum
// opens new files when it surfaces, and the previous pair is ended ('X') and
// closed durably, so a power cut costs at most the open segment (whose cycles
// up to the cut still read).
//
// Per row the work is bounded: the values are encoded into a fixed buffer per
// file (no allocation after start()); a buffer goes to the sink when it could
// not hold another cycle or every `flush_every_cycles` rows. Cycles in a
// buffer the sink refused are counted lost (as the CSV log counts its lost
// rows) and the next cycle stores every value anew, so nothing read later is
// wrong: the reader sees a gap.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "glider/firmware/log/slocum_format.hpp"
#include "glider/firmware/log/slocum_list.hpp"
#include "glider/firmware/log/slocum_sink.hpp"
#include "glider/hal/log_record.hpp"

namespace glider::fw {

struct SlocumLogOptions {
  std::string vehicle = "glider";           // the names' first word (Slocum: the vehicle name)
  std::string mission_name = "MISSION.MI";  // header mission_name (upper-cased, as GliderDOS)
  int mission_of_day = 0;                   // <mission> in the long name: missions started that UTC day before
  int mission_number = 0;                   // the 8.3 name's first 4 digits: missions run before
  SlocumSelection sbd;                      // the .sbd's sensors (parse_slocum_list)
  bool write_sbd = true;
  std::uint32_t flush_every_cycles = 60;  // at most this many rows wait in a buffer
  // UTC of row time 0, added to every row's time: m_present_time (Unix
  // seconds, as a Slocum's), the names' <yyyy>-<ddd> and the header's
  // fileopen_time. The target's rows are UTC already (0); SIL's count from
  // its launch, at the simulated UTC launch time given here (its CSV log
  // keeps the seconds since launch).
  hal::Micros utc_at_zero_us = 0;
};

struct SlocumFileCounters {
  std::uint64_t cycles_written = 0;  // data cycles the sink accepted (the file-open cycle not counted)
  std::uint64_t cycles_lost = 0;     // rows that did not reach the file (sink refused)
  std::uint64_t files = 0;           // files opened
  std::uint64_t bytes = 0;           // bytes the sink accepted
};

// One open file: its sensors, the values it holds, its buffer.
class SlocumFileEncoder {
 public:
  static constexpr std::size_t kBufferBytes = 8192;
  static constexpr std::size_t kMaxCycleBytes = 1 + (kSlocumFlightSensorCount + 3) / 4 + 8 * kSlocumFlightSensorCount;

  // Start-up: what the file stores; `skip_empty` leaves out cycles in which
  // nothing but the time would be stored (the decimated files).
  void configure(const SlocumSelection& selection, int slot, const char* extension, bool skip_empty);
  const SlocumSelection& selection() const { return selection_; }
  const std::string& sensor_list() const { return list_; }
  std::uint32_t crc() const { return crc_; }
  const char* extension() const { return extension_; }

  // Opens `name` and writes the header (`header`, `size`), the sensor list
  // when `list_in_file`, the known-bytes cycle and the file-open cycle
  // (`values`, dropped by readers). False: the sink refused the open or the
  // header; both are tried again at every flush (the rows in between lost).
  bool open(SlocumSink& sink, const char* name, const char* header, std::size_t size, bool list_in_file,
            const double* values);
  // One row: its cycle into the buffer (flushed when needed).
  void cycle(SlocumSink& sink, const double* values, std::uint32_t flush_every);
  // Ends the file ('X'), writes what is buffered, closes durably.
  bool close(SlocumSink& sink);

  const SlocumFileCounters& counters() const { return counters_; }
  std::uint64_t unrepresentable() const { return unrepresentable_; }
  bool is_open() const { return open_; }

 private:
  // The stored bytes of `value` for sensor `i` into `out` (little-endian);
  // false when the value is not finite or does not fit the sensor's type.
  static bool store(std::size_t i, double value, std::uint8_t* out, std::uint64_t& bits);
  void encode(const double* values, bool file_open_cycle);
  void flush(SlocumSink& sink);
  void forget_held();

  SlocumSelection selection_{};
  std::array<std::uint16_t, kSlocumFlightSensorCount> sensors_{};  // the stored sensors' indices
  std::size_t count_ = 0;
  std::size_t state_bytes_ = 0;
  int slot_ = 0;
  const char* extension_ = "dbd";
  bool skip_empty_ = false;
  std::string list_;
  std::uint32_t crc_ = 0;

  std::array<std::uint64_t, kSlocumFlightSensorCount> held_{};  // stored bits of the value a reader holds
  std::array<bool, kSlocumFlightSensorCount> held_valid_{};
  std::array<double, kSlocumFlightSensorCount> stored_at_s_{};  // decimation: time of the last stored value
  std::array<bool, kSlocumFlightSensorCount> stored_once_{};
  std::array<char, kBufferBytes> buffer_{};
  std::size_t used_ = 0;
  std::uint32_t buffered_cycles_ = 0;
  bool open_ = false;
  bool broken_ = false;           // the header could not be made: rows lost until the next segment
  std::array<char, 128> name_{};  // the open file's name (the open is retried until the sink takes it)
  bool opened_ = false;
  std::size_t header_bytes_ = 0;   // header bytes at the buffer's start that have not reached the file
  bool needs_open_cycle_ = false;  // a refused flush took the file-open cycle with it
  std::uint64_t unrepresentable_ = 0;
  SlocumFileCounters counters_;
};

class SlocumLogger {
 public:
  SlocumLogger(SlocumSink& sink, SlocumLogOptions options);
  SlocumLogger(const SlocumLogger&) = delete;
  SlocumLogger& operator=(const SlocumLogger&) = delete;

  // Start-up: writes the sensor-list caches (cac/<crc>.cac). False: error().
  bool start();
  // One log row, m_present_time = `time_us` + utc_at_zero_us. Opens the
  // first segment, or a new one when the vehicle has just reached the
  // surface. Returns false if the row cannot reach the .dbd.
  bool write(const hal::FlightLogRecord& record, hal::Micros time_us);
  // Ends and closes the open segment. False if any row or file was lost.
  bool finish();

  const SlocumFileCounters& dbd() const { return dbd_.counters(); }
  const SlocumFileCounters& sbd() const { return sbd_.counters(); }
  std::uint64_t rows() const { return rows_; }
  std::int32_t segments() const { return segment_ + 1; }
  std::uint64_t unrepresentable() const { return dbd_.unrepresentable() + sbd_.unrepresentable(); }
  const std::string& error() const { return error_; }
  std::uint32_t dbd_crc() const { return dbd_.crc(); }
  std::uint32_t sbd_crc() const { return sbd_.crc(); }
  // The open segment's long name without extension ("glider-2026-330-0-3").
  const char* full_name() const { return full_name_.data(); }

 private:
  void start_segment(hal::Micros time_us, const double* values);
  bool write_cache(const SlocumFileEncoder& file);
  std::size_t format_header(const SlocumFileEncoder& file, hal::Micros time_us, bool factored, char* out,
                            std::size_t capacity) const;

  SlocumSink& sink_;
  SlocumLogOptions options_;
  SlocumFileEncoder dbd_;
  SlocumFileEncoder sbd_;
  std::int32_t segment_ = -1;
  std::int32_t last_depth_state_ = 0;
  UtcDate mission_date_{};
  std::array<char, 96> full_name_{};  // "vehicle-yyyy-ddd-m-s"
  std::array<char, 96> file_stem_{};  // "vehicle-yyyy-ddd-mm-sss" (the sortable form)
  std::uint64_t rows_ = 0;
  bool started_ = false;
  std::string error_;
};

// The logger as a log sink of the SIL (m_present_time: the row's own time).
class SlocumLogSink final : public hal::LogSink {
 public:
  explicit SlocumLogSink(SlocumLogger& logger) : logger_(logger) {}
  bool write(const hal::FlightLogRecord& record) override { return logger_.write(record, record.time_us); }

 private:
  SlocumLogger& logger_;
};

}  // namespace glider::fw
