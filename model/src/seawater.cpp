// SPDX-License-Identifier: Apache-2.0
#include "glider/model/seawater.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

// TEOS-10 for a glider CTD. The numeric coefficients below are copied
// exactly from GSW-C, the C version of the Gibbs SeaWater (GSW)
// Oceanographic Toolbox of TEOS-10 (github.com/TEOS-10/GSW-C):
//   gsw_internal_const.h                 (commit 2c6246427d0376fdeb9537f0baededd846300d62):
//       GSW_TEOS10_CONSTANTS, GSW_SP_COEFFICIENTS, the v*** of GSW_SPECVOL_COEFFICIENTS
//   toolbox/gsw_sp_from_c.c, gsw_hill_ratio_at_sp2.c, gsw_ct_from_pt.c,
//   gsw_entropy_part_zerop.c             (commit a12ab1b2beefc77a02eff4ede7ca4ad40fb5f03f)
//   toolbox/gsw_pt0_from_t.c, gsw_entropy_part.c, gsw_gibbs_pt0_pt0.c,
//   gsw_specvol.c                        (commit 2808c6df0ab25c4c3b138235d26c89b8d30a36f0)
// (the toolbox/ files are what GSW-C concatenates into gsw_oceanographic_toolbox.c).
// Copyright (c) 2011, SCOR/IAPSO WG127. GSW is distributed under a BSD-3-clause
// style licence: redistribution and use, in source and binary forms, are
// permitted provided that the copyright notice, the conditions and the
// disclaimer are retained, and the name of SCOR/IAPSO WG127 and of its
// contributors is not used to endorse or promote derived products. THE GSW
// SOFTWARE IS PROVIDED "AS IS", WITHOUT ANY EXPRESS OR IMPLIED WARRANTIES.
//
// The polynomials are evaluated in the same order as in GSW-C, so results
// agree with it (and with python3-gsw, which wraps it) to rounding.

