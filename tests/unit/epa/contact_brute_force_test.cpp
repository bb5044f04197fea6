// contact() against brute-force facet enumeration of the Minkowski difference
// (tests/oracle/penetration.hpp): random penetrating pairs of small polytopes (4 to 8 points, or 3
// for a triangle; flat, needle, slab and duplicate-point sets among them) in random rotations,
// boxes against polytopes and boxes, and capsules and spheres (a segment or point core grown by
// the radius) against polytopes and boxes. Each case needs |depth - oracle| <= 1e-9 * size and an
// optimal normal, h_{A-B}(normal) = depth within 1e-9 * size.
//
// Default: 10,500 cases (6,000 polytope pairs, 1,500 box-polytope, 1,000 box-box, 1,000
// capsule-polytope, 500 capsule-box, 500 sphere-polytope); MINK_TEST_SWEEP_SCALE multiplies them.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/check.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt), where the
// names of this file's helpers (kinds, cases) would clash with other files' helpers.
namespace contact_brute_force_test {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

enum PointSetKind { kGeneric, kFlat, kDuplicates, kNeedle, kRound, kSlab, kPointSetKinds };

const char* kind_name(int kind) {
  static const char* const kNames[] = {"generic", "flat", "duplicates", "needle", "round", "slab"};
  return kNames[kind];
}

/// A random point set in its local frame, about `scale` across: 4 to 8 points (a flat set may be
/// a triangle), of the given kind.
std::vector<Vec3> random_point_set(Rng& rng, int kind, double scale) {
  const int count = rng.integer(kind == kFlat ? 3 : 4, 8);
  std::vector<Vec3> pts;
  const double jitter = rng.chance(0.2) ? 0.0 : rng.log_uniform(1e-9, 1e-3);
  for (int i = 0; i < count; ++i) {
    Vec3 p = rng.in_ball(scale);
    switch (kind) {
      case kFlat:
        p.z() = 0;
        break;
      case kDuplicates:
        if (i > 0 && rng.chance(0.5)) p = pts[rng.integer(0, i - 1)];
        break;
      case kNeedle:  // along x, with a jitter across it (sometimes none: collinear)
        p = Vec3(rng.uniform(-scale, scale), jitter * scale * rng.uniform(-1, 1),
                 jitter * scale * rng.uniform(-1, 1));
        break;
      case kRound:
        p = scale * rng.unit();
        break;
      case kSlab:
        p.z() *= 1e-3;
        break;
      default:
        break;
    }
    pts.push_back(p);
  }
  return pts;
}

double bounding_radius(const std::vector<Vec3>& pts) {
  double r = 0;
  for (const Vec3& p : pts) r = std::max(r, p.norm());
  return r;
}

std::vector<Vec3> box_corners_local(const Vec3& half) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(Vec3((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                           (i & 4) ? half.z() : -half.z()));
  return corners;
}

/// A random point of conv(pts): exponential weights, normalised.
Vec3 random_convex_combination(Rng& rng, const std::vector<Vec3>& pts) {
  Vec3 sum = Vec3::Zero();
  double total = 0;
  for (const Vec3& p : pts) {
    const double w = -std::log(rng.uniform(1e-12, 1));
    sum += w * p;
    total += w;
  }
  return sum / total;
}

/// B's pose, placed so that a random point of A (of conv(la)) and one of B (of conv(lb)) meet,
/// then shifted by up to `reach` in a random direction. Up to six tries, halving the shift, until
/// the oracle says the pair penetrates (`depth_of` gives its depth for a pose); the last try has
/// no shift, so the shapes share a point. Returns the last pose tried.
template <class DepthOf>
Pose place_penetrating(Rng& rng, const Pose& pa, const std::vector<Vec3>& la,
                       const std::vector<Vec3>& lb, double reach, const DepthOf& depth_of,
                       Real& depth) {
  const Vec3 common = pa.apply(random_convex_combination(rng, la));
  const Vec3 xb = random_convex_combination(rng, lb);
  Pose pb = Pose::from(Vec3::Zero(), rng.rotation());
  const Vec3 direction = rng.unit();
  double shift = reach * rng.uniform(0, 1);
  for (int attempt = 0; attempt < 6; ++attempt, shift *= 0.5) {
    if (attempt == 5) shift = 0;
    pb.translation = common - pb.rotation * xb + shift * direction;
    depth = depth_of(pb);
    if (depth > 0) break;
  }
  return pb;
}

/// One random penetrating polytope pair; case i of the sweep (every fourth through Shape).
/// `allow_limit`: IterationLimit is accepted, within its error_bound (see
/// NeedlesWithinTheToleranceOfTouching).
void polytope_pair_case(std::uint64_t seed, int i, oracle::DepthWorst& worst,
                        bool allow_limit = false) {
  SCOPED_TRACE(oracle::seed_note(seed));
  Rng rng(seed);
  const int ka = rng.integer(0, kPointSetKinds - 1);
  int kb = rng.integer(0, kPointSetKinds - 1);
  if (ka == kNeedle && kb == kNeedle) kb = kGeneric;  // two needles: A - B has no volume
  const double sa = rng.log_uniform(0.05, 2), sb = rng.log_uniform(0.05, 2);
  const auto la = random_point_set(rng, ka, sa), lb = random_point_set(rng, kb, sb);
  SCOPED_TRACE(testing::Message() << kind_name(ka) << " A (" << la.size() << " points), "
                                  << kind_name(kb) << " B (" << lb.size() << " points)");
  const double size = bounding_radius(la) + bounding_radius(lb);
  const Pose pa = rng.pose(5);
  const auto wa = oracle::world_points(la, pa);
  std::vector<V3> wb;
  Real depth = 0;
  const Pose pb = place_penetrating(
      rng, pa, la, lb, 0.5 * (sa + sb),
      [&](const Pose& p) {
        wb = oracle::world_points(lb, p);
        return oracle::polytope_penetration(wa, wb).depth;
      },
      depth);
  const auto a = mink::Polytope::make(la), b = mink::Polytope::make(lb);
  ASSERT_TRUE(a && b);
  mink::ContactResult got;
  if (i % 4 == 3) {  // the run-time Shape path
    got =
        mink::contact(mink::Shape::polytope(la).value(), pa, mink::Shape::polytope(lb).value(), pb);
  } else {
    got = mink::contact(a.value(), pa, b.value(), pb);
  }
  oracle::expect_contact_matches(depth, oracle::points_support(wa), oracle::points_support(wb), got,
                                 size, pa.translation.norm(), worst, oracle::kDepthTolerance,
                                 allow_limit, ka == kNeedle || kb == kNeedle);
}

/// A needle 1e-8 thick against a set with duplicate points, penetrating by 2.6e-9 of the size:
/// EPA's nearest face is a sliver (a vertex of A against three points of the needle) and the
/// origin's projection lies outside it by 5e-9 of the size. Clamped barycentric coordinates put
/// the witness points 1e-3 of the size apart from -depth * normal; the sliver's point nearest the
/// projection does not. Kept as its own test, as well as in the sweep, to name it.
TEST(ContactBruteForce, NeedleAgainstDuplicatesSliverFace) {
  oracle::DepthWorst worst("contact polytope-polytope (needle sliver)");
  polytope_pair_case(405913, 5913, worst);
}

/// A flat set of 4 points against a needle of 5, penetrating by 2e-3 of the size, from a sweep 40
/// times the default: A - B has a large flat facet nearest the origin, and EPA sampled it at points
/// that made new faces slivers across the needle's width. Their normals, off by rounding over the
/// sine of a 1e-8 angle, tilted one plane until the origin lay 1e-3 beyond it; P was no longer
/// convex, and EPA cycled through the same support points until the cap (IterationLimit after 455
/// support calls, with the right depth but an error bound of 5e-3). An expansion that makes such
/// a face now takes the neighbour into the region: 5 support calls, the depth exact.
TEST(ContactBruteForce, FlatAgainstNeedleSliverExpansion) {
  oracle::DepthWorst worst("contact polytope-polytope (flat against needle)");
  polytope_pair_case(606441, 206441, worst);
}

/// Needles 1e-8 thick (or thinner) against duplicate-point and round sets, from a sweep 30 times
/// the default: the pairs touch or penetrate by 2e-12 to 2.5e-10 of the size, GJK crawls along
/// the needle without enclosing the origin, and the answer is IterationLimit with a distance or
/// depth within its error_bound, which is within the 1e-9 bar. The support descent behind those
/// answers drifted from a unit normal by up to 2e-9 (its step direction, from a gradient 1e-9 of
/// the support point, is not orthogonal to the normal to rounding); the normal must be unit.
TEST(ContactBruteForce, NeedlesWithinTheToleranceOfTouching) {
  oracle::DepthWorst worst("contact polytope-polytope (needles touching)");
  for (const std::uint64_t seed : {429535, 455446, 562496, 418206, 576388})
    polytope_pair_case(seed, static_cast<int>(seed - 400000), worst, /*allow_limit=*/true);
}

TEST(ContactBruteForce, PolytopePairs) {
  const std::uint64_t base = 400000;
  const int n = oracle::sweep_count(6000, 2000);
  oracle::DepthWorst worst("contact polytope-polytope");
  for (int i = 0; i < n; ++i) {
    polytope_pair_case(base + i, i, worst);
  }
  EXPECT_GT(worst.penetrating, n * 8 / 10) << "the sweep should be mostly penetrating";
}

TEST(ContactBruteForce, BoxPolytope) {
  const std::uint64_t base = 410000;
  const int n = oracle::sweep_count(1500);
  oracle::DepthWorst worst("contact box-polytope");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box box{
        Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2))};
    const int kb = rng.integer(0, kPointSetKinds - 1);
    const double sb = rng.log_uniform(0.05, 2);
    const auto lb = random_point_set(rng, kb, sb);
    SCOPED_TRACE(testing::Message() << kind_name(kb) << " B (" << lb.size() << " points)");
    const double size = box.half_extents.norm() + bounding_radius(lb);
    const Pose pa = rng.pose(5);
    const auto wa = oracle::world_points(box_corners_local(box.half_extents), pa);
    std::vector<V3> wb;
    Real depth = 0;
    const Pose pb = place_penetrating(
        rng, pa, box_corners_local(box.half_extents), lb, 0.5 * (box.half_extents.norm() + sb),
        [&](const Pose& p) {
          wb = oracle::world_points(lb, p);
          return oracle::polytope_penetration(wa, wb).depth;
        },
        depth);
    const auto b = mink::Polytope::make(lb);
    ASSERT_TRUE(b);
    const auto got = mink::contact(box, pa, b.value(), pb);
    oracle::expect_contact_matches(depth, oracle::points_support(wa), oracle::points_support(wb),
                                   got, size, pa.translation.norm(), worst);
  }
  EXPECT_GT(worst.penetrating, n * 8 / 10);
}

