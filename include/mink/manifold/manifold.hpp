/// @file manifold.hpp
/// The contact manifold query: up to four contact points that describe the whole contact patch of
/// two convex shapes (a box resting on a table gets its four corners, not one point), for physics
/// engines that need resting contact to stay still.
///
/// Frames: shapes in their local frames with poses to the world; results in the world frame.
///
/// Normal: the contact query's (epa/contact.hpp): unit, from A towards B, the direction in which
/// B moves to separate. Every point shares it.
///
/// Points: each manifold point is a pair on the two surfaces, point_a on A's and point_b on B's,
/// with point_b - point_a = -depth * normal. depth > 0 penetrating, depth < 0 a gap (speculative
/// points, see `margin`). position() is their midpoint, the symmetric choice: swapping A and B
/// flips the normal and keeps the positions and depths.
///
/// How (the steps of the clipping approach used by Box2D, Bullet and Jolt):
///  1. The normal and depth: the contact query (GJK, EPA on the cores), or for two boxes the
///     separating axis test (box_box.hpp), which gives the same answer for a fixed cost.
///  2. The support features (feature.hpp) of A along the normal and of B against it: a face, an
///     edge or a vertex of each core, pushed out by the core radius (so a capsule is its segment
///     moved out by its radius, a sphere one point).
///  3. Reference = the face more aligned with the normal (the larger face on a near tie, A on a
///     tie: a box resting on a table is clipped against the table, so the points are the box's
///     corners); incident = the other feature. The incident feature is clipped against the
///     reference face's side planes (Sutherland–Hodgman; the planes contain the normal), and each
///     clipped point gets its own depth: its distance along the normal to the reference face's
///     plane. Parallel edges clip against each other's end planes (capsule on capsule: 2 points).
///  4. Points whose depth is below -max(margin, touching tolerance) are dropped, the rest reduced
///     to at most four (clip.hpp): the deepest point, the point farthest from it, the largest
///     triangle, the largest added area.
///  A vertex against anything, and two crossing edges, give one point: the contact's deepest (or
///  closest) points.
///
/// Tolerances: a feature is a face or edge when its points are within
/// `feature_tolerance * bounding_radius` of the support plane (feature.hpp); a generous value is
/// harmless because clipped points keep their own depths, with one exception: a rounded face or
/// edge (rounded box, capsule side) tilted from the normal by an angle t that the tolerance lets
/// through is moved out by its radius r along the wrong direction, so its points are off the
/// surface by about r t^2 / 2 (1e-7 of the size for t = 1e-3). Every point is on both surfaces to
/// rounding for boxes and polytopes whose feature is a true face; cylinder and cone caps are
/// polygons of 16 rim points, so points clipped against a cap (not the rim points themselves)
/// are inside the disc by up to 2 % of its radius.
///
/// Cost: no allocation. A box pair is about the price of one separating axis test plus clipping;
/// other pairs cost one contact() plus a scan of each polytope's points.
#pragma once

#include <array>
#include <type_traits>

#include "mink/epa/contact.hpp"
#include "mink/manifold/box_box.hpp"
#include "mink/manifold/clip.hpp"
#include "mink/manifold/feature.hpp"

namespace mink {

template <class S>
struct ManifoldOptionsT {
  /// Separated shapes closer than this get a speculative manifold: points with negative depth
  /// (the gap), for contact before touching. Points of a penetrating manifold that are apart by
  /// more than this are dropped. (unit: length, >= 0)
  S margin = S(0);
  /// A face or edge counts as such when its points are within this fraction of the shape's
  /// bounding radius of the support plane. (unit: dimensionless)
  S feature_tolerance = S(1e-3);
  /// GJK and EPA tolerances of the contact query underneath.
  TolerancesT<S> tolerances = {};
};

template <class S>
struct ManifoldPointT {
  Vec3T<S> point_a = Vec3T<S>::Zero();  ///< on A's surface, world frame
  Vec3T<S> point_b = Vec3T<S>::Zero();  ///< on B's surface, world frame
  S depth = S(0);  ///< (unit: length) > 0 penetrating, < 0 gap; point_b - point_a = -depth * normal

