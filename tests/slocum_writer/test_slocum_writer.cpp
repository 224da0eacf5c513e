// SPDX-License-Identifier: Apache-2.0
// The firmware's Slocum writer (docs/slocum-binary.md, "Writing") checked
// with the project's reader (tools/files/slocum): a SIL flight's .dbd equals its
// CSV log value for value (8-byte sensors bit for bit, 4-byte ones as the
// float nearest the logged double, integers exactly); the .sbd holds what
// its sbdlist asks and nothing else; the caches' CRCs are Slocum's; a power
// cut keeps every closed segment; a failing sink loses rows (counted) but
// never makes a wrong value; a bad sbdlist.dat is refused with file:line.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_format.hpp"
#include "glider/firmware/log/slocum_list.hpp"
#include "glider/firmware/log/slocum_lz4_sink.hpp"
#include "glider/firmware/log/slocum_writer.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/slocum/binary_file.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/lz4_blocks.hpp"

namespace {

using namespace glider;
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(GLIDER_TEST_OUTPUT_DIR) / "slocum_writer" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> files_with(const fs::path& dir, const std::string& extension) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == extension) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The value a sensor of `bytes` stored bytes reads back as, for a logged double.
double stored(double value, int bytes) {
  if (std::isnan(value)) return value;
  return bytes == 4 ? static_cast<double>(static_cast<float>(value)) : value;
}

bool same(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

int sensor_bytes(const std::string& name) {
  const auto i = fw::slocum_flight_sensor(name);
  return i ? fw::kSlocumFlightSensors[*i].bytes : 0;
}

// A SIL flight of the box mission (12 surfacings) with the CSV log and the
// Slocum files, the .sbd chosen by `sbdlist`.
struct Flight {
  fs::path dir;
  fs::path csv;
  sil::ScenarioResult result;
};

Flight fly(const std::string& name, const std::string& sbdlist, bool lz4 = false) {
  Flight flight;
  flight.dir = fresh_dir(name);
  flight.csv = flight.dir / "flight.csv";
  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_comet.toml");
  const auto loaded = fw::mission_file::load_mission_file(
      GLIDER_SOURCE_DIR "/boards/missions/box_current/missions/box.mi", sil::mission_vehicle(vehicle, 200.0), {});
  CHECK_TRUE(loaded.config.has_value());
  sil::ScenarioOptions options;
  options.max_sim_time_s = 43200.0;
  options.log_path = flight.csv.string();
  options.slocum_directory = (flight.dir / "slocum").string();
  options.slocum_lz4 = lz4;
  options.slocum.vehicle = "comet";
  options.slocum.mission_name = "box.mi";
  const fw::SlocumListResult list = fw::parse_slocum_list(sbdlist, "test sbdlist.dat");
  CHECK_EQUAL(std::string(), list.error);
  options.slocum.sbd = list.selection;
  flight.result = sil::run_scenario(vehicle, *loaded.config, options);
  CHECK_EQUAL(std::string(), flight.result.error);
  return flight;
}

}  // namespace

TEST_GROUP(SlocumWriterFormat){};

// Slocum's sensor_list_crc, on the six real caches (each named by its CRC).
TEST(SlocumWriterFormat, ListCrcIsSlocumsOnTheRealCaches) {
  int checked = 0;
  for (const char* deployment : {"comet-2016", "comet-2019"}) {
    const fs::path cac = fs::path(GLIDER_SOURCE_DIR "/tests/data/real/dbd") / deployment / "cac";
    for (const auto& entry : fs::directory_iterator(cac)) {
      char crc[16];
      std::snprintf(crc, sizeof crc, "%08x", static_cast<unsigned>(fw::slocum_list_crc(read_text(entry.path()))));
      CHECK_EQUAL(entry.path().stem().string(), std::string(crc));
      ++checked;
    }
  }
  CHECK_EQUAL(6, checked);
}

