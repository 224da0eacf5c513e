// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_select_delay_side.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glider/fitting_core/identifiability.hpp"

namespace glider::diagnose {
namespace {

constexpr HeadingEffect kYaw = HeadingEffect::kYawDelay;
constexpr HeadingEffect kServo = HeadingEffect::kFinDelay;

std::vector<HeadingFinding>::iterator finding_of(std::vector<HeadingFinding>& findings, HeadingEffect e) {
  return std::find_if(findings.begin(), findings.end(), [e](const HeadingFinding& f) { return f.effect == e; });
}

// The RMS of a link's residuals over `samples` (the finite ones; NaN: none).
double rms_of(const HeadingResiduals& residuals, const HeadingValues& values, std::span<const std::size_t> samples) {
  std::vector<double> r;
  residuals(values, samples, r);
  double sum = 0.0;
  std::size_t n = 0;
  for (const double x : r) {
    if (!std::isfinite(x)) continue;
    sum += x * x;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : std::numeric_limits<double>::quiet_NaN();
}

// The servo's rows cannot reject a dead time of `delay`: its fin error with
// it is within the servo's margins of its own (every row, both halves: the
// question is what the rows can see, not what the selection would take).
bool servo_blind_to(const LinkFit& servo, double delay, const DelaySides& s) {
  HeadingValues late = servo.values;
  at(late, kServo) = delay;
  const double with = rms_of(s.servo_residuals, late, s.servo_samples.all),
               own = rms_of(s.servo_residuals, servo.values, s.servo_samples.all);
  return std::isfinite(with) && std::isfinite(own) && fitting_core::indistinguishable(with, own, s.servo_margins);
}

// The correlation of the two sides' signatures on the training samples at
// `values`, the link's other findings projected out (heading_fit.cpp's
// judge_pairs).
double side_correlation(const LinkFit& yaw, const HeadingValues& values, HeadingEffect chosen,
                        HeadingEffect alternative, const DelaySides& s) {
  std::vector<double> base;
  s.yaw_residuals(values, s.yaw_samples.train, base);
  auto signature = [&](int id) {
    const auto e = static_cast<HeadingEffect>(id);
    HeadingValues stepped = values;
    const double step = 0.1 * info(e).scale;
    at(stepped, e) += step;
    std::vector<double> r;
    s.yaw_residuals(stepped, s.yaw_samples.train, r);
    return fitting_core::signature_column(r, base, step);
  };
  fitting_core::EffectSet set;
  for (const HeadingFinding& f : yaw.findings) set.push_back(static_cast<int>(f.effect == kYaw ? chosen : f.effect));
  for (const fitting_core::ScreenedPair& p :
       fitting_core::pair_correlations(set, {static_cast<int>(alternative)}, signature)) {
    if (set[p.finding] == static_cast<int>(chosen)) return p.correlation;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

bool choose_delay_side(LinkFit& yaw, const LinkFit& servo, const DelaySides& s) {
  const auto delay = finding_of(yaw.findings, kYaw);
  if (delay == yaw.findings.end()) return false;
  if (std::any_of(servo.findings.begin(), servo.findings.end(),
                  [](const HeadingFinding& f) { return f.effect == kServo; })) {
    return false;
  }
  const double value = delay->value;
  if (!servo_blind_to(servo, std::abs(value), s)) return false;
  // The same delay on either side, the link's other values held: within a
  // row the fin leaving the reading that late and the yaw following it that
  // late are one column; where the dead time would push the fin's move past
  // the next reading (which logs it done) the fin leaves earlier, and the
  // held-out yos tell the sides apart by it. The better of the two stands.
  HeadingValues on_servo = yaw.values;
  at(on_servo, kYaw) = delay->nominal;
  at(on_servo, kServo) = value;
  const double yaw_rms = rms_of(s.yaw_residuals, yaw.values, s.yaw_samples.heldout),
               servo_rms = rms_of(s.yaw_residuals, on_servo, s.yaw_samples.heldout);
  const bool servo_wins = std::isfinite(servo_rms) && servo_rms < yaw_rms;
  HeadingAmbiguity pair;
  pair.chosen = servo_wins ? kServo : kYaw;
  pair.alternative = servo_wins ? kYaw : kServo;
  pair.alternative_value = value;
  pair.chosen_heldout_rms = servo_wins ? servo_rms : yaw_rms;
  pair.alternative_heldout_rms = servo_wins ? yaw_rms : servo_rms;
  pair.ambiguous =
      fitting_core::indistinguishable(pair.alternative_heldout_rms, pair.chosen_heldout_rms, s.yaw_select.margins);
  if (servo_wins) {
    // The finding moves to the servo's side, its value, interval and
    // scores the delay's (one column); the pairs judged on the delay's
    // slot now name it.
    delay->effect = kServo;
    delay->nominal = at(servo.values, kServo);
    yaw.values = on_servo;
    for (HeadingAmbiguity& a : yaw.identifiability) {
      if (a.chosen == kYaw) a.chosen = kServo;
    }
    for (LinkFit::ScreenedCorrelation& c : yaw.screen) {
      if (c.chosen == kYaw) c.chosen = kServo;
    }
  }
  pair.correlation = side_correlation(yaw, yaw.values, pair.chosen, pair.alternative, s);
  yaw.screen.push_back({pair.chosen, pair.alternative, pair.correlation});
  // Judged where the signatures correlate as the link's other pairs are.
  if (pair.correlation >= s.yaw_select.ambiguity_screen_correlation) yaw.identifiability.push_back(pair);
  return servo_wins;
}

double bound_delay_split(LinkFit& yaw, LinkFit& servo, const DelaySides& s) {
  const auto delay = finding_of(yaw.findings, kYaw);
  if (delay == yaw.findings.end()) return 0.0;
  const double dead_time = at(servo.values, kServo), total = std::abs(delay->value);
  constexpr double kStepS = 0.25;
  double unseen = 0.0;
  for (double x = kStepS; x <= total + 1e-9 && servo_blind_to(servo, dead_time + x, s); x += kStepS) unseen = x;
  if (unseen <= 0.0) return 0.0;
  delay->ci95_low = std::max(0.0, delay->ci95_low - unseen);
  if (const auto fin = finding_of(servo.findings, kServo); fin != servo.findings.end()) fin->ci95_high += unseen;
  yaw.delay_split_s = unseen;
  return unseen;
}

}  // namespace glider::diagnose
