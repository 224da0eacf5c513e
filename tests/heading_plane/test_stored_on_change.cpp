// SPDX-License-Identifier: Apache-2.0
// A column a decimated Slocum file stores on change (an .sbd's m_fin, at
// most every 4 s): between two readings it is held where the writer checked
// it and found it unchanged, a straight line where it moved.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>
#include <vector>

#include "glider/diagnose/stored_on_change.hpp"
#include "glider/flightlog/gaps.hpp"

using namespace glider;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> seconds(int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(i);
  return t;
}

}  // namespace

TEST_GROUP(StoredOnChange){};

// Stored at 0, 4 and 8 while moving, then unchanged until it moved again
// and was stored at 20: the storing interval is 4 s; held from 8 up to 19
// (the last row the writer found it unchanged at), the move in the last second.
TEST(StoredOnChange, HeldWhereTheWriterFoundItUnchangedALineWhereItMoved) {
  const std::vector<double> t = seconds(21);
  std::vector<double> fin(t.size(), kNaN);
  fin[0] = 0.0;
  fin[4] = 0.4;
  fin[8] = 0.2;
  fin[20] = 0.3;
  DOUBLES_EQUAL(4.0, diagnose::storing_interval_s(t, fin), 1e-12);
  const flightlog::Column filled = diagnose::fill_stored_on_change(t, fin, 30.0);
  DOUBLES_EQUAL(0.1, filled[1], 1e-12);  // moving: the line 0 -> 0.4
  DOUBLES_EQUAL(0.3, filled[6], 1e-12);  // the line 0.4 -> 0.2
  for (int k = 9; k <= 19; ++k) DOUBLES_EQUAL(0.2, filled[static_cast<std::size_t>(k)], 1e-12);
  DOUBLES_EQUAL(0.3, filled[20], 1e-12);
  // Not the line across the hold: a slow ramp the fin never flew.
  const flightlog::Column line = flightlog::interpolate_linear(t, fin, 30.0);
  CHECK(std::abs(line[14] - filled[14]) > 0.04);
}

// A column stored at every row is the straight line between neighbours (as
// a full-resolution file's); gaps longer than the limit stay empty.
TEST(StoredOnChange, EveryRowStoredIsTheLineAndLongGapsStayEmpty) {
  std::vector<double> t = seconds(10);
  t.push_back(60.0);
  t.push_back(61.0);
  std::vector<double> fin;
  for (double x : t) fin.push_back(std::sin(0.3 * x));
  const flightlog::Column filled = diagnose::fill_stored_on_change(t, fin, 30.0);
  const flightlog::Column line = flightlog::interpolate_linear(t, fin, 30.0);
  for (std::size_t k = 0; k < t.size(); ++k) DOUBLES_EQUAL(line[k], filled[k], 1e-12);
  // Stores at 0, 9 and 60 s: between 0 and 9 the rows every second, then
  // nothing for 51 s: across that gap nothing is known.
  std::vector<double> sparse(t.size(), kNaN);
  sparse[0] = 0.1;
  sparse[9] = 0.1;
  sparse[10] = 0.5;
  const flightlog::Column gap = diagnose::fill_stored_on_change(t, sparse, 30.0);
  DOUBLES_EQUAL(0.1, gap[5], 1e-12);
  DOUBLES_EQUAL(0.5, gap[10], 1e-12);
  std::vector<double> across(t.size(), kNaN);
  across[0] = 0.1;
  across[10] = 0.5;
  CHECK(std::isnan(diagnose::fill_stored_on_change(t, across, 30.0)[5]));
}

// Which Slocum files store on change: the decimated flight and science kinds
// (either case), not the full-resolution .dbd / .ebd nor a CSV.
TEST(StoredOnChange, DecimatedFilesByTheirKind) {
  CHECK(diagnose::decimated_file("a/unit_123-2026-330-0-0.sbd"));
  CHECK(diagnose::decimated_file("01230000.SCD"));
  CHECK(diagnose::decimated_file("x.tbd"));
  CHECK(diagnose::decimated_file("x.mbd"));
  CHECK_FALSE(diagnose::decimated_file("x.dbd"));
  CHECK_FALSE(diagnose::decimated_file("x.ebd"));
  CHECK_FALSE(diagnose::decimated_file("x.csv"));
  CHECK(diagnose::any_decimated({"x.dbd", "x.sbd"}));
  CHECK_FALSE(diagnose::any_decimated({"x.dbd", "x.ebd"}));
}

// An .sbd's log as glider-diagnose reads it: the commands held between their
// stores (at most the age given), the heading filled on the shorter arc, the
// depth never held, and m_fin held only when asked (else left as stored, for
// fill_stored_on_change).
TEST(StoredOnChange, CommandsHeldTheFinAsStored) {
  const std::vector<double> t = seconds(8);
  std::vector<double> command(t.size(), kNaN), fin(t.size(), kNaN), depth(t.size(), kNaN), heading(t.size(), kNaN);
  command[0] = 1.0;
  command[6] = 2.0;
  fin[0] = 0.1;
  fin[4] = 0.2;
  depth[0] = 5.0;
  depth[4] = 9.0;
  heading[0] = 6.2;
  heading[2] = 0.2;  // across north: the shorter arc
  const flightlog::FlightLog log("test", {}, {"m_present_time", "c_heading", "m_fin", "m_depth", "m_heading"},
                                 {t, command, fin, depth, heading}, 0);
  const flightlog::FlightLog as_stored = diagnose::hold_stored_columns(log, 3.0, false);
  DOUBLES_EQUAL(1.0, as_stored.column("c_heading")[3], 1e-12);
  CHECK(std::isnan(as_stored.column("c_heading")[4]));  // older than 3 s
  DOUBLES_EQUAL(2.0, as_stored.column("c_heading")[7], 1e-12);
  CHECK(std::isnan(as_stored.column("m_fin")[2]));
  CHECK(std::isnan(as_stored.column("m_depth")[2]));
  const double mid = as_stored.column("m_heading")[1];
  CHECK(mid > 6.2 || mid < 0.2);
  DOUBLES_EQUAL(0.1, diagnose::hold_stored_columns(log, 3.0, true).column("m_fin")[2], 1e-12);
}
