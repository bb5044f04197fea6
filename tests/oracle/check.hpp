/// @file check.hpp
/// Comparison of mink's distance()/intersect() results with an oracle Answer, with the
/// tolerances stated once here, and the bookkeeping of the worst error seen in a sweep.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"

namespace oracle {

/// Distance error allowed on separated pairs, relative to the size of the case (the brief's
/// accuracy bar).
inline constexpr double kDistanceTolerance = 1e-10;
/// Cases whose true signed gap is within this (relative to size) of zero are "touching": either
/// intersect answer is accepted there, since mink counts touching within 1e-12 * size as
/// intersecting and rounding of the inputs alone moves the gap by about 1e-16 * size.
inline constexpr double kTouchingBand = 1e-9;

/// The angle between two directions (radians; accurate near 0, where acos is not).
inline double angle(const mink::Vec3& u, const mink::Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// The rounding of world coordinates of a scene placed up to `translation` from the origin:
/// 16 eps times its largest coordinate (a scene 1e3 away is built to 1e3 eps).
inline double world_rounding(const mink::Vec3& translation) {
  return 16 * std::numeric_limits<double>::epsilon() * translation.cwiseAbs().maxCoeff();
}

/// Largest errors of a sweep, printed at its end.
struct Worst {
  std::string name;
  double distance = 0;  ///< |distance - oracle| / size
  double point = 0;     ///< |point - oracle point| / (size + |position|)
  double normal = 0;    ///< |normal - oracle normal|
  int separated = 0, intersecting = 0, touching = 0;

  explicit Worst(std::string n) : name(std::move(n)) {}
  ~Worst() {
    std::printf(
        "[  worst   ] %s: distance %.3g (relative), point %.3g (relative), normal %.3g; "
        "%d separated, %d intersecting, %d touching cases\n",
        name.c_str(), distance, point, normal, separated, intersecting, touching);
  }
};

inline bool has_nan(const mink::DistanceResult& r) {
  return std::isnan(r.distance) || !r.normal.allFinite() || !r.point_a.allFinite() ||
         !r.point_b.allFinite() || std::isnan(r.error_bound);
}

/// Checks a distance and an intersect result against the oracle. `size` is the natural scale of
/// the case (sum of bounding radii); `position_scale` the magnitude of world coordinates.
/// `unique_points`: the closest points are unique, so compare them too. The normal is always
/// unique for separated convex shapes (the closest point of the Minkowski difference is).
inline void expect_matches(const Answer& expected, const mink::DistanceResult& got,
                           const mink::IntersectResult& got_bool, double size,
                           double position_scale, bool unique_points, Worst& worst) {
  ASSERT_FALSE(has_nan(got)) << "NaN in distance result";
  ASSERT_NE(got.status, mink::Status::InvalidInput) << got.error;
  EXPECT_NE(got.status, mink::Status::IterationLimit);
  const double gap = static_cast<double>(expected.gap);
  const double band = kTouchingBand * size;
  if (std::abs(gap) <= band) {
    ++worst.touching;
    // Touching: the distance must still be tiny whichever way the flag went.
    EXPECT_LE(got.distance, band) << "touching case, tolerance " << band;
    return;
  }
  if (gap < 0) {
    ++worst.intersecting;
    EXPECT_TRUE(got.intersect) << "oracle gap " << gap;
    EXPECT_EQ(got.status, mink::Status::Intersecting);
    EXPECT_EQ(got.distance, 0.0);
    EXPECT_TRUE(got_bool.intersect) << "intersect() disagrees, oracle gap " << gap;
    return;
  }
  ++worst.separated;
  EXPECT_FALSE(got.intersect) << "oracle gap " << gap;
  EXPECT_EQ(got.status, mink::Status::Separated);
  EXPECT_FALSE(got_bool.intersect) << "intersect() disagrees, oracle gap " << gap;
  const double derr = std::abs(got.distance - static_cast<double>(expected.distance)) / size;
  worst.distance = std::max(worst.distance, derr);
  EXPECT_LE(derr, kDistanceTolerance)
      << "distance " << got.distance << " oracle " << static_cast<double>(expected.distance)
      << " (relative tolerance " << kDistanceTolerance << ")";
  // Normal: its error is about the points' error over the distance; compare when the distance is
  // not tiny against the size (tolerance 1e-8 absolute on a unit vector).
  if (gap > 1e-3 * size) {
    const double nerr = (got.normal - expected.normal.cast<double>()).norm();
    worst.normal = std::max(worst.normal, nerr);
    EXPECT_LE(nerr, 1e-8) << "normal " << got.normal.transpose() << " oracle "
                          << expected.normal.cast<double>().transpose() << " (tolerance 1e-8)";
  }
  EXPECT_NEAR(got.normal.norm(), 1.0, 1e-12) << "normal not unit (tolerance 1e-12)";
  // point_b - point_a = distance * normal (tolerance 1e-10 relative to size + position).
  const double consistency =
      (got.point_b - got.point_a - got.distance * got.normal).norm() / (size + position_scale);
  EXPECT_LE(consistency, 1e-10) << "point_b - point_a != distance * normal";
  if (unique_points) {
    const double scale = size + position_scale;
    const double perr = std::max((got.point_a - expected.point_a.cast<double>()).norm(),
                                 (got.point_b - expected.point_b.cast<double>()).norm()) /
                        scale;
    worst.point = std::max(worst.point, perr);
    EXPECT_LE(perr, 1e-9) << "points a " << got.point_a.transpose() << " b "
                          << got.point_b.transpose() << " oracle a "
                          << expected.point_a.cast<double>().transpose() << " b "
                          << expected.point_b.cast<double>().transpose()
                          << " (relative tolerance 1e-9)";
  }
}

}  // namespace oracle
