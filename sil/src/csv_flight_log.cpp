// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/csv_flight_log.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "glider/units.hpp"

namespace glider::sil {
namespace {

void append_number(std::string& line, double value) {
  if (std::isfinite(value)) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    line.append(buffer, result.ptr);
  }
  line.push_back(',');
}

void append_integer(std::string& line, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  line.append(buffer, result.ptr);
  line.push_back(',');
}

// Microseconds as exact decimal seconds ("12.5", "3").
void append_time(std::string& line, hal::Micros us) {
  append_integer(line, us / hal::kMicrosPerSecond);
  line.pop_back();
  long long fraction = us % hal::kMicrosPerSecond;
  if (fraction != 0) {
    char digits[7];
    for (int i = 5; i >= 0; --i) {
      digits[i] = static_cast<char>('0' + fraction % 10);
      fraction /= 10;
    }
    int length = 6;
    while (length > 0 && digits[length - 1] == '0') --length;
    line.push_back('.');
    line.append(digits, static_cast<std::size_t>(length));
  }
  line.push_back(',');
}

}  // namespace

const char* CsvFlightLog::header() {
  return "m_present_time,m_depth,m_depth_rate,m_pitch,m_roll,m_heading,m_ballast_pumped,c_ballast_pumped,"
         "m_battpos,c_battpos,c_pitch,m_depth_state,x_yo_count,x_abort_cause,x_loop_overruns,"
         "c_heading,m_fin,c_fin,m_gps_lat,m_gps_lon,m_lat,m_lon,m_water_vx,m_water_vy,m_leakdetect,"
         "m_coulomb_amphr_total,m_battery,x_waypoint,x_waypoints_reached,x_segment,x_dr_error_m,x_dr_distance_m,x_"
         "mission_complete,"
         "sci_water_temp,sci_water_cond,sci_water_pressure,"
         "sim_east_m,sim_north_m,sim_depth_m,sim_heading_rad,sim_pitch_rad,sim_speed_m_s,sim_alpha_rad,"
         "sim_glide_path_rad,sim_horizontal_speed_m_s,sim_depth_rate_m_s,sim_net_buoyancy_kg,"
         "sim_ballast_pumped_cc,sim_battpos_in,sim_fin_rad,sim_yaw_rate_rad_s,sim_density_kg_m3,sim_u_water_m_s,sim_v_"
         "water_m_s,"
         "sim_w_water_m_s,sim_temperature_c,sim_practical_salinity";
}

CsvFlightLog::CsvFlightLog(const std::string& path, const Metadata& metadata, const model::GliderSimulator& sim,
                           const SimCtd& ctd, const LogGaps& gaps, std::uint64_t gap_seed)
    : path_(path),
      out_(path, std::ios::out | std::ios::trunc),
      sim_(sim),
      ctd_(ctd),
      gaps_(gaps),
      gap_random_(gap_seed) {
  if (!out_) {
    ok_ = false;
    error_ = path + ": cannot open for writing: " + std::strerror(errno);
    return;
  }
  for (const auto& [key, value] : metadata) {
    out_ << "# " << key << ": " << value << '\n';
  }
  out_ << header() << '\n';
  line_.reserve(512);
  ok_ = static_cast<bool>(out_);
  if (!ok_) error_ = path + ": write failed";
}

hal::Micros CsvFlightLog::draw_us(double min_s, double max_s) {
  return static_cast<hal::Micros>(std::llround((min_s + (max_s - min_s) * gap_random_.uniform()) * 1e6));
}

bool CsvFlightLog::thinned_out(const hal::FlightLogRecord& r) {
  if (!gaps_.enabled) return false;
  const bool surface = r.m_depth_state == 0;
  if (surface && !at_surface_) {
    surface_gap_end_us_ = r.time_us + draw_us(gaps_.surface_gap_min_s, gaps_.surface_gap_max_s);
  }
  at_surface_ = surface;
  if (surface && r.time_us < surface_gap_end_us_) return true;
  if (r.time_us < next_row_us_) return true;
  next_row_us_ = r.time_us + draw_us(gaps_.min_interval_s, gaps_.max_interval_s);
  return false;
}

