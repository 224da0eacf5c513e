// SPDX-License-Identifier: Apache-2.0
#pragma once
// The instrument of the fin the heading fit reads the fin's effectiveness
// from, cleared of the random yaw (docs/health.md "The fin projected on the
// command and the lagged heading"; used as the logged fin's instrument, not
// in its place: fin_iv.hpp).
// In a random yaw the autopilot moves the fin against yaw the vehicle did not
// make: that part of the fin is correlated with the yaw rate the model leaves
// unexplained, and a fit of the yaw rate on the logged fin reads the fin weak
// (0.51-0.87 for 1). The command of now less the heading of a while ago
// (longer than the random yaw's correlation) drives the fin through the
// autopilot - the turns - but is not correlated with the random yaw of now:
// the fin projected on it (the first stage of two-stage least squares) keeps
// the fin's turns and drops the part that answers the water.
#include "glider/flightlog/flight_log.hpp"

namespace glider::health {

// The shortest lag of the heading: 5 times the comet logs' random-yaw
// correlation (4 s, docs/heading-control.md; exp(-5) = 0.7 % of it left).
inline constexpr double kFinInstrumentLagS = 20.0;

// `log` with m_fin replaced, at every row where it is defined, by its
// least-squares projection (over the rows under water, m_depth > 2 m) onto a
// constant, the glide's sign (m_pitch's last reading) and the wrapped c_heading of the
// row less m_heading lag_s, 1.5 lag_s and 2 lag_s before it, each as it is
// and clipped to +-15 deg (the fin's saturation). Throws std::runtime_error
// naming the log when a column is missing or too few rows define them.
flightlog::FlightLog with_fin_on_lagged_heading(const flightlog::FlightLog& log, double lag_s = kFinInstrumentLagS);

}  // namespace glider::health
