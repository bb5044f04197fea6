/// @file shape_zoo.hpp
/// Every kind of shape the queries accept, described by plain parameters so that the tests can
/// build it three ways: as a static mink type, as a run-time mink::Shape, and as this file's own
/// support function and membership test (written here from the shape's definition, not taken from
/// mink).
#pragma once

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/random.hpp"

namespace zoo {

using mink::Vec3;
using oracle::Real;
using oracle::V3;

enum Kind {
  kSphere,
  kBox,
  kCapsule,
  kCylinder,
  kCone,
  kEllipsoid,
  kPolytope,
  kPoint,
  kSegment,
  kTriangle,
  kSumSegmentBox,  ///< MinkowskiSum{Segment, Box}
  kRoundedCone,    ///< Rounded{Cone, margin}
  kKindCount
};

inline const char* kind_name(int kind) {
  static const char* const kNames[] = {"sphere",  "box",       "capsule",          "cylinder",
                                       "cone",    "ellipsoid", "polytope",         "point",
                                       "segment", "triangle",  "sum(segment,box)", "rounded(cone)"};
  return kNames[kind];
}

/// A shape by its parameters. r, h: radius and half height; v: box half extents or ellipsoid
/// radii; p, q, c: point, segment and triangle corners; points: polytope; margin: rounding.
struct Desc {
  int kind = kSphere;
  double r = 0, h = 0, margin = 0;
  Vec3 v = Vec3::Zero(), p = Vec3::Zero(), q = Vec3::Zero(), c = Vec3::Zero();
  std::vector<Vec3> points;

