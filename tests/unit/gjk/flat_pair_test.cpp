// Nearly parallel flat features: a cylinder's cap, a cone's base or a polytope prism's face
// tilted by 1e-10 to 1e-3 rad on a box's face, a polytope's or a cylinder's cap, and a capsule
// across a cap, apart or overlapping. The witness points are unique (the tilt picks one rim
// point, one corner, or one point of the smaller disc's rim) and known in closed form: the
// scenes are built about the ground shape's top face (normal +z), the tilted shape turned about
// a horizontal axis k, so its lower rim is lowest along k x z, with no cancellation at any tilt.
// Both shapes are then moved by one rigid motion (see make_scene() for why only a translation
// below 1e-6 rad).
//
// Before gjk/flat_pair.hpp, every point of the overlap was within the features' tolerance of
// the depth, and GJK's or EPA's point was any of them: a cylinder on a box tilted 2.2e-9 rad had
// its point 0.05 of its radius off (stop 62's curved probe: up to 0.12 of the size), a prism on
// a box 0.7.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Shape;
using mink::Vec3;

enum class FlatKind {
  CapOnBox,         // a cylinder standing on a box face
  BaseOnCap,        // a cone's base on a wider cylinder's cap
  WideBaseOverCap,  // a wide cone's base tilted over a narrow cylinder's cap: A's rim decides
  CapsuleOverCap,   // a capsule lying across a cylinder's cap (its segment against the disc)
  PrismOnFace,      // a polytope prism on a box or a polytope box: its lowest corner
};

struct FlatScene {
  Shape a, b;
  Pose pose_a, pose_b;
  Vec3 normal, point_a, point_b;  // world frame, the exact answer
  double depth = 0;               // > 0 overlapping, < 0 apart by -depth
  double size = 0;
  std::string note;
};

