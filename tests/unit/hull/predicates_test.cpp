// The exact predicates of mink/hull/predicates.hpp against integer arithmetic (__int128) on
// inputs chosen so that the filter cannot decide: exactly degenerate sets and perturbations of
// one unit in the last place.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mink/hull/predicates.hpp"

namespace {

__extension__ typedef __int128 i128;  // GCC and Clang

int sign128(i128 x) {
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

// Coordinates k * 2^-s with |k| < 2^29: differences < 2^30 units, triple products < 2^90.
struct Scaled {
  double v[3];
  long long k[3];
};

Scaled scaled(long long x, long long y, long long z, int s) {
  return {{std::ldexp(double(x), -s), std::ldexp(double(y), -s), std::ldexp(double(z), -s)},
          {x, y, z}};
}

int orient3d_int(const Scaled& a, const Scaled& b, const Scaled& c, const Scaled& d) {
  i128 u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = b.k[i] - a.k[i];
    v[i] = c.k[i] - a.k[i];
    w[i] = d.k[i] - a.k[i];
  }
  const i128 det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                   w[2] * (u[0] * v[1] - u[1] * v[0]);
  return sign128(det);
}

TEST(HullPredicates, Orient3dMatchesIntegerArithmeticNearPlanes) {
  std::mt19937_64 g(7);
  std::uniform_int_distribution<long long> coord(-(1LL << 28), 1LL << 28);
  std::uniform_int_distribution<int> small(-3, 3);
  int exact_zero = 0, checked = 0;
  for (int it = 0; it < 20000; ++it) {
    // a, b, c and d = a + i (b - a) + j (c - a) + a small perturbation: d is on the plane or
    // a few units off it, where the filter cannot decide.
    const long long a[3] = {coord(g), coord(g), coord(g)};
    long long b[3], c[3], d[3];
    for (int k = 0; k < 3; ++k) {
      b[k] = a[k] + coord(g) / 4;
      c[k] = a[k] + coord(g) / 4;
    }
    const int i = small(g), j = small(g);
    for (int k = 0; k < 3; ++k) d[k] = a[k] + i * (b[k] - a[k]) + j * (c[k] - a[k]);
    if (it % 3 != 0) d[it % 3] += small(g);
    const int s = 1 + it % 40;
    const Scaled pa = scaled(a[0], a[1], a[2], s), pb = scaled(b[0], b[1], b[2], s),
                 pc = scaled(c[0], c[1], c[2], s), pd = scaled(d[0], d[1], d[2], s);
    const int expected = orient3d_int(pa, pb, pc, pd);
    EXPECT_EQ(mink::exact::orient3d(pa.v, pb.v, pc.v, pd.v), expected);
    EXPECT_EQ(mink::exact::orient3d_exact(pa.v, pb.v, pc.v, pd.v), expected);
    exact_zero += expected == 0;
    ++checked;
  }
  EXPECT_GT(exact_zero, checked / 4);
}

TEST(HullPredicates, Orient2dUlpGrid) {
  // Shewchuk's classic picture: orient2d(p, q, r) with p on a 256 x 256 grid of ulps around
  // (0.5, 0.5) and q, r on the diagonal. In units of 2^-53 all values are integers below 2^58.
  const double q[3] = {12, 12, 0}, r[3] = {24, 24, 0};
  const double ulp = std::ldexp(1.0, -53);
  int wrong = 0, zero = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const double p[3] = {0.5 + i * ulp, 0.5 + j * ulp, 0};
      const i128 px = (i128(1) << 52) + i, py = (i128(1) << 52) + j;
      const i128 qx = i128(12) << 53, rx = i128(24) << 53;
      const i128 det = (qx - px) * (rx - py) - (qx - py) * (rx - px);
      const int expected = sign128(det);
      zero += expected == 0;
      if (mink::exact::orient2d(p, q, r, 0, 1) != expected) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(zero, 256);  // the diagonal i == j
}

TEST(HullPredicates, OrientAlongAndDotSign) {
  // orient_along with n = the exact normal of an axis plane reduces to orient2d.
  std::mt19937_64 g(3);
  std::uniform_int_distribution<long long> coord(-(1LL << 26), 1LL << 26);
  const double n[3] = {0, 0, 1};
  for (int it = 0; it < 5000; ++it) {
    const Scaled a = scaled(coord(g), coord(g), coord(g), 20);
    const Scaled b = scaled(a.k[0] + coord(g) / 8, a.k[1] + coord(g) / 8, coord(g), 20);
    // c on the line a b in x, y (or one unit off), any z.
    const long long t = 1 + it % 5;
    const Scaled c = scaled(a.k[0] + t * (b.k[0] - a.k[0]) + (it % 3 == 0 ? 1 : 0),
                            a.k[1] + t * (b.k[1] - a.k[1]), coord(g), 20);
    const i128 det =
        i128(b.k[0] - a.k[0]) * (c.k[1] - a.k[1]) - i128(b.k[1] - a.k[1]) * (c.k[0] - a.k[0]);
    EXPECT_EQ(mink::exact::orient_along(a.v, b.v, c.v, n), sign128(det));
    EXPECT_EQ(mink::exact::orient2d(a.v, b.v, c.v, 0, 1), sign128(det));
    // dot_sign along an integer direction.
    const double m[3] = {3, -4, 5};
    const i128 dot =
        3 * i128(b.k[0] - a.k[0]) - 4 * i128(b.k[1] - a.k[1]) + 5 * i128(b.k[2] - a.k[2]);
    EXPECT_EQ(mink::exact::dot_sign(m, a.v, b.v), sign128(dot));
  }
  // Equal projections along a direction with a tiny difference in the tail.
  const double x[3] = {1, 0, 0}, y[3] = {1 + std::ldexp(1.0, -52), 0, 0}, dir[3] = {1, 1e-300, 0};
  EXPECT_EQ(mink::exact::dot_sign(dir, x, y), 1);
  EXPECT_EQ(mink::exact::dot_sign(dir, y, x), -1);
  EXPECT_EQ(mink::exact::dot_sign(dir, x, x), 0);
}

TEST(HullPredicates, MergedSumEqualsGrowthSum) {
  // add() (linear merge) against add_by_growth() (the textbook quadratic sum) on expansions
  // built like the predicates build theirs: differences, products, scalings, wide exponents.
  using namespace mink::exact;
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-60, 60);
  auto rnd = [&] { return std::ldexp(u(g), ex(g)); };
  for (int it = 0; it < 20000; ++it) {
    const auto a = mul(difference(rnd(), rnd()), difference(rnd(), rnd()));
    const auto b = scale(mul(difference(rnd(), rnd()), difference(rnd(), rnd())), rnd());
    const auto fast = add(a, b);
    const auto slow = add_by_growth(a, b);
    EXPECT_EQ(sign(add_by_growth(fast, negate(slow))), 0);
    EXPECT_EQ(sign(fast), sign(slow));
    // Cancellation to exactly zero.
    EXPECT_EQ(sign(add(a, negate(a))), 0);
    EXPECT_EQ(sign(add(add(a, b), negate(add_by_growth(b, a)))), 0);
  }
}

