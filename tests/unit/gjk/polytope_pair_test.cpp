// intersect() of two small polytopes with face planes (query/polytope_pair.hpp): a point of the
// first support call that lies inside the other polytope proves the overlap. Checked against brute
// force over the Minkowski difference of the points, and against the same polytopes without
// planes (GJK alone), from deep overlaps to gaps within rounding of touching, far from the world
// origin too.
#include <gtest/gtest.h>

#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;

std::vector<Vec3> random_points(oracle::Rng& rng, int n) {
  // On an ellipsoid (every point a vertex) or in a box (some inside), about the origin.
  const Vec3 axes(rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1));
  const bool on_surface = rng.chance(0.5);
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    if (on_surface) {
      points.push_back(axes.cwiseProduct(rng.unit()));
    } else {
      points.push_back(
          Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)).cwiseProduct(axes));
    }
  }
  return points;
}

TEST(PolytopePair, CommonPointAgreesWithBruteForceAndWithGjk) {
  const int n = oracle::sweep_count(1500, 300);
  int overlapping = 0, separated = 0, proven_by_a_point = 0, planes_missing = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = 515000 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const std::vector<Vec3> a_points = random_points(rng, rng.integer(4, 10));
    const std::vector<Vec3> b_points = random_points(rng, rng.integer(4, 10));
    const auto a = mink::Polytope::make(a_points);
    const auto b = mink::Polytope::make(b_points);
    const auto a_plain = mink::Polytope::make(a_points);
    const auto b_plain = mink::Polytope::make(b_points);
    ASSERT_TRUE(a && b && a_plain && b_plain);
    planes_missing += !a->build_face_planes() || !b->build_face_planes();

    // B's point farthest along -u placed at A's point farthest along u, then moved by `gap` along
    // u: touching at that point for gap 0, apart by gap above it, overlapping below it.
    const Vec3 offset = rng.chance(0.25) ? Vec3(-3e5, 1e6, 2e6) : Vec3::Zero();
    const Pose pa = Pose::from(offset, rng.rotation());
    Pose pb = Pose::from(Vec3::Zero(), rng.rotation());
    const Vec3 u = rng.unit();
    const double size = a->bounding_radius() + b->bounding_radius();
    const double gaps[] = {-0.3, -0.1, -1e-3, -1e-6, -1e-9, -1e-11, 0, 1e-11, 1e-9, 1e-6, 1e-3};
    const double gap = gaps[i % 11] * size;
    const oracle::V3 on_a =
        oracle::support_point_of(oracle::world_points(a_points, pa), oracle::widen(u));
    const oracle::V3 on_b =
        oracle::support_point_of(oracle::world_points(b_points, pb), oracle::widen(Vec3(-u)));
    pb.translation = (on_a - on_b + oracle::widen(u) * oracle::Real(gap)).cast<double>();

    const double distance = double(oracle::polytope_pair(oracle::world_points(a_points, pa),
                                                         oracle::world_points(b_points, pb))
                                       .distance);
    const auto got = mink::intersect(*a, pa, *b, pb);
    const auto plain = mink::intersect(*a_plain, pa, *b_plain, pb);
    ASSERT_EQ(got.status == mink::Status::Intersecting || got.status == mink::Status::Separated,
              true)
        << "status " << int(got.status);
    // Touching counts as intersecting up to 1e-12 of the size: closer than that must intersect,
    // farther than 1e-11 of it must not; between, either (as for every boolean test).
    if (distance > 1e-11 * size) {
      EXPECT_FALSE(got.intersect) << "distance " << distance;
    }
    if (distance <= 1e-12 * size) {
      EXPECT_TRUE(got.intersect) << "distance " << distance;
    }
    if (distance > 1e-11 * size || distance == 0) {
      EXPECT_EQ(got.intersect, plain.intersect) << "distance " << distance;
    }
    overlapping += distance == 0;
    separated += distance > 1e-11 * size;
    proven_by_a_point += got.intersect && got.iterations == 1;
  }
  EXPECT_EQ(planes_missing, 0);
  EXPECT_GT(overlapping, n / 3);
  EXPECT_GT(separated, n / 4);
  // The path is taken: a common point after one support call for a good share of overlaps.
  EXPECT_GT(proven_by_a_point, overlapping / 4);
}

std::vector<Vec3> cube_corners(double half) {
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k)
    corners.push_back(half * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
  return corners;
}

// A small cube inside a large one's face: B's corner farthest towards A is inside A. Without face
// planes (a new polytope, before kPolytopePlanesAfterQueries queries) GJK decides; with them the
// corner does, after one support call, and the cache keeps its direction; a warm cache then
// starts GJK from it.
TEST(PolytopePair, TheFirstSupportPointDecidesOnlyWithPlanes) {
  const auto a = mink::Polytope::make(cube_corners(1));
  const auto b = mink::Polytope::make(cube_corners(0.2));
  ASSERT_TRUE(a && b);
  const Pose pa = Pose::identity();
  const Pose pb = Pose::from(Vec3(1.1, 0.3, 0), mink::Quat::Identity());
  const auto fresh = mink::intersect(*a, pa, *b, pb);
  EXPECT_TRUE(fresh.intersect);
  EXPECT_GT(fresh.iterations, 1);
  ASSERT_TRUE(a->build_face_planes() && b->build_face_planes());
  mink::GjkCache cache;
  const auto with_planes = mink::intersect(*a, pa, *b, pb, {}, &cache);
  EXPECT_TRUE(with_planes.intersect);
  EXPECT_EQ(with_planes.iterations, 1);
  ASSERT_EQ(cache.size, 1);
  EXPECT_EQ(cache.directions[0], Vec3(1.1, 0.3, 0));
  const auto warm = mink::intersect(*a, pa, *b, pb, {}, &cache);
  EXPECT_TRUE(warm.intersect);
  // Moved out beyond A's face: the first support plane separates them.
  const Pose apart = Pose::from(Vec3(1.5, 0, 0), mink::Quat::Identity());
  const auto separated = mink::intersect(*a, pa, *b, apart);
  EXPECT_FALSE(separated.intersect);
  EXPECT_EQ(separated.iterations, 1);
}

