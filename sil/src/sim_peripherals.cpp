// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/sim_peripherals.hpp"

#include <algorithm>
#include <cmath>

#include "glider/units.hpp"

namespace glider::sil {
namespace {

hal::Micros seconds_to_us(double s) { return static_cast<hal::Micros>(std::llround(s * 1e6)); }

}  // namespace

SimGps::SimGps(const model::GliderSimulator& sim, const SimClock& clock, const FaultInjection& faults,
               const GpsModel& model, std::uint64_t noise_seed, std::uint64_t acquisition_seed)
    : sim_(sim),
      clock_(clock),
      faults_(faults),
      model_(model),
      frame_(model.launch),
      noise_random_(noise_seed),
      acquisition_random_(acquisition_seed) {}

hal::GpsFix SimGps::read() {
  const hal::Micros now = clock_.now_us();
  const model::Truth truth = sim_.truth();
  const bool antenna_out = truth.depth_m < model_.antenna_out_depth_m && !faults_.gps_dead;
  if (!antenna_out) {
    acquiring_ = false;  // the last fix stays, ageing: the firmware checks its time
    return last_;
  }
  if (!acquiring_) {
    acquiring_ = true;
    const double ttff =
        model_.time_to_first_fix_min_s +
        (model_.time_to_first_fix_max_s - model_.time_to_first_fix_min_s) * acquisition_random_.uniform();
    first_fix_us_ = now + seconds_to_us(ttff);
    next_fix_us_ = first_fix_us_;
  }
  if (now >= next_fix_us_) {
    const fw::EastNorth position{truth.east_m + model_.noise_m * noise_random_.gaussian(),
                                 truth.north_m + model_.noise_m * noise_random_.gaussian()};
    const fw::LatLon fix = frame_.to_global(position);
    last_ = {fix.lat_deg, fix.lon_deg, 1, 8, 1.0, now, true};
    next_fix_us_ = now + seconds_to_us(model_.fix_interval_s);
  }
  return last_;
}

bool SimDropWeight::set(bool active) {
  if (active && !released_) {
    released_ = true;
    released_at_us_ = clock_.now_us();
  }
  return true;
}

SimPowerMonitor::SimPowerMonitor(const model::GliderSimulator& sim, const SimClock& clock, const FaultInjection& faults,
                                 const PowerModel& model)
    : sim_(sim),
      clock_(clock),
      faults_(faults),
      model_(model),
      last_us_(clock.now_us()),
      last_pump_m3_(sim.pump().position()),
      last_battery_m_(sim.battery().position()),
      last_fin_rad_(sim.fin().position()) {}

hal::PowerSample SimPowerMonitor::read() {
  const hal::Micros now = clock_.now_us();
  const double dt = hal::to_seconds(now - last_us_);
  const double pump = sim_.pump().position();
  const double battery = sim_.battery().position();
  const double fin = sim_.fin().position();
  double joules = (model_.hotel_w + faults_.extra_load_w) * dt;
  const double pumped_out_cc = m3_to_cc(std::max(pump - last_pump_m3_, 0.0));
  const double depth = std::max(sim_.truth().depth_m, 0.0);
  const double gauge_pa = depth * 1025.0 * 9.81;
  joules += pumped_out_cc * (model_.pump_fixed_j_per_cc + cc_to_m3(1.0) * gauge_pa / model_.pump_efficiency);
  joules += m_to_in(std::fabs(battery - last_battery_m_)) * model_.slide_j_per_in;
  joules += std::fabs(fin - last_fin_rad_) * model_.fin_j_per_rad;
  energy_j_ += joules;
  const double used_fraction = charge_amphr_ / model_.capacity_amphr;
  const double volts =
      model_.voltage_full_v - (model_.voltage_full_v - model_.voltage_empty_v) * std::min(used_fraction, 1.0);
  charge_amphr_ += joules / volts / 3600.0;
  last_us_ = now;
  last_pump_m3_ = pump;
  last_battery_m_ = battery;
  last_fin_rad_ = fin;
  return {volts, charge_amphr_, now, true};
}

}  // namespace glider::sil
