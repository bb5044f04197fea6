/// @file axial_pair.hpp
/// Penetration depth of two solids of revolution whose axes are parallel (coincident or coaxial
/// cylinders, cones, spheroids, a sphere on a cone's axis), as a problem in the plane.
///
/// Why: where the cores of such a pair overlap, A - B is a solid of revolution too, and when the
/// origin lies on its axis (coaxial shapes, coincident ones) every normal around a circle is as
/// good as any other. EPA then refines a polytope inscribed in that circle until its faces' sag
/// is below its tolerance: tens of thousands of faces, so it ran into its cap (80-150 us, status
/// IterationLimit, for two coincident cylinders).
///
/// How: A - B is symmetric about the line through c_a - c_b (the cores' axis points) along the
/// common axis w. The origin lies in one half-plane through that line, along e (the part of
/// c_b - c_a orthogonal to w), and the boundary point of A - B nearest to it lies in that plane:
/// the support value of A - B in a direction depends on its angle to w only, apart from the term
/// the origin's offset adds, which is largest towards e. So the depth is the distance from the
/// origin to the boundary of A - B's section by the plane span(e, w), a convex set in the plane,
/// and EPA in two dimensions finds it: each step splits one edge of a polygon inscribed in the
/// section, so it is exact on polygonal sections (cylinders, cones, segments) and converges on
/// curved ones (spheroids) in a few dozen steps.
///
/// Axes count as parallel when their angle, times the larger bounding radius, is within a
/// hundredth of EPA's tolerance (`relative_depth * size`): taking one for the other then moves a
/// shape's points by less than that, and `error_bound` includes it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mink/gjk/gjk.hpp"
#include "mink/math/orthogonal.hpp"
#include "mink/query/status.hpp"
#include "mink/query/tolerances.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// How a core is symmetric: about a line (`axis` through `centre`), about every line through
/// `centre` (a point), or not at all.
enum class AxisKind { None, Line, Any };

template <class S>
struct CoreAxis {
  AxisKind kind = AxisKind::None;
  Vec3T<S> centre = Vec3T<S>::Zero();  ///< a point of the axis (local frame)
  Vec3T<S> axis = Vec3T<S>::UnitZ();   ///< unit (local frame), for AxisKind::Line
};

/// AxialCore<T>::of(shape): the symmetry of T's core, for the cores that are solids (or points and
/// segments) of revolution.
template <class T>
struct AxialCore : std::false_type {};

template <class S>
struct AxialCore<CylinderT<S>> : std::true_type {
  static CoreAxis<S> of(const CylinderT<S>&) { return {AxisKind::Line}; }
};
template <class S>
struct AxialCore<ConeT<S>> : std::true_type {
  static CoreAxis<S> of(const ConeT<S>&) { return {AxisKind::Line}; }
};
template <class S>
struct AxialCore<CapsuleT<S>> : std::true_type {
  static CoreAxis<S> of(const CapsuleT<S>&) { return {AxisKind::Line}; }
};
template <class S>
struct AxialCore<SphereT<S>> : std::true_type {
  static CoreAxis<S> of(const SphereT<S>&) { return {AxisKind::Any}; }
};
template <class S>
struct AxialCore<PointT<S>> : std::true_type {
  static CoreAxis<S> of(const PointT<S>& p) { return {AxisKind::Any, p.position}; }
};
template <class S>
struct AxialCore<SegmentT<S>> : std::true_type {
  static CoreAxis<S> of(const SegmentT<S>& s) {
    const Vec3T<S> along = s.b - s.a;
    if (along == Vec3T<S>::Zero()) return {AxisKind::Any, s.a};
    return {AxisKind::Line, s.core_centre(), unit_of(along)};
  }
};
/// A spheroid: two equal radii, the axis along the third.
template <class S>
struct AxialCore<EllipsoidT<S>> : std::true_type {
  static CoreAxis<S> of(const EllipsoidT<S>& e) {
    const Vec3T<S>& r = e.radii;
    if (r.x() == r.y() && r.y() == r.z()) return {AxisKind::Any};
    if (r.x() == r.y()) return {AxisKind::Line, Vec3T<S>::Zero(), Vec3T<S>::UnitZ()};
    if (r.x() == r.z()) return {AxisKind::Line, Vec3T<S>::Zero(), Vec3T<S>::UnitY()};
    if (r.y() == r.z()) return {AxisKind::Line, Vec3T<S>::Zero(), Vec3T<S>::UnitX()};
    return {};
  }
};
template <class T>
struct AxialCore<Rounded<T>> : std::bool_constant<AxialCore<T>::value> {
  static auto of(const Rounded<T>& r) { return AxialCore<T>::of(r.shape); }
};

