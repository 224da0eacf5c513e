// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/log_writer.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>

namespace glider::truth {
namespace {

void number(std::string& out, double x) {
  if (!std::isfinite(x)) return;  // empty field
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, result.ptr);
}

constexpr const char* kHeader =
    "m_present_time,m_depth,m_pitch,m_roll,m_heading,c_heading,m_fin,c_fin,m_ballast_pumped,c_ballast_pumped,"
    "m_battpos,c_battpos,c_pitch,m_depth_state,x_yo_count,sci_water_temp,sci_water_pressure,sci_water_density";

}  // namespace

std::string log_text(const FlightResult& f, const LogSettings& settings) {
  std::mt19937_64 rng(settings.seed ^ 0x5eed7417u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string out;
  out += "# source: glider-truth, the independent truth simulator (tools/science/truth)\n";
  out += "# vehicle_file: " + settings.vehicle_file + "\n";
  char settings_line[256];
  std::snprintf(settings_line, sizeof settings_line,
                "# settings_at_file_open: u_hd_fin_ap_gain=%.17g u_hd_fin_ap_igain=%.17g u_hd_fin_ap_dgain=%.17g "
                "u_heading_rate_deadband=%.17g f_fin_safety_max=%.17g\n",
                f.stated_gain, f.stated_igain, f.stated_dgain, f.rate_deadband_rad_s, f.vehicle.heading.fin_max_rad);
  out += settings_line;
  const bool dvl = settings.dvl_noise_m_s >= 0.0;
  out += kHeader;
  out += dvl ? ",sci_speed_through_water\n" : "\n";
  // Its own stream: the log without the DVL stays the same bits.
  std::mt19937_64 dvl_rng(settings.seed ^ 0xd71a5eedu);
  std::normal_distribution<double> dvl_noise(0.0, dvl ? settings.dvl_noise_m_s : 0.0);
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  double last_c_ballast = kNaN, last_c_battpos = kNaN, last_c_pitch = kNaN;
  std::size_t rows = 0;
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    const Sample& s = f.samples[i];
    const bool edge = i == 0 || i + 1 == f.samples.size();
    if (!edge && u(rng) < 0.02) continue;  // a cycle the glider did not log
    auto changed = [kNaN](double x, double& last) {
      const bool c = !(x == last) && !(std::isnan(x) && std::isnan(last));
      if (c) last = x;
      return c ? x : kNaN;
    };
    const bool ctd = s.depth_m > 0.5 && u(rng) >= 0.05;
    number(out, s.time_s);
    for (double x :
         {s.depth_m, s.pitch_rad, s.roll_rad, s.heading_rad, s.c_heading_rad, s.fin_rad, s.c_fin_rad, s.ballast_cc,
          changed(s.c_ballast_cc, last_c_ballast), s.battpos_in, changed(s.c_battpos_in, last_c_battpos),
          changed(s.c_pitch_rad, last_c_pitch), static_cast<double>(s.depth_state), static_cast<double>(s.yo_count),
          ctd ? s.temperature_c : kNaN, ctd ? s.pressure_bar : kNaN, ctd ? s.density_kg_m3 : kNaN}) {
      out += ',';
      number(out, x);
    }
    if (dvl) {
      out += ',';
      const double noise = dvl_noise(dvl_rng);
      if (s.depth_state == 1 && s.true_depth_m > settings.dvl_min_depth_m) number(out, s.speed_m_s + noise);
    }
    out += '\n';
    ++rows;
  }
  out += "# end: complete rows=" + std::to_string(rows) + " lost=0\n";
  return out;
}

void write_log(const std::string& path, const FlightResult& flight, const LogSettings& settings) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot write " + path);
  file << log_text(flight, settings);
  if (!file.flush()) throw std::runtime_error("cannot write " + path);
}

}  // namespace glider::truth
