/// @file feature.hpp
/// Support features: the whole face, edge or vertex of a shape that is farthest along a direction,
/// not just one support point. Contact manifolds (manifold.hpp) clip one shape's feature against
/// the other's.
///
/// Frame: the shape's local frame, like support_core().
///
/// Cores only: a sphere's feature is its centre, a capsule's its segment; the caller pushes the
/// feature out by core_radius() along d.
///
/// Which feature: every point of the core's surface whose height along the unit direction is
/// within `tolerance` (unit: length) of the support plane belongs to it. So a box whose face is
/// tilted from the direction by less than about tolerance / (face width) gives the face, a box
/// tilted more gives an edge or a vertex. A generous tolerance is safe for the manifold: the
/// points it clips keep their own depths, and points that are not in contact fall out there.
///
/// Customisation: a shape type gives manifolds its features by an overload
/// `void support_feature(const T&, const Vec3T<S>& d, S tolerance, SupportFeatureT<S>& out)`
/// in its own namespace (found by argument-dependent lookup). Shapes without one get a feature
/// sampled from the support mapping (support_feature_of() below).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mink/math/orthogonal.hpp"
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
#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"
#include "mink/support/shape.hpp"

namespace mink {

/// Most points a feature holds: a polytope face with more vertices keeps an evenly spread subset,
/// a cylinder's or cone's cap is this many rim points.
inline constexpr int kMaxFeaturePoints = 16;

/// A vertex (1 point), an edge (2 points) or a convex polygon (3 or more points, ordered
/// counter-clockwise about `normal`) of a shape, in the shape's frame.
template <class S>
struct SupportFeatureT {
  int count = 0;                        ///< 1, 2 or 3..kMaxFeaturePoints
  Vec3T<S> normal = Vec3T<S>::UnitZ();  ///< polygons: unit outward face normal; else unused
  Vec3T<S> points[kMaxFeaturePoints];   ///< (unit: length)
  /// A cylinder's or cone's cap: the points are a polygon on its rim, and the rim itself is the
  /// circle of this radius about disc_centre in the face's plane (the manifold adds the points
  /// where the other feature's edges cross it). 0 for every other feature. (unit: length)
  S disc_radius = S(0);
  Vec3T<S> disc_centre = Vec3T<S>::Zero();
  /// A single point on a cylinder's or cone's rim (a cap seen edge-on or from the side): the
  /// rim is the circle of this radius about rim_centre, normal to the unit rim_axis (the cap's
  /// outward normal). Where the contact is that rim against another core's edge, the point
  /// moves along it (rim_against_edge()). 0 for every other feature, caps included, which
  /// keep their rim in disc_radius. (unit: length)
  S rim_radius = S(0);
  Vec3T<S> rim_centre = Vec3T<S>::Zero();
  Vec3T<S> rim_axis = Vec3T<S>::UnitZ();
  /// A cap swept along a segment (a cylinder's or cone's cap in a sum with a segment): the
  /// polygon's points are samples of its outline, and the face itself is the stadium of the
  /// points within stadium_radius of the segment stadium_ends[0]-stadium_ends[1], in the
  /// face's plane. 0 for every other feature. (unit: length)
  S stadium_radius = S(0);
  Vec3T<S> stadium_ends[2] = {Vec3T<S>::Zero(), Vec3T<S>::Zero()};

  /// A cylinder's or cone's cap (disc_radius holds its rim).
  bool is_cap() const { return disc_radius > S(0); }
  /// A single point on a cylinder's or cone's rim (rim_radius holds the rim).
  bool is_rim_point() const { return count == 1 && rim_radius > S(0); }
  /// A cap swept along a segment (stadium_radius holds its round ends).
  bool is_stadium() const { return stadium_radius > S(0); }
  /// The disc whose rim may hold a contact with a point seen over the face at `toward` (same
  /// frame): a cap's own, or the round end of a stadium nearer `toward` taken as a whole disc.
  /// False for every other feature.
  bool disc_towards(const Vec3T<S>& toward, Vec3T<S>& centre, S& radius) const {
    if (is_cap()) {
      centre = disc_centre;
      radius = disc_radius;
      return true;
    }
    if (!is_stadium()) return false;
    const bool second =
        (toward - stadium_ends[1]).squaredNorm() < (toward - stadium_ends[0]).squaredNorm();
    centre = stadium_ends[second ? 1 : 0];
    radius = stadium_radius;
    return true;
  }