  /// Midpoint of point_a and point_b (the same when A and B are swapped).
  Vec3T<S> position() const { return S(0.5) * (point_a + point_b); }
};

template <class S>
struct ManifoldResultT {
  /// Intersecting: count >= 1 points. Separated: count points (speculative, depth < 0) when the
  /// distance is within `margin`, else count = 0. IterationLimit: GJK or EPA hit the cap; the
  /// manifold is built on the best estimate. InvalidInput: nothing was computed, `error` says why.
  Status status = Status::InvalidInput;
  bool intersect = false;               ///< the shapes share a point (touching counts)
  S distance = S(0);                    ///< >= 0 (unit: length), as contact()
  S depth = S(0);                       ///< >= 0 (unit: length), as contact()
  Vec3T<S> normal = Vec3T<S>::UnitZ();  ///< unit, world frame, from A towards B, shared by points
  int count = 0;                        ///< number of valid entries of `points`, 0..4
  std::array<ManifoldPointT<S>, 4> points = {};  ///< the deepest first
  S error_bound = S(0);  ///< as contact(): bound on the error of distance or depth (unit: length)
  int iterations = 0;    ///< support evaluations of GJK and EPA (0 for two boxes)
  bool normal_chosen = false;   ///< as contact(): several normals were equally good
  const char* error = nullptr;  ///< reason for InvalidInput, else nullptr
};

using ManifoldOptions = ManifoldOptionsT<double>;
using ManifoldPoint = ManifoldPointT<double>;
using ManifoldResult = ManifoldResultT<double>;

namespace detail {

/// Box and Rounded<Box> (the run-time Shape's single box core), for the separating-axis path.
template <class T>
struct BoxCore : std::false_type {};
template <class S>
struct BoxCore<BoxT<S>> : std::true_type {
  static const Vec3T<S>& half_extents(const BoxT<S>& b) { return b.half_extents; }
};
template <class S>
struct BoxCore<Rounded<BoxT<S>>> : std::true_type {
  static const Vec3T<S>& half_extents(const Rounded<BoxT<S>>& b) { return b.shape.half_extents; }
};

/// The clipped contact points in A's frame, before reduction.
template <class S>
struct ClippedPoints {
  int count = 0;
  Vec3T<S> on_a[kMaxClipPoints];
  Vec3T<S> on_b[kMaxClipPoints];
  PlanarPoint<S> planar[kMaxClipPoints];  ///< seen along the normal, with the depths
  /// The features were two crossing edges (or an edge and a vertex, or two vertices): no
  /// clipping, `count` is 0 and the caller gives one point.
  SupportFeatureT<S> feature_a, feature_b;
};

/// The clipping of clip_features() when the reference face is a face of a box with half extents
/// h: in the box's frame, where the face's side planes are axis aligned. `to_a` takes the box's
/// frame to A's (nullptr: it is A's); `ref_point` is a corner of the reference face (pushed out by
/// the radius), `incident` the incident feature, `n` the normal, all in A's frame.
template <class S>
void clip_by_box_face(const Vec3T<S>& h, const PoseT<S>* to_a, const Vec3T<S>& face_normal,
                      const Vec3T<S>& ref_point, const SupportFeatureT<S>& incident,
                      const Vec3T<S>& n, bool ref_is_a, S min_depth, S slack,
                      ClippedPoints<S>& out) {
  auto local_dir = [&](const Vec3T<S>& d) { return to_a ? to_a->inverse_rotate(d) : d; };
  auto local_point = [&](const Vec3T<S>& p) { return to_a ? to_a->inverse_apply(p) : p; };
  const Vec3T<S> m = local_dir(face_normal);  // +-e_k up to rounding
  const Vec3T<S> am = m.cwiseAbs();
  const int k = am.x() >= am.y() && am.x() >= am.z() ? 0 : (am.y() >= am.z() ? 1 : 2);
  const int iu = (k + 1) % 3, iv = (k + 2) % 3;
  const S side = m[k] > S(0) ? S(1) : S(-1);
  const S w = side * local_point(ref_point)[k];  // the face's plane: side * p[k] = w
  // Points move along `axis` (the normal, turned to point through the face) onto the plane.
  const Vec3T<S> nl = local_dir(n);
  const Vec3T<S> axis = side * nl[k] > S(0) ? nl : Vec3T<S>(-nl);
  const S inv = S(1) / std::abs(nl[k]);
  PlanarPoint<S> buffer[2][kMaxClipPoints];
  int count = incident.count;
  for (int i = 0; i < count; ++i) {
    const Vec3T<S> p = local_point(incident.points[i]);
    const S t = (w - side * p[k]) * inv;
    buffer[0][i] = {p[iu] + t * axis[iu], side * (p[iv] + t * axis[iv]), t};
  }
  // The side lines in the order of the face's edges (counter-clockwise about its normal, which
  // the factor `side` on y keeps for both faces of the axis): y <= h_v, x >= -h_u, y >= -h_v,
  // x <= h_u.
  const S hu = h[iu], hv = h[iv];
  using P = PlanarPoint<S>;
  count = clip_by_line(
      buffer[0], count, [hv](const P& p) { return hv - p.y; }, slack, buffer[1]);
  count = clip_by_line(
      buffer[1], count, [hu](const P& p) { return p.x + hu; }, slack, buffer[0]);
  count = clip_by_line(
      buffer[0], count, [hv](const P& p) { return p.y + hv; }, slack, buffer[1]);
  count = clip_by_line(
      buffer[1], count, [hu](const P& p) { return hu - p.x; }, slack, buffer[0]);
  const int cur = 0;
  for (int i = 0; i < count; ++i) {
    const PlanarPoint<S>& p = buffer[cur][i];
    if (!(p.depth >= min_depth)) continue;
    Vec3T<S> on_ref;
    on_ref[iu] = p.x;
    on_ref[iv] = side * p.y;
    on_ref[k] = side * w;
    Vec3T<S> on_inc = on_ref - p.depth * axis;
    if (to_a) {
      on_ref = to_a->apply(on_ref);
      on_inc = to_a->apply(on_inc);
    }
    out.on_a[out.count] = ref_is_a ? on_ref : on_inc;
    out.on_b[out.count] = ref_is_a ? on_inc : on_ref;
    out.planar[out.count] = p;
    ++out.count;
  }
}

/// Steps 2 and 3 of manifold.hpp's outline, in A's frame: `rel` is B's pose in A's frame, `n` the
/// unit normal in A's frame, `min_depth` the least depth kept (negative: a gap).
template <ConvexShape A, ConvexShape B>
void clip_features(const A& a, const B& b, const PoseT<typename A::Scalar>& rel,
                   const Vec3T<typename A::Scalar>& n, typename A::Scalar feature_tolerance,
                   typename A::Scalar min_depth, typename A::Scalar size,
                   ClippedPoints<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  auto& fa = out.feature_a;
  auto& fb = out.feature_b;
  support_feature_of(a, n, feature_tolerance * a.bounding_radius(), fa);
  support_feature_of(b, rel.inverse_rotate(-n), feature_tolerance * b.bounding_radius(), fb);
  fb.normal = rel.rotate(fb.normal);
  // The radius moves a face along its own normal (exact: the rounded surface over a face is the
  // face moved out) and an edge or a vertex along the contact normal.
  const Vec3T<S> push_a = a.core_radius() * (fa.count >= 3 ? fa.normal : n);
  const Vec3T<S> push_b = b.core_radius() * (fb.count >= 3 ? fb.normal : Vec3T<S>(-n));
  for (int i = 0; i < fa.count; ++i) fa.points[i] += push_a;
  for (int i = 0; i < fb.count; ++i) fb.points[i] = rel.apply(fb.points[i]) + push_b;
  out.count = 0;

  // The reference feature: a face (>= 3 points) with its plane (normal m, offset w) and side
  // planes, or an edge with its end planes.
  const SupportFeatureT<S>* ref;
  const SupportFeatureT<S>* inc;
  bool ref_is_a;
  Vec3T<S> m;
  if (fa.count >= 3 || fb.count >= 3) {
    if (fa.count >= 3 && fb.count >= 3) {
      const S align_a = fa.normal.dot(n), align_b = -fb.normal.dot(n);
      auto area = [](const SupportFeatureT<S>& f) {
        Vec3T<S> sum = Vec3T<S>::Zero();
        for (int i = 1; i + 1 < f.count; ++i)
          sum += (f.points[i] - f.points[0]).cross(f.points[i + 1] - f.points[0]);
        return sum.norm();
      };
      if (std::abs(align_a - align_b) > S(1e-3))
        ref_is_a = align_a > align_b;
      else
        ref_is_a = area(fa) >= area(fb) * (S(1) - S(1e-6));
    } else {
      ref_is_a = fa.count >= 3;
    }
    ref = ref_is_a ? &fa : &fb;
    inc = ref_is_a ? &fb : &fa;
    m = ref->normal;
  } else if (fa.count == 2 && fb.count == 2) {
    const Vec3T<S> ea = fa.points[1] - fa.points[0], eb = fb.points[1] - fb.points[0];
    const S la = ea.norm();
    // Parallel when B's edge strays from A's line by at most the tolerance over its length.
    if (!(la > S(0)) || ea.cross(eb).norm() > feature_tolerance * size * la) return;
    ref_is_a = true;
    ref = &fa;
    inc = &fb;
    m = n - n.dot(ea / la) * (ea / la);
    if (!(m.norm() > S(0.5))) return;
    m.normalize();
  } else {
    return;
  }
  const S mn = m.dot(n);
  if (!(std::abs(mn) > S(0.5))) return;  // a face this oblique is not a contact face
  // Points up to 1e-8 of the size outside a side plane count as inside: an incident edge that
  // lies along a side plane (equal boxes stacked flush) and is turned by rounding or a 1e-9
  // rotation would otherwise be cut at an arbitrary point along its length, and the manifold
  // would flicker between corners and such points.
  const S slack = S(1e-8) * size;
  if (ref->count >= 3) {
    if constexpr (BoxCore<A>::value) {
      const PoseT<S>* a_frame = nullptr;  // A's frame is the frame of the results
      if (ref_is_a)
        return clip_by_box_face(BoxCore<A>::half_extents(a), a_frame, m, ref->points[0], *inc, n,
                                true, min_depth, slack, out);
    }
    if constexpr (BoxCore<B>::value) {
      if (!ref_is_a)
        return clip_by_box_face(BoxCore<B>::half_extents(b), &rel, m, ref->points[0], *inc, n,
                                false, min_depth, slack, out);
    }
  }

  // Seen along the normal: every point is projected along n onto the plane of (u, v) and clipped
  // there in 2D, which is clipping by the planes that contain the normal (not the face normal m:
  // the clipped points then move along the normal onto the face and stay inside it when the face
  // is tilted). Each point carries its depth: its distance along the normal to the reference
  // plane m . p = w.
  Vec3T<S> u, v;
  plane_basis(n, u, v);
  S w = -std::numeric_limits<S>::infinity();
  for (int i = 0; i < ref->count; ++i) w = std::max(w, m.dot(ref->points[i]));
  const S inv = S(1) / std::abs(mn);
  PlanarPoint<S> buffer[2][kMaxClipPoints];
  int count = inc->count;
  for (int i = 0; i < count; ++i) {
    const Vec3T<S>& p = inc->points[i];
    buffer[0][i] = {u.dot(p), v.dot(p), (w - m.dot(p)) * inv};
  }
  int cur = 0;
  // The clip lines a x + b y >= c - slack |(a, b)|, all set up before any clipping (their square
  // roots then overlap instead of waiting on each other).
  struct Line {
    S a, b, c, slack;
  };
  Line lines[kMaxFeaturePoints];
  int line_count = 0;
  auto add_line = [&](S nx, S ny, const Vec3T<S>& through) {
    lines[line_count++] = {nx, ny, nx * u.dot(through) + ny * v.dot(through),
                           slack * std::sqrt(nx * nx + ny * ny)};
  };
  if (ref->count >= 3) {
    // The polygon is counter-clockwise about m, so about n when m . n > 0: its inside is on the
    // left of each edge.
    const S side = mn > S(0) ? S(1) : S(-1);
    for (int i = 0; i < ref->count; ++i) {
      const Vec3T<S>& r0 = ref->points[i];
      const Vec3T<S> edge = ref->points[i + 1 == ref->count ? 0 : i + 1] - r0;
      add_line(-side * v.dot(edge), side * u.dot(edge), r0);
    }
  } else {
    // Between the planes through the edge's ends, across the edge.
    const Vec3T<S> edge = ref->points[1] - ref->points[0];
    const S ex = u.dot(edge), ey = v.dot(edge);
    add_line(ex, ey, ref->points[0]);
    add_line(-ex, -ey, ref->points[1]);
  }
  for (int i = 0; i < line_count && count > 0; ++i) {
    const Line& l = lines[i];
    count = clip_by_line(
        buffer[cur], count, [&l](const PlanarPoint<S>& p) { return l.a * p.x + l.b * p.y - l.c; },
        l.slack, buffer[1 - cur]);
    cur = 1 - cur;
  }
  const S inv_mn = S(1) / mn;
  for (int i = 0; i < count; ++i) {
    const PlanarPoint<S>& p = buffer[cur][i];
    if (!(p.depth >= min_depth)) continue;
    // Back to 3D: the point of the reference plane above (x, y) along n, and the incident point
    // `depth` below it.
    const Vec3T<S> in_plane = p.x * u + p.y * v;
    const Vec3T<S> on_ref = in_plane + ((w - m.dot(in_plane)) * inv_mn) * n;
    const Vec3T<S> on_inc = on_ref + (mn > S(0) ? -p.depth : p.depth) * n;
    out.on_a[out.count] = ref_is_a ? on_ref : on_inc;
    out.on_b[out.count] = ref_is_a ? on_inc : on_ref;
    out.planar[out.count] = p;
    ++out.count;
  }
}

/// Step 4 and the world frame: reduces `clipped` to at most four points of `result`.
template <class S>
void keep_four(const ClippedPoints<S>& clipped, const PoseT<S>& pose_a, S size,
               ManifoldResultT<S>& result) {
  int keep[4];
  const int kept = detail::reduce_to_four(clipped.planar, clipped.count, S(1e-9) * size, keep);
  result.count = kept;
  for (int i = 0; i < kept; ++i) {
    result.points[i].point_a = pose_a.apply(clipped.on_a[keep[i]]);
    result.points[i].point_b = pose_a.apply(clipped.on_b[keep[i]]);
    result.points[i].depth = clipped.planar[keep[i]].depth;
  }
}

/// The manifold of shapes whose normal and depth come from contact().
template <ConvexShape A, ConvexShape B>
ManifoldResultT<typename A::Scalar> manifold_from_contact(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const ManifoldOptionsT<typename A::Scalar>& options) {
  using S = typename A::Scalar;
  ManifoldResultT<S> result;
  const ContactResultT<S> c = contact(a, pose_a, b, pose_b, options.tolerances);
  result.status = c.status;
  result.error = c.error;
  result.intersect = c.intersect;
  result.distance = c.distance;
  result.depth = c.depth;
  result.normal = c.normal;
  result.error_bound = c.error_bound;
  result.iterations = c.iterations;
  result.normal_chosen = c.normal_chosen;
  if (c.status == Status::InvalidInput || (!c.intersect && !(c.distance <= options.margin)))
    return result;
  const S size = a.bounding_radius() + b.bounding_radius();
  const S min_depth = -std::max(options.margin, options.tolerances.relative * size);
  const Vec3T<S> n = pose_a.inverse_rotate(c.normal);
  ClippedPoints<S> clipped;
  clip_features(a, b, pose_a.relative(pose_b), n, options.feature_tolerance, min_depth, size,
                clipped);
  if (clipped.count > 0) {
    keep_four(clipped, pose_a, size, result);
  } else {
    // A vertex, crossing edges, or features that the clipping could not match: the contact's
    // deepest (or closest) points.
    result.count = 1;
    result.points[0].point_a = c.point_a;
    result.points[0].point_b = c.point_b;
    result.points[0].depth = c.intersect ? c.depth : -c.distance;
  }
  return result;
}

}  // namespace detail

/// Contact manifold between a (at pose_a) and b (at pose_b); see the file comment.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar> ManifoldResultT<typename A::Scalar>
manifold(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
         const PoseT<typename A::Scalar>& pose_b,
         const ManifoldOptionsT<typename A::Scalar>& options = {}) {
  using S = typename A::Scalar;
  if constexpr (detail::BoxCore<A>::value && detail::BoxCore<B>::value) {
    // Two boxes: the separating axis test gives EPA's depth and normal whenever the cores overlap.
    ManifoldResultT<S> result;
    if ((result.error = detail::query_input_error(a, pose_a, b, pose_b))) return result;
    if (!(options.margin >= S(0)) || !(options.feature_tolerance >= S(0))) {
      result.error = "manifold margin and feature_tolerance must be >= 0";
      return result;
    }
    const PoseT<S> rel = pose_a.relative(pose_b);
    const S size = a.bounding_radius() + b.bounding_radius();
    const auto axis = detail::box_box_axis(detail::BoxCore<A>::half_extents(a),
                                           detail::BoxCore<B>::half_extents(b), rel.rotation,
                                           rel.translation, S(1e-9) * size);
    if (axis.overlap > options.tolerances.relative * size) {
      const S min_depth = -std::max(options.margin, options.tolerances.relative * size);
      detail::ClippedPoints<S> clipped;
      detail::clip_features(a, b, rel, axis.normal, options.feature_tolerance, min_depth, size,
                            clipped);
      const auto& fa = clipped.feature_a;
      const auto& fb = clipped.feature_b;
      if (clipped.count == 0 && fa.count == 2 && fb.count == 2) {
        // Crossing edges: their closest points, already on the surfaces (pushed by the radii).
        Vec3T<S> on_a, on_b;
        detail::closest_points_of_segments(fa.points[0], fa.points[1], fb.points[0], fb.points[1],
                                           on_a, on_b);
        clipped.on_a[0] = on_a;
        clipped.on_b[0] = on_b;
        clipped.planar[0] = {S(0), S(0), (on_a - on_b).dot(axis.normal)};
        clipped.count = 1;
      }
      if (clipped.count > 0) {
        result.status = Status::Intersecting;
        result.intersect = true;
        result.depth = axis.overlap + a.core_radius() + b.core_radius();
        result.normal = pose_a.rotate(axis.normal);
        detail::keep_four(clipped, pose_a, size, result);
        return result;
      }
    }
    // Cores apart or touching (the axis test gives no distance), or no points: the general path.
  }
  if (!(options.margin >= S(0)) || !(options.feature_tolerance >= S(0))) {
    ManifoldResultT<S> result;
    result.error = "manifold margin and feature_tolerance must be >= 0";
    return result;
  }
  return detail::manifold_from_contact(a, pose_a, b, pose_b, options);
}

}  // namespace mink