namespace glider::model::seawater {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// TEOS-10 constants (GSW_TEOS10_CONSTANTS).
constexpr double kCp0 = 3991.86795711963;         // "specific heat" of potential enthalpy [J/(kg K)]
constexpr double kCelsiusZeroK = 273.15;          // [K]
constexpr double kSso = 35.16504;                 // Standard Ocean Reference Salinity [g/kg]
constexpr double kUps = kSso / 35.0;              // SP -> SR [g/kg]
constexpr double kSfac = 0.0248826675584615;      // 1/(40 kUps): salinity scaling of the fits
constexpr double kOffset = 5.971840214030754e-1;  // 24 g/kg * kSfac: keeps the 75-term sqrt away from 0
constexpr double kC3515_mS_cm = 42.9140;          // C(SP=35, t68=15, p=0)

// PSS-78 (GSW_SP_COEFFICIENTS).
constexpr double a0 = 0.0080, a1 = -0.1692, a2 = 25.3851, a3 = 14.0941, a4 = -7.0261, a5 = 2.7081;
constexpr double b0 = 0.0005, b1 = -0.0056, b2 = -0.0066, b3 = -0.0375, b4 = 0.0636, b5 = -0.0144;
constexpr double c0 = 0.6766097, c1 = 2.00564e-2, c2 = 1.104259e-4, c3 = -6.9698e-7, c4 = 1.0031e-9;
constexpr double d1 = 3.426e-2, d2 = 4.464e-4, d3 = 4.215e-1, d4 = -3.107e-3;
constexpr double e1 = 2.070e-5, e2 = -6.370e-10, e3 = 3.989e-15;
constexpr double k = 0.0162;

bool finite(double a, double b, double c) { return std::isfinite(a) && std::isfinite(b) && std::isfinite(c); }
bool in(double x, double lo, double hi) { return x >= lo && x <= hi; }

// PSS-78 works in IPTS-68 temperature; this is its temperature factor.
double t68_from_t90(double t90) { return t90 * 1.00024; }
double ft68_of(double t68) { return (t68 - 15.0) / (1.0 + k * (t68 - 15.0)); }

double pss78_salinity(double rtx, double ft68) {
  return a0 + (a1 + (a2 + (a3 + (a4 + a5 * rtx) * rtx) * rtx) * rtx) * rtx +
         ft68 * (b0 + (b1 + (b2 + (b3 + (b4 + b5 * rtx) * rtx) * rtx) * rtx) * rtx);
}

double pss78_dsalinity_drtx(double rtx, double ft68) {
  return a1 + (2 * a2 + (3 * a3 + (4 * a4 + 5 * a5 * rtx) * rtx) * rtx) * rtx +
         ft68 * (b1 + (2 * b2 + (3 * b3 + (4 * b4 + 5 * b5 * rtx) * rtx) * rtx) * rtx);
}

// Hill et al. (1986) low-salinity form without its scale factor.
double hill_raw_salinity(double sp_pss78, double rt, double rtx, double ft68) {
  const double x = 400.0 * rt;
  const double sqrty = 10.0 * rtx;
  const double part1 = 1.0 + x * (1.5 + x);
  const double part2 = 1.0 + sqrty * (1.0 + sqrty * (1.0 + sqrty));
  return sp_pss78 - a0 / part1 - b0 * ft68 / part2;
}

// The factor that makes the Hill formula equal PSS-78 at SP = 2
// (gsw_hill_ratio_at_sp2): Rt at SP = 2 from a fitted first guess and one
// modified Newton step, then the ratio there.
double hill_ratio_at_sp2(double t90) {
  constexpr double g0 = 2.641463563366498e-1, g1 = 2.007883247811176e-4, g2 = -4.107694432853053e-6,
                   g3 = 8.401670882091225e-8, g4 = -1.711392021989210e-9, g5 = 3.374193893377380e-11,
                   g6 = -5.923731174730784e-13, g7 = 8.057771569962299e-15, g8 = -7.054313817447962e-17,
                   g9 = 2.859992717347235e-19;
  constexpr double sp2 = 2.0;
  const double t68 = t68_from_t90(t90);
  const double ft68 = ft68_of(t68);
  const double rtx0 =
      g0 +
      t68 * (g1 + t68 * (g2 + t68 * (g3 + t68 * (g4 + t68 * (g5 + t68 * (g6 + t68 * (g7 + t68 * (g8 + t68 * g9))))))));
  const double sp_est = pss78_salinity(rtx0, ft68);
  double rtx = rtx0 - (sp_est - sp2) / pss78_dsalinity_drtx(rtx0, ft68);
  const double rtxm = 0.5 * (rtx + rtx0);
  rtx = rtx0 - (sp_est - sp2) / pss78_dsalinity_drtx(rtxm, ft68);
  return 2.0 / hill_raw_salinity(sp2, rtx * rtx, rtx, ft68);
}

// The parts of the TEOS-10 Gibbs function (as fitted in GSW: g03 the pure
// water part, g08 the saline part) that potential temperature needs.
// x2 = sfac*SA, y = t/40, z = p/1e4.

// Entropy less its SA-only terms at (SA, t, p): -dg/dt (gsw_entropy_part).
double entropy_part(double sa, double t, double p) {
  const double x2 = kSfac * sa;
  const double x = std::sqrt(x2);
  const double y = t * 0.025;
  const double z = p * 1e-4;
  const double g03 =
      z * (-270.983805184062 +
           z * (776.153611613101 + z * (-196.51255088122 + (28.9796526294175 - 2.13290083518327 * z) * z))) +
      y * (-24715.571866078 +
           z * (2910.0729080936 +
                z * (-1513.116771538718 + z * (546.959324647056 + z * (-111.1208127634436 + 8.68841343834394 * z)))) +
           y * (2210.2236124548363 +
                z * (-2017.52334943521 +
                     z * (1498.081172457456 +
                          z * (-718.6359919632359 + (146.4037555781616 - 4.9892131862671505 * z) * z))) +
                y * (-592.743745734632 +
                     z * (1591.873781627888 +
                          z * (-1207.261522487504 + (608.785486935364 - 105.4993508931208 * z) * z)) +
                     y * (290.12956292128547 +
                          z * (-973.091553087975 +
                               z * (602.603274510125 + z * (-276.361526170076 + 32.40953340386105 * z))) +
                          y * (-113.90630790850321 + y * (21.35571525415769 - 67.41756835751434 * z) +
                               z * (381.06836198507096 + z * (-133.7383902842754 + 49.023632509086724 * z)))))));
  const double g08 =
      x2 *
      (z * (729.116529735046 +
            z * (-343.956902961561 + z * (124.687671116248 + z * (-31.656964386073 + 7.04658803315449 * z)))) +
       x * (x * (y * (-137.1145018408982 + y * (148.10030845687618 + y * (-68.5590309679152 + 12.4848504784754 * y))) -
                 22.6683558512829 * z) +
            z * (-175.292041186547 + (83.1923927801819 - 29.483064349429 * z) * z) +
            y * (-86.1329351956084 + z * (766.116132004952 + z * (-108.3834525034224 + 51.2796974779828 * z)) +
                 y * (-30.0682112585625 - 1380.9597954037708 * z + y * (3.50240264723578 + 938.26075044542 * z)))) +
       y * (1760.062705994408 +
            y * (-675.802947790203 +
                 y * (365.7041791005036 + y * (-108.30162043765552 + 12.78101825083098 * y) +
                      z * (-1190.914967948748 + (298.904564555024 - 145.9491676006352 * z) * z)) +
                 z * (2082.7344423998043 + z * (-614.668925894709 + (340.685093521782 - 33.3848202979239 * z) * z))) +
            z * (-1721.528607567954 +
                 z * (674.819060538734 + z * (-356.629112415276 + (88.4080716616 - 15.84003094423364 * z) * z)))));
  return -(g03 + g08) * 0.025;
}

// entropy_part at p = 0 (gsw_entropy_part_zerop).
double entropy_part_zerop(double sa, double pt0) {
  const double x2 = kSfac * sa;
  const double x = std::sqrt(x2);
  const double y = pt0 * 0.025;
  const double g03 =
      y * (-24715.571866078 + y * (2210.2236124548363 +
                                   y * (-592.743745734632 +
                                        y * (290.12956292128547 + y * (-113.90630790850321 + y * 21.35571525415769)))));
  const double g08 =
      x2 *
      (x * (x * (y * (-137.1145018408982 + y * (148.10030845687618 + y * (-68.5590309679152 + 12.4848504784754 * y)))) +
            y * (-86.1329351956084 + y * (-30.0682112585625 + y * 3.50240264723578))) +
       y * (1760.062705994408 +
            y * (-675.802947790203 + y * (365.7041791005036 + y * (-108.30162043765552 + 12.78101825083098 * y)))));
  return -(g03 + g08) * 0.025;
}

// d2g/dt2 at p = 0, i.e. -d(entropy)/dt there (gsw_gibbs_pt0_pt0).
double gibbs_pt0_pt0(double sa, double pt0) {
  const double x2 = kSfac * sa;
  const double x = std::sqrt(x2);
  const double y = pt0 * 0.025;
  const double g03 =
      -24715.571866078 +
      y * (4420.4472249096725 +
           y * (-1778.231237203896 + y * (1160.5182516851419 + y * (-569.531539542516 + y * 128.13429152494615))));
  const double g08 =
      x2 *
      (1760.062705994408 +
       x * (-86.1329351956084 +
            x * (-137.1145018408982 + y * (296.20061691375236 + y * (-205.67709290374563 + 49.9394019139016 * y))) +
            y * (-60.136422517125 + y * 10.50720794170734)) +
       y * (-1351.605895580406 + y * (1097.1125373015109 + y * (-433.20648175062206 + 63.905091254154904 * y))));
  return (g03 + g08) * 0.000625;
}

// Potential temperature at 0 dbar: the temperature at which the water has,
// at the surface, the entropy it has at (t, p). Fitted first guess, then two
// modified Newton steps on entropy (gsw_pt0_from_t).
double pt0_from_t(double sa, double t, double p) {
  const double s1 = sa / kUps;
  double pt0 =
      t +
      p * (8.65483913395442e-6 - s1 * 1.41636299744881e-6 - p * 7.38286467135737e-9 +
           t * (-8.38241357039698e-6 + s1 * 2.83933368585534e-8 + t * 1.77803965218656e-8 + p * 1.71155619208233e-10));
  double dentropy_dt = kCp0 / ((kCelsiusZeroK + pt0) * (1.0 - 0.05 * (1.0 - sa / kSso)));
  const double true_entropy_part = entropy_part(sa, t, p);
  for (int iteration = 0; iteration < 2; ++iteration) {
    const double pt0_old = pt0;
    const double dentropy = entropy_part_zerop(sa, pt0_old) - true_entropy_part;
    pt0 = pt0_old - dentropy / dentropy_dt;
    const double pt0m = 0.5 * (pt0 + pt0_old);
    dentropy_dt = -gibbs_pt0_pt0(sa, pt0m);
    pt0 = pt0_old - dentropy / dentropy_dt;
  }
  return pt0;
}

// Conservative Temperature is potential enthalpy / cp0 (gsw_ct_from_pt).
double ct_from_pt(double sa, double pt) {
  const double x2 = kSfac * sa;
  const double x = std::sqrt(x2);
  const double y = pt * 0.025;
  const double pot_enthalpy =
      61.01362420681071 +
      y * (168776.46138048015 +
           y * (-2735.2785605119625 +
                y * (2574.2164453821433 +
                     y * (-1536.6644434977543 +
                          y * (545.7340497931629 + (-50.91091728474331 - 18.30489878927802 * y) * y))))) +
      x2 *
          (268.5520265845071 +
           y * (-12019.028203559312 +
                y * (3734.858026725145 +
                     y * (-2046.7671145057618 +
                          y * (465.28655623826234 + (-0.6370820302376359 - 10.650848542359153 * y) * y)))) +
           x * (937.2099110620707 +
                y * (588.1802812170108 + y * (248.39476522971285 + (-3.871557904936333 - 2.6268019854268356 * y) * y)) +
                x * (-1687.914374187449 + x * (246.9598888781377 + x * (123.59576582457964 - 48.5891069025409 * x)) +
                     y * (936.3206544460336 +
                          y * (-942.7827304544439 +
                               y * (369.4389437509002 + (-33.83664947895248 - 9.987880382780322 * y) * y))))));
  return pot_enthalpy / kCp0;
}

// The 75-term polynomial for specific volume [m^3/kg] (Roquet et al. 2015;
// gsw_specvol). xs = sqrt(sfac*SA + offset), ys = CT/40, z = p/1e4.
double specific_volume(double sa, double ct, double p) {
  constexpr double v000 = 1.0769995862e-3, v001 = -6.0799143809e-5, v002 = 9.9856169219e-6, v003 = -1.1309361437e-6,
                   v004 = 1.0531153080e-7, v005 = -1.2647261286e-8, v006 = 1.9613503930e-9, v010 = -3.1038981976e-4,
                   v011 = 2.4262468747e-5, v012 = -5.8484432984e-7, v013 = 3.6310188515e-7, v014 = -1.1147125423e-7,
                   v020 = 6.6928067038e-4, v021 = -3.4792460974e-5, v022 = -4.8122251597e-6, v023 = 1.6746303780e-8,
                   v030 = -8.5047933937e-4, v031 = 3.7470777305e-5, v032 = 4.9263106998e-6, v040 = 5.8086069943e-4,
                   v041 = -1.7322218612e-5, v042 = -1.7811974727e-6, v050 = -2.1092370507e-4, v051 = 3.0927427253e-6,
                   v060 = 3.1932457305e-5, v100 = -1.5649734675e-5, v101 = 1.8505765429e-5, v102 = -1.1736386731e-6,
                   v103 = -3.6527006553e-7, v104 = 3.1454099902e-7, v110 = 3.5009599764e-5, v111 = -9.5677088156e-6,
                   v112 = -5.5699154557e-6, v113 = -2.7295696237e-7, v120 = -4.3592678561e-5, v121 = 1.1100834765e-5,
                   v122 = 5.4620748834e-6, v130 = 3.4532461828e-5, v131 = -9.8447117844e-6, v132 = -1.3544185627e-6,
                   v140 = -1.1959409788e-5, v141 = 2.5909225260e-6, v150 = 1.3864594581e-6, v200 = 2.7762106484e-5,
                   v201 = -1.1716606853e-5, v202 = 2.1305028740e-6, v203 = 2.8695905159e-7, v210 = -3.7435842344e-5,
                   v211 = -2.3678308361e-7, v212 = 3.9137387080e-7, v220 = 3.5907822760e-5, v221 = 2.9283346295e-6,
                   v222 = -6.5731104067e-7, v230 = -1.8698584187e-5, v231 = -4.8826139200e-7, v240 = 3.8595339244e-6,
                   v300 = -1.6521159259e-5, v301 = 7.9279656173e-6, v302 = -4.6132540037e-7, v310 = 2.4141479483e-5,
                   v311 = -3.4558773655e-6, v312 = 7.7618888092e-9, v320 = -1.4353633048e-5, v321 = 3.1655306078e-7,
                   v330 = 2.2863324556e-6, v400 = 6.9111322702e-6, v401 = -3.4102187482e-6, v402 = -6.3352916514e-8,
                   v410 = -8.7595873154e-6, v411 = 1.2956717783e-6, v420 = 4.3703680598e-6, v500 = -8.0539615540e-7,
                   v501 = 5.0736766814e-7, v510 = -3.3052758900e-7, v600 = 2.0543094268e-7;
  const double xs = std::sqrt(kSfac * sa + kOffset);
  const double ys = ct * 0.025;
  const double z = p * 1e-4;
  // Terms grouped by power of z: each bracket is a polynomial in xs and ys.
  const double z0 = v000 + xs * (v010 + xs * (v020 + xs * (v030 + xs * (v040 + xs * (v050 + v060 * xs))))) +
                    ys * (v100 + xs * (v110 + xs * (v120 + xs * (v130 + xs * (v140 + v150 * xs)))) +
                          ys * (v200 + xs * (v210 + xs * (v220 + xs * (v230 + v240 * xs))) +
                                ys * (v300 + xs * (v310 + xs * (v320 + v330 * xs)) +
                                      ys * (v400 + xs * (v410 + v420 * xs) + ys * (v500 + v510 * xs + v600 * ys)))));
  const double z1 = v001 + xs * (v011 + xs * (v021 + xs * (v031 + xs * (v041 + v051 * xs)))) +
                    ys * (v101 + xs * (v111 + xs * (v121 + xs * (v131 + v141 * xs))) +
                          ys * (v201 + xs * (v211 + xs * (v221 + v231 * xs)) +
                                ys * (v301 + xs * (v311 + v321 * xs) + ys * (v401 + v411 * xs + v501 * ys))));
  const double z2 = v002 + xs * (v012 + xs * (v022 + xs * (v032 + v042 * xs))) +
                    ys * (v102 + xs * (v112 + xs * (v122 + v132 * xs)) +
                          ys * (v202 + xs * (v212 + v222 * xs) + ys * (v302 + v312 * xs + v402 * ys)));
  const double z3 = v003 + xs * (v013 + v023 * xs) + ys * (v103 + v113 * xs + v203 * ys);
  const double z4 = v004 + v014 * xs + v104 * ys;
  return z0 + z * (z1 + z * (z2 + z * (z3 + z * (z4 + z * (v005 + v006 * z)))));
}

// gsw_infunnel without its freezing-point bound (see the header).
bool in_density_funnel(double sa, double ct, double p) {
  if (!in(sa, 0.0, kMaxAbsoluteSalinityGKg) || !in(ct, kMinTemperatureC, kMaxTemperatureC) ||
      !in(p, 0.0, kMaxDensityPressureDbar)) {
    return false;
  }
  if (p > 500.0 && p < 6500.0) return sa >= p * 5e-3 - 2.5 && ct <= 31.66666666666667 - p * 3.333333333333334e-3;
  if (p >= 6500.0) return sa >= 30.0 && ct <= 10.0;
  return true;
}

}  // namespace

