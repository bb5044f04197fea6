/// @file shape.hpp
/// Shape: any shape of mink chosen at run time (for the command line, bindings and scenes).
///
/// A Shape is a Minkowski sum of primitive cores plus a radius, so every composition the JSON
/// protocol allows (sums of sums, rounded sums, rounded spheres) flattens into one plain value:
/// a sphere is its centre (a Sphere core of radius 0), a capsule its segment (a Capsule core of
/// radius 0), `rounded` adds to the radius and `sum` concatenates the cores and adds the radii.
/// Queries on two Shapes dispatch once on the pair of core types and then run the same inlined
/// template code as the static shapes.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "mink/expected.hpp"
#include "mink/shapes/box.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/hull_shape.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/polytope.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/shapes/triangle.hpp"
#include "mink/support/concept.hpp"

namespace mink {

/// Polytopes and hulls are shared, not copied, when a Shape is copied.
using SharedPolytope = std::shared_ptr<const Polytope>;
using SharedHull = std::shared_ptr<const ConvexHullShape>;

/// The primitive cores a Shape is made of. Every alternative has radius 0: a sphere's core is held
/// as a Sphere of radius 0 (the origin) and a capsule's as a Capsule of radius 0 (the segment
/// along z of its half height); the radius is the Shape's. A Point or a Segment would be the same
/// set, but their queries rotate the point or both end points and check their coordinates, where a
/// sphere's take the pose's translation and a capsule's scale one column of the rotation: a
/// capsule pair through a Shape took 20 ns for intersect() against the typed call's 8.
using Core = std::variant<Point, Sphere, Segment, Capsule, Triangle, Box, Cylinder, Cone, Ellipsoid,
                          SharedPolytope, SharedHull>;

namespace detail {
template <class T>
inline constexpr bool kSharedCore =
    std::is_same_v<T, SharedPolytope> || std::is_same_v<T, SharedHull>;
}  // namespace detail

class Shape {
 public:
  using Scalar = double;

  /// Each factory validates its input and says what is wrong.
  static Expected<Shape> sphere(double radius);
  static Expected<Shape> box(const Vec3& half_extents);
  static Expected<Shape> capsule(double radius, double half_height);
  static Expected<Shape> cylinder(double radius, double half_height);
  static Expected<Shape> cone(double radius, double half_height);
  /// Three equal radii give a sphere: its centre as the core, with that radius, as sphere() builds
  /// it.
  static Expected<Shape> ellipsoid(const Vec3& radii);
  /// A point at the origin is held as a Sphere core of radius 0, as sphere(0) builds it (the
  /// same set, and its faster closed forms); cores() shows that core.
  static Expected<Shape> point(const Vec3& p);
  /// A segment symmetric about the origin along z (a == -b) is held as a Capsule core, as
  /// capsule(0, |b.z|) builds it (a Sphere core when a == b == 0); cores() shows that core.
  static Expected<Shape> segment(const Vec3& a, const Vec3& b);
  static Expected<Shape> triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  /// The convex hull of `points` (Polytope): support scans them, with no set-up cost, and a set of
  /// 64 points or more switches to climbing its hull after kPolytopeHullAfterSupports queries
  /// (shapes/polytope.hpp, "From scan to hull"): one-off queries never build a hull, shapes kept
  /// across many queries climb. Errors: no points, a NaN or infinite coordinate.
  static Expected<Shape> polytope(std::span<const Vec3> points);
  /// The convex hull of the same points as a ConvexHullShape: the hull built now, support by
  /// climbing from the first query, for shapes known to be kept. Same support values as
  /// polytope() up to the hull's tolerance (shapes/hull_shape.hpp, "Accuracy"). Building costs
  /// about as much as 2,000 to 6,000 scans of the points (docs/architecture.md, "Hull shape").
  /// Errors: as build_convex_hull.
  static Expected<Shape> convex_hull(std::span<const Vec3> points);
  /// A hull shape from a built hull (for instance with HullOptions::max_vertices).
  static Expected<Shape> convex_hull(const ConvexHull& hull);
  /// Minkowski sum ("sweep") of two shapes in the same frame.
  static Expected<Shape> sum(const Shape& a, const Shape& b);
  /// The shape grown by `margin` ("collision skin").
  static Expected<Shape> rounded(const Shape& shape, double margin);

  /// The same shape with every length (coordinates, extents, radii) multiplied by `factor`
  /// (finite, > 0; a power of two keeps it exact). Polytopes are copied and hulls rebuilt from
  /// their vertices. The run-time queries solve pairs of tiny or huge shapes this way
  /// (src/shape_dispatch.hpp). Errors: a bad factor, or lengths that overflow.
  Expected<Shape> scaled(double factor) const;

  /// The cores, in canonical form: wherever a Shape is made or scaled, a point at the origin (or
  /// a capsule's core of no length) becomes a Sphere core and a segment symmetric about the
  /// origin along z a Capsule core (the same sets).
  const std::vector<Core>& cores() const { return cores_; }

  Vec3 support_core(const Vec3& d) const;
  Vec3 core_centre() const;
  double core_radius() const { return radius_; }
  double bounding_radius() const { return bounding_radius_; }
  const char* error() const { return cores_.empty() ? "shape is empty" : nullptr; }

 private:
  static Expected<Shape> from_core(Core core, double radius);
  std::vector<Core> cores_;
  double radius_ = 0;
  double bounding_radius_ = 0;
};

template <class T>
struct ScaledCopy;  // query/scale_range.hpp

/// A Shape's scaled copy for the queries' range of lengths (query/scale_range.hpp): the run-time
/// queries solve tiny and huge pairs through it, as the typed ones do.
template <>
struct ScaledCopy<Shape> {
  static double length(const Shape& shape) { return shape.bounding_radius(); }
  static std::optional<Shape> copy(const Shape& shape, double factor) {
    auto scaled = shape.scaled(factor);
    if (!scaled) return std::nullopt;
    return std::move(scaled).value();
  }
};

/// Calls `f` on the primitive behind `core`: the shape itself, or the one a shared pointer holds
/// (not null: Shape's factories never store a null one).
template <class F>
decltype(auto) visit_core(const Core& core, F&& f) {
  return std::visit(
      [&f](const auto& c) -> decltype(auto) {
        if constexpr (detail::kSharedCore<std::decay_t<decltype(c)>>)
          return f(*c);
        else
          return f(c);
      },
      core);
}

/// Support of one primitive core.
inline Vec3 support_core(const Core& core, const Vec3& d) {
  return visit_core(core, [&d](const auto& c) -> Vec3 { return c.support_core(d); });
}

/// A point of one primitive core towards its middle.
inline Vec3 core_centre(const Core& core) {
  return visit_core(core, [](const auto& c) -> Vec3 { return c.core_centre(); });
}

inline Vec3 Shape::core_centre() const {
  Vec3 centre = Vec3::Zero();
  for (const Core& core : cores_) centre += mink::core_centre(core);
  return centre;
}

inline Vec3 Shape::support_core(const Vec3& d) const {
  Vec3 s = mink::support_core(cores_[0], d);
  for (std::size_t i = 1; i < cores_.size(); ++i) s += mink::support_core(cores_[i], d);
  return s;
}

}  // namespace mink
