// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/csv_flight_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

#include "glider/firmware/log/log_text.hpp"
#include "glider/hal/sim_log_columns.hpp"
#include "glider/units.hpp"

namespace glider::sil {
namespace {

constexpr std::size_t kFlushBytes = 64 * 1024;  // whole rows, at most this much held in memory

// The SIL's appended columns (hal::kSimLogColumns) of the vehicle's truth and
// the simulated CTD's reading.
hal::SimLogRow sim_log_row(const model::Truth& t, const CtdReading& ctd) {
  hal::SimLogRow row;
  row.sci_water_temp = ctd.temperature_c;
  row.sci_water_cond = ctd.conductivity_s_m;
  row.sci_water_pressure = ctd.pressure_bar;
  row.sim_east_m = t.east_m;
  row.sim_north_m = t.north_m;
  row.sim_depth_m = t.depth_m;
  row.sim_heading_rad = t.heading_rad;
  row.sim_pitch_rad = t.pitch_rad;
  row.sim_speed_m_s = t.speed_m_s;
  row.sim_alpha_rad = t.alpha_rad;
  row.sim_glide_path_rad = t.glide_path_rad;
  row.sim_horizontal_speed_m_s = t.horizontal_speed_m_s;
  row.sim_depth_rate_m_s = t.depth_rate_m_s;
  row.sim_net_buoyancy_kg = t.net_buoyancy_kg;
  row.sim_ballast_pumped_cc = m3_to_cc(t.pumped_volume_m3);
  row.sim_battpos_in = m_to_in(t.battery_pos_m);
  row.sim_fin_rad = t.fin_rad;
  row.sim_yaw_rate_rad_s = t.yaw_rate_rad_s;
  row.sim_density_kg_m3 = t.water.density_kg_m3;
  row.sim_u_water_m_s = t.water.current_east_m_s;
  row.sim_v_water_m_s = t.water.current_north_m_s;
  row.sim_w_water_m_s = t.water.vertical_velocity_m_s;
  row.sim_temperature_c = t.water.temperature_c;
  row.sim_practical_salinity = t.water.practical_salinity;
  return row;
}

}  // namespace

std::string CsvFlightLog::header() {
  std::string header = fw::log_header();
  for (const hal::SimLogColumn& column : hal::kSimLogColumns) {
    header += ',';
    header += column.name;
  }
  return header;
}

CsvFlightLog::CsvFlightLog(const std::string& path, const Metadata& metadata, const model::GliderSimulator& sim,
                           const SimCtd& ctd, const LogGaps& gaps, std::uint64_t gap_seed, LogEncoding encoding)
    : path_(path), sim_(sim), ctd_(ctd), encoding_(encoding), gaps_(gaps), gap_random_(gap_seed) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    ok_ = false;
    error_ = path + ": cannot open for writing: " + std::strerror(errno);
    return;
  }
  pending_.reserve(kFlushBytes + 4096);
  pending_ += "# writer: glider-sil\n";  // one of our writers: the log ends with a trailer (docs/flight-log.md)
  if (encoding_ == LogEncoding::kBinary) pending_ += fw::kBinaryEncodingLine;
  for (const auto& [key, value] : metadata) {
    pending_ += "# " + key + ": " + value + '\n';
  }
  pending_ += header() + '\n';
  // The text lines join the first checked block (docs/flight-log.md, "Binary logs").
  if (encoding_ == LogEncoding::kBinary) encoder_.cover(pending_.data(), pending_.size());
  flush();
}

CsvFlightLog::~CsvFlightLog() {
  if (fd_ >= 0) ::close(fd_);
}