// A rotation orthonormal only to the 1e-6 that pose_error() allows (a scaling by 1 - 2.5e-7):
// A's corner taken to B's frame by the transpose lands 2.5e-8 inside B, while B as GJK sees it
// (its points mapped by the rotation itself) is 7.5e-8 beyond A's face. No common point may be
// claimed from the transpose within its error.
TEST(PolytopePair, ARotationOffByItsToleranceClaimsNoCommonPoint) {
  const auto a = mink::Polytope::make(cube_corners(1));
  const auto b = mink::Polytope::make(cube_corners(0.2));
  ASSERT_TRUE(a && b && a->build_face_planes() && b->build_face_planes());
  const double s = 1 - 2.5e-7;
  Pose pb;
  pb.rotation = s * mink::Mat3::Identity();
  pb.translation = Vec3(1.2 + 2.5e-8, 0.9, 0.9);
  ASSERT_EQ(mink::pose_error(pb), nullptr);
  const auto got = mink::intersect(*a, Pose::identity(), *b, pb);
  EXPECT_EQ(got.status, mink::Status::Separated);
  EXPECT_FALSE(got.intersect);
  const auto d = mink::distance(*a, Pose::identity(), *b, pb);
  EXPECT_NEAR(d.distance, 7.5e-8, 1e-12);
}

// B's first support value is taken along the world's direction, -R_B^T (t_B - t_A), which is
// -R^T d only to R_A's error. A's rotation here is a scaling by 1 + 2.5e-7 (within pose_error()'s
// 1e-6): as GJK sees the pair (B mapped by R_A^T R_B), B's face is 5e-8 inside A's, but the world's
// direction puts the support values 5e-8 apart. The values may not claim the gap: they must
// clear it by their slack, and B's corner inside A proves the overlap.
TEST(PolytopePair, TheValuesClaimNoGapWithinTheirSlack) {
  const auto a = mink::Polytope::make(cube_corners(1));
  const auto b = mink::Polytope::make(cube_corners(0.2));
  ASSERT_TRUE(a && b && a->build_face_planes() && b->build_face_planes());
  const double s = 1 + 2.5e-7;
  Pose pa;
  pa.rotation = s * mink::Mat3::Identity();
  ASSERT_EQ(mink::pose_error(pa), nullptr);
  const Pose pb = Pose::from(Vec3(0.2 + (1 - 5e-8) / s, 0, 0), mink::Quat::Identity());
  const auto got = mink::intersect(*a, pa, *b, pb);
  EXPECT_EQ(got.status, mink::Status::Intersecting);
  EXPECT_TRUE(got.intersect);
  const auto d = mink::distance(*a, pa, *b, pb);
  EXPECT_TRUE(d.intersect);
}

// Apart by 1e-7, less than the values' slack (4e-6 of B's bounding radius) but more than the
// touching tolerance: the support points decide, B's taken again along -R^T d itself.
TEST(PolytopePair, APairApartWithinTheSlackIsToldByItsPoints) {
  const auto a = mink::Polytope::make(cube_corners(1));
  const auto b = mink::Polytope::make(cube_corners(0.2));
  ASSERT_TRUE(a && b && a->build_face_planes() && b->build_face_planes());
  const Pose pb = Pose::from(Vec3(1.2 + 1e-7, 0, 0), mink::Quat::Identity());
  const auto got = mink::intersect(*a, Pose::identity(), *b, pb);
  EXPECT_EQ(got.status, mink::Status::Separated);
  EXPECT_EQ(got.iterations, 1);
  const auto d = mink::distance(*a, Pose::identity(), *b, pb);
  EXPECT_NEAR(d.distance, 1e-7, 1e-15);
}

// Origins in the same place: the first direction is A's +x, and B's is that axis turned by both
// rotations. Each polytope lies off its origin: A below x = -2 in its frame, B above x = 1, so
// +x separates them by 3; a copy of A in A's place overlaps it along that axis.
TEST(PolytopePair, CoincidentOriginsTakeAsXAxis) {
  std::vector<Vec3> below, above;
  for (const Vec3& c : cube_corners(0.5)) {
    below.push_back(c + Vec3(-2.5, 0, 0));
    above.push_back(c + Vec3(1.5, 0, 0));
  }
  const auto a = mink::Polytope::make(below);
  const auto b = mink::Polytope::make(above);
  const auto a_copy = mink::Polytope::make(below);
  ASSERT_TRUE(a && b && a_copy);
  ASSERT_TRUE(a->build_face_planes() && b->build_face_planes() && a_copy->build_face_planes());
  oracle::Rng rng(9917);
  for (int i = 0; i < 50; ++i) {
    const Vec3 origin(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10));
    const Pose pa = Pose::from(origin, rng.rotation());
    const auto apart = mink::intersect(*a, pa, *b, pa);
    EXPECT_EQ(apart.status, mink::Status::Separated);
    EXPECT_EQ(apart.iterations, 1);
    EXPECT_NEAR(mink::distance(*a, pa, *b, pa).distance, 3, 1e-12);
    EXPECT_TRUE(mink::intersect(*a, pa, *a_copy, pa).intersect);
  }
}

}  // namespace
