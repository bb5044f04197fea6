// The first phase of the boolean test (gjk.hpp, enclose_origin) claims "intersecting" only when
// origin_volume() signs all four barycentric volumes of its tetrahedron. These tests check that
// predicate against exact integer arithmetic, and the whole boolean test on pairs whose Minkowski
// difference is flat or a sliver, where a rounded volume has no reliable sign.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;

__extension__ typedef __int128 Int;  // GCC and Clang on 64-bit targets

/// x . (y x z) exactly, for integer coordinates below 2^30 (products stay below 2^92).
Int exact_volume(const std::int64_t x[3], const std::int64_t y[3], const std::int64_t z[3]) {
  const Int c0 = Int(y[1]) * z[2] - Int(y[2]) * z[1];
  const Int c1 = Int(y[2]) * z[0] - Int(y[0]) * z[2];
  const Int c2 = Int(y[0]) * z[1] - Int(y[1]) * z[0];
  return Int(x[0]) * c0 + Int(x[1]) * c1 + Int(x[2]) * c2;
}

Vec3 to_vec(const std::int64_t p[3], double scale) {
  return Vec3(double(p[0]) * scale, double(p[1]) * scale, double(p[2]) * scale);
}

/// origin_volume()'s value when its sign is certain, else 0.
double certain_volume(const Vec3& x, const Vec3& y, const Vec3& z) {
  const auto volume = mink::detail::origin_volume(x, y, z);
  return volume.certain ? volume.value : 0.0;
}

int sign(Int v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}
int sign(double v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

// Integer points below 2^30, so the double products round. Half the cases are random; the other
// half are nearly flat: y = x + e (e up to 2^10) and z = x + y + f (f in {-1, 0, 1}^3), whose
// exact volume x . (e x f) lies between 0 and about 2^40, across the filter's bound (about 8 eps
// times 2^90). certain_volume() must either give the exact sign or say 0 (not certain), never
// the wrong sign, and it must sign random tetrahedra, or the first phase would decide nothing.
// Scaled by powers of two (exactly) from 2^-300 to 2^300, so the bound must hold away from 1 too.
TEST(BooleanPhase, CertainVolumeNeverGivesTheWrongSign) {
  oracle::Rng rng(4242);
  const int kMax = 1 << 28;
  int random_signed = 0, random_count = 0, flat_signed = 0, flat_unsigned = 0;
  for (int i = 0; i < 60000; ++i) {
    std::int64_t x[3], y[3], z[3];
    const bool flat = i % 2 == 1;
    const int spread = 1 << rng.integer(0, 10);
    for (int k = 0; k < 3; ++k) {
      x[k] = rng.integer(-kMax, kMax);
      y[k] = flat ? x[k] + rng.integer(-spread, spread) : rng.integer(-kMax, kMax);
      z[k] = flat ? x[k] + y[k] + rng.integer(-1, 1) : rng.integer(-kMax, kMax);
    }
    const double scale = std::ldexp(1.0, rng.integer(-300, 300));
    const double got = certain_volume(to_vec(x, scale), to_vec(y, scale), to_vec(z, scale));
    const Int exact = exact_volume(x, y, z);
    if (got != 0.0) {
      ASSERT_EQ(sign(got), sign(exact)) << "case " << i << ": wrong sign";
    }
    if (flat) {
      flat_signed += got != 0.0;
      flat_unsigned += got == 0.0;
    } else {
      ++random_count;
      random_signed += got != 0.0;
    }
  }
  // A random tetrahedron of the cube is far from flat but for a few in ten thousand.
  EXPECT_GT(random_signed, random_count * 99 / 100);
  // The nearly flat ones straddle the bound: both outcomes occur, so the sign check above saw
  // volumes just beyond the bound.
  EXPECT_GT(flat_signed, 1000);
  EXPECT_GT(flat_unsigned, 1000);
}

TEST(BooleanPhase, CertainVolumeRefusesNonFiniteAndUnderflow) {
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  EXPECT_EQ(certain_volume(x, y, z), 1.0);
  EXPECT_EQ(certain_volume(y, x, z), -1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(certain_volume(Vec3(nan, 0, 0), y, z), 0.0);
  EXPECT_EQ(certain_volume(Vec3(inf, 0, 0), y, z), 0.0);
  EXPECT_EQ(certain_volume(Vec3(1e200, 0, 0), Vec3(0, 1e200, 0), z), 0.0);
  // Products below the normal range carry absolute, not relative, rounding: not certain.
  EXPECT_EQ(certain_volume(Vec3(1e-110, 0, 0), Vec3(0, 1e-110, 0), Vec3(0, 0, 1e-110)), 0.0);
  EXPECT_EQ(certain_volume(Vec3(1e-90, 0, 0), Vec3(0, 1e-90, 0), Vec3(0, 0, 1e-90)), 1e-270);
}

/// The boolean test against brute force over the Minkowski difference of the points, placed in
/// the world in long double (far from the origin, double world coordinates would be off by more
/// than the thresholds below).
void expect_boolean_matches_brute_force(const std::vector<Vec3>& a_points, const Pose& pa,
                                        const std::vector<Vec3>& b_points, const Pose& pb) {
  const auto a = mink::Polytope::make(a_points);
  const auto b = mink::Polytope::make(b_points);
  ASSERT_TRUE(a && b);
  std::vector<oracle::V3> wa, wb;
  for (const Vec3& p : a_points)
    wa.push_back(oracle::widen(pa.rotation) * oracle::widen(p) + oracle::widen(pa.translation));
  for (const Vec3& p : b_points)
    wb.push_back(oracle::widen(pb.rotation) * oracle::widen(p) + oracle::widen(pb.translation));
  const double distance = double(oracle::polytope_pair(wa, wb).distance);
  const auto got = mink::intersect(*a, pa, *b, pb);
  ASSERT_NE(got.status, mink::Status::InvalidInput);
  // Touching counts as intersecting up to 1e-12 of the size (the sum of the bounding radii, about
  // 3 here). Closer than 1e-12 must intersect; farther than 1e-11 must not; between, either.
  if (distance > 1e-11) {
    EXPECT_FALSE(got.intersect) << "distance " << distance;
  }
  if (distance <= 1e-12) {
    EXPECT_TRUE(got.intersect) << "distance " << distance;
  }
}

// Flat pairs: both polytopes in one plane, so A - B is flat and every tetrahedron of the first
// phase is degenerate; the origin lies in that plane (overlapping or not) or just off it. Slivers:
// one polytope flat, the other a needle across its plane. Random in-plane rotations, far from
// the world origin too.
TEST(BooleanPhase, FlatAndSliverPairsMatchBruteForce) {
  const int n = oracle::sweep_count(600);
  int overlapping = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = 777000 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    std::vector<Vec3> a_points, b_points;
    const int na = rng.integer(3, 8), nb = rng.integer(1, 8);
    for (int k = 0; k < na; ++k)
      a_points.push_back(Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0));
    const bool sliver = i % 2 == 1;
    for (int k = 0; k < nb; ++k)
      b_points.push_back(
          sliver ? Vec3(1e-9 * rng.uniform(-1, 1), 1e-9 * rng.uniform(-1, 1), rng.uniform(-1, 1))
                 : Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0));
    const Vec3 offset = rng.chance(0.3) ? Vec3(1e6, -2e6, 5e5) : Vec3::Zero();
    const mink::Quat turn(Eigen::AngleAxisd(rng.uniform(0, 6.3), Vec3::UnitZ()));
    const mink::Quat tilt = rng.rotation();
    const Vec3 shift(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2),
                     rng.chance(0.5) ? 0.0 : rng.uniform(-1e-10, 1e-10));
    const Pose pa = Pose::from(offset, tilt);
    const Pose pb = Pose::from(offset + tilt * shift, tilt * turn);
    expect_boolean_matches_brute_force(a_points, pa, b_points, pb);
    overlapping +=
        mink::intersect(*mink::Polytope::make(a_points), pa, *mink::Polytope::make(b_points), pb)
            .intersect;
  }
  // Both answers occur often enough for the sweep to test both.
  EXPECT_GT(overlapping, n / 10);
  EXPECT_LT(overlapping, n * 9 / 10);
}

