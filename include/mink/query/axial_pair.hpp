/// @file axial_pair.hpp
/// Penetration depth of two solids of revolution whose axes are parallel or nearly so (coincident
/// or coaxial cylinders, cones, spheroids, a sphere on a cone's axis), as problems in the plane.
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
///
/// Axes tilted by more than that but at most kAxialMaxTilt: A - B is no longer symmetric, but
/// every direction lies in some plane through A's axis, and A - B's support values along the
/// directions of a plane are those of its projection onto the plane. So the depth is the least,
/// over the planes' angle, of the origin's depth in the projection, a planar EPA each
/// (tilted_axial_depth()). The tilt makes that a small change of a function that was constant
/// (coincident shapes) or had one smooth minimum (the origin off the axis), apart from notches at
/// two planes known in advance, which those planes, a scan and Brent's method find; EPA in space
/// refined the nearly round polytope around the circle of nearly equal normals and ran into its cap
/// (coincident cones tilted by 1e-6 rad: 9e-7 off, 65 us, IterationLimit; now exact to 1e-12, about
/// 400 support calls). Away from A - B's axis (side by side, end to end) there is no such band,
/// and EPA in space goes first (epa_suits_tilted_axes()), the planes only where it stops at
/// kAxialEpaBudget.
///
/// Tilted further, EPA in space answers first, in a third of the time, but a spheroid against a
/// cone, capsule or spheroid (a nearly round section: a band of nearly equal normals) can still
/// stop it at its cap; then the same planes do (kAxialFallbackTilt).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"
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
  /// A cone's side normal along the axis: the sine of its lean from the plane across the axis,
  /// in (0, 1); 0 for the other cores, whose flat sides (if any) lie along the axis or across it,
  /// as a disc's (a cone of no height, or so little that the sine rounds to 1) does.
  S slant = S(0);
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
  static CoreAxis<S> of(const ConeT<S>& c) {
    // The side from the rim (radius, -h) to the apex (0, h) has the normal (2h, radius).
    const S length = planar_length(S(2) * c.half_height, c.radius);
    const S sine = length > S(0) ? c.radius / length : S(0);
    return {AxisKind::Line, Vec3T<S>::Zero(), Vec3T<S>::UnitZ(), sine < S(1) ? sine : S(0)};
  }
};
/// A capsule of no length is a sphere, symmetric about every line through its centre, as a
/// segment of no length is a point: as a line, a sphere's centre 1e-6 off a cylinder's axis ran
/// EPA to its cap (2,103 support calls, the depth 3.6e-7 short).
template <class S>
struct AxialCore<CapsuleT<S>> : std::true_type {
  static CoreAxis<S> of(const CapsuleT<S>& c) {
    return {c.half_height == S(0) ? AxisKind::Any : AxisKind::Line};
  }
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
  Status status = Status::Intersecting;  ///< or IterationLimit (a cap, bounds apart)
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

/// Axes tilted by more than this (radians) are left to EPA in space: the least depth over the
/// planes through A's axis is then no longer a small change of a constant, and could have minima
/// narrower than the scan's spacing.
inline constexpr double kAxialMaxTilt = 1e-2;
/// EPA in space's cap on axes tilted by at most kAxialMaxTilt (and more than counts as parallel),
/// before the planes answer (epa_suits_tilted_axes()). Where it closes it takes tens of support
/// calls, up to about 400 on two cylinders side by side (stop 90's probe).
inline constexpr int kAxialEpaBudget = 512;
/// How far off A - B's axis, as a fraction of the section's radius there, the origin must lie for
/// EPA in space to have the first try where the sides hold the least support value. At a
/// hundredth it closed in about 120 support calls (20 us, as long as the planes take); 1e-3 off,
/// it took 350 (85 us), and closer in it stopped at its cap. On stop 90's probe 0.02 and 0.005
/// gave the least time in all, and 0.002 ran into the cap (stop 92).
inline constexpr double kAxialOffAxis = 0.02;
/// After EPA in space stops at its cap, the planes through A's axis answer up to this tilt: at
/// any tilt, since the tilt is measured as the sine of the axes' angle. Far from parallel the
/// least depth over the planes can have minima narrower than the scan's spacing, so contact()
/// takes the planes' answer only where it is no deeper than EPA's polished one (both are support
/// values of A - B, never below the true depth). Random pairs tilted by 3e-3 to 1.57 rad match a
/// dense two-angle oracle to 1e-9 of the size (tests/unit/epa/contact_axial_test.cpp).
inline constexpr double kAxialFallbackTilt = 1.0;
/// Planes the tilted path scans (over half a turn) before refining the best, and its cap on
/// planes in all.
inline constexpr int kAxialScanPlanes = 12;
inline constexpr int kAxialMaxPlanes = 64;

/// Witness points for an answer of the cores, the unit normal n and the depth (B moves by depth
/// along n to separate): points of A and B that touch once B has moved that far. a and b come in
/// as the answer's own points and are replaced by the touching points (returning true) when
/// those are closer to b = a - depth n; either way what is left of a - b - depth n is then shared
/// evenly between them.
///
/// Why: a plane's answer (tilted_axial_depth()) has points of the projection's polygon, which
/// drops what lies off the plane, and a normal known to about 1e-9 rad. Where it lands on a kink
/// of the depth over the normals (two caps whose rims nearly meet, a cone's apex in a cap), the
/// support points along it are rim points of both caps; their offset across n was shared evenly
/// and moved both off their shapes (by up to 3e-5 of the size). Moved apart by depth plus a few
/// touching tolerances, the shapes are separated by about that, and GJK's closest points are
/// points of the shapes (a combination of support points) whose offset is that gap.
template <class A, class B>
bool touching_points(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& n,
                     typename A::Scalar depth, typename A::Scalar size,
                     const TolerancesT<typename A::Scalar>& tol, int& iterations,
                     Vec3T<typename A::Scalar>& a, Vec3T<typename A::Scalar>& b) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const S shift = depth + S(4) * tol.relative * size;
  const CoreDifference<A, B> moved{diff.a, diff.b, diff.rotation, V(diff.translation + shift * n)};
  const auto gjk = run_gjk_distance(moved, S(0), size, tol, nullptr);
  iterations += gjk.iterations;
  V on_a, on_b;
  if (gjk.status == Status::Separated) {
    gjk.simplex.witness_points(on_a, on_b);
    on_b -= shift * n;
  }
  const S given = share_residual(a, b, n, depth);
  if (gjk.status != Status::Separated || !is_finite(on_a) || !is_finite(on_b)) return false;
  if (!(share_residual(on_a, on_b, n, depth) < given)) return false;
  a = on_a;
  b = on_b;
  return true;
}