  /// Sets every point slot to zero, used or not: a copy of the feature then reads no
  /// uninitialised memory (GCC's -Wmaybe-uninitialized stopped on such copies).
  void clear_points() {
    for (Vec3T<S>& p : points) p.setZero();
  }
  /// Marks the feature as no cap, rim point or stadium: what its points show is all there is.
  void clear_curves() {
    disc_radius = S(0);
    rim_radius = S(0);
    stadium_radius = S(0);
  }
  void set_point(const Vec3T<S>& p) {
    count = 1;
    points[0] = p;
    clear_curves();
  }
  /// The point p on the rim of `radius` about `centre`, normal to the unit `axis`.
  void set_rim_point(const Vec3T<S>& p, const Vec3T<S>& centre, const Vec3T<S>& axis, S radius) {
    set_point(p);
    rim_radius = radius;
    rim_centre = centre;
    rim_axis = axis;
  }
  void set_edge(const Vec3T<S>& p, const Vec3T<S>& q) {
    count = 2;
    points[0] = p;
    points[1] = q;
    clear_curves();
  }
};

namespace detail {

/// The corners of the convex hull of `count` (<= kCapacity) points seen along unit `n` (Andrew's
/// monotone chain), counter-clockwise about n, as indices into `points`, written to `corners`;
/// returns their number (1: all one point, 2: all on a segment). Collinear points are dropped, and
/// corners apart by no more than the coordinates' rounding (1e-12 of their extent) are one: a
/// sampled feature of a sum met one rim point twice, 5e-17 apart, and the "edge" between them,
/// pointing anywhere, moved a manifold point of the rounded sum across it, 2 % of the size inside
/// the shape.
template <int kCapacity, class S>
int convex_outline(const Vec3T<S>* points, int count, const Vec3T<S>& n, int* corners) {
  if (count <= 1) {
    corners[0] = 0;
    return 1;
  }
  Vec3T<S> u, v;
  plane_basis(n, u, v);
  struct Planar {
    S x, y;
    int i;
  };
  Planar p[kCapacity], hull[2 * kCapacity + 2];
  for (int i = 0; i < count; ++i) p[i] = {points[i].dot(u), points[i].dot(v), i};
  std::sort(p, p + count, [](const Planar& a, const Planar& b) {
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.i < b.i)));
  });
  // Corners apart by no more than the coordinates' rounding (1e-12 of their extent) are one,
  // and a corner within that of the line through its neighbours is none: the sums of two
  // parallel faces met points along their common sides 1e-17 off the line.
  S extent = S(0);
  for (int i = 0; i < count; ++i) extent = std::max({extent, std::abs(p[i].x), std::abs(p[i].y)});
  const S merge = S(1e-12) * extent;
  // Whether a lies right of the line from o to b or within `merge` of it (|turn| / |b - o| is
  // its distance; the sum of |b - o|'s coordinates bounds that length within sqrt 2).
  auto drop = [merge](const Planar& o, const Planar& a, const Planar& b) {
    const S turn = (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    return turn <= merge * (std::abs(b.x - o.x) + std::abs(b.y - o.y));
  };
  // Collinear and repeated points are dropped, so the hull is strictly convex.
  int k = 0;
  for (int i = 0; i < count; ++i) {
    while (k >= 2 && drop(hull[k - 2], hull[k - 1], p[i])) --k;
    hull[k++] = p[i];
  }
  for (int i = count - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && drop(hull[k - 2], hull[k - 1], p[i])) --k;
    hull[k++] = p[i];
  }
  // The last point repeats the first.
  auto apart = [merge](const Planar& a, const Planar& b) {
    return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)) > merge;
  };
  int n_hull = 0;
  for (int j = 0; j + 1 < k; ++j)
    if (n_hull == 0 || apart(hull[j], hull[n_hull - 1])) hull[n_hull++] = hull[j];
  while (n_hull > 1 && !apart(hull[n_hull - 1], hull[0])) --n_hull;
  n_hull = std::max(n_hull, 1);
  for (int j = 0; j < n_hull; ++j) corners[j] = hull[j].i;
  return n_hull;
}

/// The feature spanned by `count` points that all lie within the tolerance of one support plane
/// with unit normal `n`: their convex hull seen along n (convex_outline()), as a vertex, an edge
/// or a counter-clockwise polygon whose normal is the plane's fitted normal (Newell). count >= 1;
/// at most 64 points are read.
template <class S>
void feature_from_points(const Vec3T<S>* points, int count, const Vec3T<S>& n,
                         SupportFeatureT<S>& out) {
  count = std::min(count, 64);
  int corners[64];
  const int n_hull = convex_outline<64>(points, count, n, corners);
  if (n_hull == 1) {
    out.set_point(points[corners[0]]);
    return;
  }
  if (n_hull == 2) {
    out.set_edge(points[corners[0]], points[corners[1]]);
    return;
  }
  // More corners than a feature holds: an evenly spread subset (it stays convex).
  const int kept = std::min(n_hull, kMaxFeaturePoints);
  out.count = kept;
  out.clear_curves();
  for (int j = 0; j < kept; ++j) out.points[j] = points[corners[(j * n_hull) / kept]];
  Vec3T<S> normal = Vec3T<S>::Zero();
  for (int j = 0; j < kept; ++j) {
    const Vec3T<S>& a = out.points[j];
    const Vec3T<S>& b = out.points[(j + 1) % kept];
    normal += (a - out.points[0]).cross(b - out.points[0]);
  }
  out.normal = normal != Vec3T<S>::Zero() && normal.dot(n) > S(0) ? unit_of(normal) : n;
}