namespace {

// PSS-78 (with the Hill extension) without the range checks: the forward
// function that conductivity_from_practical_salinity() inverts. NaN for a
// negative conductivity ratio.
double practical_salinity_unchecked(double conductivity_s_m, double temperature_c, double pressure_dbar) {
  const double c_ms_cm = conductivity_s_m * 10.0;
  const double t68 = t68_from_t90(temperature_c);
  const double ft68 = ft68_of(t68);
  const double p = pressure_dbar;
  const double r = c_ms_cm / kC3515_mS_cm;
  // rt_lc is the UNESCO (1983) rt: C(35, t, 0)/C(35, 15, 0).
  const double rt_lc = c0 + (c1 + (c2 + (c3 + c4 * t68) * t68) * t68) * t68;
  const double rp = 1.0 + (p * (e1 + e2 * p + e3 * p * p)) / (1.0 + d1 * t68 + d2 * t68 * t68 + (d3 + d4 * t68) * r);
  const double rt = r / (rp * rt_lc);
  if (rt < 0.0) return kNaN;
  const double rtx = std::sqrt(rt);
  double sp = pss78_salinity(rtx, ft68);
  // PSS-78 is defined for SP >= 2; below, GSW's scaled Hill et al. (1986)
  // form, which meets PSS-78 exactly at SP = 2 and goes to 0 with C.
  if (sp < 2.0) sp = hill_ratio_at_sp2(temperature_c) * hill_raw_salinity(sp, rt, rtx, ft68);
  return sp;
}

bool in_sp_input_range(double temperature_c, double pressure_dbar) {
  return in(temperature_c, kMinTemperatureC, kMaxTemperatureC) && in(pressure_dbar, 0.0, kMaxPressureDbar);
}

}  // namespace