TEST(HullPredicates, ExpansionArithmeticIsExact) {
  using namespace mink::exact;
  // (1 + 2^-60) - 1 = 2^-60 exactly, through sums of expansions.
  const auto one = expansion(1.0), tiny = expansion(std::ldexp(1.0, -60));
  const auto s = sub(add(one, tiny), one);
  EXPECT_EQ(estimate(s), std::ldexp(1.0, -60));
  // (2^27 + 1)^2 = 2^54 + 2^28 + 1 is not a double; the expansion holds it.
  const auto big = expansion(134217729.0);
  const auto sq = mul(big, big);
  EXPECT_EQ(sign(sub(sq, expansion(std::ldexp(1.0, 54) + std::ldexp(1.0, 28)))), 1);
  EXPECT_EQ(sign(sub(sub(sq, expansion(std::ldexp(1.0, 54) + std::ldexp(1.0, 28))), expansion(1))),
            0);
  // Exact cross product rounding of a needle triangle.
  const double a[3] = {0, 0, 0}, b[3] = {1, 1e-17, 0}, c[3] = {2, 3e-17, 1e-30};
  double n[3];
  cross_rounded(a, b, c, n);
  EXPECT_DOUBLE_EQ(n[2], 1 * 3e-17 - 1e-17 * 2);
}

TEST(HullPredicates, CrossRoundedIsWithinOneUlpOfIntegerCross) {
  // Coordinates k 2^-s with |k| < 2^29: each cross component is an exact integer (< 2^61) times
  // 2^-2s, so __int128 gives it exactly; cross_rounded must be within one unit in the last
  // place of it (the double-double fast path gives the nearest double, the exact path at most
  // one unit off). Generic triangles take the fast path, near-degenerate ones the exact one.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> coord(-(1LL << 28), 1LL << 28);
  std::uniform_int_distribution<long long> nudge(-3, 3);
  const int s = 20;
  for (int it = 0; it < 20000; ++it) {
    Scaled a = scaled(coord(rng), coord(rng), coord(rng), s);
    Scaled b = scaled(coord(rng), coord(rng), coord(rng), s);
    Scaled c = scaled(coord(rng), coord(rng), coord(rng), s);
    if (it % 2 == 1) {  // c nearly on the line ab
      c = scaled(a.k[0] + 2 * (b.k[0] - a.k[0]) / 3 + nudge(rng),
                 a.k[1] + 2 * (b.k[1] - a.k[1]) / 3 + nudge(rng),
                 a.k[2] + 2 * (b.k[2] - a.k[2]) / 3 + nudge(rng), s);
    }
    double n[3];
    mink::exact::cross_rounded(a.v, b.v, c.v, n);
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const i128 exact =
          i128(b.k[i] - a.k[i]) * (c.k[j] - a.k[j]) - i128(b.k[j] - a.k[j]) * (c.k[i] - a.k[i]);
      // The exact value, held exactly by a long double (64-bit significand).
      const long double value = std::ldexp(static_cast<long double>(exact), -2 * s);
      const double below = static_cast<double>(value);
      const long double err = std::fabs(static_cast<long double>(n[k]) - value);
      const long double ulp = std::fabs(static_cast<long double>(std::nextafter(below, HUGE_VAL)) -
                                        static_cast<long double>(below));
      EXPECT_LE(err, ulp * 1.0001L) << "component " << k << " of triangle " << it;
      if (exact == 0) {
        EXPECT_EQ(n[k], 0.0);
      }
    }
  }
}

}  // namespace
