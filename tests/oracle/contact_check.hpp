/// @file contact_check.hpp
/// Comparison of mink's contact() results with an independent penetration depth
/// (tests/oracle/penetration.hpp), with the tolerances stated once here, and the bookkeeping of
/// the worst errors seen in a sweep.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "mink/mink.hpp"
#include "oracle/penetration.hpp"

namespace oracle {

/// Depth error allowed, relative to the size of the case (sum of bounding radii), for shapes
/// whose cores are polytopes, points or segments (EPA converges exactly on them; it stops at
/// 1e-10 of the size at the latest).
inline constexpr double kDepthTolerance = 1e-9;
/// The same for curved cores (cylinder, cone, ellipsoid), on which EPA converges linearly.
inline constexpr double kCurvedDepthTolerance = 1e-7;

/// World support function of one shape: h(u) = max over the shape of u . x (u need not be unit).
using SupportFn = std::function<Real(const V3&)>;

/// Largest errors of a sweep, printed at its end.
struct DepthWorst {
  std::string name;
  double depth = 0;       ///< |depth - oracle| / size
  double optimality = 0;  ///< (h_{A-B}(normal) - depth) / size: 0 for an optimal normal
  double points = 0;      ///< |point_b - point_a + depth normal| / (size + |position|)
  double support = 0;     ///< points off the support planes along the normal, / (size + |position|)
  int penetrating = 0, touching = 0, separated = 0;
  /// Cases whose points break point_b - point_a = -depth * normal: the first few fail one by
  /// one (with the case's trace), the rest are counted in one failure at the end of the sweep.
  int point_failures = 0;
  static constexpr int kShownPointFailures = 3;

  explicit DepthWorst(std::string n) : name(std::move(n)) {}
  ~DepthWorst() {
    std::printf(
        "[  worst   ] %s: depth %.3g, optimality %.3g, points %.3g, support planes %.3g "
        "(relative); %d penetrating, %d touching, %d separated cases\n",
        name.c_str(), depth, optimality, points, support, penetrating, touching, separated);
    if (point_failures > kShownPointFailures) {
      ADD_FAILURE() << name << ": " << point_failures << " of " << penetrating
                    << " penetrating cases break point_b - point_a = -depth * normal (worst "
                    << points << " relative; the first " << kShownPointFailures
                    << " are reported above)";
    }
  }
};

inline bool all_finite(const mink::ContactResult& r) {
  return std::isfinite(r.distance) && std::isfinite(r.depth) && r.normal.allFinite() &&
         r.point_a.allFinite() && r.point_b.allFinite() && std::isfinite(r.error_bound);
}

inline std::string describe(const mink::ContactResult& r) {
  char buffer[768];
  std::snprintf(buffer, sizeof buffer,
                "status %s, depth %.17g, distance %.17g, normal (%.17g, %.17g, %.17g), point_a "
                "(%.17g, %.17g, %.17g), point_b (%.17g, %.17g, %.17g), error_bound %.3g, "
                "iterations %d, normal_chosen %d",
                mink::to_string(r.status), r.depth, r.distance, r.normal.x(), r.normal.y(),
                r.normal.z(), r.point_a.x(), r.point_a.y(), r.point_a.z(), r.point_b.x(),
                r.point_b.y(), r.point_b.z(), r.error_bound, r.iterations, int(r.normal_chosen));
  return buffer;
}

/// Checks a contact() result against an independent depth. `expected` is the true depth
/// (negative: apart by at least its magnitude), `ha` and `hb` the world support functions of A
/// and B (h_{A-B}(u) = ha(u) + hb(-u)); `size` the natural scale of the case (sum of bounding
/// radii), `position_scale` the magnitude of the world coordinates. Checks, relative to size:
///   - depth within `tolerance` of the oracle, and the normal optimal: h_{A-B}(normal) = depth
///     (the normal need not be the oracle's when several are equally good);
///   - point_b - point_a = -depth * normal, point_a on A's support plane along the normal and
///     point_b on B's along -normal (the deepest points), each on its own shape (outside_by());
///   - status, intersect, finite outputs, unit normal.
/// Cases whose oracle depth is within `tolerance * size` of 0 are touching: any status but
/// IterationLimit (which a needle may give, with an error_bound within twice the tolerance), a
/// depth and distance within twice the tolerance, and each point on its own shape. `allow_limit`
/// (curved cores): IterationLimit is accepted with a finite error_bound, which then widens the
/// depth and optimality tolerances; otherwise it fails. How far world point p lies outside the
/// shape of support function h, as far as 26 directions (the faces, edges and corners of a cube)
/// and `extra` tell: max of u . p - h(u) over unit u. A lower bound of p's distance from the shape
/// (0 or less: no direction shows it outside).
inline double outside_by(const SupportFn& h, const mink::Vec3& p, const V3& extra) {
  const V3 x = widen(p);
  Real worst = -std::numeric_limits<Real>::infinity();
  auto consider = [&](const V3& u) { worst = std::max(worst, u.dot(x) - h(u)); };
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) consider(V3(Real(i), Real(j), Real(k)).normalized());
  consider(extra);
  consider(V3(-extra));
  return static_cast<double>(worst);
}

