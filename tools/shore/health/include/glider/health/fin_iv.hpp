// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fin's effectiveness and the roll offset by instrumental variables
// (two-stage least squares done properly; docs/health.md "The fin by
// instrumental variables"). The heading plane's yaw rate is fitted as
//   measured = model(logged fin; fin effectiveness, roll offset) + error,
// where in a random yaw the logged fin is correlated with the error (the
// autopilot answers the water). Putting the projected fin (fin_instrument.hpp)
// in the model in its place - the substitution - is biased even in still
// water: the model's yaw lag filters the projection's residual, which is
// then no longer orthogonal to the filtered projection (read 0.8-2.7 % high,
// its intervals too narrow). Here the error is the LOGGED fin's, and the
// projected fin's model sensitivities are the instruments: the values solve
//   W' e(values) = 0,  W = d model(projected fin) / d values,
//   e = model(logged fin) - measured,
// with the IV sandwich covariance, each glide a cluster.
#include <cstddef>

#include "glider/flightlog/flight_log.hpp"
#include "glider/health/effects.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::health {

struct FinByInstruments {
  EffectValue fin;         // fin effectiveness (ratio to the vehicle's)
  EffectValue roll_deg;    // the roll offset added to the logged roll (deg, as health reports it)
  std::size_t glides = 0;  // the clusters
};

// `logged`: the segment with m_fin as the file stored it (`stored_on_change`:
// a decimated file's, diagnose/stored_on_change.hpp); `projected`: the same
// rows with m_fin replaced by with_fin_on_lagged_heading. Throws
// std::runtime_error (or diagnose::HeadingUnavailable) naming why when the
// heading plane cannot use the segment or the two do not share their samples.
FinByInstruments fin_by_instruments(const model::VehicleParams& vehicle, const flightlog::FlightLog& logged,
                                    bool stored_on_change, const flightlog::FlightLog& projected);

}  // namespace glider::health