template <class A, class B>
inline constexpr bool kAxialPair = AxialCore<A>::value&& AxialCore<B>::value;

/// The answer of axial_depth(), in A's frame, for the cores.
template <class S>
struct AxialDepth {
  Status status = Status::Intersecting;  ///< or IterationLimit (the cap, bounds apart)
  /// The cores' depth, >= 0: the nearest edge's distance when the planar EPA closed its bracket;
  /// at the cap, the least support value seen (which separates the shapes), as EPA answers.
  S depth = S(0);
  Vec3T<S> normal;      ///< unit, the direction B moves to separate
  Vec3T<S> on_a, on_b;  ///< deepest points of the cores: on_b - on_a = -depth n
  S error_bound = S(0);
  int iterations = 0;
  bool normal_chosen = false;  ///< the origin on the axis: every normal around it was as good
};

/// Steps of the planar EPA. Polygonal sections need a handful; a spheroid's, about 2 log2 of
/// 1 / tolerance.
inline constexpr int kAxialMaxVertices = 128;

/// The depth of the cores of diff.a and diff.b (B posed by diff.rotation, diff.translation in A's
/// frame) when both are solids of revolution about parallel axes (see the file comment); nothing
/// when they are not, or when the planar section has no area or shows the cores apart (the
/// caller's EPA answers then). `size`: the sum of the bounding radii.
template <class A, class B>
std::optional<AxialDepth<typename A::Scalar>> axial_depth(
    const CoreDifference<A, B>& diff, typename A::Scalar size,
    const TolerancesT<typename A::Scalar>& tol) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const CoreAxis<S> axis_a = AxialCore<A>::of(diff.a), axis_b = AxialCore<B>::of(diff.b);
  if (axis_a.kind == AxisKind::None || axis_b.kind == AxisKind::None) return std::nullopt;
  if (axis_a.kind == AxisKind::Any && axis_b.kind == AxisKind::Any) return std::nullopt;
  const V centre_a = axis_a.centre;
  const V centre_b = diff.rotation * axis_b.centre + diff.translation;
  const V axis_b_in_a = diff.rotation * axis_b.axis;
  const V w = axis_a.kind == AxisKind::Line ? axis_a.axis : axis_b_in_a;
  // The angle between the axes moves B's points by at most tilt times its bounding radius.
  S tilt_error = S(0);
  if (axis_a.kind == AxisKind::Line && axis_b.kind == AxisKind::Line) {
    const S tilt = w.cross(axis_b_in_a).norm();
    tilt_error = tilt * std::max(diff.a.bounding_radius(), diff.b.bounding_radius());
    if (!(tilt_error <= S(0.01) * tol.relative_depth * size)) return std::nullopt;
  }
  // e: towards the origin's side of A - B's axis, which passes through centre_a - centre_b.
  const V offset = centre_b - centre_a;
  const V radial = offset - offset.dot(w) * w;
  bool on_axis = radial == V::Zero();
  V e;
  if (!on_axis) {
    e = unit_of(radial);
    e -= e.dot(w) * w;  // the rounding of the projection, along w
    on_axis = !(e.squaredNorm() > S(0.25));
  }
  // On the axis every direction orthogonal to w is as good: orthogonal()'s (A's +x for an axis
  // along z, the common case).
  if (on_axis) e = orthogonal(w).cross(w);
  e = unit_of(e);
  const V f = w.cross(e);  // normal to the plane: support points are projected into it

  struct Vertex {
    S x, y;  // the point of A - B in the plane: along e, along w
    V a, b;  // its points of the cores, in the planes through their axes
  };
  struct Edge {
    S nx, ny, distance;  // outward unit normal of the edge from this vertex to the next; its offset
  };
  Vertex vertices[kAxialMaxVertices];
  Edge edges[kAxialMaxVertices];
  int count = 0, iterations = 0;
  S upper = std::numeric_limits<S>::infinity();  // the least support value seen, in best_u
  Vertex best{};
  S best_u[2] = {S(1), S(0)};
  auto support = [&](S ux, S uy) {
    SimplexVertexT<S> s;
    diff.support(ux * e + uy * w, s);
    ++iterations;
    Vertex v;
    // Ties (a cylinder's cap along w) may leave the plane; the projection of a point of a solid
    // of revolution onto a plane through its axis lies in the solid, with the same support value.
    v.a = s.a - (s.a - centre_a).dot(f) * f;
    v.b = s.b - (s.b - centre_b).dot(f) * f;
    const V point = v.a - v.b;
    v.x = point.dot(e);
    v.y = point.dot(w);
    if (const S value = ux * v.x + uy * v.y; value < upper) {
      upper = value;
      best = v;
      best_u[0] = ux;
      best_u[1] = uy;
    }
    return v;
  };
  auto make_edge = [](const Vertex& p, const Vertex& q) {
    const S dx = q.x - p.x, dy = q.y - p.y;
    const S length = std::hypot(dx, dy);
    Edge edge{dy / length, -dx / length, S(0)};
    edge.distance = edge.nx * p.x + edge.ny * p.y;
    return edge;
  };
  // Eight directions around: their support points come in counter-clockwise order.
  constexpr S kDiagonal = S(0.70710678118654752440);
  const S start[8][2] = {{1, 0},  {kDiagonal, kDiagonal},   {0, 1},  {-kDiagonal, kDiagonal},
                         {-1, 0}, {-kDiagonal, -kDiagonal}, {0, -1}, {kDiagonal, -kDiagonal}};
  for (const auto& u : start) {
    const Vertex v = support(u[0], u[1]);
    if (count > 0 && v.x == vertices[count - 1].x && v.y == vertices[count - 1].y) continue;
    vertices[count++] = v;
  }
  while (count > 1 && vertices[count - 1].x == vertices[0].x &&
         vertices[count - 1].y == vertices[0].y)
    --count;
  if (count < 3) return std::nullopt;  // a segment or a point: no area, EPA's degenerate rules
  for (int i = 0; i < count; ++i) edges[i] = make_edge(vertices[i], vertices[(i + 1) % count]);
  // A zero-length or inward edge means the polygon is not convex after all (rounding of a
  // section thinner than it): leave it to EPA.
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(edges[i].distance)) return std::nullopt;

  const S touch = tol.relative * size;
  const S target = tol.relative * size;  // the plane is cheap: aim at GJK's tolerance
  S scale = S(0);
  for (int i = 0; i < count; ++i)
    scale = std::max({scale, std::abs(vertices[i].x), std::abs(vertices[i].y)});
  const S floor = S(16) * std::numeric_limits<S>::epsilon() * scale;
  int nearest = 0;
  bool converged = false;
  while (true) {
    nearest = 0;
    for (int i = 1; i < count; ++i)
      if (edges[i].distance < edges[nearest].distance) nearest = i;
    const Edge edge = edges[nearest];
    if (count == kAxialMaxVertices || iterations >= tol.max_iterations) break;
    // EPA's rule: done when the support along the nearest edge's own normal gains at most the
    // tolerance on it, so that its normal is as good as its distance (a bound from other
    // directions would leave its normal off by the square root of the tolerance).
    const Vertex v = support(edge.nx, edge.ny);
    if (upper < -touch) return std::nullopt;  // a direction shows the cores apart
    const S gain = edge.nx * v.x + edge.ny * v.y - edge.distance;
    if (!(gain > std::max(target, floor))) {
      converged = edge.distance >= S(0);
      break;
    }
    // Insert v between nearest and next.
    for (int i = count; i > nearest + 1; --i) {
      vertices[i] = vertices[i - 1];
      edges[i] = edges[i - 1];
    }
    vertices[nearest + 1] = v;
    ++count;
    edges[nearest] = make_edge(vertices[nearest], v);
    edges[nearest + 1] = make_edge(v, vertices[(nearest + 2) % count]);
    if (!std::isfinite(edges[nearest].distance) || !std::isfinite(edges[nearest + 1].distance))
      return std::nullopt;
  }
  const Edge edge = edges[nearest];
  if (!(edge.distance >= S(0))) return std::nullopt;  // the origin is not proven inside
  const S lower = edge.distance;
  AxialDepth<S> out;
  out.iterations = iterations;
  out.error_bound = std::max(S(0), upper - lower) + tilt_error;
  if (converged) {
    // The point of the nearest edge closest to the origin, and the cores' points there. A flat
    // side of the section may be split into several edges in a line (a cylinder's support along
    // its side is any point of it), and the nearest one need not hold the origin's foot: take,
    // among the edges in line with it, the one the foot lies on (or least beyond).
    auto foot_parameter = [&](int i) {
      const Vertex& p = vertices[i];
      const Vertex& q = vertices[(i + 1) % count];
      const S dx = q.x - p.x, dy = q.y - p.y;
      return ((lower * edge.nx - p.x) * dx + (lower * edge.ny - p.y) * dy) / (dx * dx + dy * dy);
    };
    auto beyond = [](S t) { return std::max({S(0), -t, t - S(1)}); };
    int holder = nearest;
    S t = foot_parameter(nearest);
    for (int i = 0; i < count && beyond(t) > S(0); ++i) {
      const Edge& other = edges[i];
      if (i == nearest || other.nx * edge.nx + other.ny * edge.ny < S(1) - S(1e-9) ||
          std::abs(other.distance - lower) > std::max(target, floor))
        continue;
      if (const S ti = foot_parameter(i); beyond(ti) < beyond(t)) {
        holder = i;
        t = ti;
      }
    }
    t = std::clamp(t, S(0), S(1));
    const Vertex& p = vertices[holder];
    const Vertex& q = vertices[(holder + 1) % count];
    out.depth = lower;
    out.normal = unit_of(V(edge.nx * e + edge.ny * w));
    out.on_a = p.a + t * (q.a - p.a);
    out.on_b = p.b + t * (q.b - p.b);
  } else {
    // The cap, on a section nearly as round as a circle about the origin (a spheroid all but a
    // sphere): as EPA does, the upper end, which separates the shapes, with its support points;
    // what is left of a - b - depth n (the offset of the support point along the section) is
    // split between them so that on_b - on_a = -depth n holds.
    out.depth = upper;
    out.normal = unit_of(V(best_u[0] * e + best_u[1] * w));
    const V residual = S(0.5) * (best.a - best.b - upper * out.normal);
    out.on_a = best.a - residual;
    out.on_b = best.b + residual;
  }
  out.normal_chosen = on_axis && std::abs(out.normal.dot(e)) > S(0);
  if (on_axis && out.normal.dot(e) < S(0)) {
    // The mirror image across the plane through the axis orthogonal to e is as good: answer on
    // e's side, so that the choice is the documented one.
    out.normal -= S(2) * out.normal.dot(e) * e;
    out.on_a -= S(2) * (out.on_a - centre_a).dot(e) * e;
    out.on_b -= S(2) * (out.on_b - centre_b).dot(e) * e;
  }
  out.status = converged || upper - lower <= tol.relative_depth * size ? Status::Intersecting
                                                                       : Status::IterationLimit;
  return out;
}

}  // namespace mink::detail
