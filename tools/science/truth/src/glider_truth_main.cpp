// SPDX-License-Identifier: Apache-2.0
// glider-truth: a flight log with hidden effects from the independent truth
// simulator (tools/science/truth), and the truth beside it as JSON.
//   glider-truth --effect drag_change=1.2 --effect pump_lag=8 --seed 7 --out log.csv --truth truth.json
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "glider/cli/tool.hpp"
#include "glider/truth/flight.hpp"
#include "glider/truth/log_writer.hpp"

namespace {

nlohmann::ordered_json truth_json(const glider::truth::FlightRequest& request, const glider::truth::FlightResult& f,
                                  const std::string& variant, double wall_s, std::size_t log_rows) {
  using nlohmann::ordered_json;
  ordered_json effects = ordered_json::object();
  for (const auto& [id, value] : f.truth) effects[id] = value;
  ordered_json hidden = ordered_json::object();
  for (const auto& [id, value] : request.effects) hidden[id] = value;
  const auto& um = f.vehicle.unmodelled;
  const auto& w = f.water;
  return ordered_json{{"seed", request.seed},
                      {"variant", variant},
                      {"vehicle_file", request.vehicle_path},
                      {"effects", effects},
                      {"effects_requested", hidden},
                      {"flight",
                       {{"pitch_control", glider::truth::to_string(f.control)},
                        {"cycle_s", f.cycle_s},
                        {"yos", request.yos},
                        {"dive_to_m", f.dive_to_m},
                        {"climb_to_m", f.climb_to_m},
                        {"pitch_target_rad", f.pitch_target_rad},
                        {"depth_sensor_lag_s", f.depth_sensor_lag_s},
                        {"hull_reference_temperature_c", f.vehicle.reference_temperature_c},
                        {"samples", f.samples.size()},
                        {"log_rows", log_rows},
                        {"simulated_s", f.samples.empty() ? 0.0 : f.samples.back().time_s},
                        {"integrator_steps", {{"accepted", f.steps_accepted}, {"rejected", f.steps_rejected}}},
                        {"wall_s", wall_s}}},
                      {"unmodelled",
                       {{"lift_lag_chords", um.lift_lag_chords},
                        {"chord_m", um.chord_m},
                        {"cl_q", um.cl_q},
                        {"drag_reynolds_exponent", um.drag_reynolds_exponent},
                        {"yaw_second_pole_s", um.yaw_second_pole_s},
                        {"fin_roll_per_rad", um.fin_roll_per_rad},
                        {"roll_time_constant_s", um.roll_time_constant_s}}},
                      {"water",
                       {{"surface_temperature_c", w.surface_temperature_c},
                        {"deep_temperature_c", w.deep_temperature_c},
                        {"thermocline_m", w.thermocline_m},
                        {"wave_w_m_s", w.wave_w_m_s},
                        {"wave_period_s", w.wave_period_s},
                        {"current_east_m_s", w.current_east_m_s},
                        {"current_north_m_s", w.current_north_m_s},
                        {"shear_per_s", w.shear_per_s},
                        {"hidden_w_m_s", w.hidden_w_m_s},
                        {"hidden_w_from_m", w.hidden_w_from_m},
                        {"hidden_w_to_m", w.hidden_w_to_m}}}};
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-truth",
                         "Fly the independent truth simulator with hidden effects; write the flight log and the truth");
  CLI::App& app = tool.app();
  glider::truth::FlightRequest request;
  std::string variant = "shallow", vehicle, out_path, truth_path, control;
  std::vector<std::string> effects;
  double cycle_s = 0.0, dive_to_m = 0.0;
  app.add_option("--variant", variant,
                 "shallow: slocum_shallow.toml's numbers, 40-90 m yos; deep: slocum_we01.toml's, 80-180 m yos")
      ->check(CLI::IsMember({"shallow", "deep"}))
      ->capture_default_str();
  app.add_option("--vehicle", vehicle, "vehicle file whose published numbers the truth flies (overrides the variant's)")
      ->check(CLI::ExistingFile);
  app.add_option("--effect", effects, "hidden effect ID=VALUE (repeatable; ids of the diagnosis's vocabulary)");
  tool.add_integer("--seed", request.seed, 0, glider::cli::kMaxSeed, "",
                   "draws (controller, cycle, depths, water, unmodelled terms, noise)")
      ->capture_default_str();
  tool.add_integer("--yos", request.yos, 1, 200, "", "yos flown")->capture_default_str();
  app.add_option("--control", control, "pitch control (else drawn)")->check(CLI::IsMember({"pi", "bang-bang"}));
  tool.add_number("--cycle-s", cycle_s, {0.5, 10.0, "s"}, "control and log cycle (else drawn in 1-8 s)");
  tool.add_number("--dive-to-m", dive_to_m, {10.0, 1000.0, "m"}, "inflection depth (else drawn)");
  double dvl_noise_m_s = -1.0;
  tool.add_number("--dvl-noise", dvl_noise_m_s, {0.0, 1.0, "m/s"},
                  "write a DVL's speed through water (sci_speed_through_water, dives below 12 m): the true speed plus "
                  "white noise of this sigma");
  app.add_option("--out", out_path, "flight-log CSV to write")->required();
  app.add_option("--truth", truth_path, "JSON with the hidden effects' true values and the draws");
  return tool.run(argc, argv, [&]() -> int {
    request.deep = variant == "deep";
    request.vehicle_path = !vehicle.empty() ? vehicle
                                            : std::string(GLIDER_SOURCE_DIR) + "/boards/vehicles/" +
                                                  (request.deep ? "slocum_we01.toml" : "slocum_shallow.toml");
    for (const std::string& e : effects) {
      try {
        request.effects.insert(glider::truth::parse_effect(e));
      } catch (const std::invalid_argument& error) {
        return tool.fail(glider::cli::kUsage, error.what());
      }
    }
    if (!control.empty()) {
      request.control = control == "pi" ? glider::truth::PitchControl::kPi : glider::truth::PitchControl::kBangBang;
    }
    if (cycle_s > 0.0) request.cycle_s = cycle_s;
    if (dive_to_m > 0.0) request.dive_to_m = dive_to_m;
    const auto start = std::chrono::steady_clock::now();
    const glider::truth::FlightResult flight = glider::truth::fly(request);
    const std::string text = glider::truth::log_text(flight, {request.vehicle_path, request.seed, dvl_noise_m_s});
    {
      std::ofstream file(out_path, std::ios::binary);
      if (!(file << text) || !file.flush()) throw std::runtime_error("cannot write " + out_path);
    }
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t rows = 0;
    for (char c : text) rows += c == '\n' ? 1 : 0;
    rows -= 5;  // the metadata, header and trailer lines
    if (!truth_path.empty()) {
      std::ofstream file(truth_path);
      if (!(file << truth_json(request, flight, variant, wall_s, rows).dump(2) << '\n') || !file.flush()) {
        throw std::runtime_error("cannot write " + truth_path);
      }
    }
    std::printf(
        "glider-truth: seed %llu, %s, %s pitch control, %.2f s cycle, %d yos to %.1f m: %zu rows, %.0f s "
        "simulated, %.3f s wall (%zu steps)\n",
        static_cast<unsigned long long>(request.seed), variant.c_str(), glider::truth::to_string(flight.control),
        flight.cycle_s, request.yos, flight.dive_to_m, rows, flight.samples.back().time_s, wall_s,
        flight.steps_accepted);
    return static_cast<int>(glider::cli::kOk);
  });
}