/// The depth of the origin in A - B seen in the plane span(e, w) (e, w orthonormal, in A's frame):
/// EPA in two dimensions on the projection of the cores' difference onto that plane, whose
/// support value along a direction of the plane is A - B's. With `section` (parallel solids of
/// revolution, the plane through their axes), each core's support point is first projected onto
/// the plane through its own axis point (centre_a, centre_b), which keeps it in the core with the
/// same support value: a tie (a cylinder's cap) may leave the plane. Without it, the answer's
/// points are the projection's polygon's, not yet with on_b - on_a = -depth n (the caller places
/// its best plane's: touching_points()). Nothing when the projection has no area, shows the
/// cores apart, or overflows.
template <class A, class B>
std::optional<AxialDepth<typename A::Scalar>> planar_depth(
    const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& e,
    const Vec3T<typename A::Scalar>& w, bool section, const Vec3T<typename A::Scalar>& centre_a,
    const Vec3T<typename A::Scalar>& centre_b, typename A::Scalar size,
    const TolerancesT<typename A::Scalar>& tol) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const V f = w.cross(e);  // normal to the plane

  struct Vertex {
    S x, y;  // the point of A - B in the plane: along e, along w
    V a, b;  // its points of the cores
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
    Vertex v{S(0), S(0), s.a, s.b};
    if (section) {
      v.a -= (s.a - centre_a).dot(f) * f;
      v.b -= (s.b - centre_b).dot(f) * f;
    }
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
    const S length = planar_length(dx, dy);  // std::hypot() was a twelfth of the planes' time
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
  // A zero-length edge (rounding of a section thinner than that) has no normal: leave it to EPA.
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(edges[i].distance)) return std::nullopt;

  // The plane is cheap: aim at GJK's tolerance, which also tells touching cores.
  const S target = tol.relative * size;
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
    if (upper < -target) return std::nullopt;  // a direction shows the cores apart
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
  out.error_bound = std::max(S(0), upper - lower);
  V a, b;
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
    a = p.a + t * (q.a - p.a);
    b = p.b + t * (q.b - p.b);
  } else {
    // The cap, on a section nearly as round as a circle about the origin (a spheroid all but a
    // sphere): as EPA does, the upper end, which separates the shapes, with its support points.
    out.depth = upper;
    out.normal = unit_of(V(best_u[0] * e + best_u[1] * w));
    a = best.a;
    b = best.b;
  }
  // On a section the projected points are the cores' own (each is symmetric about the plane),
  // and what is left of a - b - depth n (the offset of the support point along the section at the
  // cap) is shared between them so that on_b - on_a = -depth n holds. Off it, the points are the
  // projection's, and tilted_axial_depth() places its best plane's (touching_points()).
  if (section) share_residual(a, b, out.normal, out.depth);
  out.on_a = a;
  out.on_b = b;
  out.status = converged || upper - lower <= tol.relative_depth * size ? Status::Intersecting
                                                                       : Status::IterationLimit;
  return out;
}