// Writes the held rows with as few write() calls as the kernel allows. A
// failure (disk full) cuts the file back to the last whole row.
bool CsvFlightLog::flush() {
  if (!ok_ || pending_.empty()) return ok_;
  std::size_t done = 0;
  while (done < pending_.size()) {
    const ssize_t n = ::write(fd_, pending_.data() + done, pending_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      if (::ftruncate(fd_, static_cast<off_t>(flushed_bytes_)) != 0) {
        error_ = path_ + ": write failed (" + std::strerror(error) + ") and the torn row could not be cut off";
      } else {
        error_ = path_ + ": write failed after " + std::to_string(rows_) + " rows: " + std::strerror(error);
      }
      ok_ = false;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  flushed_bytes_ += pending_.size();
  pending_.clear();
  return true;
}

hal::Micros CsvFlightLog::draw_us(double min_s, double max_s) {
  return static_cast<hal::Micros>(std::llround((min_s + (max_s - min_s) * gap_random_.uniform()) * 1e6));
}

bool CsvFlightLog::thinned_out(const hal::FlightLogRecord& r) {
  if (!gaps_.enabled) return false;
  const bool surface = r.m_depth_state == 0;
  if (surface && !at_surface_) {
    surface_gap_end_us_ = r.time_us + draw_us(gaps_.surface_gap_min_s, gaps_.surface_gap_max_s);
  }
  at_surface_ = surface;
  if (surface && r.time_us < surface_gap_end_us_) return true;
  if (r.time_us < next_row_us_) return true;
  next_row_us_ = r.time_us + draw_us(gaps_.min_interval_s, gaps_.max_interval_s);
  return false;
}

bool CsvFlightLog::write(const hal::FlightLogRecord& r) {
  if (!ok_) return false;
  if (thinned_out(r)) return true;  // not logged by design: not a lost row
  const model::Truth t = sim_.truth();
  // The science bay is off at the surface (m_depth_state 0), as in real logs.
  const bool science_missed = gaps_.enabled && gap_random_.uniform() < gaps_.sci_blank_fraction;
  const CtdReading ctd = science_missed ? CtdReading{} : ctd_.sample(t, r.m_depth_state != 0);
  const hal::SimLogRow sim_row = sim_log_row(t, ctd);
  std::array<double, hal::kSimLogColumns.size()> sim_values{};
  for (std::size_t i = 0; i < sim_values.size(); ++i) sim_values[i] = hal::kSimLogColumns[i].value(sim_row);
  if (encoding_ == LogEncoding::kBinary) {
    constexpr std::size_t kFirmware = hal::kLogColumns.size();
    std::array<double, kFirmware + hal::kSimLogColumns.size()> values{};
    for (std::size_t i = 1; i < kFirmware; ++i) values[i] = hal::kLogColumns[i].value(r);
    std::copy(sim_values.begin(), sim_values.end(), values.begin() + kFirmware);
    char record[fw::kMaxBinaryRecordBytes];
    pending_.append(record, encoder_.encode(r.time_us, values.data(), values.size(), record));
  } else if (!append_csv_row(r, sim_values)) {
    return false;
  }
  ++rows_;
  if (pending_.size() < kFlushBytes) return true;
  close_block();
  return flush();
}

// A binary log's block ends where its bytes go to the file: a check record.
void CsvFlightLog::close_block() {
  if (encoding_ != LogEncoding::kBinary) return;
  char check[fw::kBinaryCheckRecordBytes];
  pending_.append(check, encoder_.close_block(check));
}

bool CsvFlightLog::append_csv_row(const hal::FlightLogRecord& r, std::span<const double> sim_values) {
  char line[fw::kLogFieldsMaxChars + 1024];
  std::size_t at = formatter_.fields(r, r.time_us, line, sizeof line);
  std::size_t column = 0;
  for (const double value : sim_values) {
    const std::size_t n = at > 0 ? formatter_.number(column++, value, line + at, sizeof line - at) : 0;
    at = n > 0 ? at + n : 0;
  }
  if (at == 0) {
    ok_ = false;
    error_ = path_ + ": a row did not fit its buffer";
    return false;
  }
  line[at - 1] = '\n';
  pending_.append(line, at);
  return true;
}

bool CsvFlightLog::finish(std::string_view outcome, std::uint64_t lost) {
  if (fd_ < 0) return ok_;
  char trailer[256];
  const std::size_t n = fw::format_log_trailer(outcome, rows_, lost, trailer, sizeof trailer);
  if (ok_) {
    pending_.append(trailer, n);
    if (encoding_ == LogEncoding::kBinary) encoder_.cover(trailer, n);
    close_block();  // a finished binary log ends in the check of its last block and trailer
  }
  flush();
  return close();
}

bool CsvFlightLog::close() {
  if (fd_ < 0) return ok_;
  flush();
  if (::close(fd_) != 0 && ok_) {
    ok_ = false;
    error_ = path_ + ": close failed: " + std::strerror(errno);
  }
  fd_ = -1;
  return ok_;
}

}  // namespace glider::sil
