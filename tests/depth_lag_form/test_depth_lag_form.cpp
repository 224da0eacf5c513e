// SPDX-License-Identifier: Apache-2.0
// The depth lag in two forms (depth_lag.hpp): a first-order sensor's
// reading is exact for a depth straight between samples, and one dynamic
// flight model read through both views (dynamic_flight_model.hpp) keeps
// their answers apart though it remembers answers and shares its flights.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "glider/diagnose/depth_lag.hpp"
#include "glider/diagnose/dynamic_flight_model.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::diagnose;

namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

EffectValues with_depth_lag(double lag_s) {
  EffectValues x = nominal_values();
  x[static_cast<std::size_t>(Effect::kDepthLag)] = lag_s;
  return x;
}

}  // namespace

TEST_GROUP(DepthLagForm){};

TEST(DepthLagForm, AFirstOrderSensorIsExactThroughASlopeChange) {
  // A descent at 0.2 m/s that turns to 0.05 m/s at t0 (on a sample), on an
  // epoch clock with a 1.5 s cycle: the sensor starts lag x 0.2 behind and
  // after t0 closes on the new slope as exp(-(t - t0) / lag).
  const double lag = 2.5, s1 = 0.2, s2 = 0.05, t0 = 30.0;
  std::vector<double> t, z;
  for (int k = 0; k < 60; ++k) {
    const double tk = 1.5 * k;
    t.push_back(1.466e9 + tk);
    z.push_back(tk <= t0 ? 5.0 + s1 * tk : 5.0 + s1 * t0 + s2 * (tk - t0));
  }
  std::vector<double> read = z;
  first_order_lag(t, read, lag);
  for (std::size_t k = 0; k < z.size(); ++k) {
    const double tk = 1.5 * static_cast<double>(k);
    const double exact = tk <= t0 ? z[k] - lag * s1 : z[k] - lag * s2 - lag * (s1 - s2) * std::exp(-(tk - t0) / lag);
    DOUBLES_EQUAL(exact, read[k], 1e-9);
  }
  // No lag leaves the depth; read_depth_late reads each form as its own function.
  std::vector<double> same = z, delayed = z, delay = z, sensed = z;
  first_order_lag(t, same, 0.0);
  CHECK(same_bits(z, same));
  read_depth_late(DepthLagForm::kDelay, t, delayed, lag);
  delay_depth(t, delay, lag);
  CHECK(same_bits(delay, delayed));
  read_depth_late(DepthLagForm::kFirstOrder, t, sensed, lag);
  CHECK(same_bits(read, sensed));
}

TEST(DepthLagForm, OneModelThroughBothViewsKeepsTheFormsApart) {
  const Observations obs = prepare_observations(
      glider::flightlog::read_flight_log(GLIDER_SOURCE_DIR "/tests/data/real/comet-2019-222-02-154.csv"));
  const glider::model::VehicleParams vehicle =
      glider::model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_comet.toml");
  const std::vector<std::size_t>& samples = obs.track.scored;
  CHECK(samples.size() > 100);
  const DynamicFlightModel model(vehicle, obs.track);
  const DepthLagView delayed(model, DepthLagForm::kDelay), sensed(model, DepthLagForm::kFirstOrder);
  // Each view's answer from a model of its own: what one shared model must give.
  std::vector<double> delay_alone, sensor_alone;
  {
    const DynamicFlightModel own(vehicle, obs.track);
    DepthLagView(own, DepthLagForm::kDelay).predict(with_depth_lag(3.0), true, samples, delay_alone);
  }
  {
    const DynamicFlightModel own(vehicle, obs.track);
    DepthLagView(own, DepthLagForm::kFirstOrder).predict(with_depth_lag(3.0), true, samples, sensor_alone);
  }
  CHECK(!same_bits(delay_alone, sensor_alone));  // the forms differ in the turns
  // Asked in turns, and with the lag's sign the optimiser may give (fitted as
  // |value|): each view's answer is its own, remembered or not.
  std::vector<double> a, b, c, d;
  delayed.predict(with_depth_lag(3.0), true, samples, a);
  sensed.predict(with_depth_lag(3.0), true, samples, b);
  delayed.predict(with_depth_lag(-3.0), true, samples, c);
  sensed.predict(with_depth_lag(-3.0), true, samples, d);
  CHECK(same_bits(delay_alone, a));
  CHECK(same_bits(sensor_alone, b));
  CHECK(same_bits(delay_alone, c));
  CHECK(same_bits(sensor_alone, d));
  // The model asked directly: without a form it reads a delay, as before the
  // views; with one, that form's, whichever form it was asked in before.
  std::vector<double> direct, direct_sensor, direct_delay;
  model.predict(with_depth_lag(3.0), true, samples, direct);
  CHECK(same_bits(delay_alone, direct));
  model.predict(with_depth_lag(3.0), DepthLagForm::kFirstOrder, true, samples, direct_sensor);
  CHECK(same_bits(sensor_alone, direct_sensor));
  model.predict(with_depth_lag(3.0), DepthLagForm::kDelay, true, samples, direct_delay);
  CHECK(same_bits(delay_alone, direct_delay));
}
