// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glider/firmware/log/binary_rows.hpp"
#include "glider/firmware/log/log_text.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/simulator.hpp"
#include "glider/sil/sim_ctd.hpp"

namespace glider::sil {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Real Slocum logs are not one row per second: the flight computer logs a
// dbd cycle every ~4 s (2-5 s), the science columns miss a cycle now and then,
// and nothing is logged during the surface dialogs (gaps of 20-230 s; see
// /work/shared/data/real/README.md). Enabled, the SIL log is thinned the same
// way, from its own seeded stream, so analyses are tested on data shaped
// like the real logs. The firmware and the run's statistics still see every
// cycle: only the file is thinned.
struct LogGaps {
  bool enabled = false;
  double min_interval_s = 2.0;       // a row is kept, then the next one at least
  double max_interval_s = 5.0;       //   U(min, max) seconds later
  double sci_blank_fraction = 0.05;  // of the kept rows, with empty sci_* fields
  double surface_gap_min_s = 20.0;   // every time the glider reaches the surface
  double surface_gap_max_s = 200.0;  //   (m_depth_state 0), no rows for U(min, max) s
};

// The file's form: the CSV text, or its binary form (firmware/log/
// binary_rows.hpp: the same lines but a record per row, read by every tool
// and converted back to the same CSV bytes on demand).
enum class LogEncoding { kCsv, kBinary };

// Writes the flight log in the project's CSV format (docs/flight-log.md):
// `# key: value` metadata, one header line, one row per firmware cycle, with
// the simulator's truths appended as sim_ columns. The CTD columns (sci_*)
// are the SimCtd's readings of the water at the vehicle. The firmware columns
// are the target's (fw::format_log_fields: shortest exact numbers, so the same
// run gives the same bytes; NaN is an empty field). Rows are held in memory
// and written whole, 64 KiB at a time, with write(2): the file only ever ends
// on a row boundary (a failed write is cut back to the last whole row), and a
// finished log ends with the `# end: ...` trailer (finish()).
class CsvFlightLog final : public hal::LogSink {
 public:
  CsvFlightLog(const std::string& path, const Metadata& metadata, const model::GliderSimulator& sim, const SimCtd& ctd,
               const LogGaps& gaps = {}, std::uint64_t gap_seed = 0, LogEncoding encoding = LogEncoding::kCsv);

  ~CsvFlightLog() override;
  CsvFlightLog(const CsvFlightLog&) = delete;
  CsvFlightLog& operator=(const CsvFlightLog&) = delete;

  bool write(const hal::FlightLogRecord& record) override;

  // Writes the trailer ("complete", "aborted <cause>" or "stopped <reason>",
  // `lost` rows the firmware could not hand over) and closes.
  bool finish(std::string_view outcome, std::uint64_t lost);
  // Writes what is held and closes, without a trailer (a run that failed);
  // false (with error()) if anything was not written.
  bool close();
  bool ok() const { return ok_; }
  const std::string& error() const { return error_; }
  std::uint64_t rows() const { return rows_; }  // written (after thinning)

  static std::string header();

 private:
  // True if the row of this record is left out of the file (LogGaps);
  // never when thinning is off.
  bool thinned_out(const hal::FlightLogRecord& record);
  hal::Micros draw_us(double min_s, double max_s);

  bool flush();
  void close_block();
  bool append_csv_row(const hal::FlightLogRecord& record, std::span<const double> sim_values);

  std::string path_;
  int fd_ = -1;
  std::string pending_;              // whole rows not yet written
  std::uint64_t flushed_bytes_ = 0;  // the file's length: always a row boundary
  const model::GliderSimulator& sim_;
  SimCtd ctd_;
  LogEncoding encoding_;
  fw::LogRowFormatter formatter_;  // kCsv: the same bytes as fw::format_log_fields, faster
  fw::BinaryRowEncoder encoder_;   // kBinary
  LogGaps gaps_;
  PortableRandom gap_random_;
  hal::Micros next_row_us_ = 0;          // thinning: the earliest time of the next row
  hal::Micros surface_gap_end_us_ = -1;  // no rows before this while at the surface
  bool at_surface_ = false;
  bool ok_ = true;
  std::string error_;
  std::uint64_t rows_ = 0;
};

}  // namespace glider::sil