inline void expect_contact_matches(Real expected, const SupportFn& ha, const SupportFn& hb,
                                   const mink::ContactResult& got, double size,
                                   double position_scale, DepthWorst& worst,
                                   double tolerance = kDepthTolerance, bool allow_limit = false,
                                   bool needle = false) {
  ASSERT_TRUE(all_finite(got)) << "non-finite output: " << describe(got);
  ASSERT_NE(got.status, mink::Status::InvalidInput) << got.error;
  EXPECT_EQ(got.error, nullptr);
  const double tol = tolerance * size;
  const double e = static_cast<double>(expected);
  if (got.status == mink::Status::IterationLimit) {
    // A needle touching within the tolerance: GJK crawls along it (its direction there is
    // rounding noise) and says so, with a bound within what touching cases are held to below
    // (2 tol; NeedlesWithinTheToleranceOfTouching).
    const bool needle_touching = needle && std::abs(e) <= tol && got.error_bound <= 2 * tol;
    EXPECT_TRUE(allow_limit || needle_touching)
        << "iteration limit: " << describe(got) << "; oracle depth " << e << ", tolerance " << tol;
  }
  EXPECT_NEAR(got.normal.norm(), 1.0, 1e-12) << "normal not unit (tolerance 1e-12)";
  EXPECT_GE(got.depth, 0.0);
  EXPECT_GE(got.distance, 0.0);
  EXPECT_GE(got.error_bound, 0.0);
  if (e < -tol) {
    ++worst.separated;
    EXPECT_EQ(got.status, mink::Status::Separated) << "oracle depth " << e << "; " << describe(got);
    EXPECT_FALSE(got.intersect);
    EXPECT_EQ(got.depth, 0.0);
    return;
  }
  const V3 n = widen(got.normal);
  const double scale = size + position_scale;
  if (e <= tol) {
    ++worst.touching;
    EXPECT_LE(got.depth, 2 * tol) << "touching case, oracle depth " << e << "; " << describe(got);
    EXPECT_LE(got.distance, 2 * tol) << "touching case, oracle depth " << e;
    EXPECT_LE(outside_by(ha, got.point_a, n), 2 * tolerance * scale)
        << "point_a off A; " << describe(got);
    EXPECT_LE(outside_by(hb, got.point_b, n), 2 * tolerance * scale)
        << "point_b off B; " << describe(got);
    return;
  }
  ++worst.penetrating;
  if (!got.intersect) {  // the rest would only repeat this
    worst.depth = std::max(worst.depth, e / size);
    ADD_FAILURE() << "not intersecting, but the oracle depth is " << e << " (" << e / size
                  << " of the size); " << describe(got);
    return;
  }
  if (!allow_limit) {
    EXPECT_EQ(got.status, mink::Status::Intersecting) << describe(got);
  }
  EXPECT_EQ(got.distance, 0.0);
  // A capped run (accepted only with allow_limit) promises its error_bound on top. So does a
  // needle 1e-8 as thick as it is long: EPA's polytope cannot be kept convex in double there and
  // it stops with the bracket it has, which must then hold.
  const bool bracket = got.status == mink::Status::IterationLimit || needle;
  const double slack = tol + (bracket ? got.error_bound : 0.0);
  const double derr = std::abs(got.depth - e) / size;
  worst.depth = std::max(worst.depth, derr);
  EXPECT_LE(derr * size, slack) << "depth " << got.depth << " oracle " << e
                                << " (relative tolerance " << tolerance << "); " << describe(got);
  const Real h_a = ha(n), h_b = hb(V3(-n));
  const double gap = static_cast<double>(h_a + h_b) - got.depth;
  worst.optimality = std::max(worst.optimality, std::abs(gap) / size);
  EXPECT_LE(std::abs(gap), slack) << "h_{A-B}(normal) = " << static_cast<double>(h_a + h_b)
                                  << " but depth " << got.depth << " (the normal is not optimal; "
                                  << "oracle depth " << e << ", tolerance " << tol << ")";
  const double consistency = (got.point_b - got.point_a + got.depth * got.normal).norm() / scale;
  worst.points = std::max(worst.points, consistency);
  if (!(consistency <= tolerance) && worst.point_failures++ < DepthWorst::kShownPointFailures) {
    ADD_FAILURE() << "point_b - point_a != -depth * normal: off by " << consistency * scale
                  << " (relative " << consistency << ", tolerance " << tolerance << "); "
                  << describe(got);
  }
  const double off_a = std::abs(static_cast<double>(n.dot(widen(got.point_a)) - h_a)) / scale;
  const double off_b = std::abs(static_cast<double>(n.dot(widen(got.point_b)) + h_b)) / scale;
  worst.support = std::max({worst.support, off_a, off_b});
  EXPECT_LE(off_a, tolerance) << "point_a is not A's deepest point along the normal";
  EXPECT_LE(off_b, tolerance) << "point_b is not B's deepest point along -normal";
  EXPECT_LE(outside_by(ha, got.point_a, n), slack + tolerance * scale)
      << "point_a off A; " << describe(got);
  EXPECT_LE(outside_by(hb, got.point_b, n), slack + tolerance * scale)
      << "point_b off B; " << describe(got);
}

