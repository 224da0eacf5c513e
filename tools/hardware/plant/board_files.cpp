// SPDX-License-Identifier: Apache-2.0
#include "board_files.hpp"

#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "glider/units.hpp"

namespace glider::plant {
namespace {

// Shortest text that reads back to the same double.
std::string number(double value) {
  std::ostringstream out;
  out << std::setprecision(17) << value;
  return out.str();
}

// Twelve digits: 250e-6 m^3 reads as 250 cc, not 250.00000000000003 (which
// the pump axis, limited to 250 cc, would refuse).
std::string rounded(double value) {
  std::ostringstream out;
  out << std::setprecision(12) << value;
  return out.str();
}

void write_axis(std::ostream& out, const hal_linux::AxisConfig& axis) {
  const std::string& u = axis.unit;
  out << "\n[" << axis.name << "]\nslave = " << axis.slave << "\nbase_address = " << axis.base_address
      << "\ncounts_per_unit = " << number(axis.counts_per_unit) << "\ntravel_min_" << u << " = "
      << number(axis.travel_min) << "\ntravel_max_" << u << " = " << number(axis.travel_max) << "\nmin_" << u << " = "
      << number(axis.min) << "\nmax_" << u << " = " << number(axis.max) << "\nrate_" << u
      << "_s = " << number(axis.rate) << "\nmax_rate_" << u << "_s = " << number(axis.max_rate) << "\n";
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

std::filesystem::path write_board_files(const std::filesystem::path& directory, const hal_linux::ModbusBoard& actuators,
                                        const PlantEndpoints& e) {
  std::filesystem::create_directories(directory);
  std::filesystem::create_directories(e.log_directory);
  const hal_linux::BusConfig& bus = actuators.bus;
  std::ostringstream a;
  a << "# SPDX-License-Identifier: Apache-2.0\n# Written by glider-plant: the actuator board " << actuators.source
    << "\n# served over Modbus TCP by the plant.\nname = \"plant_actuators\"\n\n[bus]\ntransport = \"tcp\"\nhost = \""
    << e.host << "\"\nport = " << e.port << "\nresponse_timeout_ms = " << bus.response_timeout_ms
    << "\nbyte_timeout_ms = " << bus.byte_timeout_ms << "\nretries = " << bus.retries
    << "\ncycle_period_ms = " << bus.cycle_period_ms << "\ncycle_budget_ms = " << bus.cycle_budget_ms << "\n";
  write_axis(a, actuators.pump);
  write_axis(a, actuators.slide);
  if (actuators.rudder) write_axis(a, *actuators.rudder);
  write_file(directory / "actuators.toml", a.str());

  std::ostringstream b;
  b << "# SPDX-License-Identifier: Apache-2.0\n# Written by glider-plant: the glider's devices are the plant's.\n"
       "name = \"plant\"\ndescription = \"hardware in the loop: glider-plant's devices\"\n"
       "bench = true   # a bench board: glider-firmware --time-scale is allowed\n\n"
       "[loop]\nsched_fifo = false\nlock_memory = false\nstats_every_s = 60\n\n"
       "[actuators]\nboard = \"actuators.toml\"\n\n[gps]\ndevice = \""
    << e.gps_device << "\"\nbaud = 9600\n\n[compass]\ndevice = \"" << e.compass_device
    << "\"\nbaud = 19200\n\n[depth]\ndevice = \"" << e.depth_device << "\"\nbaud = 9600\nslave = " << e.keller.slave
    << "\nsurface_pressure_bar = " << number(e.keller.surface_pressure_bar)
    << "\nwater_density_kg_m3 = " << number(e.keller.water_density_kg_m3)
    << "\nmax_pressure_bar = " << number(e.keller.max_pressure_bar) << "\n\n[log]\ndirectory = \""
    << e.log_directory.string() << "\"\n";
  if (!e.modem_device.empty()) {
    // Any number reaches the plant's --shore; no DCD wire on a pty (NO CARRIER ends a call).
    b << "\n[modem]\ndevice = \"" << e.modem_device << "\"\nbaud = 19200\ndcd = false\nvehicle_name = \""
      << e.modem_vehicle_name << "\"\nprimary_number = \"0088160000519\"\n";
  }
  const fw::mission_file::MissionVehicle& v = e.vehicle.vehicle;
  b << "\n[vehicle]   # the plant's vehicle model, as glider-sil derives it from the vehicle file\n"
    << "max_working_depth_m = " << rounded(v.max_working_depth_m)
    << "\nballast_min_cc = " << rounded(v.limits.ballast_min_cc)
    << "\nballast_max_cc = " << rounded(v.limits.ballast_max_cc)
    << "\nbattery_min_in = " << rounded(v.limits.battery_min_in)
    << "\nbattery_max_in = " << rounded(v.limits.battery_max_in)
    << "\nfin_max_deg = " << rounded(rad_to_deg(v.fin_max_rad))
    << "\nfin_rate_deg_s = " << rounded(rad_to_deg(v.fin_rate_rad_s))
    << "\nyaw_gain_per_m = " << rounded(v.yaw_gain_per_m) << "\nfin_delay_s = " << rounded(e.vehicle.fin_delay_s)
    << "\nheading_law = \"" << e.heading_law << "\"\n";
  write_file(directory / "board.toml", b.str());
  return directory / "board.toml";
}

}  // namespace glider::plant
