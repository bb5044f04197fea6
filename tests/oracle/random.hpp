/// @file random.hpp
/// Seeded random inputs for the sweeps. Every case draws from its own generator seeded with
/// `base_seed + index`, so a failure message's seed reproduces that one case alone.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

#include "mink/math/pose.hpp"

namespace oracle {

/// Built with AddressSanitizer (GCC's macro, or Clang's feature test).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

/// Number of cases of a sweep: `default_count` times the integer in MINK_TEST_SWEEP_SCALE (1 when
/// unset). Big sweeps: MINK_TEST_SWEEP_SCALE=20 ./mink_tests. `sanitized_count` (when given)
/// replaces `default_count` under the sanitizers, for the sweeps that run ten times longer there
/// than anything else: that build looks for memory and undefined-behaviour faults, which the
/// smaller sweep walks the same code paths for, and the Release build runs the full sweep.
inline int sweep_count(int default_count, int sanitized_count = 0) {
  const char* env = std::getenv("MINK_TEST_SWEEP_SCALE");
  const int scale = env ? std::max(1, std::atoi(env)) : 1;
  return (kSanitized && sanitized_count > 0 ? sanitized_count : default_count) * scale;
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  /// log-uniform in [lo, hi] (both > 0): sizes spread over the range's decades.
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool chance(double p) { return uniform(0, 1) < p; }

  mink::Vec3 in_cube(double half) {
    return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
  }
  mink::Vec3 in_ball(double radius) {
    while (true) {
      const mink::Vec3 v = in_cube(1);
      if (v.squaredNorm() <= 1) return radius * v;
    }
  }
  mink::Vec3 unit() {
    while (true) {
      const mink::Vec3 v = in_cube(1);
      const double n = v.squaredNorm();
      if (n > 1e-4 && n <= 1) return v / std::sqrt(n);
    }
  }
  /// Uniformly distributed rotation (normalised Gaussian quaternion).
  mink::Quat rotation() {
    std::normal_distribution<double> g;
    mink::Quat q(g(engine_), g(engine_), g(engine_), g(engine_));
    return q.normalized();
  }
  mink::Pose pose(double translation_radius) {
    return mink::Pose::from(in_ball(translation_radius), rotation());
  }

 private:
  std::mt19937_64 engine_;
};

inline std::string seed_note(std::uint64_t seed) {
  return "case seed = " + std::to_string(seed);
}

}  // namespace oracle