/// A cap of `kMaxFeaturePoints` points on the circle of `radius` at height z, counter-clockwise
/// about (0, 0, sign(z_normal)).
template <class S>
void rim_feature(S radius, S z, S z_normal, SupportFeatureT<S>& out) {
  out.count = kMaxFeaturePoints;
  out.clear_curves();
  out.disc_radius = radius;
  out.disc_centre = {S(0), S(0), z};
  out.normal = Vec3T<S>(S(0), S(0), z_normal >= S(0) ? S(1) : S(-1));
  for (int i = 0; i < kMaxFeaturePoints; ++i) {
    const S angle = S(2) * std::numbers::pi_v<S> * S(i) / S(kMaxFeaturePoints);
    const S c = std::cos(angle), s = std::sin(angle);
    out.points[z_normal >= S(0) ? i : kMaxFeaturePoints - 1 - i] = {radius * c, radius * s, z};
  }
}

/// The support point along d of a cylinder or cone (`shape`), with its rim when it lies on the
/// rim of the cap whose outward normal is (0, 0, `cap_side`): a cone's apex, a cap's centre (d
/// along the axis) and the point of a rim of radius 0 are plain points.
template <class Shape, class S>
void set_core_point(const Shape& shape, const Vec3T<S>& d, S cap_side, SupportFeatureT<S>& out) {
  const Vec3T<S> p = shape.support_core(d);
  const Vec3T<S> centre(S(0), S(0), p.z());
  if (shape.radius > S(0) && (p.x() != S(0) || p.y() != S(0)))
    out.set_rim_point(p, centre, Vec3T<S>(S(0), S(0), cap_side), shape.radius);
  else
    out.set_point(p);
}

}  // namespace detail

// Features of the primitive shapes. d need not be unit, must not be zero (a zero d gives a vertex).

template <class S>
void support_feature(const PointT<S>& shape, const Vec3T<S>&, S, SupportFeatureT<S>& out) {
  out.set_point(shape.position);
}

template <class S>
void support_feature(const SphereT<S>&, const Vec3T<S>&, S, SupportFeatureT<S>& out) {
  out.set_point(Vec3T<S>::Zero());
}

template <class S>
void support_feature(const EllipsoidT<S>& shape, const Vec3T<S>& d, S, SupportFeatureT<S>& out) {
  out.set_point(shape.support_core(d));  // strictly convex: always a single point
}

namespace detail {

/// The shape of a box's support feature along d: the axes it extends along (an axis is free when
/// flipping its coordinate changes the height d . p by at most `limit`; unit: length, times |d|)
/// and, for a face, the axis of its normal: the fixed axis, or for a box small against the
/// tolerance (all free) the axis most aligned with d. An axis of zero extent is never free: the
/// long edge of a box flat in z would otherwise be a "face" of width 0 whose normal (x or y) is
/// far from d, and a rounded box's witness point was pushed out along it (by the radius, 90
/// degrees off the contact normal). For the same reason a box rounded by `radius` keeps a face
/// only while pushing along the face's normal instead of d costs at most the tolerance,
/// radius (1 - cos t) <= limit / |d| for the tilt t: a core 3.6e-15 thick passes the flatness test
/// at any tilt, and is then the edge along its least tilted free axis.
struct BoxFeatureAxes {
  unsigned free_mask;  ///< bit i set: axis i is free
  int free_count;      ///< 0 a vertex, 1 an edge, 2 or 3 a face
  int face_axis;       ///< the face's normal axis when free_count >= 2, else -1

