// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pilot's tide for the place: tidal constituents of the depth-averaged
// current (each component's amplitude and phase, with their 1-sigma errors),
// read from a small TOML file (docs/forecast.md, "Session 44: the tide's
// phase from a constituents file"). A regional tide model gives them for the
// place, or `glider forecast fit-tide` from an earlier deployment's
// depth-averaged currents there (tide_fit.hpp). With them the tidal prior's
// tide is this table (its mean and phase), no longer a tide of random phase;
// what the table may be wrong by is the prior's tide width.
//
//   reference_utc = 2019-08-21T00:00:00Z   # the phases' time origin
//   [M2]                                   # M2, S2, N2, K2, K1, O1, P1, Q1, M4
//   east_amplitude_m_s = 0.31              # >= 0, <= 3
//   east_phase_deg = 123.0                 # [-360, 360]
//   north_amplitude_m_s = 0.12
//   north_phase_deg = 300.0
//   amplitude_sigma_m_s = 0.08             # 1 sigma of each amplitude, [0, 3]
//   phase_sigma_deg = 30.0                 # 1 sigma of each phase, [0, 180]
//   [mean]                                 # optional: a residual mean (a fit's)
//   east_m_s = 0.02                        # [-3, 3]
//   north_m_s = -0.01
//
// A component is amplitude x cos(omega (t - reference) - phase), omega the
// constituent's angular speed (its period fixed: nodal corrections are not
// applied; a year's M2 amplitude moves by up to 3.7 %, inside any sigma a
// pilot has). The east and north errors are taken as independent.
#include <filesystem>
#include <string>
#include <vector>

namespace glider::forecast {

struct TideComponent {
  double amplitude_m_s = 0.0;
  double phase_deg = 0.0;
  double amplitude_sigma_m_s = 0.0;
  double phase_sigma_deg = 0.0;
};

struct TideConstituent {
  std::string name;  // one of tide_constituent_names()
  double period_s = 0.0;
  TideComponent east, north;
};

struct TideTable {
  double reference_utc_s = 0.0;
  std::vector<TideConstituent> constituents;
  double mean_east_m_s = 0.0, mean_north_m_s = 0.0;  // [mean]: zero when absent
  std::string source;                                // the file it was read from
};

// The constituents a table may name, and each one's period (s); throws
// std::invalid_argument for another name.
const std::vector<std::string>& tide_constituent_names();
double tide_constituent_period_s(const std::string& name);

// Reads and checks a table: a bad file (a syntax error, an unknown key or
// constituent, a missing amplitude or phase, NaN, a value out of range) throws
// std::runtime_error naming file:line, the key, the value and the range.
TideTable read_tide_table(const std::filesystem::path& file);
// The table as the file above (what fit-tide writes); read_tide_table reads it back.
std::string format_tide_table(const TideTable& table, const std::string& comment);

// The table's current (component 0 east, 1 north) averaged over a segment
// centred on utc_s lasting span_s (0: at that instant).
double tide_mean(const TideTable& table, int component, double utc_s, double span_s);
// The covariance of the table's error in one component between two segment
// means (linearised in the amplitude's and the phase's errors).
double tide_error_covariance(const TideTable& table, int component, double t1, double s1, double t2, double s2);

}  // namespace glider::forecast
