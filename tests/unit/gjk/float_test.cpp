// The query templates instantiated with float: answers within float accuracy of the analytic
// ones (computed in long double by tests/oracle/analytic.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"
#include "oracle/random.hpp"

namespace {

using PoseF = mink::PoseT<float>;
using Vec3F = mink::Vec3T<float>;

TEST(GjkFloat, SphereAndBoxMatchAnalytic) {
  const std::uint64_t base = 70000;
  const int n = oracle::sweep_count(500);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const mink::SphereT<float> s{float(rng.uniform(0.2, 1))};
    const mink::BoxT<float> b{
        Vec3F(float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)))};
    const mink::Quat qd = rng.rotation();
    const PoseF pb = PoseF::from(Vec3F::Zero(), qd.cast<float>());
    const PoseF ps = PoseF::from_translation(rng.in_ball(3).cast<float>());
    // The oracle sees exactly the float inputs, widened.
    const oracle::WorldBox wb{b.half_extents.cast<oracle::Real>(), pb.rotation.cast<oracle::Real>(),
                              oracle::V3::Zero()};
    const auto expected = oracle::sphere_box(ps.translation.cast<oracle::Real>(), s.radius, wb);
    const auto got = mink::distance(s, ps, b, pb);
    const auto got_bool = mink::intersect(s, ps, b, pb);
    const float size = s.radius + b.half_extents.norm();
    ASSERT_TRUE(std::isfinite(got.distance));
    // Float tolerance: 1e-5 of the size (64 float epsilons is about 8e-6).
    const float tol = 1e-5f * size;
    if (expected.gap > tol) {
      EXPECT_FALSE(got.intersect);
      EXPECT_FALSE(got_bool.intersect);
      EXPECT_NEAR(got.distance, float(expected.distance), tol);
      if (expected.gap > 0.01f) {
        EXPECT_LE((got.normal - expected.normal.cast<float>()).norm(), 1e-3f);
      }
    } else if (expected.gap < -tol) {
      EXPECT_TRUE(got.intersect);
      EXPECT_TRUE(got_bool.intersect);
    }
  }
}

TEST(GjkFloat, SpheresApartExample) {
  const mink::SphereT<float> a{1.0f}, b{0.5f};
  const auto r = mink::distance(a, PoseF::identity(), b, PoseF::from_translation(Vec3F(3, 0, 0)));
  EXPECT_EQ(r.status, mink::Status::Separated);
  EXPECT_NEAR(r.distance, 1.5f, 1e-6f);
  EXPECT_NEAR(r.normal.x(), 1.0f, 1e-6f);
}

}  // namespace

namespace {

// contact() in float: penetrating boxes against the minimum overlap of their projections on the
// 15 separating axes, computed here in long double.
TEST(ContactFloat, BoxBoxDepthMatchesSeparatingAxes) {
  const std::uint64_t base = 71000;
  const int n = oracle::sweep_count(300);
  int penetrating = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const mink::BoxT<float> a{
        Vec3F(float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)))};
    const mink::BoxT<float> b{
        Vec3F(float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)), float(rng.uniform(0.2, 1)))};
    const mink::Quat qa = rng.rotation();
    const mink::Quat qb = rng.rotation();
    const PoseF pa = PoseF::from(Vec3F::Zero(), qa.cast<float>());
    const PoseF pb = PoseF::from(rng.in_ball(1).cast<float>(), qb.cast<float>());
    using oracle::Real;
    using oracle::V3;
    const oracle::M3 ra = pa.rotation.cast<Real>(), rb = pb.rotation.cast<Real>();
    const V3 ea = a.half_extents.cast<Real>(), eb = b.half_extents.cast<Real>();
    const V3 t = pb.translation.cast<Real>();
    Real depth = std::numeric_limits<Real>::infinity();
    auto axis = [&](V3 u) {
      if (u.norm() < 1e-6L) return;
      u.normalize();
      const Real half_a = (ra.transpose() * u).cwiseAbs().dot(ea);
      const Real half_b = (rb.transpose() * u).cwiseAbs().dot(eb);
      depth = std::min(depth, half_a + half_b - std::abs(u.dot(t)));
    };
    for (int p = 0; p < 3; ++p) {
      axis(ra.col(p));
      axis(rb.col(p));
      for (int q = 0; q < 3; ++q) axis(ra.col(p).cross(rb.col(q)));
    }
    const auto got = mink::contact(a, pa, b, pb);
    const float size = a.half_extents.norm() + b.half_extents.norm();
    ASSERT_NE(got.status, mink::Status::InvalidInput);
    ASSERT_TRUE(std::isfinite(got.depth) && mink::is_finite(got.normal));
    EXPECT_NEAR(got.normal.norm(), 1.0f, 1e-5f);
    if (depth > 1e-4L * size) {
      ++penetrating;
      EXPECT_TRUE(got.intersect);
      EXPECT_NEAR(got.depth, float(depth), 1e-5f * size);
    }
  }
  EXPECT_GT(penetrating, n / 4);
}

// Float's range of exact lengths is 2^-15 to 2^15 (query/scale_range.hpp): cubes of half side 2^40
// and 2^-40, a unit apart or overlapping by a quarter in units of their side, as boxes and as
// polytopes (copied and rebuilt on every query), answer as the unit cubes do.
TEST(GjkFloat, CubesFarOutsideFloatsRange) {
  for (const int exponent : {-40, 40}) {
    const float s = std::ldexp(1.0f, exponent);
    SCOPED_TRACE(s);
    const mink::BoxT<float> box{Vec3F(s, s, s)};
    std::vector<Vec3F> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back(s * Vec3F(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    const auto cube = mink::PolytopeT<float>::make(corners).value();
    const PoseF at = PoseF::from_translation(s * Vec3F(7, -3, 2));
    const PoseF apart = PoseF::from_translation(s * Vec3F(10, -2.5f, 2.25f));
    const PoseF over = PoseF::from_translation(s * Vec3F(8.75f, -2.5f, 2.25f));
    auto check = [&](const auto& a, const auto& b) {
      const auto d = mink::distance(a, at, b, apart);
      ASSERT_EQ(d.status, mink::Status::Separated);
      EXPECT_NEAR(d.distance / s, 1.0f, 1e-5f);
      EXPECT_NEAR(d.normal.x(), 1.0f, 1e-5f);
      EXPECT_FALSE(mink::intersect(a, at, b, apart).intersect);
      const auto c = mink::contact(a, at, b, over);
      ASSERT_TRUE(c.intersect);
      EXPECT_NEAR(c.depth / s, 0.25f, 1e-5f);
      EXPECT_NEAR(c.normal.x(), 1.0f, 1e-5f);
      EXPECT_NEAR(c.point_a.x() / s, 8.0f, 1e-5f);
      const auto m = mink::manifold(a, at, b, over);
      ASSERT_EQ(m.count, 4);
      for (int i = 0; i < m.count; ++i) EXPECT_NEAR(m.points[i].depth / s, 0.25f, 1e-5f);
    };
    check(box, box);
    check(cube, cube);
    check(box, cube);
  }
}

}  // namespace
