// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/sim_hal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glider/hal/time.hpp"
#include "glider/units.hpp"

namespace glider::sil {

SimHal::SimHal(model::GliderSimulator& sim, const SimClock& clock, const SensorNoise& noise, std::uint64_t seed,
               const PeripheralModels& peripherals)
    : sim_(sim),
      clock_(clock),
      noise_(noise),
      random_(seed),
      gps_(sim, clock, faults_, peripherals.gps, derived_seed(seed, kGpsNoiseStream),
           derived_seed(seed, kGpsAcquisitionStream)),
      leak_(clock, faults_),
      drop_weight_(clock),
      power_(sim, clock, faults_, peripherals.power) {}

hal::DepthSample SimHal::read() {
  if (faults_.depth_frozen) return last_depth_;
  hal::DepthSample sample;
  sample.time_us = clock_.now_us();
  sample.depth_m = sim_.state()[model::kZ] + noise_.depth_m * gaussian();
  sample.valid = !faults_.depth_invalid;
  last_depth_ = sample;
  return sample;
}

hal::AttitudeSample SimHal::read_attitude() {
  if (faults_.attitude_frozen) return last_attitude_;
  hal::AttitudeSample sample;
  sample.time_us = clock_.now_us();
  const double pitch = sim_.state()[model::kTheta] + noise_.pitch_rad * gaussian();
  double roll = sim_.dynamics().vehicle().heading.roll_offset_rad + noise_.roll_rad * gaussian();
  const double two_pi = 2.0 * std::numbers::pi;
  double heading =
      delayed_heading(hal::to_seconds(sample.time_us), sim_.state()[model::kPsi]) + noise_.heading_rad * gaussian();
  // The model's pitch angle runs on past +-90 deg when a vehicle somersaults
  // (a polar with no glide at the mission's pitch); a compass reports Euler
  // angles (attitude_sensor.hpp): past vertical the pitch comes back and the
  // roll and heading turn over by 180 deg, as the serial driver's compass does.
  sample.pitch_rad = pitch;
  if (std::abs(pitch) > std::numbers::pi / 2.0) {
    sample.pitch_rad = std::asin(std::sin(pitch));
    if (std::cos(pitch) < 0.0) {
      roll += std::numbers::pi;
      heading += std::numbers::pi;
    }
  }
  sample.roll_rad = std::remainder(roll, two_pi);
  sample.heading_rad = std::fmod(std::fmod(heading, two_pi) + two_pi, two_pi);
  sample.valid = !faults_.attitude_invalid;
  last_attitude_ = sample;
  return sample;
}

double SimHal::delayed_heading(double now_s, double heading_rad) {
  if (!(noise_.heading_delay_s > 0.0)) return heading_rad;
  heading_history_[history_next_] = {now_s, heading_rad};
  history_next_ = (history_next_ + 1) % kHeadingHistory;
  history_count_ = std::min(history_count_ + 1, kHeadingHistory);
  const double wanted = now_s - noise_.heading_delay_s;
  // Newest to oldest: the pair of readings around `wanted`, linearly between.
  auto at = [this](std::size_t back) {
    return heading_history_[(history_next_ + kHeadingHistory - 1 - back) % kHeadingHistory];
  };
  for (std::size_t back = 0; back + 1 < history_count_; ++back) {
    const auto [t1, h1] = at(back);
    const auto [t0, h0] = at(back + 1);
    if (t0 <= wanted) return t1 > t0 ? h0 + (h1 - h0) * (wanted - t0) / (t1 - t0) : h0;
  }
  return at(history_count_ - 1).second;
}

bool SimHal::inject(const std::string& name) {
  if (!apply_fault(name, faults_)) return false;
  if (faults_.pump_stuck) sim_.command_pumped_volume_m3(sim_.pump().position());
  return true;
}

void SimHal::command_volume_cc(double volume_cc) {
  if (faults_.pump_stuck) {
    sim_.command_pumped_volume_m3(sim_.pump().position());  // stops where it is
    return;
  }
  sim_.command_pumped_volume_m3(cc_to_m3(volume_cc));
}

hal::ActuatorReading SimHal::read_volume_cc() {
  hal::ActuatorReading reading;
  reading.time_us = clock_.now_us();
  reading.position = m3_to_cc(sim_.pump().position());
  reading.valid = true;
  reading.fault = faults_.pump_fault;
  return reading;
}

void SimHal::command_position_in(double position_in) { sim_.command_battery_pos_m(in_to_m(position_in)); }

hal::ActuatorReading SimHal::read_position_in() {
  hal::ActuatorReading reading;
  reading.time_us = clock_.now_us();
  reading.position = m_to_in(sim_.battery().position());
  reading.valid = true;
  reading.fault = faults_.battery_fault;
  return reading;
}

}  // namespace glider::sil

namespace glider::sil {

hal::ActuatorReading SimHal::RudderPort::read_angle_rad() {
  hal::ActuatorReading reading;
  reading.time_us = owner_.clock_.now_us();
  reading.position = owner_.sim_.fin().position();
  reading.valid = true;
  reading.fault = owner_.faults_.fin_fault;
  return reading;
}

}  // namespace glider::sil
