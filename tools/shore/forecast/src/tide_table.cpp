// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/tide_table.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace glider::forecast {
namespace fs = std::filesystem;

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

struct Named {
  const char* name;
  double period_h;
};
// The constituents' periods (hours; Schureman's speeds).
constexpr Named kConstituents[] = {{"M2", 12.4206012},  {"S2", 12.0},        {"N2", 12.65834751},
                                   {"K2", 11.96723606}, {"K1", 23.93446966}, {"O1", 25.81934171},
                                   {"P1", 24.06588766}, {"Q1", 26.868350},   {"M4", 6.210300601}};

// Days since 1970-01-01 of a civil date (proleptic Gregorian).
long long days_from_civil(int y, unsigned m, unsigned d) {
  y -= m <= 2 ? 1 : 0;
  const int era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return static_cast<long long>(era) * 146097 + static_cast<long long>(doe) - 719468;
}

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// A value's check: `where` is file:line: key.
double checked(const std::string& where, const toml::node& node, double low, double high, const char* unit) {
  const std::optional<double> value = node.value<double>();
  if (!value)
    throw std::runtime_error(where + " is not a number (allowed: " + number(low) + " to " + number(high) + " " + unit +
                             ")");
  if (!(*value >= low && *value <= high)) {  // NaN fails too
    throw std::runtime_error(where + " = " + number(*value) + " is outside [" + number(low) + ", " + number(high) +
                             "] " + unit);
  }
  return *value;
}

// A component's phase, wrapped into [0, 360).
double wrapped(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0.0 ? w + 360.0 : w;
}

}  // namespace

const std::vector<std::string>& tide_constituent_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Named& n : kConstituents) out.emplace_back(n.name);
    return out;
  }();
  return names;
}

double tide_constituent_period_s(const std::string& name) {
  for (const Named& n : kConstituents) {
    if (name == n.name) return n.period_h * 3600.0;
  }
  std::string allowed;
  for (const Named& n : kConstituents) allowed += (allowed.empty() ? "" : ", ") + std::string(n.name);
  throw std::invalid_argument("'" + name + "' is not a tidal constituent (allowed: " + allowed + ")");
}

TideTable read_tide_table(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw std::runtime_error(file.string() + ": no such tide table");
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                             std::string(e.description()));
  }
  TideTable table;
  table.source = file.string();
  auto at = [&](const toml::node& node) {
    return file.string() + ":" + std::to_string(node.source().begin.line) + ": ";
  };
  // The reference first (the keys come sorted, the constituents' capitals before it).
  const toml::node* reference = root.get("reference_utc");
  if (reference == nullptr) throw std::runtime_error(file.string() + ": no reference_utc (the phases' time origin)");
  const std::optional<toml::date_time> when = reference->value<toml::date_time>();
  if (!when || !when->offset) {
    throw std::runtime_error(at(*reference) +
                             "reference_utc is not a date-time with its offset (e.g. 2019-08-21T00:00:00Z)");
  }
  table.reference_utc_s =
      static_cast<double>(days_from_civil(when->date.year, when->date.month, when->date.day)) * 86400.0 +
      when->time.hour * 3600.0 + when->time.minute * 60.0 + when->time.second + when->time.nanosecond * 1e-9 -
      when->offset->minutes * 60.0;
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (name == "reference_utc") continue;
    const toml::table* section = node.as_table();
    if (section == nullptr) {
      throw std::runtime_error(at(node) + "key '" + name +
                               "' is not a tide table entry (allowed: reference_utc, "
                               "[mean], [CONSTITUENT])");
    }
    if (name == "mean") {
      for (const auto& [k, v] : *section) {
        const std::string where = at(v) + "mean." + std::string(k.str());
        if (k.str() == "east_m_s") {
          table.mean_east_m_s = checked(where, v, -3.0, 3.0, "m/s");
        } else if (k.str() == "north_m_s") {
          table.mean_north_m_s = checked(where, v, -3.0, 3.0, "m/s");
        } else {
          throw std::runtime_error(where + ": unknown key (allowed: east_m_s, north_m_s)");
        }
      }
      continue;
    }
    TideConstituent c;
    c.name = name;
    try {
      c.period_s = tide_constituent_period_s(name);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(at(node) + "[" + name + "]: " + e.what());
    }
    for (const TideConstituent& other : table.constituents) {
      if (other.name == name) throw std::runtime_error(at(node) + "[" + name + "] given twice");
    }
    std::optional<double> values[6];
    static const char* const keys[6] = {"east_amplitude_m_s", "east_phase_deg",      "north_amplitude_m_s",
                                        "north_phase_deg",    "amplitude_sigma_m_s", "phase_sigma_deg"};
    static const double lows[6] = {0.0, -360.0, 0.0, -360.0, 0.0, 0.0};
    static const double highs[6] = {3.0, 360.0, 3.0, 360.0, 3.0, 180.0};
    static const char* const units[6] = {"m/s", "deg", "m/s", "deg", "m/s", "deg"};
    for (const auto& [k, v] : *section) {
      const std::string where = at(v) + name + "." + std::string(k.str());
      int which = -1;
      for (int i = 0; i < 6; ++i) {
        if (k.str() == keys[i]) which = i;
      }
      if (which < 0) {
        throw std::runtime_error(where +
                                 ": unknown key (allowed: east_amplitude_m_s, east_phase_deg, north_amplitude_m_s, "
                                 "north_phase_deg, amplitude_sigma_m_s, phase_sigma_deg)");
      }
      values[which] = checked(where, v, lows[which], highs[which], units[which]);
    }
    for (int i = 0; i < 6; ++i) {
      if (!values[i]) {
        throw std::runtime_error(at(node) + "[" + name + "] has no " + keys[i] + " (" + number(lows[i]) + " to " +
                                 number(highs[i]) + " " + units[i] + ")");
      }
    }
    c.east = {*values[0], *values[1], *values[4], *values[5]};
    c.north = {*values[2], *values[3], *values[4], *values[5]};
    table.constituents.push_back(c);
  }
  if (table.constituents.empty()) {
    throw std::runtime_error(file.string() + ": no constituent (at least one of [M2], [S2], [K1], ...)");
  }
  return table;
}