TEST(ContactBruteForce, BoxBox) {
  // The Minkowski difference of the corners (64 points) and the separating axes must agree, and
  // mink with both.
  const std::uint64_t base = 420000;
  const int n = oracle::sweep_count(1000);
  oracle::DepthWorst worst("contact box-box (corners)");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box a{
        Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2))};
    const mink::Box b{
        Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2))};
    const double size = a.half_extents.norm() + b.half_extents.norm();
    const Pose pa = rng.pose(5);
    const auto wa = oracle::world_points(box_corners_local(a.half_extents), pa);
    std::vector<V3> wb;
    Real depth = 0;
    const Pose pb = place_penetrating(
        rng, pa, box_corners_local(a.half_extents), box_corners_local(b.half_extents), 0.7 * size,
        [&](const Pose& p) {
          wb = oracle::world_points(box_corners_local(b.half_extents), p);
          return oracle::polytope_penetration(wa, wb).depth;
        },
        depth);
    const oracle::WorldBox ba{widen(a.half_extents), widen(pa.rotation), widen(pa.translation)};
    const oracle::WorldBox bb{widen(b.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto sat = oracle::box_box_penetration(ba, bb);
    if (depth > 0) {
      ASSERT_NEAR(double(sat.depth), double(depth), 1e-12 * size) << "oracles disagree";
    }
    const auto got = mink::contact(a, pa, b, pb);
    oracle::expect_contact_matches(depth, oracle::points_support(wa), oracle::points_support(wb),
                                   got, size, pa.translation.norm(), worst);
  }
  EXPECT_GT(worst.penetrating, n * 8 / 10);
}

