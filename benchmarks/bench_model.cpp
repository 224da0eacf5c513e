// SPDX-License-Identifier: Apache-2.0
// Speed of the vehicle model: one submerged RK4 step of the full dynamics, one
// derivative evaluation, and the steady-glide solvers. Run:
//   build/release/benchmarks/bench_model
#include <benchmark/benchmark.h>

#include "glider/model/simulator.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

namespace {

const VehicleParams& vehicle() {
  static const VehicleParams v = load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  return v;
}

void BM_DerivativeEvaluation(benchmark::State& state) {
  const GliderDynamics dyn(vehicle(), Environment{});
  const MassInputs m{-250e-6, 0.002, 0.0, 0.0, 0.0, 0.05};
  const State s = dyn.make_state(50.0, -0.45, 0.45, 0.02, 0.001, m);
  for (auto _ : state) benchmark::DoNotOptimize(dyn.derivative(0.0, s, m));
}
BENCHMARK(BM_DerivativeEvaluation);

// One submerged integration step (1 s of flight, 4 evaluations; shorter
// where a servo stops inside it), servos moving.
void BM_SimulatorStep(benchmark::State& state) {
  GliderSimulator sim(vehicle(), Environment{});
  sim.reset_at_depth(100.0, 0.0, 0.0);
  sim.command_pumped_volume_m3(-250e-6);
  sim.command_battery_pos_m(0.01);
  for (auto _ : state) {
    sim.advance(GliderSimulator::kDefaultStepS);
    benchmark::DoNotOptimize(sim.state());
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      GliderSimulator::kDefaultStepS * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulatorStep);

void BM_SteadyGlideForPath(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(steady_glide_for_path(vehicle().hydro, 1025.0, 25.0, 0.25));
}
BENCHMARK(BM_SteadyGlideForPath);

void BM_SolveEquilibrium(benchmark::State& state) {
  const GliderDynamics dyn(vehicle(), Environment{});
  const MassInputs m{-250e-6, 0.0025, 0.0, 0.0, 0.0, 0.0};
  for (auto _ : state) benchmark::DoNotOptimize(solve_equilibrium(dyn, m, 100.0));
}
BENCHMARK(BM_SolveEquilibrium);

void BM_SolveTrim(benchmark::State& state) {
  const GliderDynamics dyn(vehicle(), Environment{});
  for (auto _ : state) benchmark::DoNotOptimize(solve_trim(dyn, 25.0, 0.25, 100.0));
}
BENCHMARK(BM_SolveTrim);

}  // namespace

BENCHMARK_MAIN();
