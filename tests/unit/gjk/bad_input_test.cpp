// Bad input to shapes, poses and queries: a clear error (InvalidInput with a reason, or a failed
// Expected), never a crash, a hang or a NaN in an answer.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/check.hpp"

namespace {

using mink::Pose;
using mink::Vec3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Both queries, both orders, report InvalidInput with a reason and no NaN.
template <class A, class B>
void expect_invalid(const A& a, const Pose& pa, const B& b, const Pose& pb) {
  for (int swap = 0; swap < 2; ++swap) {
    SCOPED_TRACE(swap ? "B, A" : "A, B");
    const auto r = swap ? mink::distance(b, pb, a, pa) : mink::distance(a, pa, b, pb);
    const auto i = swap ? mink::intersect(b, pb, a, pa) : mink::intersect(a, pa, b, pb);
    EXPECT_EQ(r.status, mink::Status::InvalidInput);
    ASSERT_NE(r.error, nullptr);
    EXPECT_GT(std::string(r.error).size(), 0u);
    EXPECT_FALSE(oracle::has_nan(r));
    EXPECT_FALSE(r.intersect);
    EXPECT_EQ(i.status, mink::Status::InvalidInput);
    ASSERT_NE(i.error, nullptr);
    EXPECT_FALSE(i.intersect);
  }
}

TEST(GjkBadInput, NonFiniteOrNegativeShapeParameters) {
  const mink::Sphere good{1};
  const Pose p = Pose::identity();
  for (const double bad : {kNaN, kInf, -kInf, -1.0}) {
    SCOPED_TRACE(testing::Message() << "value " << bad);
    expect_invalid(mink::Sphere{bad}, p, good, p);
    expect_invalid(mink::Box{Vec3(1, bad, 1)}, p, good, p);
    expect_invalid(mink::Capsule{bad, 1}, p, good, p);
    expect_invalid(mink::Capsule{1, bad}, p, good, p);
    expect_invalid(mink::Cylinder{bad, 1}, p, good, p);
    expect_invalid(mink::Cylinder{1, bad}, p, good, p);
    expect_invalid(mink::Cone{bad, 1}, p, good, p);
    expect_invalid(mink::Cone{1, bad}, p, good, p);
    expect_invalid(mink::Ellipsoid{Vec3(1, 1, bad)}, p, good, p);
    expect_invalid(mink::Rounded<mink::Sphere>{good, bad}, p, good, p);
    expect_invalid(mink::MinkowskiSum<mink::Sphere, mink::Sphere>{good, mink::Sphere{bad}}, p, good,
                   p);
    if (!std::isfinite(bad)) {
      expect_invalid(mink::Point{Vec3(bad, 0, 0)}, p, good, p);
      expect_invalid(mink::Segment{Vec3::Zero(), Vec3(0, bad, 0)}, p, good, p);
      expect_invalid(mink::Triangle{Vec3::Zero(), Vec3::UnitX(), Vec3(0, 0, bad)}, p, good, p);
    }
  }
}

TEST(GjkBadInput, PolytopeFromEmptyOrNonFinitePoints) {
  const auto empty = mink::Polytope::make(std::vector<Vec3>{});
  EXPECT_FALSE(empty);
  EXPECT_FALSE(empty.error().empty());
  for (const double bad : {kNaN, kInf}) {
    const auto p = mink::Polytope::make(std::vector<Vec3>{Vec3::Zero(), Vec3(1, bad, 0)});
    EXPECT_FALSE(p);
    EXPECT_FALSE(p.error().empty());
  }
}

TEST(GjkBadInput, NonFinitePoses) {
  const mink::Box box{Vec3(1, 1, 1)};
  for (const double bad : {kNaN, kInf}) {
    Pose t = Pose::identity();
    t.translation.y() = bad;
    Pose r = Pose::identity();
    r.rotation(1, 2) = bad;
    expect_invalid(box, t, box, Pose::identity());
    expect_invalid(box, r, box, Pose::identity());
    const auto shape = mink::Shape::box(Vec3(1, 1, 1));
    ASSERT_TRUE(shape);
    expect_invalid(*shape, t, *shape, Pose::identity());
    expect_invalid(*shape, r, *shape, Pose::identity());
  }
}

// The poses are tested by one sum over both (gjk.hpp, query_input_error()): infinities of
// either sign on either side make it non-finite, and so does a sum of finite entries that
// overflows, which must not count as a pose that is not finite.
TEST(GjkBadInput, PosesTestedByOneSum) {
  const mink::Capsule capsule{0.5, 1.0};
  Pose plus = Pose::identity(), minus = Pose::identity();
  plus.translation.x() = kInf;
  minus.rotation(2, 0) = -kInf;
  const auto both = mink::distance(capsule, plus, capsule, minus);
  EXPECT_EQ(both.status, mink::Status::InvalidInput);
  ASSERT_NE(both.error, nullptr);
  EXPECT_STREQ(both.error, "pose of A is not finite");
  const auto only_b = mink::contact(capsule, Pose::identity(), capsule, minus);
  EXPECT_EQ(only_b.status, mink::Status::InvalidInput);
  ASSERT_NE(only_b.error, nullptr);
  EXPECT_STREQ(only_b.error, "pose of B is not finite");
  // Finite entries whose sum overflows: pairs near the largest double, apart and coincident.
  const Pose far_a = Pose::from_translation(Vec3(1e308, 0, 0));
  const Pose far_b = Pose::from_translation(Vec3(0.9e308, 0, 0));
  const auto far = mink::distance(capsule, far_a, capsule, far_b);
  EXPECT_EQ(far.status, mink::Status::Separated) << (far.error ? far.error : "");
  EXPECT_NEAR(far.distance, 1e307, 1e295);
  const auto same = mink::contact(capsule, far_a, capsule, far_a);
  EXPECT_TRUE(same.intersect) << (same.error ? same.error : "");
  EXPECT_TRUE(mink::intersect(capsule, far_a, capsule, far_a).intersect);
}

/// Every typed query on (a, b) reports `expected` (the message of the shape's own error(), or of
/// the pose), and on (b, a) `expected_swapped`; a null message: no error.
template <class A, class B>
void expect_error(const A& a, const Pose& pa, const B& b, const Pose& pb, const char* expected,
                  const char* expected_swapped) {
  auto check = [&](const char* error, const char* query) {
    SCOPED_TRACE(query);
    if (!expected) {
      EXPECT_EQ(error, nullptr) << error;
      return;
    }
    ASSERT_NE(error, nullptr);
    EXPECT_STREQ(error, expected);
  };
  check(mink::intersect(a, pa, b, pb).error, "intersect A, B");
  check(mink::distance(a, pa, b, pb).error, "distance A, B");
  check(mink::contact(a, pa, b, pb).error, "contact A, B");
  expected = expected_swapped;
  check(mink::intersect(b, pb, a, pa).error, "intersect B, A");
  check(mink::distance(b, pb, a, pa).error, "distance B, A");
  check(mink::contact(b, pb, a, pa).error, "contact B, A");
}

/// The same message in both orders.
template <class A, class B>
void expect_error(const A& a, const Pose& pa, const B& b, const Pose& pb, const char* expected) {
  expect_error(a, pa, b, pb, expected, expected);
}

// Shapes made of lengths alone are tested together with the poses, by one sum and one minimum
// (gjk.hpp, lengths_and_poses_valid()): each length of each shape, bad alone or beside bad values
// elsewhere, must still get its own shape's message, in the order the shapes come; -0 is a
// length; finite lengths and translations whose sum overflows are valid.
TEST(GjkBadInput, LengthsTestedWithThePoses) {
  const Pose p = Pose::identity();
  const mink::Box box{Vec3(1, 2, 3)};
  const mink::Rounded<mink::Box> rounded_box{box, 0.25};
  const mink::Capsule capsule{0.5, 1};
  const mink::Ellipsoid ellipsoid{Vec3(1, 2, 0.5)};
  for (const double bad : {kNaN, kInf, -kInf, -1e-300, -1.0}) {
    SCOPED_TRACE(testing::Message() << "value " << bad);
    for (int k = 0; k < 3; ++k) {
      mink::Box bad_box = box;
      bad_box.half_extents[k] = bad;
      const char* message = bad_box.error();
      ASSERT_NE(message, nullptr);
      expect_error(bad_box, p, capsule, p, message);
      expect_error(bad_box, p, box, p, message);
      expect_error(bad_box, p, rounded_box, p, message);
      mink::Ellipsoid bad_ellipsoid = ellipsoid;
      bad_ellipsoid.radii[k] = bad;
      expect_error(bad_ellipsoid, p, box, p, bad_ellipsoid.error());
    }
    const mink::Rounded<mink::Box> bad_margin{box, bad};
    expect_error(bad_margin, p, box, p, bad_margin.error());
    expect_error(bad_margin, p, capsule, p, bad_margin.error());
    const mink::Cylinder bad_cylinder{0.5, bad};
    const mink::Cone bad_cone{bad, 1};
    expect_error(bad_cylinder, p, bad_cone, p, bad_cylinder.error(), bad_cone.error());
    // A bad pose beside a bad length: the shape's message comes first, as error() order says.
    Pose bad_pose = Pose::identity();
    bad_pose.rotation(0, 1) = bad;
    const mink::Sphere bad_sphere{bad};
    if (!std::isfinite(bad)) {
      expect_error(box, bad_pose, capsule, p, "pose of A is not finite", "pose of B is not finite");
      expect_error(box, p, capsule, bad_pose, "pose of B is not finite", "pose of A is not finite");
      expect_error(bad_sphere, bad_pose, box, p, bad_sphere.error());
    }
  }
  // Infinities of both signs in one sum: NaN, still caught.
  expect_error(mink::Box{Vec3(1, kInf, 1)}, p, mink::Sphere{-kInf}, p,
               mink::Box{Vec3(1, kInf, 1)}.error(), mink::Sphere{-kInf}.error());
  // -0 is a length.
  expect_error(mink::Box{Vec3(-0.0, 1, 1)}, p, mink::Capsule{-0.0, -0.0}, p, nullptr);
  expect_error(mink::Rounded<mink::Box>{box, -0.0}, p, mink::Sphere{-0.0}, p, nullptr);
  // Finite lengths whose sum overflows, and translations whose sum does.
  const mink::Box huge{Vec3(6e307, 6e307, 6e307)};  // its six lengths sum to 3.6e308
  expect_error(huge, p, huge, Pose::from_translation(Vec3(1e307, 0, 0)), nullptr);
  EXPECT_DOUBLE_EQ(mink::contact(huge, p, huge, Pose::from_translation(Vec3(1e307, 0, 0))).depth,
                   1.1e308);
  expect_error(box, Pose::from_translation(Vec3(1.5e308, 1.5e308, 0)), capsule,
               Pose::from_translation(Vec3(1.5e308, 1.5e308, 1)), nullptr);
  const auto far = mink::distance(box, Pose::from_translation(Vec3(1.5e308, 1.5e308, 0)), capsule,
                                  Pose::from_translation(Vec3(1.5e308, 1.5e308, 10)));
  EXPECT_EQ(far.status, mink::Status::Separated);
  EXPECT_NEAR(far.distance, 10 - 3 - 1.5, 1e-12);
}

TEST(GjkBadInput, QuaternionAndPoseValidation) {
  EXPECT_EQ(mink::quaternion_error(mink::Quat(1, 0, 0, 0)), nullptr);
  EXPECT_EQ(mink::quaternion_error(mink::Quat(0.5, 0.5, 0.5, 0.5)), nullptr);
  EXPECT_NE(mink::quaternion_error(mink::Quat(1.1, 0, 0, 0)), nullptr);
  EXPECT_NE(mink::quaternion_error(mink::Quat(0, 0, 0, 0)), nullptr);
  EXPECT_NE(mink::quaternion_error(mink::Quat(1 + 2e-6, 0, 0, 0)), nullptr);
  EXPECT_NE(mink::quaternion_error(mink::Quat(kNaN, 0, 0, 0)), nullptr);
  EXPECT_NE(mink::quaternion_error(mink::Quat(kInf, 0, 0, 0)), nullptr);
  Pose scaled = Pose::identity();
  scaled.rotation *= 2;
  EXPECT_NE(mink::pose_error(scaled), nullptr);
  Pose mirror = Pose::identity();
  mirror.rotation(2, 2) = -1;
  EXPECT_NE(mink::pose_error(mirror), nullptr);
  Pose nan_pose = Pose::identity();
  nan_pose.translation.x() = kNaN;
  EXPECT_NE(mink::pose_error(nan_pose), nullptr);
  EXPECT_EQ(mink::pose_error(Pose::from(Vec3(1, 2, 3), mink::Quat(0.5, 0.5, 0.5, 0.5))), nullptr);
}

TEST(GjkBadInput, ShapeFactoriesRejectBadInput) {
  auto expect_failure = [](const mink::Expected<mink::Shape>& s, const char* what) {
    EXPECT_FALSE(s) << what;
    EXPECT_FALSE(s.error().empty()) << what;
  };
  expect_failure(mink::Shape::sphere(-1), "sphere(-1)");
  expect_failure(mink::Shape::sphere(kNaN), "sphere(NaN)");
  expect_failure(mink::Shape::box(Vec3(1, -1, 1)), "box(negative)");
  expect_failure(mink::Shape::box(Vec3(1, kInf, 1)), "box(inf)");
  expect_failure(mink::Shape::capsule(-1, 1), "capsule(-1, 1)");
  expect_failure(mink::Shape::capsule(1, kNaN), "capsule(1, NaN)");
  expect_failure(mink::Shape::cylinder(kNaN, 1), "cylinder(NaN, 1)");
  expect_failure(mink::Shape::cylinder(1, -1), "cylinder(1, -1)");
  expect_failure(mink::Shape::cone(-1, 1), "cone(-1, 1)");
  expect_failure(mink::Shape::cone(1, kInf), "cone(1, inf)");
  expect_failure(mink::Shape::ellipsoid(Vec3(1, 1, -kInf)), "ellipsoid(-inf)");
  expect_failure(mink::Shape::point(Vec3(kNaN, 0, 0)), "point(NaN)");
  expect_failure(mink::Shape::segment(Vec3::Zero(), Vec3(kInf, 0, 0)), "segment(inf)");
  expect_failure(mink::Shape::triangle(Vec3::Zero(), Vec3::UnitX(), Vec3(0, kNaN, 0)),
                 "triangle(NaN)");
  expect_failure(mink::Shape::polytope(std::vector<Vec3>{}), "polytope(empty)");
  expect_failure(mink::Shape::polytope(std::vector<Vec3>{Vec3(kNaN, 0, 0)}), "polytope(NaN)");
  const auto good = mink::Shape::sphere(1);
  ASSERT_TRUE(good);
  expect_failure(mink::Shape::rounded(*good, -0.5), "rounded(-0.5)");
  expect_failure(mink::Shape::rounded(*good, kNaN), "rounded(NaN)");
  expect_failure(mink::Shape::rounded(*good, kInf), "rounded(inf)");
}

// A default-constructed Shape holds no core: every run-time query says so, in either position,
// and computes nothing.
TEST(GjkBadInput, EmptyShapeIsAnErrorInEveryQuery) {
  const mink::Shape empty;
  const mink::Shape box = mink::Shape::box(Vec3(1, 1, 1)).value();
  const Pose pose = Pose::identity();
  for (int order = 0; order < 2; ++order) {
    const mink::Shape& a = order == 0 ? empty : box;
    const mink::Shape& b = order == 0 ? box : empty;
    const auto i = mink::intersect(a, pose, b, pose);
    const auto d = mink::distance(a, pose, b, pose);
    const auto c = mink::contact(a, pose, b, pose);
    const auto m = mink::manifold(a, pose, b, pose);
    EXPECT_EQ(i.status, mink::Status::InvalidInput);
    EXPECT_EQ(d.status, mink::Status::InvalidInput);
    EXPECT_EQ(c.status, mink::Status::InvalidInput);
    EXPECT_EQ(m.status, mink::Status::InvalidInput);
    for (const char* error : {i.error, d.error, c.error, m.error}) {
      ASSERT_NE(error, nullptr);
      EXPECT_STREQ(error, "shape is empty");
    }
    EXPECT_EQ(m.count, 0);
  }
}

TEST(GjkBadInput, NonOrthonormalRotationNeverGivesNaN) {
  // The queries leave orthonormality to the caller (pose_error checks it); a scaled or singular
  // rotation must still give a finite answer rather than NaN or a hang.
  const mink::Box box{Vec3(1, 1, 1)};
  Pose scaled = Pose::from_translation(Vec3(3, 0, 0));
  scaled.rotation *= 1.5;
  Pose singular = Pose::from_translation(Vec3(3, 0, 0));
  singular.rotation.setZero();
  for (const Pose& p : {scaled, singular}) {
    const auto r = mink::distance(box, Pose::identity(), box, p);
    EXPECT_FALSE(oracle::has_nan(r));
    EXPECT_NE(r.status, mink::Status::InvalidInput);
    const auto i = mink::intersect(box, Pose::identity(), box, p);
    (void)i;
  }
}

TEST(GjkBadInput, BadTolerancesNeverHangOrGiveNaN) {
  const mink::Ellipsoid e{Vec3(1, 2, 3)};
  const Pose pb = Pose::from_translation(Vec3(5, 1, 0));
  for (const double rel : {kNaN, -1.0, 0.0, kInf}) {
    SCOPED_TRACE(testing::Message() << "relative " << rel);
    mink::Tolerances tol;
    tol.relative = rel;
    const auto r = mink::distance(e, Pose::identity(), e, pb, tol);
    EXPECT_FALSE(oracle::has_nan(r));
    EXPECT_LE(r.iterations, tol.max_iterations + 4);
    const auto i = mink::intersect(e, Pose::identity(), e, pb, tol);
    EXPECT_LE(i.iterations, tol.max_iterations + 4);
  }
  mink::Tolerances none;
  none.max_iterations = 0;
  const auto r = mink::distance(e, Pose::identity(), e, pb, none);
  EXPECT_FALSE(oracle::has_nan(r));
}

TEST(GjkBadInput, HugeFiniteCoordinatesNeverGiveNaN) {
  // Finite but so large that squared norms overflow to infinity.
  const mink::Box big{Vec3(1e200, 1e200, 1e200)};
  const Pose far = Pose::from_translation(Vec3(1e201, 0, 0));
  const auto r = mink::distance(big, Pose::identity(), big, far);
  EXPECT_FALSE(oracle::has_nan(r)) << "status " << mink::to_string(r.status) << " distance "
                                   << r.distance << " normal " << r.normal.transpose();
  const auto i = mink::intersect(big, Pose::identity(), big, far);
  EXPECT_FALSE(i.intersect && i.status == mink::Status::Separated);
}

}  // namespace