std::string format_tide_table(const TideTable& table, const std::string& comment) {
  std::string out;
  std::size_t begin = 0;
  while (begin < comment.size()) {
    const std::size_t end = std::min(comment.find('\n', begin), comment.size());
    out += "# " + comment.substr(begin, end - begin) + "\n";
    begin = end + 1;
  }
  const auto seconds = static_cast<std::time_t>(std::llround(table.reference_utc_s));
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[200];
  std::strftime(text, sizeof text, "reference_utc = %Y-%m-%dT%H:%M:%SZ\n", &tm);
  out += text;
  std::snprintf(text, sizeof text, "\n[mean]\neast_m_s = %.4f\nnorth_m_s = %.4f\n", table.mean_east_m_s,
                table.mean_north_m_s);
  out += text;
  for (const TideConstituent& c : table.constituents) {
    std::snprintf(text, sizeof text,
                  "\n[%s]\neast_amplitude_m_s = %.4f\neast_phase_deg = %.1f\nnorth_amplitude_m_s = %.4f\n"
                  "north_phase_deg = %.1f\namplitude_sigma_m_s = %.4f\nphase_sigma_deg = %.1f\n",
                  c.name.c_str(), c.east.amplitude_m_s, wrapped(c.east.phase_deg), c.north.amplitude_m_s,
                  wrapped(c.north.phase_deg), std::max(c.east.amplitude_sigma_m_s, c.north.amplitude_sigma_m_s),
                  std::min(180.0, std::max(c.east.phase_sigma_deg, c.north.phase_sigma_deg)));
    out += text;
  }
  return out;
}

namespace {

// A harmonic averaged over a span keeps sinc(omega span / 2) of its amplitude.
double kept(double omega, double span_s) {
  const double x = 0.5 * omega * span_s;
  return std::fabs(x) < 1e-9 ? 1.0 : std::sin(x) / x;
}

const TideComponent& component_of(const TideConstituent& c, int component) { return component == 0 ? c.east : c.north; }

}  // namespace

double tide_mean(const TideTable& table, int component, double utc_s, double span_s) {
  double v = component == 0 ? table.mean_east_m_s : table.mean_north_m_s;
  for (const TideConstituent& c : table.constituents) {
    const TideComponent& k = component_of(c, component);
    const double omega = 2.0 * std::numbers::pi / c.period_s;
    v += k.amplitude_m_s * kept(omega, span_s) *
         std::cos(omega * (utc_s - table.reference_utc_s) - k.phase_deg * kDegToRad);
  }
  return v;
}

double tide_error_covariance(const TideTable& table, int component, double t1, double s1, double t2, double s2) {
  // amplitude x cos(theta - phase): its error dA cos(theta - phase) + A dphase sin(theta - phase).
  double cov = 0.0;
  for (const TideConstituent& c : table.constituents) {
    const TideComponent& k = component_of(c, component);
    const double omega = 2.0 * std::numbers::pi / c.period_s;
    const double x1 = omega * (t1 - table.reference_utc_s) - k.phase_deg * kDegToRad;
    const double x2 = omega * (t2 - table.reference_utc_s) - k.phase_deg * kDegToRad;
    const double sa = k.amplitude_sigma_m_s, sp = k.amplitude_m_s * k.phase_sigma_deg * kDegToRad;
    cov += kept(omega, s1) * kept(omega, s2) *
           (sa * sa * std::cos(x1) * std::cos(x2) + sp * sp * std::sin(x1) * std::sin(x2));
  }
  return cov;
}

}  // namespace glider::forecast
