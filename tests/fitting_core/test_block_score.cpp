// SPDX-License-Identifier: Apache-2.0
// The held-out error over blocks of a glide (fitting_core/block_score.hpp):
// white noise averages out as the block's samples, an offset a glide shares
// stays; blocks end at a new glide or after the block length.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "draws.hpp"
#include "glider/fitting_core/block_score.hpp"

using glider::fitting_core::block_rms;

TEST_GROUP(FittingCoreBlockScore) { std::mt19937_64 rng{20261127}; };

TEST(FittingCoreBlockScore, NoBlockIsThePlainRms) {
  const std::vector<double> r{3.0, -4.0, 0.0, 5.0};
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
  const std::vector<long> glide{0, 0, 0, 0};
  DOUBLES_EQUAL(std::sqrt(50.0 / 4.0), block_rms(t, glide, r, 0.0), 1e-12);
}

TEST(FittingCoreBlockScore, BlocksEndAtAGlideOrTheirLength) {
  // Blocks: {1, 3} (glide 0, 0-9 s), {5} (glide 0, 10 s), {-2} (glide 1).
  const std::vector<double> r{1.0, 3.0, 5.0, -2.0};
  const std::vector<double> t{0.0, 9.0, 10.0, 11.0};
  const std::vector<long> glide{0, 0, 0, 1};
  const double expected = std::sqrt((2.0 * 2.0 * 2.0 + 25.0 + 4.0) / 4.0);  // n_b mean_b^2 over n
  DOUBLES_EQUAL(expected, block_rms(t, glide, r, 10.0), 1e-12);
}

TEST(FittingCoreBlockScore, NoiseAveragesOutAndAGlidesOffsetStays) {
  // 1 Hz white noise of 10 mm/s on 20 glides of 600 s, half of them 3 mm/s off.
  std::vector<double> t, noise, shifted;
  std::vector<long> glide;
  const std::vector<double> white = fitting_core_test::ar1(rng, 12000, 0.0, 0.010);
  for (std::size_t i = 0; i < white.size(); ++i) {
    const long g = static_cast<long>(i / 600);
    t.push_back(static_cast<double>(i));
    glide.push_back(g);
    noise.push_back(white[i]);
    shifted.push_back(white[i] + (g % 2 == 0 ? 0.003 : 0.0));
  }
  // Sample by sample the offset adds 2 % to the RMS; over 60 s blocks the
  // noise is 10 / sqrt(60) = 1.3 mm/s and the offset more than doubles it.
  const double plain = block_rms(t, glide, noise, 0.0), plain_shifted = block_rms(t, glide, shifted, 0.0);
  const double block = block_rms(t, glide, noise, 60.0), block_shifted = block_rms(t, glide, shifted, 60.0);
  CHECK(plain_shifted / plain < 1.03);
  DOUBLES_EQUAL(0.010 / std::sqrt(60.0), block, 0.15 * 0.010 / std::sqrt(60.0));
  CHECK(block_shifted / block > 1.5);
}

TEST(FittingCoreBlockScore, NothingIsNaN) {
  const std::vector<double> none;
  const std::vector<long> no_glide;
  CHECK(std::isnan(block_rms(none, no_glide, none, 60.0)));
}