  bool free(int i) const { return (free_mask >> i) & 1u; }
  /// The lowest free axis (an edge's axis when free_count is 1); 2 when none is free.
  int first_free() const { return free(0) ? 0 : (free(1) ? 1 : 2); }
};

// Plain scalars throughout, no array of flags: an array written flag by flag and then copied as a
// whole stalls the copy's wide load on store forwarding (5 % of a box-box manifold's time).
template <class S>
[[gnu::always_inline]] inline BoxFeatureAxes box_feature_axes(const Vec3T<S>& h, const Vec3T<S>& d,
                                                              S limit, S radius = S(0)) {
  unsigned mask = 0;
  for (int i = 0; i < 3; ++i)
    mask |= (unsigned(h[i] > S(0)) & unsigned(S(2) * h[i] * std::abs(d[i]) <= limit)) << i;
  auto classify = [&d](unsigned m) {
    const int count = int(m & 1u) + int((m >> 1) & 1u) + int((m >> 2) & 1u);
    const int face = count == 3   ? dominant_axis(d)
                     : count == 2 ? (!(m & 1u) ? 0 : (!(m & 2u) ? 1 : 2))
                                  : -1;
    return BoxFeatureAxes{m, count, face};
  };
  const BoxFeatureAxes f = classify(mask);
  if (radius > S(0) && f.face_axis >= 0 && radius * (d.norm() - std::abs(d[f.face_axis])) > limit)
      [[unlikely]] {
    // The edge along the free axis least tilted against d.
    int along = -1;
    for (int i = 0; i < 3; ++i)
      if (f.free(i) && i != f.face_axis && (along < 0 || std::abs(d[i]) < std::abs(d[along])))
        along = i;
    return classify(along < 0 ? 0u : 1u << along);
  }
  return f;
}

/// Pushes the edge (p0, p1) of a core out by `radius` onto its rounded surface, towards `toward`
/// (unit): the deeper end along `toward`, where the rounded end is deepest, and the other end
/// across the edge, so that both are on the surface when the edge is tilted from `toward` by t
/// (along it, the other end would be inside by radius t^2 / 2). An edge more along `toward` than
/// across it moves along `toward` at both ends.
template <class S>
void push_rounded_edge(Vec3T<S>& p0, Vec3T<S>& p1, const Vec3T<S>& toward, S radius) {
  const Vec3T<S> edge = p1 - p0;
  const S edge_sq = edge.squaredNorm(), along = toward.dot(edge);
  const Vec3T<S> across = toward - (edge_sq > S(0) ? along / edge_sq : S(0)) * edge;
  const S length = across.norm();
  Vec3T<S>& deeper = along >= S(0) ? p1 : p0;
  Vec3T<S>& other = along >= S(0) ? p0 : p1;
  deeper += radius * toward;
  other += length > S(0.5) ? Vec3T<S>((radius / length) * across) : Vec3T<S>(radius * toward);
}

/// The points of the support feature `f` of a box with half extents h along d (box_feature_axes),
/// taken to another frame by (rotation, translation) and pushed out by `radius`: a face along its
/// outward normal, a vertex along `push` (unit, in the other frame; unused when the radius is 0),
/// an edge along `push` at its deeper end and across the edge at the other (clip_features()). The
/// order is support_feature()'s (a face counter-clockwise about its outward normal). Returns the
/// count. `rotation` may be an expression (a transpose), whose columns are then read in place.
/// Always inlined: out of line, it cost a box pair's manifold 34 instructions more (1.6 %).
template <class S, class Rotation>
[[gnu::always_inline]] inline int box_feature_points(const Vec3T<S>& h, const Vec3T<S>& d,
                                                     const BoxFeatureAxes& f,
                                                     const Rotation& rotation,
                                                     const Vec3T<S>& translation, S radius,
                                                     const Vec3T<S>& push, Vec3T<S>* out) {
  if (f.face_axis >= 0) {
    const int k = f.face_axis;
    const S side = sign_nonneg(d[k]);
    const Vec3T<S> c = rotation.col(k) * (side * (h[k] + radius)) + translation;
    const Vec3T<S> e1 = rotation.col(kNextAxis[k]) * h[kNextAxis[k]];
    const Vec3T<S> e2 = rotation.col(kPrevAxis[k]) * h[kPrevAxis[k]];  // e1 x e2 along +e_k
    const Vec3T<S> e2_signed = side * e2;
    out[0] = c + e1 + e2_signed;
    out[1] = c - e1 + e2_signed;
    out[2] = c - e1 - e2_signed;
    out[3] = c + e1 - e2_signed;
    return 4;
  }
  // The corner with the free axis (an edge's) at 0, as a sum of columns: a vector written
  // coordinate by coordinate and then read whole would stall on store forwarding.
  auto coordinate = [&](int i) { return f.free(i) ? S(0) : sign_nonneg(d[i]) * h[i]; };
  const Vec3T<S> c = rotation.col(0) * coordinate(0) + rotation.col(1) * coordinate(1) +
                     rotation.col(2) * coordinate(2) + translation;
  if (f.free_count == 0) {
    out[0] = c + radius * push;
    return 1;
  }
  const int free_axis = f.first_free();
  const Vec3T<S> e = rotation.col(free_axis) * h[free_axis];
  out[0] = c - e;
  out[1] = c + e;
  if (radius > S(0)) push_rounded_edge(out[0], out[1], push, radius);
  return 2;
}

}  // namespace detail

template <class S>
void support_feature(const BoxT<S>& box, const Vec3T<S>& d, S tolerance, SupportFeatureT<S>& out) {
  const detail::BoxFeatureAxes f =
      detail::box_feature_axes(box.half_extents, d, tolerance * d.norm());
  out.count = detail::box_feature_points(box.half_extents, d, f, Mat3T<S>::Identity().eval(),
                                         Vec3T<S>::Zero().eval(), S(0), Vec3T<S>::Zero().eval(),
                                         out.points);
  out.clear_curves();
  if (f.face_axis >= 0)
    out.normal = Vec3T<S>::Unit(f.face_axis) * detail::sign_nonneg(d[f.face_axis]);
}

