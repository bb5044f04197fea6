// lengths_of() (two lengths with one packed square root) against length_of() one at a time, to
// the last bit, at every magnitude a length can have: 0, subnormal, the ranges where the square
// underflows or overflows, and ordinary ones; box_bounding_radii() against bounding_radius(); and
// unit_of() against the quotient in long double at those magnitudes, on both sides of the bounds
// of unit_beside_root()'s range; length_at_most() against the lengths compared in long double,
// with reaches on both sides of the bounds of its range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "mink/query/box_box.hpp"

namespace mink::detail {
namespace {

/// Vectors whose coordinates have mixed magnitudes, from subnormal to near the largest, some
/// exactly 0.
template <class S>
class MixedVectors {
 public:
  explicit MixedVectors(unsigned seed) : rng_(seed) {}
  Vec3T<S> operator()() {
    Vec3T<S> v;
    for (int i = 0; i < 3; ++i)
      v[i] =
          rng_() % 5 == 0 ? S(0) : std::ldexp(unit_(rng_), exponent_(rng_) / (1 + int(rng_() % 3)));
    return v;
  }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<S> unit_{S(-1), S(1)};
  std::uniform_int_distribution<int> exponent_{std::numeric_limits<S>::min_exponent - 30,
                                               std::numeric_limits<S>::max_exponent - 2};
};

template <class S>
void check_lengths() {
  MixedVectors<S> vector(11);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3T<S> u = vector(), v = vector();
    S lu = S(-1), lv = S(-1);
    lengths_of(u, v, lu, lv);
    EXPECT_EQ(lu, length_of(u)) << u.transpose();
    EXPECT_EQ(lv, length_of(v)) << v.transpose();
  }
}

TEST(Lengths, TwoAtOnceEqualOneAtATimeDouble) {
  check_lengths<double>();
}
TEST(Lengths, TwoAtOnceEqualOneAtATimeFloat) {
  check_lengths<float>();
}

/// unit_of(v) against v / |v| in long double (v scaled by its largest coordinate first, so that
/// nothing overflows or underflows there): every coordinate within 4 eps.
template <class S>
void check_unit_of(const Vec3T<S>& v) {
  const Vec3T<S> unit = unit_of(v);
  const long double largest = std::max(
      {std::abs((long double)v.x()), std::abs((long double)v.y()), std::abs((long double)v.z())});
  const long double x = v.x() / largest, y = v.y() / largest, z = v.z() / largest;
  const long double norm = std::sqrt(x * x + y * y + z * z);
  const long double expected[3] = {x / norm, y / norm, z / norm};
  for (int k = 0; k < 3; ++k)
    EXPECT_LE(std::abs(unit[k] - expected[k]), 4 * std::numeric_limits<S>::epsilon())
        << v.transpose();
}

template <class S>
void check_unit_of_at_every_magnitude() {
  MixedVectors<S> vector(12);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3T<S> v = vector();
    if (v.isZero()) continue;
    check_unit_of(v);
  }
  // Squares at and around the bounds of the reciprocal's range (2^-1022 and 2^1022 in double),
  // and of the normal range.
  const int bounds[] = {std::numeric_limits<S>::min_exponent - 1,
                        1 - std::numeric_limits<S>::min_exponent,
                        std::numeric_limits<S>::max_exponent};
  for (const int bound : bounds) {
    for (int step = -3; step <= 3; ++step) {
      const S x = std::ldexp(S(1), (bound + step) / 2);
      check_unit_of(Vec3T<S>(x, S(0), S(0)));
      check_unit_of(Vec3T<S>(x, x, x));
      check_unit_of(Vec3T<S>(x, S(0.75) * x, -S(0.5) * x));
    }
  }
}

TEST(Lengths, UnitOfAtEveryMagnitudeDouble) {
  check_unit_of_at_every_magnitude<double>();
}
TEST(Lengths, UnitOfAtEveryMagnitudeFloat) {
  check_unit_of_at_every_magnitude<float>();
}

