// SPDX-License-Identifier: Apache-2.0
#include "glider/health/state.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

namespace glider::health {
namespace {

using nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

double finite_number(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_number()) throw std::runtime_error(std::string(key) + " is not a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw std::runtime_error(std::string(key) + " is not finite");
  return d;
}

double number_or_nan(const json& j, const char* key) {
  const json& v = j.at(key);
  if (v.is_null()) return std::nan("");
  if (!v.is_number()) throw std::runtime_error(std::string(key) + " is not a number or null");
  return v.get<double>();
}

EffectValue effect_from_json(const json& j) {
  EffectValue e;
  e.value = number_or_nan(j, "value");
  e.low = number_or_nan(j, "low");
  e.high = number_or_nan(j, "high");
  e.why = j.at("why").get<std::string>();
  e.shared_shift = finite_number(j, "shared_shift");
  if (e.judged() && std::isfinite(e.low) && !(e.low <= e.value && e.value <= e.high)) {
    throw std::runtime_error("an interval does not hold its value");
  }
  if (!e.judged() && e.why.empty()) throw std::runtime_error("a value without a number or a reason");
  return e;
}

}  // namespace

std::string state_json(const HealthState& state) {
  json segments = json::array();
  for (const SegmentMeasurement& m : state.segments) {
    json effects = json::object();
    for (std::size_t i = 0; i < kHealthEffectCount; ++i) {
      const EffectValue& e = m.effects[i];
      effects[info(health_effect(i)).id] = {{"value", number_or_null(e.value)},
                                            {"low", number_or_null(e.low)},
                                            {"high", number_or_null(e.high)},
                                            {"why", e.why},
                                            {"shared_shift", e.shared_shift}};
    }
    segments.push_back({{"name", m.name},
                        {"files", m.files},
                        {"fingerprint", m.fingerprint},
                        {"glider", m.glider},
                        {"time_offset_s", m.time_offset_s},
                        {"start_s", m.start_s},
                        {"end_s", m.end_s},
                        {"time_s", m.time_s},
                        {"judged", m.judged},
                        {"why", m.why},
                        {"cost_s", m.cost_s},
                        {"fin_spread_deg", number_or_null(m.fin_spread_deg)},
                        {"heading_spread_deg", number_or_null(m.heading_spread_deg)},
                        {"effects", effects}});
  }
  json alerts = json::array();
  for (const Alert& a : state.alerts) {
    alerts.push_back({{"id", a.id}, {"effect", info(a.effect).id}, {"kind", a.kind}});
  }
  const json j = {{"schema", kStateSchema},
                  {"measurement_version", kMeasurementVersion},
                  {"glider", state.glider},
                  {"vehicle_key", state.vehicle_key},
                  {"seconds_apart", state.seconds_apart},
                  {"segments", segments},
                  {"alerts", alerts}};
  return j.dump(1) + "\n";
}

std::optional<HealthState> read_state(const std::string& path, std::string& problem) {
  problem.clear();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  try {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot be opened");
    const json j = json::parse(in);
    if (j.at("schema") != kStateSchema) throw std::runtime_error("schema is not " + std::string(kStateSchema));
    if (j.at("measurement_version") != kMeasurementVersion) {
      throw std::runtime_error("measured by another version of health (measurement_version " +
                               j.at("measurement_version").dump() + ", this one " +
                               std::to_string(kMeasurementVersion) + ")");
    }
    HealthState s;
    s.glider = j.at("glider").get<std::string>();
    s.vehicle_key = j.at("vehicle_key").get<std::string>();
    s.seconds_apart = finite_number(j, "seconds_apart");
    std::set<std::string> names;
    double last_end = -1e300;
    for (const json& m : j.at("segments")) {
      SegmentMeasurement seg;
      seg.name = m.at("name").get<std::string>();
      if (!names.insert(seg.name).second) throw std::runtime_error("segment " + seg.name + " twice");
      seg.files = m.at("files").get<std::vector<std::string>>();
      if (seg.files.empty()) throw std::runtime_error("segment " + seg.name + " has no files");
      seg.fingerprint = m.at("fingerprint").get<std::string>();
      seg.glider = m.at("glider").get<std::string>();
      seg.time_offset_s = finite_number(m, "time_offset_s");
      seg.start_s = finite_number(m, "start_s");
      seg.end_s = finite_number(m, "end_s");
      seg.time_s = finite_number(m, "time_s");
      seg.judged = m.at("judged").get<bool>();
      seg.why = m.at("why").get<std::string>();
      seg.cost_s = finite_number(m, "cost_s");
      if (!m.at("fin_spread_deg").is_null()) seg.fin_spread_deg = finite_number(m, "fin_spread_deg");
      if (!m.at("heading_spread_deg").is_null()) seg.heading_spread_deg = finite_number(m, "heading_spread_deg");
      if (seg.end_s < seg.start_s || seg.time_s < seg.start_s || seg.time_s > seg.end_s) {
        throw std::runtime_error("segment " + seg.name + ": times not in order");
      }
      if (seg.end_s > seg.start_s && seg.start_s < last_end) {
        throw std::runtime_error("segment " + seg.name + " starts before the one before it ends");
      }
      if (seg.end_s > seg.start_s) last_end = seg.end_s;
      const json& effects = m.at("effects");
      for (std::size_t i = 0; i < kHealthEffectCount; ++i) {
        seg.effects[i] = effect_from_json(effects.at(info(health_effect(i)).id));
      }
      if (seg.judged != seg.effects[0].judged()) throw std::runtime_error("segment " + seg.name + ": judged flag");
      s.segments.push_back(std::move(seg));
    }
    for (const json& a : j.at("alerts")) {
      Alert alert;
      alert.id = a.at("id").get<std::string>();
      alert.kind = a.at("kind").get<std::string>();
      const std::string effect = a.at("effect").get<std::string>();
      bool known = false;
      for (std::size_t i = 0; i < kHealthEffectCount; ++i) {
        if (effect == info(health_effect(i)).id) {
          alert.effect = health_effect(i);
          known = true;
        }
      }
      if (!known || (alert.kind != "step" && alert.kind != "line")) throw std::runtime_error("unknown alert");
      s.alerts.push_back(alert);
    }
    return s;
  } catch (const std::exception& e) {
    problem = e.what();
    return std::nullopt;
  }
}

void write_atomically(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp");
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(temporary.string() + ": " + std::strerror(errno));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(temporary.c_str());
      throw std::runtime_error(temporary.string() + ": write: " + why);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(temporary.c_str());
    throw std::runtime_error(temporary.string() + ": fsync/close failed");
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw std::runtime_error(target.string() + ": rename: " + why);
  }
}

}  // namespace glider::health
