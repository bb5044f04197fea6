// reduce_to_four(): the forms for two and four points (the steps unrolled for a count fixed at
// compile time) against the steps run with the count given at run time, on random
// points and on the cases where they could part: equal and nearly equal depths (within
// min_length), repeated points, points on a line, and squares and rectangles, whose diagonals and
// sides tie. And against answers that need no reduction code: a convex quadrilateral keeps all four
// corners, the deepest first; points on a line keep the deepest and both ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "mink/manifold/clip.hpp"

namespace mink {
namespace {

using Point = detail::PlanarPoint<double>;

/// The kept indices of reduce_to_four() and of the steps with a run-time count: the same, slot by
/// slot, except that four points kept whole (keeps_whole_quad()) come in cyclic order after the
/// deepest, so only the deepest and the set are compared there.
void expect_same_as_general(const Point* points, int count, double min_length, int k) {
  int fast[4] = {-1, -1, -1, -1}, general[4] = {-1, -1, -1, -1};
  const int kept = detail::reduce_to_four(points, count, min_length, fast);
  const int kept_general = detail::reduce_points_to_four<0>(points, count, min_length, general);
  ASSERT_EQ(kept, kept_general) << "case " << k << ", " << count << " points";
  if (count == 4 && detail::keeps_whole_quad(points, min_length)) {
    EXPECT_EQ(fast[0], general[0]) << "case " << k;
    EXPECT_EQ(std::set<int>(fast, fast + 4), std::set<int>(general, general + 4)) << "case " << k;
    return;
  }
  for (int i = 0; i < kept; ++i) EXPECT_EQ(fast[i], general[i]) << "case " << k << ", slot " << i;
}

TEST(ReduceToFour, FixedCountsEqualTheRunTimeSteps) {
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> u(-1, 1);
  const double min_length = 1e-9;
  int compared = 0;
  for (int k = 0; k < 20000; ++k) {
    const int count = k % 2 == 0 ? 2 : 4;
    Point p[4];
    const int shape = (k / 2) % 8;
    for (int i = 0; i < count; ++i) p[i] = {u(rng), u(rng), u(rng)};
    if (shape == 1) {
      // Depths equal, or apart by about min_length: the deepest is a near tie.
      for (int i = 1; i < count; ++i) p[i].depth = p[0].depth + (u(rng) + 0.5) * min_length;
    } else if (shape == 2) {
      // A point repeated (to within min_length) over another.
      p[count - 1] = p[0];
      p[count - 1].x += u(rng) * min_length;
    } else if (shape == 3) {
      // All on a line, in random order along it.
      for (int i = 0; i < count; ++i) {
        const double s = u(rng);
        p[i].x = 0.3 + s;
        p[i].y = -0.2 + 2 * s;
      }
    } else if (shape == 4 && count == 4) {
      // A rectangle (a square one time in two): equal diagonals, equal sides, equal depths.
      const double w = 0.5 + 0.5 * std::abs(u(rng)), h = k % 4 == 1 ? w : 0.3;
      const double depth = u(rng);
      const Point corners[4] = {{w, h, depth}, {-w, h, depth}, {-w, -h, depth}, {w, -h, depth}};
      std::copy(corners, corners + 4, p);
    } else if (shape == 5) {
      // Every point the same.
      for (int i = 1; i < count; ++i) p[i] = p[0];
    } else if (shape == 6 && count == 4) {
      // A convex quadrilateral in cyclic order, one corner 0.2 to 5 min_length off the line of its
      // neighbours, on either side: where keeping all four starts or stops.
      const double off = (k % 4 == 1 ? 1 : -1) * min_length * std::exp(1.6 * u(rng));
      const double depth = u(rng);
      const Point corners[4] = {
          {0.9, 0, depth}, {0, 0.7, depth}, {-0.8, 0, depth}, {0, off, depth}};
      const int start = int(std::abs(u(rng)) * 4) & 3;
      for (int i = 0; i < 4; ++i) p[i] = corners[(start + i) & 3];
    } else if (shape == 7 && count == 4) {
      // Convex corners out of cyclic order (a crossed quadrilateral) or one inside the others'
      // triangle: the general steps decide.
      const Point convex[4] = {{1, 0, u(rng)}, {0, 1, u(rng)}, {-1, 0, u(rng)}, {0, -1, u(rng)}};
      const Point crossed[4] = {convex[0], convex[2], convex[1], convex[3]};
      const Point inside[4] = {convex[0], convex[1], {0.1, 0.2, u(rng)}, convex[2]};
      std::copy(k % 4 == 1 ? crossed : inside, (k % 4 == 1 ? crossed : inside) + 4, p);
    }
    expect_same_as_general(p, count, min_length, k);
    ++compared;
  }
  EXPECT_EQ(compared, 20000);
}

TEST(ReduceToFour, ConvexQuadrilateralKeepsAllCornersDeepestFirst) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    // Corners at increasing angles on an ellipse: convex, no three on a line.
    Point p[4];
    const double start = 6.283185307179586 * u(rng);
    for (int i = 0; i < 4; ++i) {
      const double angle = start + 1.5707963267948966 * (i + 0.8 * (u(rng) - 0.5));
      p[i] = {2 * std::cos(angle), std::sin(angle), u(rng)};
    }
    int keep[4];
    ASSERT_EQ(detail::reduce_to_four(p, 4, 1e-9, keep), 4) << "case " << k;
    const std::set<int> kept(keep, keep + 4);
    EXPECT_EQ(kept.size(), 4u) << "case " << k;
    const int deepest =
        int(std::max_element(p, p + 4,
                             [](const Point& a, const Point& b) { return a.depth < b.depth; }) -
            p);
    EXPECT_EQ(keep[0], deepest) << "case " << k;
  }
}

TEST(ReduceToFour, TwoPointsKeepTheDeeperFirstAndDropARepeat) {
  const Point apart[2] = {{0, 0, 0.1}, {1, 0, 0.2}};
  int keep[4];
  ASSERT_EQ(detail::reduce_to_four(apart, 2, 1e-9, keep), 2);
  EXPECT_EQ(keep[0], 1);
  EXPECT_EQ(keep[1], 0);
  // Depths within min_length: the first point counts as the deepest.
  const Point tied[2] = {{0, 0, 0.1}, {1, 0, 0.1 + 5e-10}};
  ASSERT_EQ(detail::reduce_to_four(tied, 2, 1e-9, keep), 2);
  EXPECT_EQ(keep[0], 0);
  // A repeat (closer than min_length): one point, the deeper.
  const Point repeat[2] = {{0, 0, 0.1}, {5e-10, 0, 0.2}};
  ASSERT_EQ(detail::reduce_to_four(repeat, 2, 1e-9, keep), 1);
  EXPECT_EQ(keep[0], 1);
}

TEST(ReduceToFour, PointsOnALineKeepTheDeepestAndBothEnds) {
  // The deepest point lies between the ends (skew edges crossing).
  const Point line[4] = {{0, 0, 0.1}, {3, 0, 0.1}, {1, 0, 0.5}, {2, 0, 0.2}};
  int keep[4];
  ASSERT_EQ(detail::reduce_to_four(line, 4, 1e-9, keep), 3);
  EXPECT_EQ(keep[0], 2);
  const std::set<int> ends(keep + 1, keep + 3);
  EXPECT_EQ(ends, (std::set<int>{0, 1}));
}

}  // namespace
}  // namespace mink