/// Parallel axes, the common one w (unit, A's frame), through centre_a and centre_b: the section
/// through the axis and the origin (see the file comment).
template <class A, class B>
std::optional<AxialDepth<typename A::Scalar>> parallel_axial_depth(
    const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& w,
    const Vec3T<typename A::Scalar>& centre_a, const Vec3T<typename A::Scalar>& centre_b,
    typename A::Scalar size, const TolerancesT<typename A::Scalar>& tol) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  // e: towards the origin's side of A - B's axis, which passes through centre_a - centre_b.
  const V offset = centre_b - centre_a;
  const V radial = part_across(offset, w);
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
  auto out = planar_depth(diff, e, w, true, centre_a, centre_b, size, tol);
  if (!out) return out;
  out->normal_chosen = on_axis && std::abs(out->normal.dot(e)) > S(0);
  if (on_axis && out->normal.dot(e) < S(0)) {
    // The mirror image across the plane through the axis orthogonal to e is as good: answer on
    // e's side, so that the choice is the documented one.
    out->normal -= S(2) * out->normal.dot(e) * e;
    out->on_a -= S(2) * (out->on_a - centre_a).dot(e) * e;
    out->on_b -= S(2) * (out->on_b - centre_b).dot(e) * e;
  }
  return out;
}

