// SPDX-License-Identifier: Apache-2.0
// The autopilot link under both clocks made one reading
// (heading_autopilot_clock.hpp): where the held-out rows cannot tell the
// clocks apart, what both name, at the middle of the two readings, its
// interval spanning both; the rest stated, not found.
#include <CppUTest/TestHarness.h>

#include <string>

#include "glider/diagnose/heading_autopilot_clock.hpp"

using namespace glider::diagnose;

namespace {

HeadingFinding finding(HeadingEffect e, double value, double low, double high, double gain) {
  HeadingFinding f;
  f.effect = e;
  f.value = value;
  f.ci95_low = low;
  f.ci95_high = high;
  f.gain = gain;
  return f;
}

LinkFit fit(std::vector<HeadingFinding> findings, double heldout_rms) {
  LinkFit f;
  f.link = HeadingLink::kAutopilot;
  f.findings = std::move(findings);
  f.extended_heldout_rms = heldout_rms;
  for (const HeadingFinding& x : f.findings) at(f.values, x.effect) = x.value;
  return f;
}

}  // namespace

TEST_GROUP(AutopilotClock){};

// A gain both clocks name: the middle, the interval over both (the measured
// clock's [2.788, 2.826] missed the truth's 2.786, the nominal's held it);
// a delay only one names is not a finding, and goes back to the nominal.
TEST(AutopilotClock, BothKeepsWhatBothNameOverBothIntervals) {
  const LinkFit measured = fit({finding(HeadingEffect::kAutopilotGain, 2.807, 2.788, 2.826, 0.5),
                                finding(HeadingEffect::kAutopilotDelay, 1.8, 1.0, 2.5, 0.52)},
                               0.0300);
  const LinkFit nominal = fit({finding(HeadingEffect::kAutopilotGain, 2.791, 2.778, 2.805, 0.5)}, 0.0301);
  HeadingValues base{};
  at(base, HeadingEffect::kAutopilotGain) = 1.5;
  AutopilotClockCheck check;
  const LinkFit merged = merge_autopilot_clocks(measured, nominal, base, AutopilotClockRule::kBoth, 0.002, check);
  CHECK_TRUE(check.fitted);
  STRCMP_EQUAL("both", check.kept);
  LONGS_EQUAL(1, merged.findings.size());
  CHECK(merged.findings[0].effect == HeadingEffect::kAutopilotGain);
  DOUBLES_EQUAL(2.799, merged.findings[0].value, 1e-12);
  DOUBLES_EQUAL(2.778, merged.findings[0].ci95_low, 1e-12);
  DOUBLES_EQUAL(2.826, merged.findings[0].ci95_high, 1e-12);
  DOUBLES_EQUAL(2.799, at(merged.values, HeadingEffect::kAutopilotGain), 1e-12);
  DOUBLES_EQUAL(0.0, at(merged.values, HeadingEffect::kAutopilotDelay), 1e-12);
  DOUBLES_EQUAL(0.5, merged.gain, 1e-12);
  LONGS_EQUAL(1, check.one_clock_only.size());
  CHECK(check.one_clock_only[0].effect == HeadingEffect::kAutopilotDelay);
}

// A reading outside the other clock's interval still lies in the merged one.
TEST(AutopilotClock, IntervalHoldsBothReadings) {
  const LinkFit measured = fit({finding(HeadingEffect::kAutopilotDelay, 1.38, 0.5, 2.0, 0.4)}, 0.03);
  const LinkFit nominal = fit({finding(HeadingEffect::kAutopilotDelay, 2.6, 2.5, 3.0, 0.4)}, 0.03);
  AutopilotClockCheck check;
  const LinkFit merged =
      merge_autopilot_clocks(measured, nominal, HeadingValues{}, AutopilotClockRule::kBoth, 0.002, check);
  DOUBLES_EQUAL(0.5, merged.findings[0].ci95_low, 1e-12);
  DOUBLES_EQUAL(3.0, merged.findings[0].ci95_high, 1e-12);
}

// The held-out rule takes one clock's fit where its held-out RMS beats the
// other's by the selection's margins, else merges.
TEST(AutopilotClock, HeldOutChoosesWhereTheRowsTell) {
  const LinkFit measured = fit({finding(HeadingEffect::kAutopilotGain, 0.36, 0.33, 0.39, 0.8)}, 0.048);
  const LinkFit nominal = fit({finding(HeadingEffect::kAutopilotGain, 0.46, 0.43, 0.49, 0.7)}, 0.059);
  AutopilotClockCheck check;
  LinkFit kept = merge_autopilot_clocks(measured, nominal, HeadingValues{}, AutopilotClockRule::kHeldOut, 0.002, check);
  STRCMP_EQUAL("measured", check.kept);
  DOUBLES_EQUAL(0.36, kept.findings[0].value, 1e-12);
  kept = merge_autopilot_clocks(nominal, measured, HeadingValues{}, AutopilotClockRule::kHeldOut, 0.002, check);
  STRCMP_EQUAL("nominal", check.kept);
  DOUBLES_EQUAL(0.36, kept.findings[0].value, 1e-12);
  const LinkFit close = fit({finding(HeadingEffect::kAutopilotGain, 0.40, 0.37, 0.43, 0.8)}, 0.0485);
  kept = merge_autopilot_clocks(measured, close, HeadingValues{}, AutopilotClockRule::kHeldOut, 0.002, check);
  STRCMP_EQUAL("both", check.kept);
  DOUBLES_EQUAL(0.38, kept.findings[0].value, 1e-12);
}