// The list's lines have the form of a glider's .cac (the real cache's own line for m_depth).
TEST(SlocumWriterFormat, SensorListLinesAreACachesLines) {
  const std::string list = fw::slocum_sensor_list(fw::all_slocum_sensors());
  CHECK(list.find("s: T    0    0 8 m_present_time timestamp\n") == 0);
  CHECK(list.find("s: T    1    1 4 m_depth m\n") != std::string::npos);
  fw::SlocumSelection some;
  some.logged[0] = some.logged[11] = true;
  const std::string partial = fw::slocum_sensor_list(some);
  CHECK(partial.find("s: F    1   -1 4 m_depth m\n") != std::string::npos);
  CHECK(partial.find("s: T   11    1 1 m_depth_state enum\n") != std::string::npos);
}

TEST(SlocumWriterFormat, FileOpenTimeIsCtimesText) {
  char text[32];
  // 2016-06-23 17:50:39 UTC: comet-2016-174-5-0's fileopen_time, day 174 in its name.
  const fw::UtcDate date = fw::utc_date(1466704239LL * 1000000);
  fw::format_fileopen_time(date, text);
  STRCMP_EQUAL("Thu_Jun_23_17:50:39_2016", text);
  CHECK_EQUAL(174, date.day_of_year);
  fw::format_fileopen_time(fw::utc_date(1735790400LL * 1000000), text);  // 2025-01-02 04:00:00
  STRCMP_EQUAL("Thu_Jan__2_04:00:00_2025", text);
}

TEST_GROUP(SlocumWriterList){};

namespace {
std::string refusal(const std::string& text) { return fw::parse_slocum_list(text, "sbdlist.dat").error; }
}  // namespace

TEST(SlocumWriterList, NamesAndDecimationsAreRead) {
  const auto r = fw::parse_slocum_list("# comment\n\nm_depth 10 # every 10 s\n  M_PITCH\nm_gps_lat 0\n", "f");
  CHECK_EQUAL(std::string(), r.error);
  CHECK_TRUE(r.selection.logged[0]);  // the time is added
  CHECK_TRUE(r.selection.logged[1]);
  CHECK_EQUAL(10.0, r.selection.interval_s[1]);
  CHECK_TRUE(r.selection.logged[*fw::slocum_flight_sensor("m_pitch")]);
  CHECK_EQUAL(4U, r.selection.count());
}

TEST(SlocumWriterList, BadListsAreRefusedWithFileAndLine) {
  STRCMP_CONTAINS("sbdlist.dat:2: sensor 'm_foo' is not one the firmware logs", refusal("m_depth\nm_foo\n").c_str());
  STRCMP_CONTAINS("sbdlist.dat:1: sensor m_depth: decimation 'nan' is not a number of seconds in [0, 86400]",
                  refusal("m_depth nan\n").c_str());
  STRCMP_CONTAINS("decimation '-1' is not", refusal("m_depth -1\n").c_str());
  STRCMP_CONTAINS("decimation 'inf' is not", refusal("m_depth inf\n").c_str());
  STRCMP_CONTAINS("decimation '1e9' is not", refusal("m_depth 1e9\n").c_str());
  STRCMP_CONTAINS("decimation 'ten' is not", refusal("m_depth ten\n").c_str());
  STRCMP_CONTAINS("sbdlist.dat:3: sensor 'm_depth' is listed twice (first at line 1)",
                  refusal("m_depth\nm_pitch\nm_depth 5\n").c_str());
  STRCMP_CONTAINS("sbdlist.dat:1: sensor m_depth: unexpected 'x'", refusal("m_depth 5 x\n").c_str());
  STRCMP_CONTAINS("sbdlist.dat:1: sensor m_present_time: decimation '5' refused",
                  refusal("m_present_time 5\n").c_str());
  STRCMP_CONTAINS("cannot open", fw::read_slocum_list("/nonexistent/sbdlist.dat").error.c_str());
}

TEST_GROUP(SlocumWriterSil){};

