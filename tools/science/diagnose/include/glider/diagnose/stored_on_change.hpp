// SPDX-License-Identifier: Apache-2.0
#pragma once
// A column a Slocum file stores only when it changed, at most every
// `interval` seconds (an .sbd's m_fin: sbdlist "m_fin 4"; the writer checks
// the value at every cycle once the interval since its last store has
// passed, and stores it at the first change). Between two stores a, b the
// value is therefore known at every logged row that came at least an
// interval after a: unchanged (a). Before that it moved from a to b at an
// unknown time: the straight line is the unbiased guess of its path.
//
// Holding the last store instead (a zero-order hold) puts every move at the
// next store, on average half an interval late: on the health SIL's 4 s
// .sbd the heading plane read the fin's authority 0.85-0.92 for 1 from that
// lag (docs/science.md "The fin on decimated data"); interpolating straight
// across every gap makes a long hold a slow ramp.
#include <filesystem>
#include <span>
#include <vector>

#include "glider/flightlog/flight_log.hpp"

namespace glider::diagnose {

// The storing interval of a column stored on change, from the gaps between
// its stores (their 10th percentile: a moving value is stored every interval;
// a full-resolution .dbd column, stored every cycle, gives the cycle). 0 with
// fewer than 3 stores.
double storing_interval_s(std::span<const double> time, std::span<const double> values);

// The column at every row: between consecutive stores a (t_a) and b (t_b)
// at most `max_gap_s` of unlogged time apart (no two logged rows further
// apart, and b's move no longer than that), a up to the last row at or after
// t_a + interval (less half a row spacing, the cycle's jitter) before t_b,
// then the straight line to b; NaN across longer gaps, before the first and
// after the last store. With every row stored this is the straight line
// between neighbours (flightlog::interpolate_linear).
flightlog::Column fill_stored_on_change(std::span<const double> time, std::span<const double> values, double max_gap_s);

// A Slocum file that stores its columns on change at most every few
// seconds (sbdlist / tbdlist / mbdlist decimation): .sbd .scd .mbd .mcd
// .tbd .tcd .nbd .ncd. A full-resolution .dbd/.ebd stores every cycle.
bool decimated_file(const std::filesystem::path& file);
// Any of `files` decimated: the fill below is the straight line wherever a
// column is stored every row, so a set mixing both kinds loses nothing.
bool any_decimated(const std::vector<std::filesystem::path>& files);

// How long a stored value is held (health and glider-diagnose): a quarter
// hour, past any dive's or climb's silence in a column that changes.
inline constexpr double kStoredHoldMaxAgeS = 900.0;

// A decimated file's log as the planes read it: the commands and the
// readings that change in steps (c_heading, c_fin, m_roll, m_ballast_pumped,
// m_depth_state, ...) forward filled between stores, at most `max_age_s`
// ("not stored" means "unchanged"); m_heading filled between stores on the
// shorter arc (30 s at most); the depth and pitch never held (a held depth
// is a false stair in the depth rate). `hold_fin` false leaves m_fin as
// stored, for fill_stored_on_change (HeadingTrackOptions::fin_stored_on_change).
flightlog::FlightLog hold_stored_columns(const flightlog::FlightLog& log, double max_age_s, bool hold_fin);

}  // namespace glider::diagnose
