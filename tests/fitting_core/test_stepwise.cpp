// SPDX-License-Identifier: Apache-2.0
// Forward-then-backward selection on a table of fits with known answers:
// the best enters while it beats the margins, an implausible value never
// competes, a measured input goes first, an effect made redundant or not
// significant leaves, the worth orders the findings.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <map>
#include <set>

#include "glider/fitting_core/stepwise.hpp"

namespace fc = glider::fitting_core;

namespace {

// Scores by the set of effects (order does not matter here); a set not in
// the table predicts as badly as the nominal model.
class Table : public fc::SelectionProblem {
 public:
  std::map<std::set<int>, fc::Score> scores;
  std::set<int> implausible, not_significant;
  std::vector<fc::EffectSet> asked;
  fc::Score score(const fc::EffectSet& effects) override {
    asked.push_back(effects);
    const auto it = scores.find({effects.begin(), effects.end()});
    return it != scores.end() ? it->second : scores.at({});
  }
  bool plausible(const fc::EffectSet&, int effect) override { return implausible.count(effect) == 0; }
  bool significant(const fc::EffectSet&, int effect) override { return not_significant.count(effect) == 0; }
};

const fc::SelectionRules kRules{{0.03, 0.0005}, {}};

}  // namespace

TEST_GROUP(FittingCoreStepwise) {
  Table t;
  void setup() override {
    t.scores[{}] = {0.020, 100.0};
    t.scores[{1}] = {0.015, 80.0};
    t.scores[{2}] = {0.012, 70.0};  // the best alone
    t.scores[{3}] = {0.019, 99.0};
    t.scores[{1, 2}] = {0.010, 60.0};
    t.scores[{2, 3}] = {0.0119, 69.0};  // 1 % better: under the margin
    t.scores[{1, 2, 3}] = {0.0099, 61.0};
  }
};

TEST(FittingCoreStepwise, TheBestEntersWhileItBeatsTheMargins) {
  const fc::EffectSet chosen = fc::forward_select(t, {}, {1, 2, 3}, kRules);
  CHECK((chosen == fc::EffectSet{2, 1}));
}

TEST(FittingCoreStepwise, AnImplausibleValueDoesNotCompete) {
  t.implausible = {2};
  const fc::EffectSet chosen = fc::forward_select(t, {}, {1, 2, 3}, kRules);
  CHECK(chosen.front() == 1);
  CHECK(std::find(chosen.begin(), chosen.end(), 2) == chosen.end());
}

TEST(FittingCoreStepwise, AMeasuredInputIsTriedAloneFirst) {
  t.scores[{4}] = {0.0195, 99.0};        // alone it does not help yet
  t.scores[{2, 4}] = {0.0100, 60.0};     // beside 2 it does
  t.scores[{1, 2, 4}] = {0.0099, 62.0};  // 1 then adds nothing
  const fc::SelectionRules rules{{0.03, 0.0005}, {4}};
  const fc::EffectSet chosen = fc::forward_select(t, {}, {1, 2, 3, 4}, rules);
  CHECK((chosen == fc::EffectSet{2, 4}));
  CHECK((t.asked.front() == fc::EffectSet{4}));  // round one: the input alone
}

TEST(FittingCoreStepwise, BackwardDropsWhatNoLongerEarnsItsPlace) {
  std::vector<double> worth;
  // 3 was forced in (as a greedy step might): without it the fit is as good.
  fc::EffectSet kept = fc::backward_eliminate(t, {2, 1, 3}, kRules, worth);
  CHECK((kept == fc::EffectSet{2, 1}));
  DOUBLES_EQUAL(0.015, worth[0], 1e-15);  // without 2: effect 1 alone
  DOUBLES_EQUAL(0.012, worth[1], 1e-15);  // without 1
  // An interval that holds "no effect" does not earn a place either.
  t.not_significant = {1};
  kept = fc::backward_eliminate(t, {2, 1}, kRules, worth);
  CHECK((kept == fc::EffectSet{2}));
  // A measured input stays once in.
  const fc::SelectionRules rules{{0.03, 0.0005}, {3}};
  kept = fc::backward_eliminate(t, {2, 3}, rules, worth);
  CHECK((kept == fc::EffectSet{2, 3}));
}

TEST(FittingCoreStepwise, RankedByWorthLargestFirst) {
  CHECK((fc::rank_by_worth({5, 6, 7}, {0.01, 0.03, 0.01}) == fc::EffectSet{6, 5, 7}));
  CHECK((fc::without({5, 6, 7}, 6) == fc::EffectSet{5, 7}));
}
