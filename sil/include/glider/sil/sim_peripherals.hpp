// SPDX-License-Identifier: Apache-2.0
#pragma once
// The simulated GPS, leak detector, drop weight and power monitor: the HAL
// devices that are not part of the flight dynamics. Deterministic (seeded),
// allocation-free after construction.
#include <cstdint>

#include "glider/firmware/geo.hpp"
#include "glider/hal/digital_io.hpp"
#include "glider/hal/gps.hpp"
#include "glider/hal/power_monitor.hpp"
#include "glider/model/simulator.hpp"
#include "glider/sil/fault_injection.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/sim_clock.hpp"

namespace glider::sil {

// A Slocum's GPS antenna sits in the tail fin: it is out of the water only
// while the glider floats at the surface. Figures are those of a small
// receiver after a dive (warm start, then 1 Hz fixes).
struct GpsModel {
  fw::LatLon launch{54.3161,
                    7.4098};         // where the simulated start (east 0, north 0) is; default: comet-2019's first fix
  double antenna_out_depth_m = 0.3;  // vehicle depth (hull centre) shallower than this: antenna in the air
  double time_to_first_fix_min_s = 20.0;
  double time_to_first_fix_max_s = 60.0;
  double fix_interval_s = 1.0;
  double noise_m = 3.0;  // 1 sigma per axis (HDOP ~1 with a consumer receiver)
};

// Where the energy goes (all assumed, Slocum-shallow-like orders of
// magnitude): a hotel load, the pump's hydraulic work at the depth it pumps
// at over its efficiency plus a fixed cost per cc, the slide and fin motors
// per unit of travel. Only pumping out (more buoyant) costs hydraulic work.
struct PowerModel {
  double capacity_amphr = 150.0;  // order of a Slocum lithium primary pack
  double voltage_full_v = 15.0;
  double voltage_empty_v = 10.5;
  double hotel_w = 0.6;
  double pump_efficiency = 0.5;  // piston pump and motor
  double pump_fixed_j_per_cc = 0.5;
  double slide_j_per_in = 60.0;  // ~3 W at 0.05 in/s
  double fin_j_per_rad = 5.0;
};

class SimGps final : public hal::GpsReceiver {
 public:
  // Position noise and times to first fix come from two streams (see
  // kGpsAcquisitionStream).
  SimGps(const model::GliderSimulator& sim, const SimClock& clock, const FaultInjection& faults, const GpsModel& model,
         std::uint64_t noise_seed, std::uint64_t acquisition_seed);
  hal::GpsFix read() override;
  const fw::LocalFrame& frame() const { return frame_; }

 private:
  const model::GliderSimulator& sim_;
  const SimClock& clock_;
  const FaultInjection& faults_;
  GpsModel model_;
  fw::LocalFrame frame_;
  PortableRandom noise_random_;
  PortableRandom acquisition_random_;
  bool acquiring_ = false;
  hal::Micros first_fix_us_ = 0;
  hal::Micros next_fix_us_ = 0;
  hal::GpsFix last_{};
};

class SimLeakDetector final : public hal::DigitalInput {
 public:
  SimLeakDetector(const SimClock& clock, const FaultInjection& faults) : clock_(clock), faults_(faults) {}
  hal::DigitalSample read() override { return {faults_.leak, clock_.now_us(), true}; }

 private:
  const SimClock& clock_;
  const FaultInjection& faults_;
};

// The burn wire of the emergency drop weight. The vehicle model has no
// droppable mass (none of the board vehicles is fitted with one), so
// releasing it is recorded, not flown.
class SimDropWeight final : public hal::DigitalOutput {
 public:
  explicit SimDropWeight(const SimClock& clock) : clock_(clock) {}
  bool set(bool active) override;
  bool released() const { return released_; }
  hal::Micros released_at_us() const { return released_at_us_; }

 private:
  const SimClock& clock_;
  bool released_ = false;
  hal::Micros released_at_us_ = -1;
};

// Coulomb counting on the energy model, integrated at every read (the
// firmware reads once per cycle) from how far the servos moved since.
class SimPowerMonitor final : public hal::PowerMonitor {
 public:
  SimPowerMonitor(const model::GliderSimulator& sim, const SimClock& clock, const FaultInjection& faults,
                  const PowerModel& model);
  hal::PowerSample read() override;
  double energy_used_j() const { return energy_j_; }

 private:
  const model::GliderSimulator& sim_;
  const SimClock& clock_;
  const FaultInjection& faults_;
  PowerModel model_;
  double energy_j_ = 0.0;
  double charge_amphr_ = 0.0;
  hal::Micros last_us_ = 0;
  double last_pump_m3_;
  double last_battery_m_;
  double last_fin_rad_;
};

}  // namespace glider::sil
