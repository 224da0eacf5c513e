// SPDX-License-Identifier: Apache-2.0
#pragma once
// Forward-then-backward selection of effects, the same for every plane: the
// plane fits sets of its effects (and caches them), this decides which set
// to keep by the rules of selection.hpp.
//
// Forward: each round, of the candidates whose fitted value is plausible,
// the one that predicts the held-out yos best enters if the set with it
// beats the set without it (both margins and the BIC); an implausible value
// is another effect's stand-in, and the next best competes instead. A
// measured input (no fitted number: a CTD's density) is tried alone at the
// start of every round until it is taken, so that a fitted effect of the
// same shape cannot take its place.
//
// Backward: forward selection is greedy - an effect taken early can become
// redundant once the others are in. Every effect must still earn its place
// in the final joint fit: the set without it must be beaten by the same
// margins, its 95 % interval must exclude "no effect" and its value be
// plausible. The weakest that does not (the lowest held-out error without
// it) leaves and the rest are refitted, until all earn. A measured input
// stays once it has earned its way in.
//
// Rank: by what each effect is worth, the held-out error without it,
// largest first.
#include <vector>

#include "glider/fitting_core/selection.hpp"

namespace glider::fitting_core {

// Effects by the plane's own ids, in the order they entered.
using EffectSet = std::vector<int>;

// What the selection asks of a plane about its fit of a set of effects.
class SelectionProblem {
 public:
  virtual ~SelectionProblem() = default;
  virtual Score score(const EffectSet& effects) = 0;
  // `effect`'s value in the fit of `effects` is inside its plausible range.
  virtual bool plausible(const EffectSet& effects, int effect) = 0;
  // `effect`'s 95 % interval in the fit of `effects` excludes its nominal value.
  virtual bool significant(const EffectSet& effects, int effect) = 0;
};

struct SelectionRules {
  Margins margins;
  std::vector<int> inputs;  // measured inputs: tried alone first each round, never dropped
};

// `current` with the candidates that enter, in the order they entered.
EffectSet forward_select(SelectionProblem& problem, EffectSet current, std::vector<int> candidates,
                         const SelectionRules& rules);

// What is left of `current` once every effect earns its place; `worth`, per
// effect left, the held-out RMS without it.
EffectSet backward_eliminate(SelectionProblem& problem, EffectSet current, const SelectionRules& rules,
                             std::vector<double>& worth);

// `effects` by worth (backward_eliminate's), largest first; ties keep their order.
EffectSet rank_by_worth(const EffectSet& effects, const std::vector<double>& worth);

// `effects` without `effect`.
EffectSet without(EffectSet effects, int effect);

}  // namespace glider::fitting_core