template <class S>
void support_feature(const SegmentT<S>& segment, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  if (std::abs(d.dot(segment.b - segment.a)) <= tolerance * d.norm())
    out.set_edge(segment.a, segment.b);
  else
    out.set_point(segment.support_core(d));
}

template <class S>
void support_feature(const CapsuleT<S>& capsule, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  // The core only: Rounded and the manifold add the radius.
  const S h = capsule.half_height;
  if (S(2) * h * std::abs(d.z()) <= tolerance * d.norm())
    out.set_edge({S(0), S(0), -h}, {S(0), S(0), h});
  else
    out.set_point(capsule.support_core(d));
}

template <class S>
void support_feature(const CylinderT<S>& cylinder, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  const S length = d.norm();
  const S rho = std::hypot(d.x(), d.y());
  const S r = cylinder.radius, h = cylinder.half_height;
  if (S(2) * r * rho <= tolerance * length) {
    // Standing on a cap: the rim points describe the contact.
    detail::rim_feature(r, detail::sign_nonneg(d.z()) * h, d.z(), out);
    return;
  }
  S ux, uy;  // planar_unit(), not r / rho: rho of 1e-318 made that infinite
  if (S(2) * h * std::abs(d.z()) <= tolerance * length &&
      detail::planar_unit(d.x(), d.y(), ux, uy)) {
    out.set_edge({r * ux, r * uy, -h}, {r * ux, r * uy, h});
    return;
  }
  detail::set_core_point(cylinder, d, S(detail::sign_nonneg(d.z())), out);
}

template <class S>
void support_feature(const ConeT<S>& cone, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  const S length = d.norm();
  const S rho = std::hypot(d.x(), d.y());
  const S r = cone.radius, h = cone.half_height;
  if (d.z() < S(0) && S(2) * r * rho <= tolerance * length) {
    detail::rim_feature(r, -h, S(-1), out);
    return;
  }
  // A cone flat to the tolerance (apex and whole rim within it along d, which looks up) shows its
  // disk from above too: the rim describes that contact, where a side line would give 2 points.
  if (d.z() >= S(0) && S(2) * (r * rho + h * d.z()) <= tolerance * length) {
    detail::rim_feature(r, -h, S(1), out);
    return;
  }
  // Apex and rim point at the same height: the side line between them.
  const S apex = h * d.z(), rim = r * rho - h * d.z();
  S ux, uy;  // planar_unit(), not r / rho: rho of 1e-318 made that infinite
  if (std::abs(apex - rim) <= tolerance * length && detail::planar_unit(d.x(), d.y(), ux, uy)) {
    out.set_edge({S(0), S(0), h}, {r * ux, r * uy, -h});
    return;
  }
  detail::set_core_point(cone, d, S(-1), out);
}

template <class S>
void support_feature(const TriangleT<S>& triangle, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  const Vec3T<S> n = detail::unit_of(d);
  Vec3T<S> corners[3] = {triangle.a, triangle.b, triangle.c};
  const S top = std::max({corners[0].dot(n), corners[1].dot(n), corners[2].dot(n)});
  Vec3T<S> near[3];
  int count = 0;
  for (const Vec3T<S>& c : corners)
    if (top - c.dot(n) <= tolerance) near[count++] = c;
  detail::feature_from_points(near, count, n, out);
}

namespace detail {

/// Most points near the support plane that a polytope or hull feature gathers.
inline constexpr int kMaxNearPoints = 64;

/// The feature of a shape made of points (a polytope or a hull, whose faces are not stored as
/// such) along unit n: `gather(top, tolerance, near)` writes the points within `tolerance` of
/// the support plane at height `top` (at most kMaxNearPoints) and returns their count. Those
/// points need not be one face: the tip of a nearly flat ridge also qualifies, and a polygon
/// through it would put manifold points inside the shape. So the polygon must be planar (every
/// near point within 1e-12 of the size of its fitted plane) and support the shape, and the
/// tolerance shrinks tenfold until it does; a face that the normal hits exactly survives.
template <class T, class Gather>
void point_set_feature(const T& shape, const Vec3T<typename T::Scalar>& n,
                       typename T::Scalar tolerance, Gather&& gather,
                       SupportFeatureT<typename T::Scalar>& out) {
  using S = typename T::Scalar;
  const Vec3T<S> top_point = shape.support_core(n);
  const S top = top_point.dot(n);
  const S flat = S(1e-12) * shape.bounding_radius();
  Vec3T<S> near[kMaxNearPoints];
  for (int round = 0; round < 4; ++round, tolerance *= S(0.1)) {
    const int count = gather(top, tolerance, near);
    feature_from_points(near, count, n, out);
    if (out.count < 3) return;
    const S w = out.normal.dot(out.points[0]);
    bool planar = true;
    for (int i = 0; i < count && planar; ++i)
      planar = std::abs(out.normal.dot(near[i]) - w) <= flat;
    // And the plane must support the shape: three near points always fit a plane, but it may
    // cut through the shape.
    if (planar && shape.support_core(out.normal).dot(out.normal) <= w + flat) return;
  }
  out.set_point(top_point);
}

}  // namespace detail