// Every .dbd value equals the CSV log's, row for row.
TEST(SlocumWriterSil, DbdReadsBackAsTheCsvLog) {
  const Flight flight = fly("dbd_equals_csv", std::string(fw::kDefaultSbdList));
  const flightlog::FlightLog csv = flightlog::read_flight_log(flight.csv);
  const auto dbd = files_with(flight.dir / "slocum", ".dbd");
  CHECK(dbd.size() >= 10);  // a segment per surfacing
  CHECK_EQUAL(static_cast<std::size_t>(flight.result.slocum_segments), dbd.size());
  CHECK_EQUAL(0U, flight.result.slocum_dbd.cycles_lost);
  CHECK(fs::exists(flight.dir / "slocum" / "cac"));
  // Names as a glider's: vehicle-year-day-mission-segment, 8.3 name in the header.
  CHECK_EQUAL(std::string("comet-1970-000-00-000.dbd"), dbd.front().filename().string());
  const slocum::BinaryFile first = slocum::read_binary_file(dbd.front());
  CHECK_EQUAL(std::string("comet-1970-000-0-0"), *first.header().tag("full_filename"));
  CHECK_EQUAL(std::string("00000000"), *first.header().tag("the8x3_filename"));
  CHECK_EQUAL(std::string("BOX.MI"), *first.header().tag("mission_name"));
  CHECK_FALSE(first.header().sensor_list_factored);  // the mission's first files carry their list
  CHECK_TRUE(slocum::read_binary_file(dbd.back()).header().sensor_list_factored);

  std::vector<std::string> inputs;
  for (const auto& f : dbd) inputs.push_back(f.string());
  slocum::DeploymentOptions options;
  const slocum::Deployment read = slocum::read_deployment(slocum::deployment_files(inputs), options);
  CHECK_EQUAL(0U, read.warnings.size());
  CHECK_EQUAL(csv.rows(), read.log.rows());
  std::size_t compared = 0;
  for (const hal::LogColumn& column : hal::kLogColumns) {
    const std::string name(column.name);
    const int bytes = sensor_bytes(name);
    const auto& want = csv.column(name);
    // A sensor with no value in the whole flight is not a column of the read log.
    bool any = false;
    for (const double v : want) any = any || !std::isnan(v);
    if (!any) continue;
    const auto& got = read.log.column(name);
    for (std::size_t row = 0; row < csv.rows(); ++row) {
      if (!same(stored(want[row], bytes), got[row])) {
        FAIL((name + " row " + std::to_string(row) + ": csv " + std::to_string(want[row]) + " dbd " +
              std::to_string(got[row]))
                 .c_str());
      }
      ++compared;
    }
  }
  CHECK(compared > 20 * csv.rows());
}

// The .sbd holds, per sensor of the list, the changed values at most once
// per decimation interval, each equal to the CSV's at its time.
TEST(SlocumWriterSil, SbdHonoursTheSbdlist) {
  const std::string list = "m_present_time\nm_depth 20\nm_pitch 60\nm_depth_state\nm_gps_lat\nm_battery 300\n";
  const Flight flight = fly("sbd_decimation", list);
  const fw::SlocumSelection selection = fw::parse_slocum_list(list, "l").selection;
  const flightlog::FlightLog csv = flightlog::read_flight_log(flight.csv);
  const auto& csv_time = csv.time();
  const auto sbd = files_with(flight.dir / "slocum", ".sbd");
  const auto dbd = files_with(flight.dir / "slocum", ".dbd");
  CHECK_EQUAL(dbd.size(), sbd.size());
  std::map<std::string, std::size_t> stored_values;
  for (std::size_t f = 0; f < sbd.size(); ++f) {
    const slocum::BinaryFile file = slocum::read_binary_file(sbd[f]);
    CHECK_TRUE(file.complete());
    CHECK_EQUAL(selection.count(), file.sensors().size());
    CHECK_EQUAL(std::string("F"), *file.header().tag("all_sensors"));
    // The segment's rows: the .dbd's times.
    const slocum::TimeSeries rows = slocum::get(slocum::read_binary_file(dbd[f]), "m_present_time");
    std::vector<double> cycle_times;  // the times of the cycles something was stored in
    for (const slocum::Sensor& sensor : file.sensors()) {
      const std::size_t index = *fw::slocum_flight_sensor(sensor.name);
      if (index == 0) continue;
      const slocum::TimeSeries got = slocum::get(file, sensor.name, true);
      // The expected series, from the CSV by the rule: changes only, at
      // most one per interval, the segment starting afresh.
      slocum::TimeSeries want;
      const auto& column = csv.column(sensor.name);
      double held = std::nan("");
      double last_t = -1e300;
      for (std::size_t row = 0; row < csv.rows(); ++row) {
        if (csv_time[row] < rows.time.front() || csv_time[row] > rows.time.back()) continue;
        const double v = stored(column[row], sensor.bytes);
        if (std::isnan(v) || csv_time[row] - last_t < selection.interval_s[index] || same(v, held)) continue;
        want.time.push_back(csv_time[row]);
        want.value.push_back(v);
        held = v;
        last_t = csv_time[row];
      }
      CHECK_EQUAL(want.time.size(), got.time.size());
      for (std::size_t i = 0; i < std::min(want.time.size(), got.time.size()); ++i) {
        CHECK(same(want.time[i], got.time[i]));
        CHECK(same(want.value[i], got.value[i]));
        if (i > 0) CHECK(got.time[i] - got.time[i - 1] >= selection.interval_s[index]);
      }
      stored_values[sensor.name] += got.time.size();
      cycle_times.insert(cycle_times.end(), got.time.begin(), got.time.end());
    }
    // A cycle is written when something besides the time is stored in it.
    std::sort(cycle_times.begin(), cycle_times.end());
    cycle_times.erase(std::unique(cycle_times.begin(), cycle_times.end()), cycle_times.end());
    const slocum::TimeSeries time = slocum::get(file, "m_present_time");
    CHECK_TRUE(time.value == cycle_times);
  }
  // The decimation thinned: m_depth (changes every cycle) at most once per 20 s.
  CHECK(stored_values["m_depth"] * 20 <= csv.rows() + 20 * sbd.size());
  CHECK(stored_values["m_depth"] * 25 > csv.rows());
  CHECK(stored_values["m_gps_lat"] > 0);
  CHECK(stored_values["m_battery"] > 0);
}

