// SPDX-License-Identifier: Apache-2.0
// Flight-log reader speed, in rows/s: a 24 h, 1 Hz SIL-like log (86 400 rows
// x 30 columns, numbers at full double precision as the SIL writes them, some
// empty fields) and the largest dbd-derived real log.
//   bench_flight_log --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glider/flightlog/flight_log.hpp"

namespace fl = glider::flightlog;

namespace {

constexpr int kDayRows = 24 * 3600;
constexpr int kColumns = 30;

void append_number(std::string& line, double value) {
  char buffer[32];
  line.append(buffer, std::to_chars(buffer, buffer + sizeof(buffer), value).ptr);
}

std::string sil_day_text() {
  std::string text = "# source: bench_flight_log synthetic 24 h SIL-like log\n# vehicle.name: bench\n";
  text += "m_present_time,m_depth,m_pitch,m_ballast_pumped,m_depth_state";
  for (int c = 5; c < kColumns; ++c) text += ",col_" + std::to_string(c);
  text += '\n';
  std::string line;
  for (int row = 0; row < kDayRows; ++row) {
    const double t = row;
    line.clear();
    append_number(line, t);
    line += ',';
    append_number(line, 25.0 + 25.0 * std::sin(t / 300.0));
    line += ',';
    append_number(line, 0.45 * std::cos(t / 300.0));
    line += ',';
    append_number(line, 230.0 * std::cos(t / 300.0));
    line += std::cos(t / 300.0) > 0 ? ",2" : ",1";
    for (int c = 5; c < kColumns; ++c) {
      line += ',';
      if ((row + c) % 10 != 0) append_number(line, std::sin(t * 0.001 * c) * c);  // 10 % empty
    }
    text += line;
    text += '\n';
  }
  return text;
}

const std::string& sil_day() {
  static const std::string text = sil_day_text();
  return text;
}

// The same text as a file, written once, removed at exit.
const std::filesystem::path& sil_day_file() {
  struct File {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("bench_flight_log_" + std::to_string(getpid()) + ".csv");
    File() { std::ofstream(path, std::ios::binary) << sil_day(); }
    ~File() { std::filesystem::remove(path); }
  };
  static const File file;
  return file.path;
}

void report(benchmark::State& state, std::size_t rows, std::size_t bytes) {
  state.counters["rows/s"] =
      benchmark::Counter(static_cast<double>(rows), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rows"] = static_cast<double>(rows);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

void BM_ReadSilDayFile(benchmark::State& state) {
  const auto& path = sil_day_file();
  std::size_t rows = 0;
  for (auto _ : state) {
    const fl::FlightLog log = fl::read_flight_log(path);
    rows = log.rows();
    benchmark::DoNotOptimize(log.time().data());
  }
  report(state, rows, sil_day().size());
}
BENCHMARK(BM_ReadSilDayFile)->Unit(benchmark::kMillisecond);

void BM_ParseSilDayInMemory(benchmark::State& state) {
  std::size_t rows = 0;
  for (auto _ : state) {
    const fl::FlightLog log = fl::parse_flight_log(sil_day(), "sil_day.csv");
    rows = log.rows();
    benchmark::DoNotOptimize(log.time().data());
  }
  report(state, rows, sil_day().size());
}
BENCHMARK(BM_ParseSilDayInMemory)->Unit(benchmark::kMillisecond);

// A tool that asks for the 4 columns it needs: the others are not parsed.
void BM_ParseSilDayFourColumns(benchmark::State& state) {
  fl::ReadOptions options;
  options.columns = {"m_depth", "m_pitch", "m_ballast_pumped"};
  std::size_t rows = 0;
  for (auto _ : state) {
    const fl::FlightLog log = fl::parse_flight_log(sil_day(), "sil_day.csv", options);
    rows = log.rows();
    benchmark::DoNotOptimize(log.time().data());
  }
  report(state, rows, sil_day().size());
}
BENCHMARK(BM_ParseSilDayFourColumns)->Unit(benchmark::kMillisecond);

void BM_ReadRealComet2016(benchmark::State& state) {
  const std::filesystem::path path = GLIDER_SOURCE_DIR "/tests/data/real/comet-2016-174-05.csv";
  std::size_t rows = 0;
  for (auto _ : state) {
    const fl::FlightLog log = fl::read_flight_log(path);
    rows = log.rows();
    benchmark::DoNotOptimize(log.time().data());
  }
  report(state, rows, std::filesystem::file_size(path));
}
BENCHMARK(BM_ReadRealComet2016)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