/// length_at_most(v, |v|^2, reach) against |v| <= reach in long double (v scaled by its largest
/// coordinate first), wherever the two lengths are more than 4 eps (or 4 of the smallest
/// subnormal steps) apart; exactly for reach 0.
template <class S>
void check_length_at_most(const Vec3T<S>& v, S reach) {
  const bool verdict = length_at_most(v, v.squaredNorm(), reach);
  if (reach == S(0)) {
    EXPECT_EQ(verdict, (v.array() == S(0)).all()) << v.transpose();
    return;
  }
  const long double largest = std::max(
      {std::abs((long double)v.x()), std::abs((long double)v.y()), std::abs((long double)v.z())});
  long double length = 0;
  if (largest > 0) {
    const long double x = v.x() / largest, y = v.y() / largest, z = v.z() / largest;
    length = largest * std::sqrt(x * x + y * y + z * z);
  }
  // A subnormal length is known to a few of the smallest steps only, not to eps.
  const long double margin = 4 * std::numeric_limits<S>::epsilon() * (long double)reach +
                             4 * (long double)std::numeric_limits<S>::denorm_min();
  if (length <= reach - margin) EXPECT_TRUE(verdict) << v.transpose() << " reach " << reach;
  if (length >= reach + margin) EXPECT_FALSE(verdict) << v.transpose() << " reach " << reach;
}

template <class S>
void check_length_at_most_at_every_magnitude() {
  MixedVectors<S> vector(13);
  const S factors[] = {S(0.5), S(1) - 16 * std::numeric_limits<S>::epsilon(),
                       S(1) + 16 * std::numeric_limits<S>::epsilon(), S(2)};
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3T<S> v = vector(), w = vector();
    const S length = length_of(v);
    check_length_at_most(v, S(0));
    check_length_at_most(v, length_of(w));  // an unrelated reach, of any magnitude
    for (const S factor : factors)
      if (std::isfinite(length * factor)) check_length_at_most(v, length * factor);
  }
  // Reaches whose squares lie at and around the bounds of the range compared on squares, against
  // vectors whose squares underflow, overflow or lie near the reach's.
  const int bounds[] = {std::numeric_limits<S>::min_exponent + 1,
                        std::numeric_limits<S>::max_exponent - 2};
  for (const int bound : bounds) {
    for (int step = -3; step <= 3; ++step) {
      const S reach = std::ldexp(S(1), (bound + step) / 2);
      for (const S scale :
           {S(0), std::numeric_limits<S>::denorm_min(), S(0.5) * reach, S(0.99) * reach,
            S(1.01) * reach, S(2) * reach, std::numeric_limits<S>::max() / S(4)}) {
        check_length_at_most(Vec3T<S>(scale, S(0), S(0)), reach);
        check_length_at_most(Vec3T<S>(Vec3T<S>(scale, scale, scale) / S(2)), reach);
      }
    }
  }
}

TEST(Lengths, LengthAtMostAtEveryMagnitudeDouble) {
  check_length_at_most_at_every_magnitude<double>();
}
TEST(Lengths, LengthAtMostAtEveryMagnitudeFloat) {
  check_length_at_most_at_every_magnitude<float>();
}

TEST(Lengths, BoxBoundingRadiiEqualBoundingRadius) {
  const Box tiny{Vec3(1e-200, 3e-201, 0)}, huge{Vec3(1e200, 2e199, 5e199)}, plain{Vec3(1, 2, 3)};
  const Rounded<Box> rounded{plain, 0.25};
  const Box boxes[] = {tiny, huge, plain, Box{Vec3::Zero()}};
  for (const Box& a : boxes) {
    for (const Box& b : boxes) {
      double ra = -1, rb = -1;
      box_bounding_radii(a, b, ra, rb);
      EXPECT_EQ(ra, a.bounding_radius());
      EXPECT_EQ(rb, b.bounding_radius());
    }
    double ra = -1, rb = -1;
    box_bounding_radii(a, rounded, ra, rb);
    EXPECT_EQ(ra, a.bounding_radius());
    EXPECT_EQ(rb, rounded.bounding_radius());
  }
}

}  // namespace
}  // namespace mink::detail