/// A capsule (radius r, core segment along local z) or, with half_height 0, a sphere, against the
/// polytope `lb` (local points) or a box: depth r + least support of core - B.
template <class RoundShape>
void round_against_points(const char* name, std::uint64_t base, int default_count, bool sphere,
                          bool box) {
  const int n = oracle::sweep_count(default_count);
  oracle::DepthWorst worst(name);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double radius = rng.log_uniform(0.01, 1);
    const double half_height = sphere ? 0.0 : rng.log_uniform(0.001, 2);
    std::vector<Vec3> lb;
    Vec3 half = Vec3::Zero();
    int kb = kGeneric;
    if (box) {
      half = Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2));
      lb = box_corners_local(half);
    } else {
      kb = rng.integer(0, kPointSetKinds - 1);
      lb = random_point_set(rng, kb, rng.log_uniform(0.05, 2));
    }
    SCOPED_TRACE(testing::Message()
                 << (box ? "box" : kind_name(kb)) << " B (" << lb.size() << " points)");
    const double size = radius + half_height + bounding_radius(lb);
    const Pose pa = rng.pose(5);
    const std::vector<Vec3> core_local =
        sphere ? std::vector<Vec3>{Vec3::Zero()}
               : std::vector<Vec3>{Vec3(0, 0, -half_height), Vec3(0, 0, half_height)};
    const auto core = oracle::world_points(core_local, pa);
    std::vector<V3> wb;
    Real depth = 0;
    const Pose pb = place_penetrating(
        rng, pa, core_local, lb, 0.5 * size,
        [&](const Pose& p) {
          wb = oracle::world_points(lb, p);
          return radius + oracle::least_support_of_difference(core, wb);
        },
        depth);
    mink::ContactResult got;
    const RoundShape a = [&] {
      if constexpr (std::is_same_v<RoundShape, mink::Sphere>)
        return mink::Sphere{radius};
      else
        return mink::Capsule{radius, half_height};
    }();
    if (box) {
      got = mink::contact(a, pa, mink::Box{half}, pb);
    } else {
      got = mink::contact(a, pa, mink::Polytope::make(lb).value(), pb);
    }
    oracle::expect_contact_matches(depth, oracle::points_support(core, radius),
                                   oracle::points_support(wb), got, size, pa.translation.norm(),
                                   worst, oracle::kDepthTolerance, false, kb == kNeedle);
  }
  EXPECT_GT(worst.penetrating, n * 8 / 10);
}