TEST_GROUP(SlocumWriterFaults){};

namespace {

// Rows of a synthetic flight: a yo per 100 cycles, at the surface every 300.
hal::FlightLogRecord synthetic_row(int i) {
  hal::FlightLogRecord r;
  r.time_us = 1'700'000'000'000'000LL + static_cast<hal::Micros>(i) * 4'000'000;
  r.m_depth = 0.37 * (i % 300);
  r.m_pitch = std::sin(i * 0.01);
  r.m_depth_state = i % 300 < 10 ? 0 : 1 + (i / 50) % 2;
  r.m_gps_lat = i % 300 < 10 ? 4330.123 + i * 1e-4 : std::nan("");
  r.m_lat = 4330.0 + i * 1e-5;
  r.x_yo_count = i / 100;
  r.x_dr_error_m = std::nan("");
  return r;
}

// A sink that stops at a byte budget, as the card does when the power goes:
// what reached it stays, nothing after (no close, no fsync).
class PowerCutSink final : public fw::SlocumSink {
 public:
  PowerCutSink(fw::SlocumSink& inner, std::size_t budget) : inner_(inner), budget_(budget) {}
  bool open(int slot, const char* name) override { return alive() && inner_.open(slot, name); }
  bool write(int slot, const char* data, std::size_t size) override {
    if (!alive() || size > budget_) {
      budget_ = 0;
      return false;
    }
    budget_ -= size;
    return inner_.write(slot, data, size);
  }
  bool close(int slot) override { return alive() && inner_.close(slot); }

 private:
  bool alive() const { return budget_ > 0; }
  fw::SlocumSink& inner_;
  std::size_t budget_;
};

// A sink that refuses writes in a window (a full card that recovers).
class FlakySink final : public fw::SlocumSink {
 public:
  explicit FlakySink(fw::SlocumSink& inner) : inner_(inner) {}
  bool open(int slot, const char* name) override { return inner_.open(slot, name); }
  bool write(int slot, const char* data, std::size_t size) override {
    ++writes_;
    if (writes_ >= 30 && writes_ < 40) return false;
    return inner_.write(slot, data, size);
  }
  bool close(int slot) override { return inner_.close(slot); }