double practical_salinity(double conductivity_s_m, double temperature_c, double pressure_dbar) noexcept {
  if (!finite(conductivity_s_m, temperature_c, pressure_dbar) || conductivity_s_m < 0.0 ||
      !in_sp_input_range(temperature_c, pressure_dbar)) {
    return kNaN;
  }
  const double sp = practical_salinity_unchecked(conductivity_s_m, temperature_c, pressure_dbar);
  if (!in(sp, 0.0, kMaxPracticalSalinity)) return kNaN;
  return sp;
}

double conductivity_from_practical_salinity(double practical_salinity, double temperature_c,
                                            double pressure_dbar) noexcept {
  if (!finite(practical_salinity, temperature_c, pressure_dbar) ||
      !in(practical_salinity, 0.0, kMaxPracticalSalinity) || !in_sp_input_range(temperature_c, pressure_dbar)) {
    return kNaN;
  }
  if (practical_salinity == 0.0) return 0.0;  // PSS-78 and Hill give SP = 0 exactly at C = 0
  const auto sp_of = [&](double c) {
    return practical_salinity_unchecked(c, temperature_c, pressure_dbar) - practical_salinity;
  };
  // SP grows strictly with C, so a bracket [lo, hi] always holds the root:
  // Newton steps (secant slope from a small step), kept inside the bracket
  // by bisection when a step would leave it. First guess: C in proportion
  // to SP (R = SP/35); Newton converges from it in ~4 steps at sea salinities.
  double lo = 0.0, hi = 1.0;
  while (sp_of(hi) < 0.0) hi *= 2.0;  // 42 at 40 degC is ~9 S/m: a few doublings at most
  double c = std::min(hi, 0.1 * kC3515_mS_cm * practical_salinity / 35.0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = sp_of(c);
    if (f == 0.0) return c;
    (f < 0.0 ? lo : hi) = c;
    const double h = 1e-7 * std::max(c, 1e-6);
    const double slope = (sp_of(c + h) - f) / h;
    double next = c - f / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    // Converged when the step is at the last bits of c: the forward function's
    // own rounding then decides, not the iteration.
    if (std::abs(next - c) <= 4.0 * std::numeric_limits<double>::epsilon() * c) return next;
    c = next;
  }
  return c;
}

