// SPDX-License-Identifier: Apache-2.0
// The state file: an update reuses every stored segment and measures only
// the new one; a damaged (truncated) or inconsistent (wrong schema, an
// interval that misses its value, times out of order, another vehicle)
// state is never trusted: the data are measured again and the result is the
// one a fresh run gives; no temporary file is left behind.
#include <CppUTest/TestHarness.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glider/health/health.hpp"
#include "glider/health/output.hpp"
#include "sil_deployment.hpp"

using namespace glider;

namespace {

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

struct Deployment {
  std::string dir;
  health::HealthOptions options;
};

Deployment fly(int surfacings) {
  Deployment d;
  d.dir = std::string(GLIDER_TEST_OUTPUT_DIR) + "/health/state";
  std::filesystem::remove_all(d.dir);
  for (int k = 0; k < surfacings; ++k) {
    const std::string error = health_sil::fly_surfacing(d.dir + "/sbd", {}, k, 8.0, 900 + k);
    CHECK_TEXT(error.empty(), error.c_str());
  }
  d.options = health_sil::health_options(d.dir, 8.0);
  return d;
}

// The report without the run's own bookkeeping (costs, counts, notes).
std::string result_of(const health::HealthRun& run) {
  health::HealthRun r = run;
  r.cost_s = 0.0;
  r.measured = r.reused = 0;
  r.notes.clear();
  for (auto& s : r.segments) s.cost_s = 0.0;
  return health::health_json(r);
}

}  // namespace

TEST_GROUP(HealthState){};

TEST(HealthState, IncrementalAndNeverTrustedWhenDamaged) {
  Deployment d = fly(1);
  const health::HealthRun first = health::update_health(d.options);
  CHECK_EQUAL(2u, first.measured);  // 1 surfacing, 2 segments each (the yos, the surface tail)
  const std::string fresh = result_of(first);

  // Nothing new: nothing measured, the same result.
  const health::HealthRun again = health::update_health(d.options);
  CHECK_EQUAL(0u, again.measured);
  CHECK_EQUAL(2u, again.reused);
  STRCMP_EQUAL(fresh.c_str(), result_of(again).c_str());

  // One new surfacing: only its segments measured.
  CHECK(health_sil::fly_surfacing(d.dir + "/sbd", {}, 1, 8.0, 901).empty());
  const health::HealthRun next = health::update_health(d.options);
  CHECK_EQUAL(2u, next.measured);
  CHECK_EQUAL(2u, next.reused);
  CHECK(result_of(next) != fresh);
  const std::string saved = health_sil::read_text(d.options.state_path);

  // Damaged or inconsistent states: each rebuilt from the data, a note says so
  // (on the first surfacing's files alone, to keep the test short: the result
  // is then the first run's).
  health::HealthOptions one = d.options;
  one.inputs = {d.dir + "/sbd/slocum_we01-1970-000-00-*.sbd"};
  const std::string cases[][2] = {
      {"truncated", saved.substr(0, saved.size() / 2)},
      {"interval missing its value",
       [&] {
         std::string s = saved;
         const auto at = s.find("\"low\": ");
         return s.replace(at, 7, "\"low\": 1e9, \"was\": ");
       }()},
      {"a shared shift that is not a number",
       [&] {
         std::string s = saved;
         const auto at = s.find("\"shared_shift\": ");
         return s.replace(at, 16, "\"shared_shift\": null, \"was\": ");
       }()},
      {"measured by the version before (the heading fit on alternate yos)",
       [&] {
         std::string s = saved;
         const std::string now = "\"measurement_version\": " + std::to_string(health::kMeasurementVersion);
         return s.replace(s.find(now), now.size(), "\"measurement_version\": 6");
       }()},
      {"wrong schema",
       [&] {
         std::string s = saved;
         return s.replace(s.find("glider-health-state/1"), 21, "glider-health-state/9");
       }()},
  };
  for (const auto& c : cases) {
    write_text(d.options.state_path, c[1]);
    const health::HealthRun rebuilt = health::update_health(one);
    CHECK_EQUAL_TEXT(2u, rebuilt.measured, c[0].c_str());
    CHECK_TEXT(!rebuilt.notes.empty() && rebuilt.notes.front().find("not trusted") != std::string::npos, c[0].c_str());
    STRCMP_EQUAL_TEXT(fresh.c_str(), result_of(rebuilt).c_str(), c[0].c_str());
  }
  // Times out of order inside the state: two segments swapped.
  {
    std::string s = saved;
    const auto a = s.find("\"start_s\": "), b = s.find("\"start_s\": ", s.find("\"start_s\": ", a + 1) + 1);
    const std::string first_value = s.substr(a, s.find(',', a) - a), third_value = s.substr(b, s.find(',', b) - b);
    s.replace(b, third_value.size(), first_value);
    s.replace(a, first_value.size(), third_value);
    write_text(d.options.state_path, s);
    const health::HealthRun rebuilt = health::update_health(one);
    CHECK_EQUAL(2u, rebuilt.measured);
    STRCMP_EQUAL(fresh.c_str(), result_of(rebuilt).c_str());
  }
  // Another vehicle: every stored value is about the old one.
  health::HealthOptions other = one;
  other.vehicle.hydro.cd0 *= 1.1;
  CHECK_EQUAL(2u, health::update_health(other).measured);
  // Atomic writes: no temporary left beside the state.
  for (const auto& entry : std::filesystem::directory_iterator(d.dir)) {
    CHECK_TEXT(entry.path().filename().string().find(".tmp") == std::string::npos, entry.path().c_str());
  }
}