template <class S>
void support_feature(const ConvexHullShapeT<S>& hull, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out);

/// A polytope that has switched to its hull (polytope.hpp) takes the hull's faces. Before, it
/// carries no faces: one scan for the support height, one for the points near it.
template <class S>
void support_feature(const PolytopeT<S>& polytope, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  if (const ConvexHullShapeT<S>* hull = polytope.hull()) {
    support_feature(*hull, d, tolerance, out);
    return;
  }
  const Vec3T<S> n = d.normalized();
  auto gather = [&](S top, S within, Vec3T<S>* near) {
    int count = 0;
    for (std::size_t i = 0; i < polytope.size() && count < detail::kMaxNearPoints; ++i) {
      const Vec3T<S> p = polytope.point(i);
      if (top - p.dot(n) <= within) near[count++] = p;
    }
    return count;
  };
  detail::point_set_feature(polytope, n, tolerance, gather, out);
}

/// A hull has its faces: among those around the support vertex, the one whose normal is closest
/// to d, when all its corners are within the tolerance of the support plane (however many
/// corners it has: more than kMaxFeaturePoints keep an evenly spread subset, still convex).
/// Otherwise (an edge or a vertex faces d, or a lower-dimensional hull) the points near the
/// support plane, found by walking the edge graph from the support vertex: the vertices above a
/// plane form a connected subgraph of a convex polytope's edges (the reason hill climbing
/// works), so the walk visits only the feature's vertices and their neighbours.
template <class S>
void support_feature(const ConvexHullShapeT<S>& hull, const Vec3T<S>& d, S tolerance,
                     SupportFeatureT<S>& out) {
  const Vec3T<S> n = d.normalized();
  const std::uint32_t start = std::uint32_t(hull.support_index(n));
  const S top = hull.point(start).dot(n);
  std::size_t best_face = hull.face_count();
  S best_alignment = -S(2);
  for (const std::uint32_t f : hull.faces_around(start)) {
    const S alignment = hull.face_normal(f).dot(n);
    if (alignment > best_alignment) {
      best_alignment = alignment;
      best_face = f;
    }
  }
  if (best_face < hull.face_count()) {
    const std::span<const std::uint32_t> loop = hull.face_loop(best_face);
    bool near = true;
    for (const std::uint32_t v : loop) near = near && top - hull.point(v).dot(n) <= tolerance;
    if (near) {
      const int corners = int(loop.size());
      out.count = std::min(corners, kMaxFeaturePoints);
      out.clear_curves();
      for (int j = 0; j < out.count; ++j)
        out.points[j] = hull.point(loop[std::size_t((j * corners) / out.count)]);
      out.normal = hull.face_normal(best_face);
      return;
    }
  }
  auto gather = [&](S top_value, S within, Vec3T<S>* near) {
    std::uint32_t found[detail::kMaxNearPoints];
    int count = 0;
    found[count] = start;
    near[count++] = hull.point(start);
    for (int i = 0; i < count; ++i)
      hull.for_each_neighbor(found[i], [&](std::uint32_t u) {
        if (count == detail::kMaxNearPoints) return;
        const Vec3T<S> p = hull.point(u);
        if (top_value - p.dot(n) > within) return;
        for (int j = 0; j < count; ++j)
          if (found[j] == u) return;
        found[count] = u;
        near[count++] = p;
      });
    return count;
  };
  detail::point_set_feature(hull, n, tolerance, gather, out);
}

template <ConvexShape T>
void support_feature_of(const T& shape, const Vec3T<typename T::Scalar>& d,
                        typename T::Scalar tolerance, SupportFeatureT<typename T::Scalar>& out);

/// A Shape's feature (defined below): its single core's own, or a sum's from its cores'.
void support_feature(const Shape& shape, const Vec3& d, double tolerance,
                     SupportFeatureT<double>& out);
template <ConvexShape A, ConvexShape B>
void support_feature(const MinkowskiSum<A, B>& sum, const Vec3T<typename A::Scalar>& d,
                     typename A::Scalar tolerance, SupportFeatureT<typename A::Scalar>& out);

/// A rounded shape's core is its inner shape's core (the manifold adds core_radius() itself).
template <ConvexShape T>
void support_feature(const Rounded<T>& shape, const Vec3T<typename T::Scalar>& d,
                     typename T::Scalar tolerance, SupportFeatureT<typename T::Scalar>& out) {
  support_feature_of(shape.shape, d, tolerance, out);
}