  std::string describe() const {
    std::ostringstream out;
    out.precision(17);
    auto vec = [&out](const char* name, const Vec3& x) {
      out << ' ' << name << "(" << x.x() << ", " << x.y() << ", " << x.z() << ")";
    };
    out << kind_name(kind) << " r=" << r << " h=" << h << " margin=" << margin;
    vec("v=", v);
    vec("p=", p);
    vec("q=", q);
    vec("c=", c);
    out << " points:";
    for (const Vec3& x : points) vec("", x);
    return out.str();
  }
};

inline Desc random_desc(oracle::Rng& rng, int kind, double scale) {
  Desc d;
  d.kind = kind;
  auto len = [&] { return scale * rng.log_uniform(0.1, 1.5); };
  d.r = len();
  d.h = len();
  d.margin = len() * 0.3;
  d.v = Vec3(len(), len(), len());
  d.p = rng.in_ball(scale);
  d.q = rng.in_ball(scale);
  d.c = rng.in_ball(scale);
  const int count = rng.integer(1, 10);
  for (int i = 0; i < count; ++i) d.points.push_back(rng.in_ball(scale));
  if (kind == kPoint) d.p = rng.in_ball(0.3 * scale);
  return d;
}

// ---- Own support values and membership (long double, local frame) ----

inline Real rho(const V3& n) {
  return std::sqrt(n.x() * n.x() + n.y() * n.y());
}

inline Real cone_support(Real r, Real h, const V3& n) {
  return std::max(h * n.z(), r * rho(n) - h * n.z());
}

/// max over the shape of n.x (n need not be unit).
inline Real support_value(const Desc& d, const V3& n) {
  const V3 p = oracle::widen(d.p), q = oracle::widen(d.q), c = oracle::widen(d.c);
  const V3 v = oracle::widen(d.v);
  const Real r = d.r, h = d.h;
  auto box = [&] {
    return v.x() * std::abs(n.x()) + v.y() * std::abs(n.y()) + v.z() * std::abs(n.z());
  };
  switch (d.kind) {
    case kSphere:
      return r * n.norm();
    case kBox:
      return box();
    case kCapsule:
      return h * std::abs(n.z()) + r * n.norm();
    case kCylinder:
      return r * rho(n) + h * std::abs(n.z());
    case kCone:
      return cone_support(r, h, n);
    case kEllipsoid:
      return v.cwiseProduct(n).norm();
    case kPolytope: {
      Real best = -std::numeric_limits<Real>::infinity();
      for (const Vec3& x : d.points) best = std::max(best, n.dot(oracle::widen(x)));
      return best;
    }
    case kPoint:
      return n.dot(p);
    case kSegment:
      return std::max(n.dot(p), n.dot(q));
    case kTriangle:
      return std::max({n.dot(p), n.dot(q), n.dot(c)});
    case kSumSegmentBox:
      return std::max(n.dot(p), n.dot(q)) + box();
    case kRoundedCone:
      return cone_support(r, h, n) + d.margin * n.norm();
  }
  return 0;
}

inline Real set_distance(std::vector<V3> pts, const V3& x) {
  for (V3& y : pts) y -= x;
  return oracle::hull_distance(pts).distance;
}

inline std::vector<V3> box_corners_local(const V3& half) {
  return oracle::box_corners({half, oracle::M3::Identity(), V3::Zero()});
}

/// Distance from x to the solid cone (0 inside), through the meridian half-plane of x: the cone's
/// section there is the triangle (0,-h), (r,-h), (0,h) in (radius, z).
inline Real cone_distance(Real r, Real h, const V3& x) {
  return set_distance({V3(0, 0, -h), V3(r, 0, -h), V3(0, 0, h)}, V3(rho(x), 0, x.z()));
}

/// Distance from x to the shape (0 inside), or nothing when this file has no membership test.
inline std::optional<Real> distance_to(const Desc& d, const V3& x) {
  const V3 p = oracle::widen(d.p), q = oracle::widen(d.q), c = oracle::widen(d.c);
  const V3 v = oracle::widen(d.v);
  const Real r = d.r, h = d.h;
  switch (d.kind) {
    case kSphere:
      return std::max(Real(0), x.norm() - r);
    case kBox:
      return set_distance(box_corners_local(v), x);
    case kCapsule:
      return std::max(
          Real(0), (x - oracle::closest_on_segment(V3(0, 0, -h), V3(0, 0, h), x).point).norm() - r);
    case kCylinder: {
      const Real dr = std::max(Real(0), rho(x) - r), dz = std::max(Real(0), std::abs(x.z()) - h);
      return std::sqrt(dr * dr + dz * dz);
    }
    case kCone:
      return cone_distance(r, h, x);
    case kEllipsoid: {
      // Inside test only: the scaled point within the unit ball (up to 1e-9 relative).
      const Real s = x.cwiseQuotient(v).norm();
      return s <= 1 + Real(1e-9) ? Real(0) : (s - 1) * v.minCoeff();
    }
    case kPolytope: {
      std::vector<V3> pts;
      for (const Vec3& y : d.points) pts.push_back(oracle::widen(y));
      return set_distance(pts, x);
    }
    case kPoint:
      return (x - p).norm();
    case kSegment:
      return (x - oracle::closest_on_segment(p, q, x).point).norm();
    case kTriangle:
      return set_distance({p, q, c}, x);
    case kSumSegmentBox: {
      std::vector<V3> pts;
      for (const V3& corner : box_corners_local(v)) {
        pts.push_back(corner + p);
        pts.push_back(corner + q);
      }
      return set_distance(pts, x);
    }
    case kRoundedCone:
      return std::max(Real(0), cone_distance(r, h, x) - d.margin);
  }
  return std::nullopt;
}

/// A bounding radius about the local origin (the natural scale of the shape).
inline double size_of(const Desc& d) {
  switch (d.kind) {
    case kSphere:
      return d.r;
    case kBox:
      return d.v.norm();
    case kCapsule:
      return d.r + d.h;
    case kCylinder:
    case kCone:
      return std::hypot(d.r, d.h);
    case kEllipsoid:
      return d.v.maxCoeff();
    case kPolytope: {
      double m = 0;
      for (const Vec3& x : d.points) m = std::max(m, x.norm());
      return m;
    }
    case kPoint:
      return d.p.norm();
    case kSegment:
      return std::max(d.p.norm(), d.q.norm());
    case kTriangle:
      return std::max({d.p.norm(), d.q.norm(), d.c.norm()});
    case kSumSegmentBox:
      return std::max(d.p.norm(), d.q.norm()) + d.v.norm();
    case kRoundedCone:
      return std::hypot(d.r, d.h) + d.margin;
  }
  return 0;
}

// ---- The same shape as mink types ----

using Static =
    std::variant<mink::Sphere, mink::Box, mink::Capsule, mink::Cylinder, mink::Cone,
                 mink::Ellipsoid, mink::Polytope, mink::Point, mink::Segment, mink::Triangle,
                 mink::MinkowskiSum<mink::Segment, mink::Box>, mink::Rounded<mink::Cone>>;

inline Static make_static(const Desc& d) {
  switch (d.kind) {
    case kSphere:
      return mink::Sphere{d.r};
    case kBox:
      return mink::Box{d.v};
    case kCapsule:
      return mink::Capsule{d.r, d.h};
    case kCylinder:
      return mink::Cylinder{d.r, d.h};
    case kCone:
      return mink::Cone{d.r, d.h};
    case kEllipsoid:
      return mink::Ellipsoid{d.v};
    case kPolytope:
      return mink::Polytope::make(d.points).value();
    case kPoint:
      return mink::Point{d.p};
    case kSegment:
      return mink::Segment{d.p, d.q};
    case kTriangle:
      return mink::Triangle{d.p, d.q, d.c};
    case kSumSegmentBox:
      return mink::MinkowskiSum<mink::Segment, mink::Box>{mink::Segment{d.p, d.q}, mink::Box{d.v}};
    case kRoundedCone:
      return mink::Rounded<mink::Cone>{mink::Cone{d.r, d.h}, d.margin};
  }
  return mink::Sphere{1};
}

inline mink::Shape make_runtime(const Desc& d) {
  switch (d.kind) {
    case kSphere:
      return mink::Shape::sphere(d.r).value();
    case kBox:
      return mink::Shape::box(d.v).value();
    case kCapsule:
      return mink::Shape::capsule(d.r, d.h).value();
    case kCylinder:
      return mink::Shape::cylinder(d.r, d.h).value();
    case kCone:
      return mink::Shape::cone(d.r, d.h).value();
    case kEllipsoid:
      return mink::Shape::ellipsoid(d.v).value();
    case kPolytope:
      return mink::Shape::polytope(d.points).value();
    case kPoint:
      return mink::Shape::point(d.p).value();
    case kSegment:
      return mink::Shape::segment(d.p, d.q).value();
    case kTriangle:
      return mink::Shape::triangle(d.p, d.q, d.c).value();
    case kSumSegmentBox:
      return mink::Shape::sum(mink::Shape::segment(d.p, d.q).value(), mink::Shape::box(d.v).value())
          .value();
    case kRoundedCone:
      return mink::Shape::rounded(mink::Shape::cone(d.r, d.h).value(), d.margin).value();
  }
  return mink::Shape::sphere(1).value();
}

}  // namespace zoo