FlatScene make_scene(std::uint64_t seed, FlatKind kind, bool overlapping) {
  oracle::Rng rng(seed);
  FlatScene s;
  const double tilt = rng.log_uniform(1e-10, 1e-3);
  const double angle = rng.uniform(0, 2 * std::numbers::pi);
  // Turned about the horizontal k by the tilt, the shape's axis leans along lean = k x z, and
  // its lower disc is lowest at its rim point along R lean = cos(tilt) lean - sin(tilt) z.
  const Vec3 k(std::cos(angle), std::sin(angle), 0);
  const Vec3 lean = k.cross(Vec3::UnitZ());
  const mink::Mat3 rotation = Eigen::AngleAxisd(tilt, k).toRotationMatrix();
  const Vec3 axis = rotation * Vec3::UnitZ();
  const double gap_or_depth = rng.uniform(1e-3, 0.05);
  const double depth = overlapping ? gap_or_depth : -gap_or_depth;
  s.depth = depth;
  Pose ground = Pose::identity(), tilted;
  tilted.rotation = rotation;
  if (kind == FlatKind::CapOnBox || kind == FlatKind::BaseOnCap) {
    // A's top face at z = top, wide enough that B's lowest rim point lies over it.
    const double top = rng.uniform(0.3, 1.0), r = rng.uniform(0.2, 0.8);
    const double half_height = rng.uniform(0.2, 1.0);
    const double reach = r + rng.uniform(0.3, 1.0);
    if (kind == FlatKind::CapOnBox) {
      s.a = Shape::box(Vec3(reach + 0.2, reach + 0.3, top)).value();
      s.b = Shape::cylinder(r, half_height).value();
    } else {
      s.a = Shape::cylinder(std::hypot(reach, reach) + 0.2, top).value();
      s.b = Shape::cone(r, half_height).value();
    }
    // The base's lowest rim point at (offset, top - depth).
    const Vec3 offset(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), top - depth);
    tilted.translation = offset - rotation * Vec3(r * lean - half_height * Vec3::UnitZ());
    s.point_b = offset;
    s.point_a = Vec3(offset.x(), offset.y(), top);
    s.normal = Vec3::UnitZ();
  } else if (kind == FlatKind::WideBaseOverCap) {
    // A's narrow cap (radius ra at z = top) under B's wide tilted base: the base is lowest over
    // A's rim point along the lean, and the normal is B's axis.
    const double top = rng.uniform(0.3, 1.0), ra = rng.uniform(0.2, 0.5);
    const double rb = ra + rng.uniform(1.0, 2.0), half_height = rng.uniform(0.2, 1.0);
    s.a = Shape::cylinder(ra, top).value();
    s.b = Shape::cone(rb, half_height).value();
    s.point_a = Vec3(0, 0, top) + ra * lean;
    // B's base plane passes depth below point_a along the axis.
    const Vec3 shift(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), 0);
    const Vec3 base_centre = s.point_a - depth * axis + (shift - shift.dot(axis) * axis);
    tilted.translation = base_centre + half_height * axis;
    s.point_b = s.point_a - depth * axis;
    s.normal = axis;
  } else if (kind == FlatKind::PrismOnFace) {
    // A prism of 2 x m corners (m = 5..12) on a box's top face (or a polytope's): its corner
    // lowest after the turn is the deepest (or closest), unique at any tilt.
    const double top = rng.uniform(0.3, 1.0), r = rng.uniform(0.2, 0.8);
    const double half_height = rng.uniform(0.1, 0.6), phase = rng.uniform(0, 1);
    const int m = rng.integer(5, 12);
    std::vector<Vec3> corners;
    for (int i = 0; i < m; ++i)
      for (const double z : {-half_height, half_height}) {
        const double t = 2 * std::numbers::pi * (i + phase) / m;
        corners.emplace_back(r * std::cos(t), r * std::sin(t), z);
      }
    s.b = Shape::polytope(corners).value();
    const Vec3 half(r + 1.0, r + 1.1, top);
    if (rng.chance(0.5)) {
      s.a = Shape::box(half).value();
    } else {
      std::vector<Vec3> box;
      for (int i = 0; i < 8; ++i)
        box.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                         i & 4 ? half.z() : -half.z());
      s.a = Shape::polytope(box).value();
    }
    Vec3 lowest = rotation * corners[0];
    for (const Vec3& c : corners)
      if ((rotation * c).z() < lowest.z()) lowest = rotation * c;
    const Vec3 offset(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), top - depth);
    tilted.translation = offset - lowest;
    s.point_b = offset;
    s.point_a = Vec3(offset.x(), offset.y(), top);
    s.normal = Vec3::UnitZ();
  } else {
    // A capsule's segment (radius rc) lying across A's cap at height `top`, turned by the tilt
    // about a horizontal axis after being laid along x: its lower end is the closest.
    const double top = rng.uniform(0.3, 1.0), ra = rng.uniform(1.0, 1.5);
    const double rc = rng.uniform(0.1, 0.3), half_length = rng.uniform(0.2, 0.6);
    s.a = Shape::cylinder(ra, top).value();
    s.b = Shape::capsule(rc, half_length).value();
    const mink::Mat3 lay =
        Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitY()).toRotationMatrix();
    const Eigen::AngleAxisd tip(tilt, Vec3::UnitY());
    tilted.rotation = tip.toRotationMatrix() * lay;
    const Vec3 along = tilted.rotation * Vec3::UnitZ();  // the segment's direction, nearly x
    const Vec3 offset(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), 0);
    // The lower end: the one whose end lies lower along z (exact: along = (cos, 0, -+sin)).
    const double sign = along.z() < 0 ? 1 : -1;
    const Vec3 low_end = Vec3(offset.x(), offset.y(), top + rc - depth);
    tilted.translation = low_end - sign * half_length * along;
    s.point_b = low_end - rc * Vec3::UnitZ();
    s.point_a = Vec3(low_end.x(), low_end.y(), top);
    s.normal = Vec3::UnitZ();
  }
  // One rigid motion for both; a translation only below 1e-6 rad. Turned, the shapes' relative
  // rotation is rounded, 1e-16 off in each entry, and the rim's lowest point moves by the radius
  // times 1e-16 over the tilt for that alone (2e-7 at 1e-10 rad): the pose given is then not
  // the scene's, and neither is its exact answer.
  const Vec3 shift = rng.in_ball(rng.chance(0.2) ? 1e3 : 3);
  const Pose motion =
      tilt >= 1e-6 ? Pose::from(shift, rng.rotation()) : Pose::from_translation(shift);
  s.pose_a = Pose{motion.rotation * ground.rotation, motion.apply(ground.translation)};
  s.pose_b = Pose{motion.rotation * tilted.rotation, motion.apply(tilted.translation)};
  s.point_a = motion.apply(s.point_a);
  s.point_b = motion.apply(s.point_b);
  s.normal = motion.rotate(s.normal);
  s.size = s.a.bounding_radius() + s.b.bounding_radius();
  char note[96];
  std::snprintf(note, sizeof note, "seed %llu tilt %.2e %s %.3g",
                static_cast<unsigned long long>(seed), tilt, overlapping ? "overlapping" : "apart",
                gap_or_depth);
  s.note = note;
  return s;
}

