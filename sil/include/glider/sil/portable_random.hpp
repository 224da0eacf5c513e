// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace glider::sil {

// Seeded random numbers that are the same on every platform: mt19937_64 is
// specified bit for bit, std::normal_distribution and
// std::uniform_real_distribution are not. Every noise and gap the SIL makes
// comes from one of these, so a run's log is identical byte for byte.
class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : rng_(seed) {}

  // Uniform in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(rng_() >> 11) * kTwoToMinus53; }

  // Standard normal by Box-Muller; the second value of each pair is kept for
  // the next call.
  double gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (static_cast<double>(rng_() >> 11) + 0.5) * kTwoToMinus53;  // (0, 1): log(u1) finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  static constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  std::mt19937_64 rng_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

// A second, independent stream from a run's seed (the golden-ratio increment
// of splitmix64), so that adding a noise source does not change the numbers
// the existing ones draw.
constexpr std::uint64_t derived_seed(std::uint64_t seed, std::uint64_t stream) {
  return seed + 0x9E3779B97F4A7C15ULL * stream;
}

// Every random stream of a run, in one place so that no two share a seed.
// Stream 0 is the run's seed itself: the firmware sensors' noise (SimHal).
enum RandomStream : std::uint64_t {
  kCtdStream = 1,
  kLogGapStream = 2,
  kGpsNoiseStream = 3,
  kYawDisturbanceStream = 4,
  // The GPS's time to first fix after each surfacing, apart from its
  // position noise: the number of fixes a surfacing produces depends on how
  // often the receiver is read (a HIL plant under load reads it at other
  // instants than SIL), and must not change the next surfacing's wait.
  kGpsAcquisitionStream = 5,
  kModemStream = 6,  // the simulated modem's link (sim_modem.hpp)
};

}  // namespace glider::sil
