// SPDX-License-Identifier: Apache-2.0
#pragma once
// The science loop on one log: the nominal model's error (baseline), each
// candidate effect fitted on half of the yos and scored on the other half,
// forward selection of the effects that really help (held-out error and the
// Bayesian information criterion), the named cause and the gain.
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/diagnose/depth_lag.hpp"
#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/fitting_core/selection.hpp"

namespace glider::diagnose {

struct Rms {
  double depth_rate_m_s = 0.0;  // NaN if no samples
  std::size_t samples = 0;
};

struct DepthBin {
  double from_m = 0.0, to_m = 0.0;
  Rms rms;
};

struct Baseline {
  Rms all, dives, climbs;
  Rms inflections;                       // the dynamic model only (the steady one does not fly turns)
  std::optional<double> rms_pitch_deg;   // forward equilibrium vs logged pitch (needs m_battpos)
  std::optional<double> rms_battpos_in;  // logged battery vs the one the model needs for the logged pitch
  std::size_t inflection_samples = 0;    // scored by the dynamic model, not by the steady one
  std::vector<DepthBin> by_depth;
  double heldout_rms_m_s = 0.0;  // on the held-out yos: the reference of the gain
};

struct Finding {
  Effect effect = Effect::kBuoyancyOffset;
  double value = 0.0;
  double ci95_low = 0.0, ci95_high = 0.0;
  double heldout_rms_m_s = 0.0;                  // of the model with this and the stronger findings
  double gain = 0.0;                             // fraction of the baseline held-out error removed so far
  bool fitted = true;                            // false: a measured input (CTD density), not a fitted number
  std::optional<double> heldout_rms_battpos_in;  // pitch_trim_offset: what it explains
  // Candidates not taken that alias this finding and that the joint fit of
  // both says are there: the interval also holds the finding's value in
  // that fit (diagnose.cpp, hold_aliased_readings); the interval of the
  // selected model alone is then ci95_conditional.
  std::vector<Effect> interval_holds_with;
  double ci95_conditional_low = 0.0, ci95_conditional_high = 0.0;
  // The value's shift when the Reynolds prior's exponent is one prior sigma
  // higher (signed; in the interval already, 0 where the prior is not
  // flown): a bias every segment of one glider shares, which the deployment
  // view carries into its levels (trend.hpp, shared bias).
  double reynolds_prior_shift = 0.0;
};

// Identifiability of a finding against an alternative whose depth-rate
// signature resembles it: the alternative fitted in the finding's place with
// the other findings. Ambiguous when it explains the held-out yos within the
// selection's own margins (the log cannot tell them apart: both readings are
// reported, `separate` says what data would); else told apart by the
// held-out yos.
struct Ambiguity {
  Effect chosen = Effect::kBuoyancyOffset, alternative = Effect::kBuoyancyOffset;
  double correlation = 0.0;  // |partial correlation| of their depth-rate signatures on the fitted samples
  double alternative_value = 0.0, alternative_ci95_low = 0.0, alternative_ci95_high = 0.0;
  double chosen_heldout_rms_m_s = 0.0, alternative_heldout_rms_m_s = 0.0;
  // The score the selection compared (held-out residuals averaged over
  // blocks of a glide this long; 0: none, the score is the RMS above): the
  // verdict takes both (fitting_core::indistinguishable(HeldOut...)).
  double score_block_s = 0.0;
  double chosen_heldout_score_m_s = 0.0, alternative_heldout_score_m_s = 0.0;
  std::string separate;
  // The alternative's value is outside the effect's plausible range
  // (flight_model.cpp, e.g. a mean vertical water velocity beyond 2 cm/s):
  // only that prior, not this log, rules it out.
  bool ruled_out_by_prior = false;
  bool ambiguous = false;
};

// A finding read again with a candidate not taken fitted beside it (the
// identifiability screen's aliases: diagnose.cpp, hold_aliased_readings):
// the finding's and the partner's values in that joint fit. `seen`: the
// partner's interval there excludes "no effect" and both are plausible
// (the finding's interval then holds this reading). `ambiguous`: not seen,
// yet the held-out yos prefer the joint fit by the selection's margins - the
// log cannot tell the two readings apart (the finding's interval holds this
// one too; `separate` says what data would).
struct BesideReading {
  Effect finding = Effect::kBuoyancyOffset, partner = Effect::kBuoyancyOffset;
  double correlation = 0.0;  // of their signatures (the screen's)
  double finding_value = 0.0, finding_ci95_low = 0.0, finding_ci95_high = 0.0;
  double partner_value = 0.0, partner_ci95_low = 0.0, partner_ci95_high = 0.0;
  double heldout_rms_m_s = 0.0, heldout_score_m_s = 0.0;                // of the joint fit
  double chosen_heldout_rms_m_s = 0.0, chosen_heldout_score_m_s = 0.0;  // of the selected fit
  bool seen = false;
  bool ambiguous = false;
  // The pump lag and the depth lag traded (diagnose.cpp, hold_traded_lag):
  // the held-out yos tell the two readings apart by less than the
  // selection's margins. A pump lag's entry is its reading alone (the depth
  // lag at none, partner 0 s) beside the finding's, read with the depth lag.
  bool lags_traded = false;
  std::string separate;
};

// The hull's volume terms (hull_compressibility, thermal_expansion) where
// the selection did not name them, each read beside the findings (the
// selected effects with it - both, where both are unnamed - fitted too, the
// interval checked by the held-out yos; diagnose.cpp, read_unnamed_volume_terms).
// On 6 yos of 40-180 m a compressibility of 0.5-3e-10 /Pa is seldom
// identifiable and an expansion of 1-7e-5 /K often seen by its interval but
// declined by the held-out margins (docs/science.md, "The hull's volume terms
// where not named"): silence said neither. `seen`: plausible and its 95 %
// interval excludes "no effect" (the log shows it at about this size; the
// held-out yos did not confirm it, so it is not a finding); else the interval
// is what this log cannot rule out. `separate` says what data would size it.
struct UnnamedReading {
  Effect effect = Effect::kHullCompressibility;
  double value = 0.0, ci95_low = 0.0, ci95_high = 0.0;
  double heldout_rms_m_s = 0.0, heldout_score_m_s = 0.0;                // with it beside the findings
  double chosen_heldout_rms_m_s = 0.0, chosen_heldout_score_m_s = 0.0;  // of the selected fit
  bool seen = false;
  bool ruled_out_by_prior = false;  // its reading is outside the plausible range (flight_model.cpp)
  std::string separate;
};

// Which flight model the diagnosis fits: the dynamic one (the project's
// dynamics driven by the measured pitch, through every sample, turns
// included; the default) or the steady one (steady glides at the measured
// pitch, gliderflight's steady-state model; faster, blind to turns).
enum class FlightModelKind { kDynamic, kSteady };
const char* to_string(FlightModelKind kind);

// The modelled speed through the water against a measured one (a DVL's
// sci_speed_through_water), which the fit never sees: an independent check.
// One yo's share of it: a yo whose measured speed departs from the others
// flown at the same pitch, ballast and depth rate is the instrument's, not
// the model's, and the RMS without it says what it costs.
struct SpeedOfYo {
  int yo = 0;
  bool heldout = false;
  std::size_t samples = 0;
  double measured_mean_m_s = 0.0;
  double nominal_mean_m_s = 0.0, nominal_rms_m_s = 0.0;
  double extended_mean_m_s = 0.0, extended_rms_m_s = 0.0;
  // The water's vertical velocity the measured speed implies (speed_reference.hpp)
  // and whether it is plausible, i.e. the reference belongs to this flight.
  double implied_water_w_m_s = std::numeric_limits<double>::quiet_NaN();
  bool reference_consistent = true;
};
struct SpeedScore {
  std::size_t samples = 0, heldout_samples = 0;
  double measured_mean_m_s = 0.0;
  double nominal_rms_m_s = 0.0, extended_rms_m_s = 0.0;                  // all samples with a measurement
  double heldout_nominal_rms_m_s = 0.0, heldout_extended_rms_m_s = 0.0;  // on the held-out yos
  std::vector<SpeedOfYo> by_yo;                                          // yo by yo
  // The median over the yos of SpeedOfYo::implied_water_w_m_s (speed_reference.hpp).
  double implied_water_w_median_m_s = std::numeric_limits<double>::quiet_NaN();
  // The same over the yos whose reference is consistent (SpeedOfYo::reference_consistent).
  double consistent_nominal_rms_m_s = 0.0, consistent_extended_rms_m_s = 0.0;
  double heldout_consistent_nominal_rms_m_s = 0.0, heldout_consistent_extended_rms_m_s = 0.0;
};

// The depth lag's form (depth_lag.hpp) where the final model fits a depth
// lag: the selected effects fitted with the lag a delay and a first-order
// sensor, the form whose fit predicts the held-out yos better taken
// (diagnose.cpp, choose_depth_lag_form). Told apart only where both views of
// the held-out error put the other beyond the selection's margins
// (fitting_core::indistinguishable); else the log does not tell them apart
// and the lag's value holds in the form chosen only.
struct DepthLagFormChoice {
  DepthLagForm form = DepthLagForm::kDelay;
  double delay_s = 0.0, first_order_s = 0.0;  // the lag each form read
  double delay_heldout_score_m_s = 0.0, first_order_heldout_score_m_s = 0.0;
  double delay_heldout_rms_m_s = 0.0, first_order_heldout_rms_m_s = 0.0;
  bool told_apart = false;
};

struct Diagnosis {
  std::string vehicle;
  FlightModelKind model = FlightModelKind::kDynamic;
  std::size_t samples_used = 0;
  std::size_t train_samples = 0, heldout_samples = 0;
  Baseline baseline;
  std::vector<Finding> findings;       // strongest first, significant only
  std::vector<Ambiguity> ambiguities;  // every pair judged (state_identifiability), ambiguous or told apart
  // Every finding against every candidate not taken: their signatures'
  // correlation (the identifiability screen's input), judged above
  // `screen_correlation`, stated below it, so no pair is passed over silently.
  struct ScreenedCorrelation {
    Effect chosen = Effect::kBuoyancyOffset, alternative = Effect::kBuoyancyOffset;
    double correlation = 0.0;
  };
  std::vector<ScreenedCorrelation> screen;
  double screen_correlation = 0.0;
  std::vector<BesideReading> beside;    // every finding read with a screened alias beside it
  std::vector<UnnamedReading> unnamed;  // the hull's volume terms not named, read beside the findings
  std::string cause = "none";
  EffectValues extended = nominal_values();
  std::optional<VerticalVelocityProfile> extended_profile;  // when the vertical velocity was fitted
  std::optional<DepthLagFormChoice> depth_lag_form;         // when a depth lag was fitted (dynamic model)
  bool extended_uses_ctd_density = false;
  Rms extended_all;  // the extended model over all samples
  double extended_heldout_rms_m_s = 0.0;
  double gain = 0.0;
  std::vector<std::string> candidates_tried;
  std::optional<SpeedScore> speed_through_water;  // when the log measures it (either model)
  // Set when the log's water was far from the vehicle's trim density: the
  // vehicle was taken as ballasted for the log's median density.
  std::optional<double> retrimmed_from_kg_m3, retrimmed_to_kg_m3;
  // The log's median temperature (NaN without one): the thermal_expansion
  // effect is about it (apply's log_temperature_c).
  double thermal_reference_c = 0.0;
  // The skin friction's Reynolds exponent the model flew (see
  // DiagnoseOptions::drag_reynolds_exponent) and the speed its cd0 holds at.
  double drag_reynolds_exponent = 0.0;
  double drag_reference_speed_m_s = 0.0;
  // The prior exponent's one-sigma uncertainty carried into every interval
  // (kDragReynoldsExponentPriorSigma), 0 where the exponent was asked for or
  // stated by the vehicle file.
  double drag_reynolds_exponent_sigma = 0.0;
};

// The prior of the skin friction's Reynolds exponent (docs/science.md,
// "Method rule: a drag that follows the Reynolds number"): the ITTC-1957
// friction line's local slope at a Slocum's Re ~ 4e5 (0.24) times the
// friction's share of the zero-lift drag (~0.4 for slocum_shallow: C_f 0.0058
// on ~1.2 m^2 wetted over cd0 0.17 on 0.1 m^2).
inline constexpr double kDragReynoldsExponentPrior = 0.1;
// Its one-sigma uncertainty: the friction's share of C_D0 is known to
// 0.2-0.8 between hull shapes and wings (0.4 slocum_shallow, ~0.8 WE01's
// reference area), so n = 0.24 x share spans about 0.05-0.2; 0.05 puts 0-0.2
// within two sigmas. A diagnosis flying the prior carries it into every
// interval (diagnose.cpp, add_reynolds_prior_uncertainty).
inline constexpr double kDragReynoldsExponentPriorSigma = 0.05;

// True when a diagnosis flies the prior: no exponent asked for and none
// stated by the vehicle file (see drag_reynolds_exponent_for).
bool flies_reynolds_prior(const model::VehicleParams& vehicle, const std::optional<double>& asked);

// The exponent every diagnosis flies (diagnose() calls it, so the CLI, the
// deployment view, health, Python and the DVL protocol agree): the one asked
// for (DiagnoseOptions::drag_reynolds_exponent, --drag-reynolds-exponent),
// else the vehicle file's when the file states the key (0 included:
// Hydrodynamics::cd0_reynolds_exponent_stated, or a non-zero exponent set in
// code), else the prior. Asking for 0 switches the prior off.
double drag_reynolds_exponent_for(const model::VehicleParams& vehicle, const std::optional<double>& asked);

struct DiagnoseOptions {
  // A finding must cut the held-out RMS by 3 % AND by half a millimetre per
  // second (fitting_core/selection.hpp: the rule every plane selects by).
  fitting_core::Margins margins{0.03, 0.0005};
  // ... on the held-out residuals averaged over blocks of a glide this long
  // (fitting_core/block_score.hpp: the depth sensor's noise averaged out,
  // an effect that lasts a glide kept); 0: sample by sample, the rule before.
  double score_block_s = 0.0;
  // Samples 1 s apart on a glide are correlated over the vehicle's ~20 s
  // response: fits use an even stride that keeps at most this many samples
  // per half (the baseline and the reported RMS use every sample).
  std::size_t max_fit_samples = 8000;
  FlightModelKind model = FlightModelKind::kDynamic;
  double max_step_s = 1.0;  // the dynamic model's integration step (RK4), at most
  // How the 95 % intervals respect the serial correlation of glider
  // residuals (fitting_core/intervals.hpp, the rule of every plane). kGlides
  // (default since issue 26 item 5): cluster-robust, each glide a cluster -
  // on the independent truth (docs/science.md, changelog) lag-1 intervals
  // held the truth in a third of the buoyancy and drag draws, too narrow
  // for errors a whole glide shares. kLag1, the rule before, stays for
  // comparison (bench_diagnose_coverage, the SIL's own inverse-crime
  // benchmark, where it met the 90 % goal); kYos, each yo a cluster.
  using Intervals = fitting_core::IntervalRule;
  Intervals intervals = Intervals::kGlides;
  // Fit exactly these effects (no selection, no significance test), e.g. to
  // compare with another tool's fit of the same parameters. Empty: select.
  std::vector<Effect> fit_only;
  // Identifiability: an unused candidate whose depth-rate signature correlates
  // with a finding's at least this much (after the other findings' are
  // projected out) is fitted in the finding's place, and the pair is judged
  // (ambiguous or told apart). Below this, the swap fit is not worth its cost.
  // 0.75 from fresh truth draws (docs/science.md): buoyancy offsets of
  // -69..+56 g against a water velocity correlate 0.81-0.98.
  double ambiguity_screen_correlation = 0.75;
  // See Diagnosis::retrimmed_to_kg_m3: how far the log's median density may be
  // from the vehicle's trim density before the vehicle is re-trimmed for it.
  double retrim_tolerance_kg_m3 = 5.0;
  // The skin friction's Reynolds-number exponent n the fitted model flies
  // (C_D0 (V / V_ref)^-n, model/hydrodynamics.hpp): unset,
  // drag_reynolds_exponent_for(vehicle, nullopt): the file's when it states
  // the key, else the prior kDragReynoldsExponentPrior. 0 switches it off
  // (the model before it, to the bit). Not fitted: over a log's 0.2-0.5 m/s it is
  // a few % of drag that drag_change and buoyancy_offset would trade for it.
  std::optional<double> drag_reynolds_exponent;
  // Score and fit only samples in this depth window (m), e.g. gliderflight's
  // 10-35 dbar; the model still flies the whole log.
  double window_min_m = -1e9, window_max_m = 1e9;
  // Called before each model fit with the effects being fitted ("nominal",
  // "buoyancy_offset+drag_change"): progress for the user on long logs.
  std::function<void(const std::string& fitting)> progress;
};

// The data cannot judge this vehicle: a refusal, never a cause (exit 1).
class CannotJudge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws CannotJudge when the vehicle cannot fly the log's settings (no
// steady glide in the logged direction at the logged pitch and ballast for
// most dives or most climbs, or too few scored samples to fit and hold out).
Diagnosis diagnose(const model::VehicleParams& nominal, const Observations& observations,
                   const DiagnoseOptions& options = {});

// The nominal vehicle a diagnosis used: the given one, re-trimmed for the
// log's water when the diagnosis says so (retrimmed_to_kg_m3). The extended
// vehicle is this one with the effects applied.
model::VehicleParams diagnosed_nominal(const model::VehicleParams& given, const Diagnosis& d);

// Depth rate of every scored sample by the nominal model and by the extended
// one (NaN where a model cannot fly it), with the measurement: what the
// report plots.
struct Predictions {
  std::vector<double> time_s, depth_m, measured_m_s, nominal_m_s, extended_m_s;
  // Speed through water at the same samples where the log measures it (a
  // DVL's; NaN elsewhere), and the two models' (empty without a measurement).
  std::vector<double> speed_measured_m_s, speed_nominal_m_s, speed_extended_m_s;
  // Pitch on the steady glides: measured, and the equilibrium pitch of the
  // nominal and extended vehicles for the logged ballast and battery (empty
  // without m_battpos).
  std::vector<double> pitch_time_s, pitch_depth_m, pitch_measured_rad, pitch_nominal_rad, pitch_extended_rad;
};
Predictions predict_all(const model::VehicleParams& nominal, const Observations& observations, const Diagnosis& d,
                        const DiagnoseOptions& options = {});

}  // namespace glider::diagnose