bool CsvFlightLog::write(const hal::FlightLogRecord& r) {
  if (!ok_) return false;
  if (thinned_out(r)) return true;  // not logged by design: not a lost row
  const model::Truth t = sim_.truth();
  line_.clear();
  append_time(line_, r.time_us);
  append_number(line_, r.m_depth);
  append_number(line_, r.m_depth_rate);
  append_number(line_, r.m_pitch);
  append_number(line_, r.m_roll);
  append_number(line_, r.m_heading);
  append_number(line_, r.m_ballast_pumped);
  append_number(line_, r.c_ballast_pumped);
  append_number(line_, r.m_battpos);
  append_number(line_, r.c_battpos);
  append_number(line_, r.c_pitch);
  append_integer(line_, r.m_depth_state);
  append_integer(line_, r.x_yo_count);
  append_integer(line_, r.x_abort_cause);
  append_integer(line_, r.x_loop_overruns);
  append_number(line_, r.c_heading);
  append_number(line_, r.m_fin);
  append_number(line_, r.c_fin);
  append_number(line_, r.m_gps_lat);
  append_number(line_, r.m_gps_lon);
  append_number(line_, r.m_lat);
  append_number(line_, r.m_lon);
  append_number(line_, r.m_water_vx);
  append_number(line_, r.m_water_vy);
  append_integer(line_, r.m_leakdetect);
  append_number(line_, r.m_coulomb_amphr_total);
  append_number(line_, r.m_battery);
  append_integer(line_, r.x_waypoint);
  append_integer(line_, r.x_waypoints_reached);
  append_integer(line_, r.x_segment);
  append_number(line_, r.x_dr_error_m);
  append_number(line_, r.x_dr_distance_m);
  append_integer(line_, r.x_mission_complete);
  // The science bay is off at the surface (m_depth_state 0), as in real logs.
  const bool science_missed = gaps_.enabled && gap_random_.uniform() < gaps_.sci_blank_fraction;
  const CtdReading ctd = science_missed ? CtdReading{} : ctd_.sample(t, r.m_depth_state != 0);
  append_number(line_, ctd.temperature_c);
  append_number(line_, ctd.conductivity_s_m);
  append_number(line_, ctd.pressure_bar);
  append_number(line_, t.east_m);
  append_number(line_, t.north_m);
  append_number(line_, t.depth_m);
  append_number(line_, t.heading_rad);
  append_number(line_, t.pitch_rad);
  append_number(line_, t.speed_m_s);
  append_number(line_, t.alpha_rad);
  append_number(line_, t.glide_path_rad);
  append_number(line_, t.horizontal_speed_m_s);
  append_number(line_, t.depth_rate_m_s);
  append_number(line_, t.net_buoyancy_kg);
  append_number(line_, m3_to_cc(t.pumped_volume_m3));
  append_number(line_, m_to_in(t.battery_pos_m));
  append_number(line_, t.fin_rad);
  append_number(line_, t.yaw_rate_rad_s);
  append_number(line_, t.water.density_kg_m3);
  append_number(line_, t.water.current_east_m_s);
  append_number(line_, t.water.current_north_m_s);
  append_number(line_, t.water.vertical_velocity_m_s);
  append_number(line_, t.water.temperature_c);
  append_number(line_, t.water.practical_salinity);
  line_.back() = '\n';
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
  if (!out_) {
    ok_ = false;
    error_ = path_ + ": write failed after " + std::to_string(rows_) + " rows: " + std::strerror(errno);
    return false;
  }
  ++rows_;
  return true;
}

bool CsvFlightLog::close() {
  if (out_.is_open()) {
    out_.flush();
    if (!out_ && ok_) {
      ok_ = false;
      error_ = path_ + ": flush failed: " + std::strerror(errno);
    }
    out_.close();
    if (out_.fail() && ok_) {
      ok_ = false;
      error_ = path_ + ": close failed";
    }
  }
  return ok_;
}

}  // namespace glider::sil