/// Axes tilted by a small angle (see kAxialMaxTilt; B's axis is `axis_b`, unit, through `centre_b`,
/// A's through `centre_a`, in A's frame): every direction lies in a plane through A's axis w, so
/// the depth is the least, over those planes, of the origin's depth in A - B's projection onto the
/// plane (planar_depth()). That depth is a function of the plane's angle which the tilt makes vary
/// by little; the plane through both axes, the one through A's axis and B's centre and a scan of
/// kAxialScanPlanes planes find the best, and Brent's method (parabolas through the last three,
/// golden sections where they fail) refines it to 1e-9 radians (in double), or until its three
/// best planes' depths agree to a hundredth of the tolerance. The answer is that
/// least plane's; `error_bound` adds the spread of the depths Brent's method saw in its final
/// bracket, an estimate rather than a bound.
template <class A, class B>
std::optional<AxialDepth<typename A::Scalar>> tilted_axial_depth(
    const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& w,
    const Vec3T<typename A::Scalar>& axis_b, const Vec3T<typename A::Scalar>& centre_a,
    const Vec3T<typename A::Scalar>& centre_b, typename A::Scalar size,
    const TolerancesT<typename A::Scalar>& tol) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  V e0, f0;
  plane_basis(w, e0, f0);
  std::optional<AxialDepth<S>> best;  // the least depth seen, on the plane at best_phi
  S best_phi = S(0);
  int iterations = 0, planes = 0;
  bool failed = false;
  auto depth_at = [&](S phi) {
    ++planes;
    const V e = std::cos(phi) * e0 + std::sin(phi) * f0;
    const auto d = planar_depth(diff, e, w, false, V::Zero(), V::Zero(), size, tol);
    if (!d) {
      failed = true;
      return std::numeric_limits<S>::infinity();
    }
    iterations += d->iterations;
    if (!best || d->depth < best->depth) {
      best = d;
      best_phi = phi;
    }
    return d->depth;
  };
  // The plane through both axes first: the support of a cylinder's or cone's flat end is kinked
  // at its axis direction, a point of the sphere of directions that only that plane holds, so
  // the depth over the planes can dip there in a notch far narrower than the scan's spacing (two
  // coincident cylinders 1e-3 rad apart, pressed out along B's axis: 3e-8 deep, 2e-5 rad wide).
  // And the plane through A's axis and B's centre (the parallel shapes' plane, file comment): the
  // least depth over the planes is there before the tilt, and where it is a notch narrower than
  // the scan's spacing, the tilt moves it by little.
  const V across = part_across(axis_b, w);
  const S phi_axes = std::atan2(across.dot(f0), across.dot(e0));
  depth_at(phi_axes);
  if (failed) return std::nullopt;
  const V offset = centre_b - centre_a;
  if (const V radial = part_across(offset, w); radial != V::Zero()) {
    depth_at(std::atan2(radial.dot(f0), radial.dot(e0)));
    if (failed) return std::nullopt;
  }
  // Then the scan over half a turn (a plane at phi + pi is the one at phi).
  const S step = S(3.14159265358979323846) / S(kAxialScanPlanes);
  for (int k = 0; k < kAxialScanPlanes; ++k) {
    depth_at(phi_axes + S(k) * step);
    if (failed) return std::nullopt;
  }
  // Brent's minimisation on the bracket around the best plane: x the best so far, w_ and v the
  // two before it, [lo, hi] the bracket.
  constexpr S kGolden = S(0.38196601125010515180);  // (3 - sqrt(5)) / 2
  // 1e-9 rad, or what the type can tell apart near pi (float).
  const S phi_tolerance = std::max(S(1e-9), S(16) * std::numeric_limits<S>::epsilon());
  S lo = best_phi - step, hi = best_phi + step;
  S x = best_phi, w_ = x, v = x;
  S fx = best->depth, fw = fx, fv = fx;
  S move = S(0), last_move = S(0);
  // Also converged when the three best planes' depths agree to a hundredth of the tolerance: past
  // that the angle is chased through rounding alone (a flat minimum: coincident spheroids,
  // tilted; 40 more planes, 0.7 ms).
  const S flat = S(0.01) * tol.relative_depth * size;
  bool converged = false;
  while (planes < kAxialMaxPlanes) {
    const S mid = S(0.5) * (lo + hi);
    if (std::abs(x - mid) <= S(2) * phi_tolerance - S(0.5) * (hi - lo) ||
        (w_ != x && v != x && v != w_ && std::max(fw, fv) - fx <= flat)) {
      converged = true;
      break;
    }
    bool golden = true;
    if (std::abs(last_move) > phi_tolerance) {
      // The parabola through (x, fx), (w_, fw), (v, fv): its vertex is x + p / q.
      const S r = (x - w_) * (fx - fv);
      S q = (x - v) * (fx - fw);
      S p = (x - v) * q - (x - w_) * r;
      q = S(2) * (q - r);
      if (q > S(0)) p = -p;
      q = std::abs(q);
      const S before = last_move;
      last_move = move;
      // Taken when it moves less than half the step before last and stays in the bracket.
      if (std::abs(p) < std::abs(S(0.5) * q * before) && p > q * (lo - x) && p < q * (hi - x)) {
        move = p / q;
        const S u = x + move;
        if (u - lo < S(2) * phi_tolerance || hi - u < S(2) * phi_tolerance)
          move = x < mid ? phi_tolerance : -phi_tolerance;
        golden = false;
      }
    }
    if (golden) {
      last_move = x >= mid ? lo - x : hi - x;
      move = kGolden * last_move;
    }
    const S u = std::abs(move) >= phi_tolerance
                    ? x + move
                    : x + (move > S(0) ? phi_tolerance : -phi_tolerance);
    const S fu = depth_at(u);
    if (failed) return std::nullopt;
    if (fu <= fx) {
      (u >= x ? lo : hi) = x;
      v = w_;
      fv = fw;
      w_ = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu <= fw || w_ == x) {
        v = w_;
        fv = fw;
        w_ = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w_) {
        v = u;
        fv = fu;
      }
    }
  }
  AxialDepth<S> out = *best;
  out.iterations = iterations;
  out.error_bound += std::max(fw, fv) - fx;
  out.normal_chosen = false;
  out.status = converged ? best->status : Status::IterationLimit;
  touching_points(diff, out.normal, out.depth, size, tol, out.iterations, out.on_a, out.on_b);
  return out;
}

