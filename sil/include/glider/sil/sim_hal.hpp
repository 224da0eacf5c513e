// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/battery_slide.hpp"
#include "glider/hal/buoyancy_pump.hpp"
#include "glider/hal/depth_sensor.hpp"
#include "glider/hal/rudder.hpp"
#include "glider/model/simulator.hpp"
#include "glider/sil/fault_injection.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/sim_clock.hpp"
#include "glider/sil/sim_peripherals.hpp"

namespace glider::sil {

// Measurement noise of the simulated sensors (1 sigma). Defaults are those of
// a Slocum's pressure sensor and compass as seen in the real logs, and of the
// science bay's pumped CTD (SBE-41 class: its stated accuracy).
struct SensorNoise {
  double depth_m = 0.01;
  double pitch_rad = 0.0017;  // 0.1 deg
  double roll_rad = 0.0017;
  double heading_rad = 0.0035;
  // Not noise but the compass's own lag: the heading it reports is the
  // vehicle's this long ago (s, a dead time; 0 = none), e.g. its filtering.
  // At most kHeadingHistory readings back (older: the oldest one kept).
  double heading_delay_s = 0.0;
  double ctd_temperature_c = 0.002;
  double ctd_conductivity_s_m = 0.0003;
  double ctd_pressure_bar = 0.002;
};

struct PeripheralModels {
  GpsModel gps{};
  PowerModel power{};
};

// The HAL implemented on the vehicle model. Deterministic: the noise comes
// from a seeded PortableRandom (the GPS from its own stream), so logs are
// bit-identical across runs and machines.
class SimHal final : public hal::DepthSensor, public hal::BuoyancyPump, public hal::BatterySlide {
 public:
  SimHal(model::GliderSimulator& sim, const SimClock& clock, const SensorNoise& noise, std::uint64_t seed,
         const PeripheralModels& peripherals = {});

  hal::DepthSample read() override;
  hal::AttitudeSample read_attitude();

  void command_volume_cc(double volume_cc) override;
  hal::ActuatorReading read_volume_cc() override;
  void command_position_in(double position_in) override;
  hal::ActuatorReading read_position_in() override;

  FaultInjection& faults() { return faults_; }
  // Switches a named fault on (fault_names()), with its side effects on the
  // plant (a stuck pump stops where it is). False if the name is unknown.
  bool inject(const std::string& name);

  // AttitudeSensor::read() would clash with DepthSensor::read(): the attitude
  // sensor is a small port object.
  hal::DepthSensor& depth() { return *this; }
  hal::AttitudeSensor& attitude() { return attitude_port_; }
  hal::Rudder& rudder() { return rudder_port_; }
  SimGps& gps() { return gps_; }
  SimLeakDetector& leak() { return leak_; }
  SimDropWeight& drop_weight() { return drop_weight_; }
  SimPowerMonitor& power() { return power_; }

 private:
  class AttitudePort final : public hal::AttitudeSensor {
   public:
    explicit AttitudePort(SimHal& owner) : owner_(owner) {}
    hal::AttitudeSample read() override { return owner_.read_attitude(); }

   private:
    SimHal& owner_;
  };

  class RudderPort final : public hal::Rudder {
   public:
    explicit RudderPort(SimHal& owner) : owner_(owner) {}
    void command_angle_rad(double angle_rad) override { owner_.sim_.command_fin_rad(angle_rad); }
    hal::ActuatorReading read_angle_rad() override;

   private:
    SimHal& owner_;
  };

  double gaussian() { return random_.gaussian(); }

  model::GliderSimulator& sim_;
  const SimClock& clock_;
  SensorNoise noise_;
  PortableRandom random_;
  FaultInjection faults_{};
  hal::DepthSample last_depth_{};  // what a frozen sensor keeps returning
  hal::AttitudeSample last_attitude_{};
  // The true heading at each attitude reading (time s, heading rad, unwrapped),
  // for the compass's dead time: a ring, newest at history_next_ - 1.
  double delayed_heading(double now_s, double heading_rad);
  static constexpr std::size_t kHeadingHistory = 64;
  std::array<std::pair<double, double>, kHeadingHistory> heading_history_{};
  std::size_t history_next_ = 0, history_count_ = 0;
  AttitudePort attitude_port_{*this};
  RudderPort rudder_port_{*this};
  SimGps gps_;
  SimLeakDetector leak_;
  SimDropWeight drop_weight_;
  SimPowerMonitor power_;
};

}  // namespace glider::sil