double absolute_salinity(double practical_salinity) noexcept {
  if (!std::isfinite(practical_salinity) || !in(practical_salinity, 0.0, kMaxPracticalSalinity)) return kNaN;
  return practical_salinity * kUps;
}

double potential_temperature(double sa_g_kg, double t_c, double p_dbar) noexcept {
  if (!finite(sa_g_kg, t_c, p_dbar) || !in(sa_g_kg, 0.0, kMaxAbsoluteSalinityGKg) ||
      !in(t_c, kMinTemperatureC, kMaxTemperatureC) || !in(p_dbar, 0.0, kMaxPressureDbar)) {
    return kNaN;
  }
  return pt0_from_t(sa_g_kg, t_c, p_dbar);
}

double conservative_temperature(double sa_g_kg, double t_c, double p_dbar) noexcept {
  const double pt0 = potential_temperature(sa_g_kg, t_c, p_dbar);
  if (std::isnan(pt0)) return kNaN;
  return ct_from_pt(sa_g_kg, pt0);
}

double density(double sa_g_kg, double ct_c, double p_dbar) noexcept {
  if (!finite(sa_g_kg, ct_c, p_dbar) || !in_density_funnel(sa_g_kg, ct_c, p_dbar)) return kNaN;
  return 1.0 / specific_volume(sa_g_kg, ct_c, p_dbar);
}

double density_from_ctd(double conductivity_s_m, double temperature_c, double pressure_dbar) noexcept {
  const double p = (pressure_dbar < 0.0 && pressure_dbar >= -kSurfaceSlackDbar) ? 0.0 : pressure_dbar;
  const double sa = absolute_salinity(practical_salinity(conductivity_s_m, temperature_c, p));
  return density(sa, conservative_temperature(sa, temperature_c, p), p);
}

}  // namespace glider::model::seawater