/// An answer that stopped at a cap (a section nearly as round as a circle about the origin, in
/// one plane or several), lowered to the least support value near its normal by descent over all
/// directions (gjk/support_descent.hpp), as EPA in space polishes its own: the depth only goes
/// down, status and bound stay. Each plane's answer at the cap is the least support value among
/// the directions its polygon tried, which on a nearly round section is off by about the square
/// of their spacing (two coincident spheroids 0.3 % from a sphere, tilted 5.5e-3 rad: 2.4e-8 of
/// the size).
template <class A, class B>
void polish_capped_depth(const CoreDifference<A, B>& diff, typename A::Scalar size,
                         const TolerancesT<typename A::Scalar>& tol,
                         AxialDepth<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  int iterations = 0;
  auto least = SupportMinimum<S>::at(diff, out.normal, iterations);
  const bool finite = descend_support(diff, out.depth - out.error_bound, tol.relative_depth * size,
                                      tol.max_iterations, iterations, least);
  out.iterations += iterations;
  if (!finite || !(least.value < out.depth)) return;
  out.depth = least.value;
  out.normal = least.normal;
  out.on_a = least.vertex.a;
  out.on_b = least.vertex.b;
  touching_points(diff, out.normal, out.depth, size, tol, out.iterations, out.on_a, out.on_b);
}

/// The cores' axes for one pair, in A's frame: what axial_depth() and epa_suits_tilted_axes()
/// both start from.
template <class S>
struct PairAxes {
  CoreAxis<S> a, b;             ///< as the cores give them (each in its own frame)
  Vec3T<S> centre_a, centre_b;  ///< a point of each axis, in A's frame
  Vec3T<S> axis_b;              ///< B's axis turned into A's frame
  Vec3T<S> w;                   ///< the axis the planes pass through: A's if it is a line, else B's
  bool two_lines = false;       ///< both solids of revolution about a line
  /// The sine of the angle between the axes when both are lines, 0 when one is symmetric about a
  /// point, -1 when either has no axis. Tilted by t, the axes move B's points by at most t times
  /// its bounding radius.
  S tilt = S(-1);
};

template <class A, class B>
PairAxes<typename A::Scalar> pair_axes(const CoreDifference<A, B>& diff) {
  using S = typename A::Scalar;
  PairAxes<S> out;
  out.a = AxialCore<A>::of(diff.a);
  out.b = AxialCore<B>::of(diff.b);
  out.centre_a = out.a.centre;
  out.centre_b = diff.rotation * out.b.centre + diff.translation;
  out.axis_b = diff.rotation * out.b.axis;
  out.w = out.a.kind == AxisKind::Line ? out.a.axis : out.axis_b;
  out.two_lines = out.a.kind == AxisKind::Line && out.b.kind == AxisKind::Line;
  if (out.a.kind == AxisKind::None || out.b.kind == AxisKind::None)
    out.tilt = S(-1);
  else
    out.tilt = out.two_lines ? out.a.axis.cross(out.axis_b).norm() : S(0);
  return out;
}

/// How far the tilt moves B's points at most (0 unless both axes are lines).
template <class A, class B>
typename A::Scalar tilt_error(const CoreDifference<A, B>& diff,
                              const PairAxes<typename A::Scalar>& axes) {
  using S = typename A::Scalar;
  if (!axes.two_lines) return S(0);
  return axes.tilt * std::max(diff.a.bounding_radius(), diff.b.bounding_radius());
}

/// Whether the planes through one common axis answer as if the axes were parallel: one is
/// symmetric about a point, or the tilt moves B's points by under 1 % of the depth tolerance.
template <class A, class B>
bool axes_count_as_parallel(const CoreDifference<A, B>& diff,
                            const PairAxes<typename A::Scalar>& axes, typename A::Scalar size,
                            const TolerancesT<typename A::Scalar>& tol) {
  return tilt_error(diff, axes) <= typename A::Scalar(0.01) * tol.relative_depth * size;
}

