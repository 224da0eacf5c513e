// SPDX-License-Identifier: Apache-2.0
#pragma once
// Health's outputs (docs/health.md): a text summary, the glider-health/1
// JSON, one PNG per effect over the deployment with the alert thresholds
// drawn, and the vehicle file with the current estimates applied (the
// forecast's input).
#include <filesystem>
#include <string>

#include "glider/health/health.hpp"

namespace glider::health {

std::string health_text(const HealthRun& run);
std::string health_json(const HealthRun& run);

// The nominal vehicle with the effects' current levels (those judged)
// applied: drag, buoyancy offset, pump rate and lag, fin gain, roll.
model::VehicleParams estimated_vehicle(const model::VehicleParams& nominal, const HealthRun& run);

// DIR/health.json, DIR/vehicle.toml, DIR/plots/EFFECT.png (each file
// written whole or not at all). Plots need gnuplot: false (and a message on
// stderr) when it fails; the rest is written regardless.
bool write_outputs(const std::filesystem::path& dir, const HealthRun& run, const model::VehicleParams& nominal);

}  // namespace glider::health