TEST(ContactBruteForce, CapsulePolytope) {
  round_against_points<mink::Capsule>("contact capsule-polytope", 430000, 1000, false, false);
}

TEST(ContactBruteForce, CapsuleBox) {
  round_against_points<mink::Capsule>("contact capsule-box", 440000, 500, false, true);
}

TEST(ContactBruteForce, SpherePolytope) {
  round_against_points<mink::Sphere>("contact sphere-polytope", 450000, 500, true, false);
}

/// One part of a Minkowski sum: a point set of any kind as a polytope, a box, a segment or a
/// triangle, with its points (the box's corners) in `pts`; `small`: a segment or a triangle only
/// (the oracle's cost grows as the cube of the sum's points).
mink::Shape random_sum_part(Rng& rng, std::vector<Vec3>& pts, bool& needle, bool small) {
  const double scale = rng.log_uniform(0.02, 2);
  switch (small ? rng.integer(2, 3) : rng.integer(0, 3)) {
    case 0: {
      const int kind = rng.integer(0, kPointSetKinds - 1);
      needle |= kind == kNeedle;
      pts = random_point_set(rng, kind, scale);
      return mink::Shape::polytope(pts).value();
    }
    case 1: {
      const Vec3 half(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2));
      pts = box_corners_local(half);
      return mink::Shape::box(half).value();
    }
    case 2:
      pts = {rng.in_ball(scale), rng.in_ball(scale)};
      return mink::Shape::segment(pts[0], pts[1]).value();
    default:
      pts = {rng.in_ball(scale), rng.in_ball(scale), rng.in_ball(scale)};
      return mink::Shape::triangle(pts[0], pts[1], pts[2]).value();
  }
}

/// A random sum of two parts (random_sum_part()), sometimes rounded, as A at `pa`, and a random
/// polytope, sometimes rounded, as B; with the sum's points p + q (local), both shapes' world
/// points in long double (where p + q is exact, or within 1e-19 of the size), and their size.
struct SumPairCase {
  mink::Shape a, b;
  double ra = 0, rb = 0;
  bool needle = false;
  std::vector<Vec3> la, lb;
  std::vector<V3> wa;
  Pose pa;
  double size = 0;

  explicit SumPairCase(Rng& rng) {
    std::vector<Vec3> p, q;
    const mink::Shape first = random_sum_part(rng, p, needle, false);
    const mink::Shape second = random_sum_part(rng, q, needle, !rng.chance(0.1));
    ra = rng.chance(0.3) ? rng.log_uniform(1e-3, 0.3) : 0.0;
    rb = rng.chance(0.3) ? rng.log_uniform(1e-3, 0.3) : 0.0;
    const mink::Shape sum = mink::Shape::sum(first, second).value();
    a = ra > 0 ? mink::Shape::rounded(sum, ra).value() : sum;
    const int kb = rng.integer(0, kPointSetKinds - 1);
    needle |= kb == kNeedle;
    lb = random_point_set(rng, kb, rng.log_uniform(0.05, 2));
    const mink::Shape polytope = mink::Shape::polytope(lb).value();
    b = rb > 0 ? mink::Shape::rounded(polytope, rb).value() : polytope;
    pa = rng.pose(5);
    for (const Vec3& x : p)
      for (const Vec3& y : q) {
        la.push_back(x + y);
        wa.push_back(widen(pa.rotation) * (widen(x) + widen(y)) + widen(pa.translation));
      }
    size = bounding_radius(p) + bounding_radius(q) + ra + bounding_radius(lb) + rb;
  }