 private:
  fw::SlocumSink& inner_;
  int writes_ = 0;
};

// A sink that refuses the first two writes after every open: the header,
// then the first buffer of cycles (a card that is slow to come back after
// the file was made).
class SlowAfterOpenSink final : public fw::SlocumSink {
 public:
  explicit SlowAfterOpenSink(fw::SlocumSink& inner) : inner_(inner) {}
  bool open(int slot, const char* name) override {
    refuse_[static_cast<std::size_t>(slot)] = 2;
    return inner_.open(slot, name);
  }
  bool write(int slot, const char* data, std::size_t size) override {
    int& refuse = refuse_[static_cast<std::size_t>(slot)];
    if (slot < 2 && refuse > 0) {  // the data files, not the caches
      --refuse;
      return false;
    }
    return inner_.write(slot, data, size);
  }
  bool close(int slot) override { return inner_.close(slot); }

 private:
  fw::SlocumSink& inner_;
  std::array<int, fw::SlocumSink::kSlots> refuse_{};
};

// Writes `rows` synthetic rows through a logger on `sink` (flushing every
// 10 rows) and finishes; returns the logger's counters.
struct Written {
  fw::SlocumFileCounters dbd;
  fw::SlocumFileCounters sbd;
  bool finished = false;
};
Written write_synthetic(fw::SlocumSink& sink, int rows) {
  fw::SlocumLogOptions options;
  options.vehicle = "unit";
  options.flush_every_cycles = 10;
  fw::SlocumLogger logger(sink, options);
  CHECK_TRUE(logger.start());
  for (int i = 0; i < rows; ++i) logger.write(synthetic_row(i), synthetic_row(i).time_us);
  Written written;
  written.finished = logger.finish();
  written.dbd = logger.dbd();
  written.sbd = logger.sbd();
  return written;
}

void check_rows(const slocum::BinaryFile& file, int first_row) {
  const slocum::TimeSeries depth = slocum::get(file, "m_depth");
  const slocum::TimeSeries time = slocum::get(file, "m_present_time");
  CHECK_EQUAL(time.time.size(), depth.time.size());
  for (std::size_t k = 0; k < depth.time.size(); ++k) {
    const int row = first_row + static_cast<int>(k);
    const hal::FlightLogRecord r = synthetic_row(row);
    CHECK(same(static_cast<double>(r.time_us) / 1e6, depth.time[k]));
    CHECK(same(stored(r.m_depth, 4), depth.value[k]));
  }
}

}  // namespace