// The answer's points and normal against the scene's, to 1e-9 of the size (and rad).
void expect_answer(const FlatScene& s, const Vec3& normal, const Vec3& point_a, const Vec3& point_b,
                   double signed_depth, const std::string& what) {
  const double bar = 1e-9 * s.size;
  EXPECT_NEAR(signed_depth, s.depth, bar) << what << ": " << s.note;
  EXPECT_LE((normal - s.normal).norm(), 1e-9) << what << ": " << s.note;
  EXPECT_LE((point_a - s.point_a).norm(), bar) << what << ": " << s.note;
  EXPECT_LE((point_b - s.point_b).norm(), bar) << what << ": " << s.note;
}

void check_kind(FlatKind kind, std::uint64_t first_seed) {
  const int cases = oracle::sweep_count(200, 40);
  for (int i = 0; i < cases; ++i) {
    const bool overlapping = i % 2 == 0;
    const FlatScene s = make_scene(first_seed + i, kind, overlapping);
    const auto ab = mink::contact(s.a, s.pose_a, s.b, s.pose_b);
    ASSERT_TRUE(ab.status == mink::Status::Intersecting || ab.status == mink::Status::Separated)
        << s.note;
    expect_answer(s, ab.normal, ab.point_a, ab.point_b, ab.intersect ? ab.depth : -ab.distance,
                  "contact(a, b)");
    // Swapped: the normal flips, the points swap.
    const auto ba = mink::contact(s.b, s.pose_b, s.a, s.pose_a);
    expect_answer(s, -ba.normal, ba.point_b, ba.point_a, ba.intersect ? ba.depth : -ba.distance,
                  "contact(b, a)");
    if (!overlapping) {
      const auto d = mink::distance(s.a, s.pose_a, s.b, s.pose_b);
      expect_answer(s, d.normal, d.point_a, d.point_b, -d.distance, "distance(a, b)");
    }
    if (::testing::Test::HasFailure()) break;  // one scene's messages, not hundreds
  }
}

TEST(FlatPair, CylinderCapTiltedOnBoxFaceHasItsLowestRimPoint) {
  check_kind(FlatKind::CapOnBox, 910000);
}

TEST(FlatPair, ConeBaseTiltedOnWiderCapHasItsLowestRimPoint) {
  check_kind(FlatKind::BaseOnCap, 920000);
}

TEST(FlatPair, WideBaseTiltedOverNarrowCapMeetsTheCapsRim) {
  check_kind(FlatKind::WideBaseOverCap, 930000);
}

TEST(FlatPair, CapsuleTiltedAcrossCapHasItsLowerEnd) {
  check_kind(FlatKind::CapsuleOverCap, 940000);
}

TEST(FlatPair, PrismTiltedOnFaceHasItsLowestCorner) {
  check_kind(FlatKind::PrismOnFace, 950000);
}

}  // namespace