/// Whether EPA in space should have the first try on cores whose axes are tilted by at most
/// kAxialMaxTilt (the planes only where it stops at kAxialEpaBudget), rather than the planes
/// through an axis. The planes take 400-1,300 support calls on every such pair (two scans of a
/// dozen planes and Brent's method, a planar EPA each, 15-25 us); EPA in space, tens, unless a
/// band of nearly equal normals stops it at its cap: near A - B's axis, about which the sides'
/// support values vary only by the origin's offset from it (coaxial or coincident shapes). So:
/// the origin at least kAxialOffAxis of the section's radius off the axis, or else A - B's least
/// support value, among directions in the half-plane through the axis and the origin, along the
/// axis (a cap, flat: no band). Those directions are sampled across the axis, along it both
/// ways, leaning from across towards it by every 15 degrees, and along the sides of cones,
/// whose least value lies where such a side leans (a wide cone about a thin one: the least value
/// 9e-4 of the size below the cap's, 6 degrees from the nearest sample, which the cap beat; EPA
/// in space went first and ran to its cap, 117 us).
/// 1 to 17 support calls, counted in `iterations`.
template <class A, class B>
bool epa_suits_tilted_axes(const CoreDifference<A, B>& diff,
                           const PairAxes<typename A::Scalar>& axes, int& iterations) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const V w = axes.w;
  const V radial = part_across(V(axes.centre_b - axes.centre_a), w);
  const S off_axis = radial.norm();
  if (!(off_axis > S(0))) return false;
  const auto value = [&](const V& u) {
    SimplexVertexT<S> v;
    diff.support(u, v);
    ++iterations;
    return u.dot(v.w);
  };
  // The origin lies off A - B's axis (through centre_a - centre_b) along radial.
  const V across = radial / off_axis;
  const S straight_across = value(across);
  if (off_axis >= S(kAxialOffAxis) * (straight_across + off_axis)) return true;
  const S caps = std::min(value(w), value(V(-w)));
  S sides = straight_across;
  const auto lean = [&](S sine) {
    const S cosine = std::sqrt(S(1) - sine * sine);
    sides = std::min(
        {sides, value(V(cosine * across + sine * w)), value(V(cosine * across - sine * w))});
  };
  for (const S sine : {S(0.25881904510252074), S(0.5), S(0.70710678118654752),
                       S(0.86602540378443865), S(0.96592582628906829)})  // 15, 30, ..., 75 degrees
    lean(sine);
  // A disc's slant is 0: its side is a cap, which must not count among the sides.
  for (const S slant : {axes.a.slant, axes.b.slant})
    if (slant > S(0)) lean(slant);
  return caps < sides;
}

/// The depth of the cores of diff.a and diff.b (B posed by diff.rotation, diff.translation in A's
/// frame, their axes `axes` = pair_axes(diff)) when both are solids of revolution about axes
/// tilted by more than `min_tilt` and at most `max_tilt` (the sine of their angle, which is the
/// angle in radians for the small tilts this path is for; the default range takes parallel axes
/// too; see the file comment); nothing when they are not, or when a planar problem has no area
/// or shows the cores apart (the caller's EPA answers then). `size`: the sum of the bounding
/// radii.
template <class A, class B>
std::optional<AxialDepth<typename A::Scalar>> axial_depth(
    const CoreDifference<A, B>& diff, const PairAxes<typename A::Scalar>& axes,
    typename A::Scalar size, const TolerancesT<typename A::Scalar>& tol,
    typename A::Scalar max_tilt = typename A::Scalar(kAxialMaxTilt),
    typename A::Scalar min_tilt = typename A::Scalar(-1)) {
  using S = typename A::Scalar;
  if (axes.a.kind == AxisKind::None || axes.b.kind == AxisKind::None) return std::nullopt;
  if (axes.a.kind == AxisKind::Any && axes.b.kind == AxisKind::Any) return std::nullopt;
  if (!(axes.tilt > min_tilt)) return std::nullopt;
  std::optional<AxialDepth<S>> out;
  if (!axes_count_as_parallel(diff, axes, size, tol)) {
    if (!(axes.tilt <= max_tilt)) return std::nullopt;
    out = tilted_axial_depth(diff, axes.w, axes.axis_b, axes.centre_a, axes.centre_b, size, tol);
    if (!out) return out;
    // And the planes through B's axis, the lesser depth: each axis's flat end has its kink at a
    // direction that only the planes through that axis hold for every angle, and the least over
    // the other axis's planes can dip there in a notch narrower than the scan (two thin discs
    // face to face, axes 9e-3 rad apart, 1e-7 deep: 2.6e-8 too deep about one axis, exact about
    // the other).
    // A scan about B's axis that gives up leaves A's answer as it was.
    auto about_b =
        tilted_axial_depth(diff, axes.axis_b, axes.w, axes.centre_b, axes.centre_a, size, tol);
    if (about_b && about_b->depth < out->depth) {
      about_b->iterations += out->iterations;
      out = about_b;
    } else if (about_b) {
      out->iterations += about_b->iterations;
    }
  } else {
    out = parallel_axial_depth(diff, axes.w, axes.centre_a, axes.centre_b, size, tol);
    if (!out) return out;
    out->error_bound += tilt_error(diff, axes);
  }
  if (out->status == Status::IterationLimit) polish_capped_depth(diff, size, tol, *out);
  return out;
}

}  // namespace mink::detail