// Pairs placed as a stack is, with the contact on the line of centres: the first phase starts
// from the difference of the centres, and when the origin lies within touching range of its
// segment to the first support point it says "intersecting" at once. Depths and gaps from deep to
// within rounding of touching, either side of the 1e-12 touching tolerance, far from the world
// origin too; intersect() and distance() against brute force over the Minkowski difference.
TEST(BooleanPhase, ContactOnTheLineOfCentresMatchesBruteForce) {
  const int n = oracle::sweep_count(400, 150);
  int overlapping = 0, separated = 0, decided_at_once = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = 888000 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    // Points about their mean, so that the local origin is the centre (as core_centre() says).
    auto cloud = [&rng](int count) {
      std::vector<Vec3> points;
      for (int k = 0; k < count; ++k) points.push_back(rng.in_ball(1.0));
      Vec3 mean = Vec3::Zero();
      for (const Vec3& p : points) mean += p / double(count);
      for (Vec3& p : points) p -= mean;
      return points;
    };
    const std::vector<Vec3> a_points = cloud(rng.integer(4, 12)),
                            b_points = cloud(rng.integer(4, 12));
    const Vec3 offset = rng.chance(0.3) ? Vec3(1e6, -2e6, 5e5) : Vec3::Zero();
    const Pose pa = Pose::from(offset + rng.in_ball(2.0), rng.rotation());
    const mink::Quat turn_b = rng.rotation();
    // B's farthest point against -axis goes to a point of A's centre-to-support segment a
    // fraction `inset` in from A's support point along axis (negative: out beyond it).
    const Vec3 axis = rng.in_ball(1.0).normalized();
    auto world_support = [](const std::vector<Vec3>& points, const Pose& pose, const Vec3& d) {
      Vec3 best = pose.apply(points[0]);
      for (const Vec3& p : points)
        if (pose.apply(p).dot(d) > best.dot(d)) best = pose.apply(p);
      return best;
    };
    const Vec3 on_a = world_support(a_points, pa, axis);
    const double insets[] = {0.5, 0.1, 1e-4, 1e-9, 1e-12, 1e-13, 0, -1e-13, -1e-11, -1e-6, -0.1};
    const double inset = insets[i % std::size(insets)];
    const Vec3 shared = on_a + inset * (pa.translation - on_a);
    const Vec3 on_b_local = world_support(b_points, Pose::from(Vec3::Zero(), turn_b), -axis);
    const Pose pb = Pose::from(shared - (1 - inset) * on_b_local, turn_b);
    expect_boolean_matches_brute_force(a_points, pa, b_points, pb);
    const auto a = *mink::Polytope::make(a_points);
    const auto b = *mink::Polytope::make(b_points);
    const auto got = mink::intersect(a, pa, b, pb);
    EXPECT_EQ(got.intersect, mink::distance(a, pa, b, pb).intersect);
    (got.intersect ? overlapping : separated) += 1;
    decided_at_once += got.intersect && got.iterations == 1;
    // The run-time Shape runs the same first phase, from the same centres.
    const auto run_time =
        mink::intersect(*mink::Shape::polytope(a_points), pa, *mink::Shape::polytope(b_points), pb);
    EXPECT_EQ(run_time.intersect, got.intersect);
    EXPECT_EQ(run_time.iterations, got.iterations);
    // So do hull shapes (their centre is the mean of the hull's vertices, not of the points).
    const auto hull = mink::intersect(*mink::ConvexHullShape::make(a_points), pa,
                                      *mink::ConvexHullShape::make(b_points), pb);
    const auto run_time_hull = mink::intersect(*mink::Shape::convex_hull(a_points), pa,
                                               *mink::Shape::convex_hull(b_points), pb);
    EXPECT_EQ(run_time_hull.intersect, hull.intersect);
    EXPECT_EQ(run_time_hull.iterations, hull.iterations);
  }
  EXPECT_GT(overlapping, n / 4);
  EXPECT_GT(separated, n / 8);
  // The segment's test decides some of them from the first support point (the rest take the
  // tetrahedron's), so the sweep reaches it.
  EXPECT_GT(decided_at_once, n / 20);
}

