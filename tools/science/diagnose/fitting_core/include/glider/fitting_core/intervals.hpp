// SPDX-License-Identifier: Apache-2.0
#pragma once
// 95 % intervals, one rule each, for every plane and the deployment view:
// the covariance of a least-squares fit's parameters from its Jacobian, with
// the noise counted over the effective sample count (effective_samples.hpp)
// or cluster-robust (each glide or yo a cluster), and Student-t intervals of
// a few independent estimates (a deployment's segments).
#include <Eigen/Core>
#include <span>

namespace glider::fitting_core {

// The normal distribution's two-sided 95 % quantile, as every plane has used it.
inline constexpr double kZ95 = 1.96;

// The minimum detectable effect's z: an effect this many sigmas from absent
// is told from absent at the 95 % level (kZ95) in 95 % of logs (+ 1.645,
// the one-sided 95 % quantile). benchmarks/identifiability.py judges a
// hidden effect identifiable at it (Z_IDENTIFIABLE).
inline constexpr double kZDetectable = kZ95 + 1.645;

struct Interval {
  double low = 0.0, high = 0.0;
};

// How an interval counts serially correlated samples. kLag1: the noise over
// the effective sample count of an AR(1) fitted to the residuals (neighbours
// share an error). kGlides / kYos: also cluster-robust, each glide (a dive, a
// climb or a turn of one yo) or each yo a cluster, Student-t on clusters - 1
// degrees of freedom (the analytic form of a block bootstrap over glides or
// yos), which sees an error shared by a whole glide (a model-form error that
// differs between dives and climbs) that lag-1 does not; the wider of the
// two is the interval: each misses what the other sees (a parameter only a
// few turns inform has few clusters whose scores can cancel).
enum class IntervalRule { kLag1, kGlides, kYos };

// The cluster of a sample under `rule`: its glide (its yo and its phase, a
// number 0-7 for a dive, a climb or a turn) or its yo; kLag1 has none (0).
long cluster_of(IntervalRule rule, int yo, int phase);

// An estimate with its 95 % interval.
struct Estimate {
  double value = 0.0, low = 0.0, high = 0.0;
};

// Covariance of the fitted parameters from the Jacobian `jac` (one row per
// residual `r`): (J'J)^+ RSS / (n_eff - k), the noise variance over the
// effective sample count (n_eff at least k + 2) - the residuals' serial
// correlation inflates it by n / n_eff.
Eigen::MatrixXd noise_covariance(const Eigen::MatrixXd& jac, std::span<const double> r);

// The cluster-robust (sandwich) covariance (J'J)^+ [sum_g (J_g' r_g)(J_g' r_g)'] (J'J)^+
// with the small-sample factor G/(G-1) (n-1)/(n-k), `cluster[i]` naming row
// i's cluster (a glide or a yo); `t_over_normal` the Student-t quantile on
// G - 1 degrees of freedom over 1.96. One cluster: infinite.
Eigen::MatrixXd cluster_covariance(const Eigen::MatrixXd& jac, std::span<const double> r, std::span<const long> cluster,
                                   double& t_over_normal);

// A mean of `x` and its 95 % interval: kLag1, the standard error over the
// effective sample count with the normal quantile; kGlides / kYos, the
// cluster-robust one (`cluster[i]`: x[i]'s glide or yo) with Student's t.
Estimate mean_with_rule(std::span<const double> x, std::span<const long> cluster, IntervalRule rule);

// The uncertainty of a least-squares fit's parameters by `rule`, from the
// Jacobian `jac` of the residuals `r` (`cluster[i]`: row i's glide or yo,
// cluster_of; unused for kLag1).
class ParameterUncertainty {
 public:
  ParameterUncertainty(const Eigen::MatrixXd& jac, std::span<const double> r, std::span<const long> cluster,
                       IntervalRule rule);
  // sigma of the combination w' p of the parameters, with kZ95 sigma its 95 %
  // half-width (a Student-t quantile folded in); sigma(j) of parameter j.
  double sigma(const Eigen::VectorXd& w) const;
  double sigma(Eigen::Index j) const;

 private:
  Eigen::MatrixXd lag1_, clustered_;
  double t_over_normal_ = 1.0;
  bool has_clustered_ = false;
};

// The sigma of an estimate that a replicate - the same model fitted to
// other data (a diagnosis's held-out yos) - can check: `sigma` widened by
// the Birge ratio |a - b| / sqrt(sigma_a^2 + sigma_b^2) where that exceeds 1
// (`a` the estimate with `sigma_a` = `sigma`, `b` the replicate with its own
// `sigma_b`). Under the fitted model the two differ by about their joint
// sigma and the ratio is near 1; where the model lacks a term the truth has,
// each fit absorbs it differently in different water, flight and controller
// states, they disagree by more than either interval allows, and an
// interval built on the model alone (Jacobian and residuals, however
// clustered) is too narrow by that ratio. Never narrows; a replicate that
// failed (not finite) leaves `sigma`.
double replicated_sigma(double sigma_a, double a, double sigma_b, double b);

// The two-sided 95 % quantile of Student's t.
double t_quantile_975(double degrees_of_freedom);

// value +- t(dof) standard_error.
Estimate t_interval(double value, double standard_error, double degrees_of_freedom);

// The central 95 % of an equal-weight mixture of normal readings of one value
// (means[i] +- sigmas[i]; a sigma of 0 is a point): the interval where
// models that read it differently are all still allowed and the data weigh
// them alike (model averaging with equal weights: Buckland, Burnham and
// Augustin 1997). The union of their own 95 % intervals claims more: each
// reading's tails at full weight. value: the mixture's mean. Needs n >= 1.
Estimate mixture_interval(std::span<const double> means, std::span<const double> sigmas);

// The mean of independent estimates of one value and its 95 % Student-t
// interval from their scatter (n - 1 degrees of freedom); needs n >= 2.
Estimate mean_with_interval(std::span<const double> values);

}  // namespace glider::fitting_core
