#pragma once
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "glider/hal/log_record.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/simulator.hpp"
#include "glider/sil/sim_ctd.hpp"

namespace glider::sil {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Writes the flight log in the project's CSV format (docs/flight-log.md):
// `# key: value` metadata, one header line, one row per firmware cycle, with
// the simulator's truths appended as sim_ columns. The CTD columns (sci_*)
// are the SimCtd's readings of the water at the vehicle. Numbers are written in
// their shortest exact form (std::to_chars), so the same run gives the same
// bytes; a value the firmware did not have (NaN) is an empty field.
class CsvFlightLog final : public hal::LogSink {
 public:
  CsvFlightLog(const std::string& path, const Metadata& metadata, const model::GliderSimulator& sim,
               const SimCtd& ctd);

  bool write(const hal::FlightLogRecord& record) override;

  // Flushes and closes; false (with error()) if anything was not written.
  bool close();
  bool ok() const { return ok_; }
  const std::string& error() const { return error_; }
  std::uint64_t rows() const { return rows_; }

  static const char* header();

 private:
  std::string path_;
  std::ofstream out_;
  const model::GliderSimulator& sim_;
  SimCtd ctd_;
  std::string line_;
  bool ok_ = true;
  std::string error_;
  std::uint64_t rows_ = 0;
};

}  // namespace glider::sil