// A power cut mid-segment: every closed segment reads whole; the cut one
// reads up to its last whole buffer.
TEST(SlocumWriterFaults, PowerCutKeepsTheClosedSegments) {
  const fs::path dir = fresh_dir("power_cut");
  fw::SlocumDirectorySink disk(dir.string());
  PowerCutSink cut(disk, 95'000);
  fw::SlocumLogOptions options;
  options.vehicle = "unit";
  fw::SlocumLogger logger(cut, options);
  CHECK_TRUE(logger.start());
  int rows = 0;
  for (; rows < 3000; ++rows) logger.write(synthetic_row(rows), synthetic_row(rows).time_us);
  CHECK_FALSE(logger.finish());
  CHECK(logger.dbd().cycles_lost > 0);
  const auto dbd = files_with(dir, ".dbd");
  CHECK(dbd.size() >= 3);
  std::size_t complete = 0;
  int first_row = 0;
  for (std::size_t f = 0; f < dbd.size(); ++f) {
    first_row = static_cast<int>(f) * 300;  // a segment per 300 rows
    if (f + 1 == dbd.size()) break;
    const slocum::BinaryFile file = slocum::read_binary_file(dbd[f]);
    CHECK_TRUE(file.complete());  // closed before the cut: whole
    check_rows(file, first_row);
    CHECK_EQUAL(300U, slocum::get(file, "m_depth").time.size());
    ++complete;
  }
  CHECK(complete >= 2);
  // The file open at the cut: empty, or its header and the cycles of every
  // buffer before the cut (never a wrong value).
  if (fs::file_size(dbd.back()) > 0) {
    const slocum::BinaryFile open = slocum::read_binary_file(dbd.back());
    CHECK_FALSE(open.complete());
    check_rows(open, first_row);
  }
}

// Writes refused for a while: those rows are lost (counted), the rows after
// them are stored with their own values (never a "same value" pointing at
// a lost cycle).
TEST(SlocumWriterFaults, RefusedWritesLoseRowsNotValues) {
  const fs::path dir = fresh_dir("flaky");
  fw::SlocumDirectorySink disk(dir.string());
  FlakySink flaky(disk);
  const Written logger = write_synthetic(flaky, 900);
  CHECK_FALSE(logger.finished);
  const std::uint64_t lost = logger.dbd.cycles_lost + logger.sbd.cycles_lost;
  CHECK(lost > 0);
  CHECK_EQUAL(900U, logger.dbd.cycles_written + logger.dbd.cycles_lost);
  std::size_t read_rows = 0;
  for (const auto& path : files_with(dir, ".dbd")) {
    // A file whose last buffer (with its end 'X') was refused ends at its
    // last whole cycle: it reads, incomplete. A refused header is written
    // with the next buffer the sink takes: no file stays empty.
    CHECK(fs::file_size(path) > 0);
    const slocum::BinaryFile file = slocum::read_binary_file(path);
    const slocum::TimeSeries depth = slocum::get(file, "m_depth");
    const slocum::TimeSeries pitch = slocum::get(file, "m_pitch");
    const slocum::TimeSeries yos = slocum::get(file, "x_yo_count");
    for (std::size_t k = 0; k < depth.time.size(); ++k) {
      const int row = static_cast<int>(std::llround((depth.time[k] - 1.7e9) / 4.0));
      const hal::FlightLogRecord r = synthetic_row(row);
      CHECK(same(stored(r.m_depth, 4), depth.value[k]));
      CHECK(same(stored(r.m_pitch, 4), pitch.value[k]));
      CHECK(same(static_cast<double>(r.x_yo_count), yos.value[k]));
    }
    read_rows += depth.time.size();
  }
  CHECK_EQUAL(static_cast<std::size_t>(logger.dbd.cycles_written), read_rows);
}

// The LZ4 forms (--slocum-lz4): the same flight's .dcd/.scd/.ccc decompress
// to the bytes of its .dbd/.sbd/.cac, and the reader reads them (the data
// files with their compressed caches) as it reads the plain ones.
TEST(SlocumWriterSil, Lz4FormsHoldTheSameBytes) {
  const Flight plain = fly("plain", std::string(fw::kDefaultSbdList));
  const Flight packed = fly("lz4", std::string(fw::kDefaultSbdList), true);
  CHECK_EQUAL(0U, files_with(packed.dir / "slocum", ".dbd").size());
  std::size_t compared = 0;
  std::uintmax_t plain_bytes = 0;
  std::uintmax_t packed_bytes = 0;
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{{".dbd", ".dcd"}, {".sbd", ".scd"}}) {
    const auto originals = files_with(plain.dir / "slocum", from);
    const auto compressed = files_with(packed.dir / "slocum", to);
    CHECK_EQUAL(originals.size(), compressed.size());
    for (std::size_t i = 0; i < std::min(originals.size(), compressed.size()); ++i) {
      CHECK_EQUAL(originals[i].stem().string(), compressed[i].stem().string());
      const slocum::Decompressed bytes = slocum::decompress_blocks(read_text(compressed[i]), compressed[i].string());
      CHECK_FALSE(bytes.damage.has_value());
      CHECK_TRUE(bytes.bytes == read_text(originals[i]));
      CHECK_TRUE(slocum::read_binary_file(compressed[i]).complete());
      plain_bytes += fs::file_size(originals[i]);
      packed_bytes += fs::file_size(compressed[i]);
      ++compared;
    }
  }
  CHECK(compared >= 20);
  CHECK(packed_bytes < plain_bytes);  // smaller (by about a fifth: encoded floats compress little)
  for (const auto& cache : files_with(packed.dir / "slocum" / "cac", ".ccc")) {
    const fs::path original = plain.dir / "slocum" / "cac" / (cache.stem().string() + ".cac");
    CHECK_TRUE(slocum::decompress_blocks(read_text(cache), cache.string()).bytes == read_text(original));
  }
  std::printf("\nLZ4: %ju bytes of .dbd/.sbd -> %ju\n", plain_bytes, packed_bytes);
}