/// The feature of any shape's core along d (not unit, not zero): the shape's own
/// support_feature() overload where it has one (every shape of the library, sums and Shapes
/// included), else a feature sampled from the support mapping (the support along d and along 8
/// directions tilted 0.1 rad around it, keeping the points within the tolerance of the support
/// plane, held to point_set_feature()'s tests).
template <ConvexShape T>
void support_feature_of(const T& shape, const Vec3T<typename T::Scalar>& d,
                        typename T::Scalar tolerance, SupportFeatureT<typename T::Scalar>& out) {
  using S = typename T::Scalar;
  if constexpr (requires { support_feature(shape, d, tolerance, out); }) {
    support_feature(shape, d, tolerance, out);
  } else {
    const Vec3T<S> n = d.normalized();
    Vec3T<S> u, v;
    detail::plane_basis(n, u, v);
    Vec3T<S> samples[9];
    samples[0] = shape.support_core(n);
    for (int i = 0; i < 8; ++i) {
      const S angle = S(2) * std::numbers::pi_v<S> * S(i) / S(8);
      samples[i + 1] = shape.support_core(n + S(0.1) * (std::cos(angle) * u + std::sin(angle) * v));
    }
    // Held to the planarity and support tests of point_set_feature(): samples of a curved part
    // (a sum with a cone or an ellipsoid) can lie within the tolerance without being on one
    // plane, and the polygon's plane then passed outside the shape (manifold points up to 4e-4 of
    // the size outside it).
    auto gather = [&](S top, S within, Vec3T<S>* near) {
      int count = 0;
      for (const Vec3T<S>& p : samples)
        if (top - p.dot(n) <= within) near[count++] = p;
      return count;
    };
    detail::point_set_feature(shape, n, tolerance, gather, out);
  }
}

namespace detail {

/// Most points of a sum's feature before its outline is taken: two caps of rim points summed.
inline constexpr int kMaxSumCombinations = kMaxFeaturePoints * kMaxFeaturePoints;

/// The points of a sum's feature along unit n within `within` of its support plane, written to
/// `near` (kMaxNearPoints of room); returns their count. `for_each_part(f)` calls f(feature)
/// with each part's own feature along n within `within`. A face of a Minkowski sum is
/// the sum of its parts' features along the same direction, so each part's exact feature (a
/// face, an edge, a rim point) is added to the outline of the sum so far, and the new outline,
/// seen along n, is kept (an evenly spread subset of it when it has more corners than there is
/// room for; it stays convex). Each part may lie up to `within` below its own plane, the sum up
/// to the number of parts times that; point_set_feature() then holds the polygon to planarity
/// and support.
template <class S, class ForEachPart>
int sum_feature_points(ForEachPart&& for_each_part, const Vec3T<S>& n, Vec3T<S>* near) {
  int count = 0;
  for_each_part([&](const SupportFeatureT<S>& f) {
    if (count == 0) {
      count = f.count;
      std::copy(f.points, f.points + f.count, near);
      return;
    }
    Vec3T<S> sums[kMaxSumCombinations];
    int m = 0;
    const int used = std::min(count, kMaxSumCombinations / f.count);
    for (int i = 0; i < used; ++i)
      for (int j = 0; j < f.count; ++j) sums[m++] = near[(i * count) / used] + f.points[j];
    int corners[kMaxSumCombinations];
    const int outline = convex_outline<kMaxSumCombinations>(sums, m, n, corners);
    count = std::min(outline, kMaxNearPoints);
    for (int i = 0; i < count; ++i) near[i] = sums[corners[(i * outline) / count]];
  });
  return count;
}

/// The feature of the sum `shape` along d from its parts' (sum_feature_points()), held to the
/// planarity and support tests of point_set_feature(), whose tolerance shrinks until the polygon
/// is a face of the sum; a cap and single points keep the cap's rim (disc_radius).
/// `for_each_part(n, within, f)` calls f with each part's feature along unit n within `within` of
/// its support plane.
template <class T, class ForEachPart>
void sum_support_feature(const T& shape, const Vec3T<typename T::Scalar>& d,
                         typename T::Scalar tolerance, ForEachPart&& for_each_part,
                         SupportFeatureT<typename T::Scalar>& out) {
  using S = typename T::Scalar;
  const Vec3T<S> n = d.normalized();
  // One part's cap and the other parts' single points: the cap moved by them, exactly, with its
  // rim. As a polygon of its rim's samples, a point over the cap between the polygon and the rim
  // lay outside it, and a cylinder's rim over a cone's base swept by a segment kept GJK's points,
  // 4e-7 of the size off the contact (stop 62's curved probe, c11_398).
  // The parts' features are gathered once, classified, and summed only when no cap case: a sum
  // of more parts than there is room for here asks them again for the outline.
  constexpr int kStoredParts = 4;
  // Likewise one part's rim point and the others' points: that rim moved by them.
  SupportFeatureT<S> stored[kStoredParts], cap, rim, edge;
  // The rim part's own point, apart from `rim` (whose points GCC cannot see set before use).
  Vec3T<S> rim_point = Vec3T<S>::Zero();
  int part_count = 0, caps = 0, rims = 0, others = 0;
  Vec3T<S> offset = Vec3T<S>::Zero();
  for_each_part(n, tolerance, [&](const SupportFeatureT<S>& f) {
    if (f.is_cap()) {
      cap = f;
      ++caps;
    } else if (f.count == 1) {
      offset += f.points[0];
      if (f.is_rim_point()) {
        rim = f;
        rim_point = f.points[0];
        ++rims;
      }
    } else {
      if (f.count == 2) edge = f;
      ++others;
    }
    if (part_count < kStoredParts) stored[part_count] = f;
    ++part_count;
  });
  if (caps == 1 && others == 0) {
    out = cap;
    for (int i = 0; i < out.count; ++i) out.points[i] += offset;
    out.disc_centre += offset;
    return;
  }
  if (caps == 0 && rims == 1 && others == 0) {
    out.set_rim_point(offset, rim.rim_centre + (offset - rim_point), rim.rim_axis, rim.rim_radius);
    return;
  }
  Vec3T<S> first_near[kMaxNearPoints];
  const auto stored_parts = [&](auto&& add) {
    for (int i = 0; i < part_count; ++i) add(stored[i]);
  };
  const auto asked_parts = [&](auto&& add) { for_each_part(n, tolerance, add); };
  const int first_count = part_count <= kStoredParts
                              ? sum_feature_points<S>(stored_parts, n, first_near)
                              : sum_feature_points<S>(asked_parts, n, first_near);
  // point_set_feature()'s first round asks for `tolerance`, which the pass above has gathered.
  bool first_round = true;
  auto gather = [&](S, S within, Vec3T<S>* near) {
    if (first_round) {
      first_round = false;
      std::copy(first_near, first_near + first_count, near);
      return first_count;
    }
    auto parts = [&](auto&& add) { for_each_part(n, within, add); };
    return sum_feature_points<S>(parts, n, near);
  };
  point_set_feature(shape, n, tolerance, gather, out);
  // A cap and an edge (and single points): a stadium, of which the polygon holds samples of
  // the round ends. Only the cap makes a polygon here, so one means it is still in.
  if (caps == 1 && others == 1 && edge.count == 2 && out.count >= 3) {
    const Vec3T<S> centre = cap.disc_centre + offset;
    out.stadium_radius = cap.disc_radius;
    out.stadium_ends[0] = centre + edge.points[0];
    out.stadium_ends[1] = centre + edge.points[1];
  }
}

}  // namespace detail