// The yes/no test compares squares of squares (a bound's square times |v|'s square), which leave
// the range of doubles at sizes beyond about 2^+-250: a sphere of 3e-152 overlapping a polytope
// of 4e-149 (3e-145 from the origin) by 1e-5 of the gap was called apart once the product
// underflowed to 0 (found by review). Round polytopes (no face planes: GJK) far from their
// size from the origin, a sphere a gap from them, at scales 2^-480 to 2^320, against the
// brute-force distance in long double.
TEST(BooleanPhase, SquaresOfSquaresAtEveryScale) {
  int checked = 0;
  for (int i = 0; i < 40; ++i) {
    const std::uint64_t seed = 515000 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const Vec3 centre = 1e4 * rng.in_ball(1.0);
    std::vector<Vec3> unit_points;
    for (int k = 0; k < 18; ++k) unit_points.push_back(centre + rng.in_ball(1.0).normalized());
    const Vec3 sphere_centre =
        centre + (1 + rng.log_uniform(1e-4, 1e-2)) * rng.in_ball(1.0).normalized();
    const int e = -480 + 20 * i;
    const double scale = std::ldexp(1.0, e);
    // The brute force at unit scale (its tolerances are absolute), scaled: a power of two
    // scales the points, the sphere's centre and their distance exactly.
    std::vector<Vec3> points;
    std::vector<oracle::V3> seen_from_sphere;
    for (const Vec3& p : unit_points) {
      points.push_back(scale * p);
      seen_from_sphere.push_back(oracle::widen(p) - oracle::widen(sphere_centre));
    }
    const long double gap = std::ldexp(oracle::hull_distance(seen_from_sphere).distance, e);
    ASSERT_GT(gap, 0.0L);
    const mink::Polytope polytope = *mink::Polytope::make(points);
    for (const double factor : {1 - 1e-5, 1 + 1e-5}) {
      SCOPED_TRACE(testing::Message() << "scale 2^" << e << " factor " << factor);
      const mink::Sphere sphere{double(gap * factor)};
      const Pose pose_sphere = Pose::from_translation(scale * sphere_centre);
      const bool got = mink::intersect(sphere, pose_sphere, polytope, Pose::identity()).intersect;
      const bool by_distance =
          mink::distance(sphere, pose_sphere, polytope, Pose::identity()).intersect;
      // Beyond 2^+-240 the GJK distance sub-algorithm's own products (a tetrahedron's squared
      // volume, the sixth power of its size) leave the range too (docs/benchmarks.md, stop 30):
      // there the yes/no test must at least agree with distance().
      if (std::abs(e) <= 240) {
        EXPECT_EQ(got, factor > 1);
        EXPECT_EQ(by_distance, factor > 1);
      }
      EXPECT_EQ(got, by_distance);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 80);
}

}  // namespace
