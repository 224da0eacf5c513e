// SPDX-License-Identifier: Apache-2.0
#pragma once
// The log schema's second part: the columns the SIL appends after the
// firmware's (hal::kLogColumns), typed as the firmware's are, with their
// units. The SIL writer (sil/src/csv_flight_log.cpp) writes them from this
// table, the reader (tools/files/flightlog/src/columns.cpp) takes their units from
// it, and a test checks it against the table in docs/flight-log.md. The
// sci_* columns are the simulated science CTD's readings (NaN: no reading),
// the sim_* columns the simulator's truths, never needed by an analysis.
// The file's bytes are those of the string header this table replaced.
#include <array>

#include "glider/hal/log_record.hpp"

namespace glider::hal {

struct SimLogRow {
  double sci_water_temp = 0.0;      // degC
  double sci_water_cond = 0.0;      // S/m
  double sci_water_pressure = 0.0;  // bar
  double sim_east_m = 0.0;          // position from the launch point
  double sim_north_m = 0.0;
  double sim_depth_m = 0.0;
  double sim_heading_rad = 0.0;
  double sim_pitch_rad = 0.0;
  double sim_speed_m_s = 0.0;  // through the water
  double sim_alpha_rad = 0.0;  // angle of attack
  double sim_glide_path_rad = 0.0;
  double sim_horizontal_speed_m_s = 0.0;
  double sim_depth_rate_m_s = 0.0;
  double sim_net_buoyancy_kg = 0.0;
  double sim_ballast_pumped_cc = 0.0;  // the pump's true position
  double sim_battpos_in = 0.0;         // the battery's true position
  double sim_fin_rad = 0.0;
  double sim_yaw_rate_rad_s = 0.0;
  double sim_density_kg_m3 = 0.0;  // of the water at the vehicle
  double sim_u_water_m_s = 0.0;    // the water's velocity east
  double sim_v_water_m_s = 0.0;    // north
  double sim_w_water_m_s = 0.0;    // up
  double sim_temperature_c = 0.0;  // of the water, without sensor noise
  double sim_practical_salinity = 0.0;
};

using SimLogColumn = LogColumnOf<SimLogRow>;

#define GLIDER_SIM_LOG_NUMBER(field, unit)                                           \
  SimLogColumn {                                                                     \
#field, unit, LogColumnKind::kNumber, [](const SimLogRow& r) { return r.field; } \
  }

inline constexpr std::array kSimLogColumns{
    GLIDER_SIM_LOG_NUMBER(sci_water_temp, "degC"),
    GLIDER_SIM_LOG_NUMBER(sci_water_cond, "S/m"),
    GLIDER_SIM_LOG_NUMBER(sci_water_pressure, "bar"),
    GLIDER_SIM_LOG_NUMBER(sim_east_m, "m"),
    GLIDER_SIM_LOG_NUMBER(sim_north_m, "m"),
    GLIDER_SIM_LOG_NUMBER(sim_depth_m, "m"),
    GLIDER_SIM_LOG_NUMBER(sim_heading_rad, "rad"),
    GLIDER_SIM_LOG_NUMBER(sim_pitch_rad, "rad"),
    GLIDER_SIM_LOG_NUMBER(sim_speed_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_alpha_rad, "rad"),
    GLIDER_SIM_LOG_NUMBER(sim_glide_path_rad, "rad"),
    GLIDER_SIM_LOG_NUMBER(sim_horizontal_speed_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_depth_rate_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_net_buoyancy_kg, "kg"),
    GLIDER_SIM_LOG_NUMBER(sim_ballast_pumped_cc, "cc"),
    GLIDER_SIM_LOG_NUMBER(sim_battpos_in, "in"),
    GLIDER_SIM_LOG_NUMBER(sim_fin_rad, "rad"),
    GLIDER_SIM_LOG_NUMBER(sim_yaw_rate_rad_s, "rad/s"),
    GLIDER_SIM_LOG_NUMBER(sim_density_kg_m3, "kg/m^3"),
    GLIDER_SIM_LOG_NUMBER(sim_u_water_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_v_water_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_w_water_m_s, "m/s"),
    GLIDER_SIM_LOG_NUMBER(sim_temperature_c, "degC"),
    GLIDER_SIM_LOG_NUMBER(sim_practical_salinity, "PSS-78"),
};

#undef GLIDER_SIM_LOG_NUMBER

}  // namespace glider::hal