// A second mission into the same directory gets the next numbers: its files
// never overwrite the first one's.
TEST(SlocumWriterFaults, NextMissionGetsTheNextNumbers) {
  const fs::path dir = fresh_dir("numbers");
  fw::SlocumDirectorySink disk(dir.string());
  const hal::Micros start = synthetic_row(0).time_us;
  for (int mission = 0; mission < 2; ++mission) {
    const fw::SlocumMissionNumbers next = fw::next_slocum_mission(dir.string(), "unit", start);
    CHECK_EQUAL(mission, next.mission_of_day);
    CHECK_EQUAL(mission, next.mission_number);
    fw::SlocumLogOptions options;
    options.vehicle = "unit";
    options.mission_of_day = next.mission_of_day;
    options.mission_number = next.mission_number;
    fw::SlocumLz4Sink packed(disk);  // the second mission in the LZ4 forms: its number is read from them
    fw::SlocumLogger logger(mission == 0 ? static_cast<fw::SlocumSink&>(disk) : packed, options);
    CHECK_TRUE(logger.start());
    for (int i = 0; i < 400; ++i) logger.write(synthetic_row(i), synthetic_row(i).time_us);
    CHECK_TRUE(logger.finish());
  }
  // Another day starts at mission 0 of that day; the 8.3 number goes on.
  const fw::SlocumMissionNumbers tomorrow = fw::next_slocum_mission(dir.string(), "unit", start + 86'400'000'000LL);
  CHECK_EQUAL(0, tomorrow.mission_of_day);
  CHECK_EQUAL(2, tomorrow.mission_number);
  const slocum::BinaryFile second = slocum::read_binary_file(dir / "unit-2023-317-01-001.dcd");
  CHECK_EQUAL(std::string("00010001"), *second.header().tag("the8x3_filename"));
  CHECK_EQUAL(std::string("unit-2023-317-1-1"), *second.header().tag("full_filename"));
}

// The header refused at the open, then the first buffer: the header goes
// with the next buffer the sink takes, after a new file-open cycle; every
// file reads whole, only the refused buffer's rows are missing.
TEST(SlocumWriterFaults, RefusedHeaderIsWrittenLater) {
  const fs::path dir = fresh_dir("header_later");
  fw::SlocumDirectorySink disk(dir.string());
  SlowAfterOpenSink slow(disk);
  const Written logger = write_synthetic(slow, 900);
  CHECK_FALSE(logger.finished);
  CHECK_EQUAL(30U, logger.dbd.cycles_lost);  // the first 10 rows of each of the 3 segments
  const auto files = files_with(dir, ".dbd");
  CHECK_EQUAL(3U, files.size());
  for (std::size_t f = 0; f < files.size(); ++f) {
    const slocum::BinaryFile file = slocum::read_binary_file(files[f]);
    CHECK_TRUE(file.complete());
    CHECK_EQUAL(290U, slocum::get(file, "m_depth").time.size());
    check_rows(file, static_cast<int>(f) * 300 + 10);
  }
}

// A value its sensor's type cannot hold (a counter past 2^24 in a 4-byte
// float, an enum past 127 in a byte) is not stored, and counted: the reader
// sees no value, never another number.
TEST(SlocumWriterFaults, UnrepresentableValuesAreNotStored) {
  const fs::path dir = fresh_dir("unrepresentable");
  fw::SlocumDirectorySink disk(dir.string());
  fw::SlocumLogOptions options;
  options.vehicle = "unit";
  options.write_sbd = false;
  fw::SlocumLogger logger(disk, options);
  CHECK_TRUE(logger.start());
  for (int i = 0; i < 4; ++i) {
    hal::FlightLogRecord r = synthetic_row(i);
    r.x_loop_overruns = i < 2 ? 16'777'216U : 16'777'217U;  // 2^24 is exact in a float, 2^24 + 1 is not
    r.m_depth_state = i == 3 ? 200 : 1;
    logger.write(r, r.time_us);
  }
  CHECK_TRUE(logger.finish());
  CHECK_EQUAL(3U, logger.unrepresentable());
  const slocum::BinaryFile file = slocum::read_binary_file(files_with(dir, ".dbd").front());
  const slocum::TimeSeries overruns = slocum::get(file, "x_loop_overruns");
  CHECK_EQUAL(2U, overruns.value.size());  // rows 0 and 1, not 2 and 3
  CHECK_EQUAL(16777216.0, overruns.value.back());
  CHECK_EQUAL(3U, slocum::get(file, "m_depth_state").value.size());  // rows 0 to 2, not 3
}