// ---- World support functions of the shapes, from their definitions (not from mink) ----

inline SupportFn sphere_support(const V3& centre, Real radius) {
  return [=](const V3& u) { return centre.dot(u) + radius * u.norm(); };
}

inline SupportFn box_support(const WorldBox& box) {
  return [=](const V3& u) {
    Real h = box.center.dot(u);
    for (int i = 0; i < 3; ++i) h += box.half[i] * std::abs(box.rotation.col(i).dot(u));
    return h;
  };
}

inline SupportFn cylinder_support(const WorldCylinder& c) {
  return [=](const V3& u) {
    const V3 l = c.rotation.transpose() * u;
    return c.center.dot(u) + c.radius * std::sqrt(l.x() * l.x() + l.y() * l.y()) +
           c.half_height * std::abs(l.z());
  };
}

inline SupportFn capsule_support(const WorldCapsule& c) {
  return [=](const V3& u) { return std::max(c.p.dot(u), c.q.dot(u)) + c.radius * u.norm(); };
}

inline SupportFn points_support(const std::vector<V3>& points, Real radius = 0) {
  return [=](const V3& u) { return support_of(points, u) + radius * u.norm(); };
}

/// World points of local points under a pose, in long double.
inline std::vector<V3> world_points(const std::vector<mink::Vec3>& local, const mink::Pose& pose) {
  std::vector<V3> out;
  out.reserve(local.size());
  for (const mink::Vec3& p : local)
    out.push_back(widen(pose.rotation) * widen(p) + widen(pose.translation));
  return out;
}

}  // namespace oracle
