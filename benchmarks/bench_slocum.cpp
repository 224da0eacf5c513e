// SPDX-License-Identifier: Apache-2.0
// Decode throughput of the Slocum binary reader on the real comet-2016
// deployment (10 .dbd + 10 .ebd, 3.4 MB): per file, and end to end (files
// found, read, decoded and merged into one flight log). Goal: >= 100 MB/s end
// to end, i.e. the 20 files in < 35 ms (issue 13; dbdreader 0.6.3 reads every
// parameter at about 5 MB/s).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "glider/slocum/binary_file.hpp"
#include "glider/slocum/deployment.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(GLIDER_SOURCE_DIR) / "tests/data/real/dbd/comet-2016";

std::int64_t total_bytes(const std::vector<fs::path>& files) {
  std::int64_t bytes = 0;
  for (const fs::path& f : files) bytes += static_cast<std::int64_t>(fs::file_size(f));
  return bytes;
}

// Every file decoded on its own (every sensor), the caches parsed once per pass.
void BM_DecodeEachFile(benchmark::State& state) {
  const std::vector<fs::path> files = glider::slocum::deployment_files({kDir.string()});
  for (auto _ : state) {
    glider::slocum::SensorListMemo memo;
    glider::slocum::ReadOptions options;
    options.memo = &memo;
    for (const fs::path& f : files) benchmark::DoNotOptimize(glider::slocum::read_binary_file(f, options));
  }
  state.SetBytesProcessed(state.iterations() * total_bytes(files));
}
BENCHMARK(BM_DecodeEachFile)->Unit(benchmark::kMillisecond);

// End to end: the directory to a flight log with every sensor (1465 columns).
void BM_DeploymentAllSensors(benchmark::State& state) {
  const std::vector<fs::path> files = glider::slocum::deployment_files({kDir.string()});
  for (auto _ : state) {
    benchmark::DoNotOptimize(glider::slocum::read_deployment(glider::slocum::deployment_files({kDir.string()}), {}));
  }
  state.SetBytesProcessed(state.iterations() * total_bytes(files));
}
BENCHMARK(BM_DeploymentAllSensors)->Unit(benchmark::kMillisecond);

// End to end with the 26 columns of the real-data CSVs (what diagnose uses).
void BM_DeploymentCsvColumns(benchmark::State& state) {
  const std::vector<fs::path> files = glider::slocum::deployment_files({kDir.string()});
  glider::slocum::DeploymentOptions options;
  options.columns = {"m_present_time",
                     "m_depth",
                     "m_pitch",
                     "m_roll",
                     "m_heading",
                     "c_heading",
                     "m_fin",
                     "c_fin",
                     "m_ballast_pumped",
                     "c_ballast_pumped",
                     "m_battpos",
                     "c_battpos",
                     "m_depth_rate",
                     "m_altitude",
                     "m_gps_lat",
                     "m_gps_lon",
                     "m_lat",
                     "m_lon",
                     "m_water_vx",
                     "m_water_vy",
                     "m_vacuum",
                     "m_leakdetect_voltage",
                     "m_depth_state",
                     "sci_water_pressure",
                     "sci_water_temp",
                     "sci_water_cond"};
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        glider::slocum::read_deployment(glider::slocum::deployment_files({kDir.string()}), options));
  }
  state.SetBytesProcessed(state.iterations() * total_bytes(files));
}
BENCHMARK(BM_DeploymentCsvColumns)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