/// A Shape of one core (a polytope or a box paired with a sum, which runs on Shapes) takes that
/// core's exact feature. A sum takes the sum of its cores' features (detail::sum_feature_points()),
/// held to the planarity and support tests of point_set_feature(), whose tolerance shrinks until
/// the polygon is a face of the sum: before, the sum's feature was sampled from 9 support points
/// 0.1 rad apart, which made a sliver "face" of a cone's base rim tilted 54 degrees from the
/// normal, and gave a polytope beside a sum sampled corners (one order found an edge of its
/// triangle, the other the triangle).
inline void support_feature(const Shape& shape, const Vec3& d, double tolerance,
                            SupportFeatureT<double>& out) {
  if (shape.cores().empty()) {
    out.set_point(Vec3::Zero());
    return;
  }
  if (shape.cores().size() == 1) {
    visit_core(shape.cores().front(),
               [&](const auto& c) { support_feature_of(c, d, tolerance, out); });
    return;
  }
  auto for_each_core = [&](const Vec3& n, double within, auto&& add) {
    for (const Core& core : shape.cores()) {
      SupportFeatureT<double> f;
      f.clear_points();  // add() copies the whole feature, its unused points too
      visit_core(core, [&](const auto& c) { support_feature_of(c, n, within, f); });
      add(f);
    }
  };
  detail::sum_support_feature(shape, d, tolerance, for_each_core, out);
}

/// A sum's feature from its two parts' (as a Shape's above).
template <ConvexShape A, ConvexShape B>
void support_feature(const MinkowskiSum<A, B>& sum, const Vec3T<typename A::Scalar>& d,
                     typename A::Scalar tolerance, SupportFeatureT<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  auto both_parts = [&](const Vec3T<S>& n, S within, auto&& add) {
    SupportFeatureT<S> f;
    f.clear_points();  // add() copies the whole feature, its unused points too
    support_feature_of(sum.a, n, within, f);
    add(f);
    support_feature_of(sum.b, n, within, f);
    add(f);
  };
  detail::sum_support_feature(sum, d, tolerance, both_parts, out);
}

}  // namespace mink
