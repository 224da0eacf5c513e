// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/stepwise.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

namespace glider::fitting_core {
namespace {

bool is_input(const SelectionRules& rules, int effect) {
  return std::find(rules.inputs.begin(), rules.inputs.end(), effect) != rules.inputs.end();
}

}  // namespace

EffectSet without(EffectSet effects, int effect) {
  std::erase(effects, effect);
  return effects;
}

EffectSet forward_select(SelectionProblem& problem, EffectSet current, std::vector<int> candidates,
                         const SelectionRules& rules) {
  bool input_declined_this_round = false;
  while (!candidates.empty()) {
    const bool inputs_alone = !input_declined_this_round && std::any_of(candidates.begin(), candidates.end(),
                                                                        [&](int e) { return is_input(rules, e); });
    std::optional<std::size_t> best;
    double best_heldout = 0.0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const bool input = is_input(rules, candidates[c]);
      if (inputs_alone != input) continue;
      EffectSet trial = current;
      trial.push_back(candidates[c]);
      const double heldout = problem.score(trial).heldout_rms;
      if (!input && !problem.plausible(trial, candidates[c])) continue;
      if (!best || heldout < best_heldout) {
        best = c;
        best_heldout = heldout;
      }
    }
    if (!best) break;
    EffectSet trial = current;
    trial.push_back(candidates[*best]);
    // Its interval is judged in the backward step: while another effect is
    // still missing, the residuals are serially correlated and inflate every
    // interval.
    if (!beats(problem.score(trial), problem.score(current), rules.margins)) {
      if (!inputs_alone) break;
      input_declined_this_round = true;  // not yet: the fitted effects get their turn
      continue;
    }
    input_declined_this_round = false;
    current = std::move(trial);
    candidates.erase(candidates.begin() + static_cast<long>(*best));
  }
  return current;
}

EffectSet backward_eliminate(SelectionProblem& problem, EffectSet current, const SelectionRules& rules,
                             std::vector<double>& worth) {
  for (;;) {
    worth.assign(current.size(), 0.0);
    std::optional<int> weakest;
    double weakest_heldout = 0.0;
    for (std::size_t j = 0; j < current.size(); ++j) {
      const int e = current[j];
      const EffectSet reduced = without(current, e);
      const Score reduced_score = problem.score(reduced);
      worth[j] = reduced_score.heldout_rms;
      const bool earns = is_input(rules, e) || (beats(problem.score(current), reduced_score, rules.margins) &&
                                                problem.significant(current, e) && problem.plausible(current, e));
      if (!earns && (!weakest || reduced_score.heldout_rms < weakest_heldout)) {
        weakest = e;
        weakest_heldout = reduced_score.heldout_rms;
      }
    }
    if (!weakest) return current;
    current = without(current, *weakest);
  }
}

EffectSet rank_by_worth(const EffectSet& effects, const std::vector<double>& worth) {
  std::vector<std::size_t> order(effects.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return worth[a] > worth[b]; });
  EffectSet ranked;
  for (std::size_t i : order) ranked.push_back(effects[i]);
  return ranked;
}

}  // namespace glider::fitting_core
