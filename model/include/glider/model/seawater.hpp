// SPDX-License-Identifier: Apache-2.0
#pragma once

// Seawater density from what a glider CTD measures, with TEOS-10 (the
// Gibbs SeaWater toolbox, GSW). No C library for it is packaged in Debian, so
// the few functions the vehicle model needs are written here, with the
// coefficients of GSW-C (see seawater.cpp), and checked against Debian's
// python3-gsw (tests/unit/test_seawater.cpp, tests/tools/).
//
// Chain: conductivity, in-situ temperature, pressure
//   -> Practical Salinity SP (PSS-78)
//   -> Absolute Salinity SA (reference composition, see absolute_salinity())
//   -> Conservative Temperature CT (Gibbs function)
//   -> in-situ density (75-term polynomial for specific volume).
//
// A Slocum CTD logs sci_water_cond [S/m], sci_water_temp [degC, ITS-90,
// in-situ] and sci_water_pressure [bar, gauge]: pressure_dbar = 10 * bar.
// Pressure here is always sea pressure (absolute minus 10.1325 dbar), which
// a gauge sensor reads to within the weather (a few tenths of a dbar).
//
// Every function is pure: no allocation, no exceptions, no state. Inputs
// that are not finite or lie outside the range the fits were made for give
// NaN (quiet, so a bad sample propagates rather than stopping a flight):
//
//   quantity                   accepted range     why
//   in-situ and Conservative T -3 .. 40 degC      75-term fit to 40 degC; -3 covers the
//                                                 freezing point at depth. PSS-78 itself
//                                                 was defined on -2 .. 35 degC; like GSW,
//                                                 it is used unchanged beyond.
//   pressure (SP, CT)          0 .. 10000 dbar    PSS-78 and Gibbs function
//   pressure (density)         0 .. 8000 dbar     75-term fit
//   Practical Salinity         0 .. 42            PSS-78 (2 .. 42), Hill et al. (1986) below 2
//   Absolute Salinity          0 .. 42 g/kg       75-term fit (so SP <= 41.8 for the chain)
//   density, below 500 dbar:   the "oceanographic funnel" of GSW's gsw_infunnel
//                              (McDougall et al. 2003; Roquet et al. 2015):
//     500 < p < 6500 dbar:  SA >= p*5e-3 - 2.5 and CT <= 31.67 - p/300
//     p >= 6500 dbar:       SA >= 30 and CT <= 10
// The funnel's lower bound, the freezing temperature, is simplified to the
// fixed -3 degC (a sample of liquid water cannot be colder than freezing).
namespace glider::model::seawater {

inline constexpr double kMinTemperatureC = -3.0;
inline constexpr double kMaxTemperatureC = 40.0;
inline constexpr double kMaxPressureDbar = 10000.0;        // PSS-78, Gibbs function
inline constexpr double kMaxDensityPressureDbar = 8000.0;  // 75-term polynomial
inline constexpr double kMaxPracticalSalinity = 42.0;
inline constexpr double kMaxAbsoluteSalinityGKg = 42.0;
// density_from_ctd() takes readings this far below 0 dbar as 0 dbar (see there).
inline constexpr double kSurfaceSlackDbar = 1.0;

// PSS-78 Practical Salinity from conductivity, as gsw_SP_from_C, including
// its Hill et al. (1986) extension below SP = 2. Conductivity in S/m (GSW
// takes mS/cm: 1 S/m = 10 mS/cm).
double practical_salinity(double conductivity_s_m, double temperature_c, double pressure_dbar) noexcept;

// The inverse of practical_salinity(): conductivity [S/m] of water of
// Practical Salinity SP at in-situ temperature and sea pressure, as
// gsw_C_from_SP (which returns mS/cm). Solved by safeguarded Newton
// iteration on practical_salinity() itself, so the two round-trip to
// rounding; NaN outside the ranges above (SP 0 .. 42). What the SIL's CTD
// logs for a water column given by temperature and salinity.
double conductivity_from_practical_salinity(double practical_salinity, double temperature_c,
                                            double pressure_dbar) noexcept;

// Absolute Salinity [g/kg] as Reference Salinity, SA = SP * 35.16504/35
// (gsw_SR_from_SP). This neglects the Absolute Salinity Anomaly, SA - SR,
// that gsw_SA_from_SP adds from position and pressure: in the open ocean it
// is < 0.006 g/kg at the surface and up to ~0.027 g/kg in the deep North
// Pacific (0.02 g/kg is ~0.015 kg/m^3 of density); in the North Sea it is
// ~0.001 g/kg. In the Baltic, whose salt is not of reference composition,
// GSW uses SA = (35.16504 - 0.087)/35 * SP + 0.087 (Feistel et al. 2010,
// gsw_SA_from_SP_Baltic): 0.070 g/kg above SR at SP 7, ~0.054 kg/m^3 of
// density. The anomaly needs GSW's global lookup table (gsw_saar_data, a few
// MB) and the vehicle's position; for buoyancy the difference is small:
// 0.05 kg/m^3 on a 52 kg (~51 litre) Slocum is 2.6 g, against a +-250 cc pump.
double absolute_salinity(double practical_salinity) noexcept;

// Potential temperature referenced to 0 dbar [degC], as gsw_pt0_from_t.
double potential_temperature(double sa_g_kg, double t_c, double p_dbar) noexcept;

// Conservative Temperature [degC] from in-situ temperature, as gsw_CT_from_t:
// potential temperature at 0 dbar (gsw_pt0_from_t), then potential enthalpy
// divided by cp0 (gsw_CT_from_pt).
double conservative_temperature(double sa_g_kg, double t_c, double p_dbar) noexcept;

// In-situ density [kg/m^3] from the 75-term polynomial for specific volume
// (Roquet et al. 2015), as gsw_rho = 1/gsw_specvol.
double density(double sa_g_kg, double ct_c, double p_dbar) noexcept;

// The whole chain for one CTD sample. A gauge pressure sensor at the surface
// reads a little below zero (offset, waves); readings down to
// -kSurfaceSlackDbar are taken as 0 dbar, an error under 0.005 kg/m^3, rather
// than losing every surface sample to NaN.
double density_from_ctd(double conductivity_s_m, double temperature_c, double pressure_dbar) noexcept;

}  // namespace glider::model::seawater