  /// The least support value of A - B with B at pb (its depth, or minus its distance).
  Real least_support(const Pose& pb, std::vector<V3>& wb) const {
    wb = oracle::world_points(lb, pb);
    return ra + rb + oracle::least_support_of_difference(wa, wb);
  }
};

/// Sums (Shape::sum) of two parts, sometimes rounded, against polytopes, sometimes rounded: the
/// sum of point sets P and Q is the hull of the points p + q, so the depth is the brute force's
/// over those points plus the radii. contact() runs GJK and EPA on the sum's support, the sum of
/// its parts' supports.
TEST(ContactBruteForce, SumsAgainstPolytopes) {
  const std::uint64_t base = 460000;
  const int n = oracle::sweep_count(400, 80);
  oracle::DepthWorst worst("contact sum-polytope");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const SumPairCase c(rng);
    std::vector<V3> wb;
    Real depth = 0;
    const Pose pb = place_penetrating(
        rng, c.pa, c.la, c.lb, 0.5 * c.size,
        [&](const Pose& pose) { return c.least_support(pose, wb); }, depth);
    const auto got = mink::contact(c.a, c.pa, c.b, pb);
    oracle::expect_contact_matches(
        depth, oracle::points_support(c.wa, c.ra), oracle::points_support(wb, c.rb), got, c.size,
        c.pa.translation.norm(), worst, oracle::kDepthTolerance, false, c.needle);
  }
  EXPECT_GT(worst.penetrating, n * 8 / 10);
}

/// The same sums placed anywhere from deep inside to a size apart: distance(), contact() and
/// intersect() against the brute force's distance (the least support value, negated), the
/// normal by its support value, and the points by their gap.
TEST(ContactBruteForce, SumsApartFromPolytopes) {
  const std::uint64_t base = 470000;
  const int n = oracle::sweep_count(200, 40);
  int separated = 0;
  double worst_distance = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const SumPairCase c(rng);
    const Pose pb = Pose::from(c.pa.translation + rng.unit() * (c.size * rng.uniform(0.3, 1.3)),
                               rng.rotation());
    std::vector<V3> wb;
    const double expected = -static_cast<double>(c.least_support(pb, wb));  // the distance
    const auto got = mink::distance(c.a, c.pa, c.b, pb);
    const auto got_contact = mink::contact(c.a, c.pa, c.b, pb);
    const auto got_bool = mink::intersect(c.a, c.pa, c.b, pb);
    const double band = oracle::kTouchingBand * c.size;
    if (std::abs(expected) <= band) continue;  // touching: either answer
    EXPECT_EQ(got_bool.intersect, expected < 0) << "oracle distance " << expected;
    EXPECT_EQ(got_contact.intersect, expected < 0) << "oracle distance " << expected;
    if (expected < 0) {
      EXPECT_EQ(got.status, mink::Status::Intersecting);
      continue;
    }
    ++separated;
    ASSERT_EQ(got.status, mink::Status::Separated) << "oracle distance " << expected;
    const double error =
        std::max(std::abs(got.distance - expected), std::abs(got_contact.distance - expected)) /
        c.size;
    worst_distance = std::max(worst_distance, error);
    EXPECT_LE(error, oracle::kDistanceTolerance) << "distance " << got.distance << ", contact "
                                                 << got_contact.distance << ", oracle " << expected;
    // The normal proves the distance: A - B lies below -distance along it.
    const Real along = oracle::support_of_difference(c.wa, wb, widen(got.normal)) + c.ra + c.rb;
    EXPECT_LE(std::abs(static_cast<double>(along) + expected) / c.size, 1e-9)
        << "the normal's support value " << static_cast<double>(along);
    EXPECT_LE((got.point_b - got.point_a - got.distance * got.normal).norm() /
                  (c.size + c.pa.translation.norm()),
              1e-10)
        << "point_b - point_a != distance * normal";
  }
  std::printf("[  worst   ] distance sum-polytope: %.3g (relative); %d of %d separated\n",
              worst_distance, separated, n);
  EXPECT_GT(separated, n / 4);
}

}  // namespace contact_brute_force_test
