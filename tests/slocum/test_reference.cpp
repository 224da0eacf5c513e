// SPDX-License-Identifier: Apache-2.0
// Every sensor of every real file decodes to exactly what dbdreader 0.6.3
// returns (reference.json): count, first/last time and value, min, max,
// correctly rounded sums and a SHA-256 of the time and value arrays; lat/lon
// both as stored (NMEA) and in decimal degrees.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "exact_sum.hpp"
#include "glider/slocum/binary_file.hpp"
#include "glider/slocum/lat_lon.hpp"
#include "reference.hpp"
#include "sha256.hpp"

namespace {

using glider::slocum::BinaryFile;
using glider::slocum::TimeSeries;
using nlohmann::json;
namespace t = glider::slocum::test;

const json& reference() {
  static const json loaded = [] {
    std::ifstream in(t::real_dbd_dir() / "reference.json");
    return json::parse(in);
  }();
  return loaded;
}

double number(const json& value) {
  if (value.is_string()) {
    const std::string s = value.get<std::string>();
    if (s == "NaN") return std::numeric_limits<double>::quiet_NaN();
    if (s == "Infinity") return std::numeric_limits<double>::infinity();
    if (s == "-Infinity") return -std::numeric_limits<double>::infinity();
  }
  return value.get<double>();
}

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// numpy's min/max: NaN if any value is NaN.
template <typename Pick>
double numpy_extreme(const std::vector<double>& v, Pick pick) {
  double m = v.front();
  for (const double x : v) {
    if (std::isnan(x)) return x;
    m = pick(m, x);
  }
  return m;
}

// Returns "" when the series matches the reference statistics, else what differs.
std::string compare(const TimeSeries& got, const json& want) {
  const auto n = want["n"].get<std::size_t>();
  if (got.time.size() != n) return "n " + std::to_string(got.time.size()) + " != " + std::to_string(n);
  if (n == 0) return "";
  const std::vector<double>& v = got.value;
  const std::vector<double>& tt = got.time;
  std::string problems;
  const auto check = [&problems](const char* what, double a, double b) {
    if (!same(a, b)) problems += std::string(what) + " " + std::to_string(a) + " != " + std::to_string(b) + "; ";
  };
  check("t_first", tt.front(), number(want["t_first"]));
  check("t_last", tt.back(), number(want["t_last"]));
  check("t_fsum", t::exact_sum(tt), number(want["t_fsum"]));
  check("v_first", v.front(), number(want["v_first"]));
  check("v_last", v.back(), number(want["v_last"]));
  check("v_min", numpy_extreme(v, [](double a, double b) { return std::min(a, b); }), number(want["v_min"]));
  check("v_max", numpy_extreme(v, [](double a, double b) { return std::max(a, b); }), number(want["v_max"]));
  if (!want["v_fsum"].is_null()) check("v_fsum", t::exact_sum(v), number(want["v_fsum"]));
  const auto count = [&v](auto predicate) {
    return static_cast<std::size_t>(std::count_if(v.begin(), v.end(), predicate));
  };
  if (count([](double x) { return std::isnan(x); }) != want["n_nan"].get<std::size_t>()) problems += "n_nan; ";
  if (count([](double x) { return std::isinf(x) && x > 0; }) != want["n_posinf"].get<std::size_t>())
    problems += "n_posinf; ";
  if (count([](double x) { return std::isinf(x) && x < 0; }) != want["n_neginf"].get<std::size_t>())
    problems += "n_neginf; ";
  if (t::sha256_of_arrays(tt, v) != want["tv_sha256"].get<std::string>()) problems += "tv_sha256; ";
  return problems;
}

}  // namespace

TEST_GROUP(SlocumReference){};

TEST(SlocumReference, EveryFileHeaderAndLayout) {
  const json& files = reference()["files"];
  CHECK_EQUAL(26U, files.size());
  for (const auto& [name, want] : files.items()) {
    glider::slocum::ReadOptions options;
    options.cache_dirs = {t::real_cache(name)};
    const BinaryFile file = glider::slocum::read_binary_file(t::real_file(name), options);
    STRCMP_EQUAL(name.c_str(), t::real_file(name).filename().string().c_str());
    CHECK_TEXT(file.complete(), name.c_str());
    CHECK_EQUAL(want["binary_offset"].get<std::size_t>(), file.binary_offset());
    CHECK(want["byte_order"] == "big" && file.byte_order() == glider::slocum::ByteOrder::kBig);
    STRCMP_EQUAL(want["time_variable"].get<std::string>().c_str(), file.time_variable().c_str());
    CHECK_EQUAL(want["n_parameters"].get<std::size_t>(), file.sensors().size());
    CHECK_EQUAL(want["science_file"].get<bool>(), file.is_science());
    const json& header = want["header"];
    CHECK_EQUAL(header["encoding_ver"].get<int>(), file.header().encoding_version);
    STRCMP_EQUAL(header["sensor_list_crc"].get<std::string>().c_str(), file.header().sensor_list_crc.c_str());
    CHECK_EQUAL(header["sensor_list_factored"].get<int>() == 1, file.header().sensor_list_factored);
    CHECK_EQUAL(header["state_bytes_per_cycle"].get<std::size_t>(), file.header().state_bytes_per_cycle);
    STRCMP_EQUAL(header["mission_name"].get<std::string>().c_str(), file.header().tag("mission_name")->c_str());
    std::map<int, std::size_t> histogram;
    for (const auto& sensor : file.sensors()) ++histogram[sensor.bytes];
    for (const auto& [bytes, count] : want["byte_size_histogram"].items()) {
      CHECK_EQUAL(count.get<std::size_t>(), histogram[std::stoi(bytes)]);
    }
  }
}

TEST(SlocumReference, EverySensorOfEveryFileAsDbdreader) {
  std::size_t checked = 0;
  std::string failures;
  for (const auto& [name, want] : reference()["files"].items()) {
    glider::slocum::ReadOptions options;
    options.cache_dirs = {t::real_cache(name)};
    const BinaryFile file = glider::slocum::read_binary_file(t::real_file(name), options);
    for (const auto& [sensor, stats] : want["parameters"].items()) {
      const auto index = file.index_of(sensor);
      if (!index || *index != stats["index"].get<std::size_t>()) {
        failures += name + " " + sensor + ": index; ";
        continue;
      }
      STRCMP_EQUAL(stats["unit"].get<std::string>().c_str(), file.sensors()[*index].unit.c_str());
      CHECK_EQUAL(stats["byte_size"].get<int>(), file.sensors()[*index].bytes);
      std::string problems = compare(glider::slocum::get(file, sensor), stats);
      if (stats.contains("raw")) {
        const std::string raw = compare(glider::slocum::get(file, sensor, /*nmea_lat_lon=*/true), stats["raw"]);
        if (!raw.empty()) problems += "raw: " + raw;
      }
      if (!problems.empty() && failures.size() < 4000) failures += name + " " + sensor + ": " + problems + "\n";
      ++checked;
    }
    for (const auto& sensor : want["parameters_without_data"]) {
      if (!glider::slocum::get(file, sensor.get<std::string>()).time.empty()) {
        failures += name + " " + sensor.get<std::string>() + ": has data, reference has none\n";
      }
      ++checked;
    }
  }
  STRCMP_EQUAL("", failures.c_str());
  // Every sensor of every file, with data or without.
  CHECK_EQUAL(reference()["summary"]["n_parameters_total"].get<std::size_t>(), checked);
}
