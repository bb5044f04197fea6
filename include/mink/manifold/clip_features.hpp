/// @file clip_features.hpp
/// Steps 2 and 3 of a contact manifold (manifold.hpp): the support features of both shapes along
/// the normal, the reference and incident feature, and the incident feature clipped against the
/// reference's side planes, each point with its own depth. (Two boxes: clip_box_pair.hpp.)
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/gjk/distance.hpp"
#include "mink/manifold/clip.hpp"
#include "mink/manifold/feature.hpp"
#include "mink/query/box_box.hpp"
#include "mink/shapes/point.hpp"

namespace mink::detail {

/// Manifolds count points up to this fraction of the size outside a side plane as inside: an
/// incident edge that lies along a side plane (equal boxes stacked flush) and is turned by
/// rounding or a 1e-9 rotation would otherwise be cut at an arbitrary point along its length, and
/// the manifold would flicker between corners and such points. The points so kept are then moved
/// onto the side plane, so that they lie on the reference face: kept where they were, a box
/// overhanging its equal by 1e-9 to 5e-8 had its corners up to 1.2e-8 of the size outside the
/// other box. (contact() clips with none: its witness points must lie on the surfaces.)
inline constexpr double kSideSlack = 1e-8;

/// The clipped contact points in A's frame, before reduction.
template <class S>
struct ClippedPoints {
  int count = 0;
  /// Each on_b is on_a - depth * n (n the normal in A's frame), as clipping makes them; false when
  /// some pair is not (the closest points of two crossing edges).
  bool pairs_along_normal = true;
  Vec3T<S> on_a[kMaxClipPoints];
  Vec3T<S> on_b[kMaxClipPoints];
  PlanarPoint<S> planar[kMaxClipPoints];  ///< seen along the normal, with the depths

  /// Appends a point from its position on the reference feature and on the incident one.
  void add(const Vec3T<S>& on_ref, const Vec3T<S>& on_inc, bool ref_is_a, const PlanarPoint<S>& p) {
    on_a[count] = ref_is_a ? on_ref : on_inc;
    on_b[count] = ref_is_a ? on_inc : on_ref;
    planar[count] = p;
    ++count;
  }
};

/// Whether A's face is the reference when both features are faces: the face more aligned with the
/// normal (alignments |face normal . n|), or on a near tie (within 1e-3) the larger, A's when the
/// areas tie to 1e-6, so that a box resting on a table is clipped against the table and its
/// corners are the points. `area_a`, `area_b` (any common measure of the faces' areas) are called
/// only on a near tie.
template <class S, class AreaA, class AreaB>
bool reference_is_a(S align_a, S align_b, AreaA&& area_a, AreaB&& area_b) {
  if (std::abs(align_a - align_b) > S(1e-3)) return align_a > align_b;
  return area_a() >= area_b() * (S(1) - S(1e-6));
}

/// The clipping of a manifold whose reference face is a face of a box with half extents h, done
/// in the box's frame, where the face's side planes are axis aligned. The face has the outward
/// normal side * e_k and the plane side * p[k] = w (h[k] plus the radius). `incident` holds the
/// `count` points of the incident feature and `n` is the unit normal out of the face
/// (side * n[k] > 0.5), both in the box's frame. `to_a` takes the box's frame to A's, the frame
/// of the results (nullptr: it is A's).
template <class S>
void clip_by_box_face(const Vec3T<S>& h, int k, S side, S w, const Vec3T<S>* incident, int count,
                      const Vec3T<S>& n, bool ref_is_a, S min_depth, S slack, const PoseT<S>* to_a,
                      ClippedPoints<S>& out) {
  const int iu = kNextAxis[k], iv = kPrevAxis[k];
  // Points move along n onto the plane.
  const S inv = S(1) / std::abs(n[k]);
  // The face's point above (x, y) is origin + x x_axis + y y_axis, all three taken to A's frame
  // once. Set up first: vectors that the compiler builds in memory coordinate by coordinate and
  // reads whole stall on store forwarding unless the stores have long completed.
  Vec3T<S> origin = Vec3T<S>::Unit(k) * (side * w), x_axis = Vec3T<S>::Unit(iu),
           y_axis = Vec3T<S>::Unit(iv) * side, n_in_a = n;
  if (to_a) {
    origin = to_a->apply(origin);
    x_axis = to_a->rotation.col(iu);
    y_axis = to_a->rotation.col(iv) * side;
    n_in_a = to_a->rotate(n);
  }
  PlanarPoint<S> buffer[2][kMaxClipPoints];
  const S nu = n[iu], nv = n[iv];  // in registers: a pair built in memory would stall too
  for (int i = 0; i < count; ++i) {
    const Vec3T<S>& p = incident[i];
    const S t = (w - side * p[k]) * inv;
    set_planar(buffer[0][i], p[iu] + t * nu, side * (p[iv] + t * nv), t);
  }
  // The side lines in the order of the face's edges (counter-clockwise about its normal, which
  // the factor `side` on y keeps for both faces of the axis): y <= h_v, x >= -h_u, y >= -h_v,
  // x <= h_u.
  // Only against the sides that some point is outside of: clipping makes new points between old
  // ones, never farther out, and a feature inside the face (a small box on a large one) needs no
  // clipping at all.
  const S hu = h[iu], hv = h[iv];
  constexpr S kInf = std::numeric_limits<S>::infinity();
  S min_x = kInf, max_x = -kInf, min_y = kInf, max_y = -kInf;
  for (int i = 0; i < count; ++i) {
    min_x = std::min(min_x, buffer[0][i].x);
    max_x = std::max(max_x, buffer[0][i].x);
    min_y = std::min(min_y, buffer[0][i].y);
    max_y = std::max(max_y, buffer[0][i].y);
  }
  int cur = 0;
  auto clip = [&](auto&& height) {
    count = clip_by_line(buffer[cur], count, height, slack, buffer[1 - cur]);
    cur = 1 - cur;
  };
  using P = PlanarPoint<S>;
  if (max_y > hv + slack) clip([hv](const P& p) { return hv - p.y; });
  if (min_x < -hu - slack) clip([hu](const P& p) { return p.x + hu; });
  if (min_y < -hv - slack) clip([hv](const P& p) { return p.y + hv; });
  if (max_x > hu + slack) clip([hu](const P& p) { return hu - p.x; });
  // Points the slack kept outside a side line go onto it: the face's point is then on the face,
  // and the incident point moves by at most the slack, along the face.
  for (int i = 0; i < count; ++i) {
    PlanarPoint<S>& p = buffer[cur][i];
    p.x = std::clamp(p.x, -hu, hu);
    p.y = std::clamp(p.y, -hv, hv);
  }
  // Back to 3D in A's frame: the point of the face above (x, y), and the incident point `depth`
  // below it along n.
  for (int i = 0; i < count; ++i) {
    const PlanarPoint<S>& p = buffer[cur][i];
    if (!(p.depth >= min_depth)) continue;
    const Vec3T<S> on_ref = origin + p.x * x_axis + p.y * y_axis;
    out.add(on_ref, on_ref - p.depth * n_in_a, ref_is_a, p);
  }
}

/// Moves `at`, a point on the line through it along `out` (unit, pointing out of `shape`), to
/// where that line leaves the shape (at `pose`; both in A's frame), by conservative advancement:
/// from a point on the support plane along `out`, each step moves along the line to the support
/// plane of the closest point, which keeps it outside; exact in one step on a face, a few on a
/// curved surface. Returns whether the walk ended touching the shape, within 1e-9 of its bounding
/// radius (the default 1e-12 costs GJK on a curved core twice the support calls, and points on
/// a curved surface are only as good as the contact normal, 1e-6 of the size off for a
/// cylinder); false when the line misses the shape or runs almost along its surface, or after 16
/// steps.
template <ConvexShape T>
bool exit_point_along(const T& shape, const PoseT<typename T::Scalar>& pose,
                      const Vec3T<typename T::Scalar>& out, Vec3T<typename T::Scalar>& at) {
  using S = typename T::Scalar;
  TolerancesT<S> tolerances;
  tolerances.relative = std::max(tolerances.relative, S(1e-9));
  tolerances.max_iterations = 64;
  const Vec3T<S> top = pose.apply(support(shape, pose.inverse_rotate(out)));
  at += std::max(S(0), out.dot(top - at)) * out;
  for (int step = 0; step < 16; ++step) {
    PoseT<S> point_pose;
    point_pose.translation = at;
    const DistanceResultT<S> d = distance(shape, pose, PointT<S>{}, point_pose, tolerances);
    if (d.status == Status::Intersecting) return true;
    // A capped GJK still gives its best estimate to step with.
    if (d.status != Status::Separated && d.status != Status::IterationLimit) return false;
    const S along = d.normal.dot(out);
    if (!(along > S(0.05)) || !(d.distance > S(0))) return false;
    at -= (d.distance / along) * out;
  }
  return false;
}

/// Step 3 for the features fa of A and fb of B (pushed out by the radii, both in A's frame);
/// clip_features()' arguments otherwise.
template <ConvexShape A, ConvexShape B>
void clip_feature_pair(const A& a, const B& b, const PoseT<typename A::Scalar>& rel,
                       const Vec3T<typename A::Scalar>& n,
                       const SupportFeatureT<typename A::Scalar>& fa,
                       const SupportFeatureT<typename A::Scalar>& fb,
                       typename A::Scalar feature_tolerance, typename A::Scalar min_depth,
                       typename A::Scalar size, typename A::Scalar slack,
                       ClippedPoints<typename A::Scalar>& out) {
  using S = typename A::Scalar;
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
      ref_is_a = reference_is_a(
          align_a, align_b, [&] { return area(fa); }, [&] { return area(fb); });
    } else {
      ref_is_a = fa.count >= 3;
    }
    ref = ref_is_a ? &fa : &fb;
    inc = ref_is_a ? &fb : &fa;
    m = ref->normal;
  } else if (fa.count == 2 && fb.count == 2) {
    const Vec3T<S> ea = fa.points[1] - fa.points[0], eb = fb.points[1] - fb.points[0];
    const S la = ea.norm(), lb = eb.norm();
    // Parallel when the shorter edge strays from the longer one's line by at most the tolerance
    // over its length. The longer edge is the reference (A's on a tie), whichever shape is A, so
    // that swapping the shapes keeps the points.
    if (!(la > S(0) && lb > S(0)) ||
        ea.cross(eb).norm() > feature_tolerance * size * std::max(la, lb))
      return;
    ref_is_a = la >= lb;
    ref = ref_is_a ? &fa : &fb;
    inc = ref_is_a ? &fb : &fa;
    // m: out of the reference shape, across its edge.
    const Vec3T<S> along = (ref_is_a ? ea / la : eb / lb);
    const Vec3T<S> out_of_ref_shape = ref_is_a ? n : Vec3T<S>(-n);
    m = part_across(out_of_ref_shape, along);
    if (!(m.norm() > S(0.5))) return;
    m.normalize();
  } else {
    return;
  }
  const S mn = m.dot(n);
  if (!(std::abs(mn) > S(0.5))) return;  // a face this oblique is not a contact face
  const Vec3T<S> out_of_ref = mn > S(0) ? n : Vec3T<S>(-n);
  // A box's face: clipped in the box's frame, against its axis-aligned sides.
  if (ref->count >= 3) {
    if constexpr (BoxCore<A>::value) {
      if (ref_is_a) {
        const int k = dominant_axis(m);  // m = +-e_k
        const S side = sign_nonneg(m[k]);
        return clip_by_box_face(BoxCore<A>::half_extents(a), k, side, side * ref->points[0][k],
                                inc->points, inc->count, out_of_ref, true, min_depth, slack,
                                static_cast<const PoseT<S>*>(nullptr), out);
      }
    }
    if constexpr (BoxCore<B>::value) {
      if (!ref_is_a) {
        const Vec3T<S> m_b = rel.inverse_rotate(m);
        const int k = dominant_axis(m_b);
        const S side = sign_nonneg(m_b[k]);
        Vec3T<S> incident[kMaxFeaturePoints];
        for (int i = 0; i < inc->count; ++i) incident[i] = rel.inverse_apply(inc->points[i]);
        return clip_by_box_face(BoxCore<B>::half_extents(b), k, side,
                                side * rel.inverse_apply(ref->points[0])[k], incident, inc->count,
                                rel.inverse_rotate(out_of_ref), false, min_depth, slack, &rel, out);
      }
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
    set_planar(buffer[0][i], u.dot(p), v.dot(p), (w - m.dot(p)) * inv);
  }
  int cur = 0;
  // The clip lines a x + b y >= c - slack |(a, b)|, all set up before any clipping (their square
  // roots then overlap instead of waiting on each other).
  struct Line {
    S a, b, c, slack;
  };
  Line lines[kMaxFeaturePoints];
  int line_count = 0;
  S ex = S(0), ey = S(0);  // a reference edge, seen along the normal
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
    ex = u.dot(edge);
    ey = v.dot(edge);
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
  // Points the slack kept outside a line go onto it, as in clip_by_box_face(); a moved point
  // goes over the lines once more, since going onto one line at a corner can leave it a little
  // outside the other.
  for (int i = 0; i < count; ++i) {
    PlanarPoint<S>& p = buffer[cur][i];
    for (int pass = 0; pass < 2; ++pass) {
      bool moved = false;
      for (int j = 0; j < line_count; ++j) {
        const Line& l = lines[j];
        const S height = l.a * p.x + l.b * p.y - l.c;
        const S ab = l.a * l.a + l.b * l.b;
        // Not onto a line whose normal's square underflows (an edge 1e-154 of the coordinates
        // long): the step would not be finite, and the point stays within the slack.
        if (!(height < S(0)) || !(ab >= std::numeric_limits<S>::min())) continue;
        const S step = -height / ab;
        p.x += step * l.a;
        p.y += step * l.b;
        moved = true;
      }
      if (!moved) break;
    }
  }
  // A reference edge: how far a point is beside it, seen along the normal (unit: length).
  S e0 = S(0), inv_e = S(0);
  if (ref->count == 2) {
    e0 = ex * v.dot(ref->points[0]) - ey * u.dot(ref->points[0]);
    inv_e = S(1) / std::hypot(ex, ey);
  }
  auto beside = [&](const PlanarPoint<S>& p) { return (ex * p.y - ey * p.x - e0) * inv_e; };
  const S on_edge = std::max(S(1e-12), S(64) * std::numeric_limits<S>::epsilon()) * size;
  if (ref->count == 2 && count == 2) {
    // Skew edges: the contact is deepest where the incident edge crosses the reference edge,
    // seen along the normal (beside the reference edge, the points moved onto its shape below
    // lose depth on both sides). That point is not among the clipped ends.
    const S s0 = beside(buffer[cur][0]), s1 = beside(buffer[cur][1]);
    if ((s0 > on_edge && s1 < -on_edge) || (s0 < -on_edge && s1 > on_edge)) {
      const PlanarPoint<S>&p0 = buffer[cur][0], &p1 = buffer[cur][1];
      const S t = s0 / (s0 - s1);
      buffer[cur][count++] = {p0.x + t * (p1.x - p0.x), p0.y + t * (p1.y - p0.y),
                              p0.depth + t * (p1.depth - p0.depth)};
    }
  }
  const S inv_mn = S(1) / mn;
  for (int i = 0; i < count; ++i) {
    PlanarPoint<S> p = buffer[cur][i];
    if (!(p.depth >= min_depth)) continue;
    // Back to 3D: the point of the reference plane above (x, y) along n, and the incident point
    // `depth` below it.
    const Vec3T<S> in_plane = p.x * u + p.y * v;
    Vec3T<S> on_ref = in_plane + ((w - m.dot(in_plane)) * inv_mn) * n;
    const Vec3T<S> on_inc = on_ref - p.depth * out_of_ref;
    if (ref->count == 2 && std::abs(beside(p)) > on_edge) {
      // The plane through a reference edge is its shape's surface only along the edge; beside
      // it, the point would be off the surface and its depth wrong. It goes onto the surface
      // along the normal instead.
      // A line that misses the shape (a thin one, or a point far beside it) has no such point:
      // the point is dropped.
      const bool on_surface = ref_is_a ? exit_point_along(a, PoseT<S>{}, out_of_ref, on_ref)
                                       : exit_point_along(b, rel, out_of_ref, on_ref);
      if (!on_surface) continue;
      p.depth = out_of_ref.dot(on_ref - on_inc);
      if (!(p.depth >= min_depth)) continue;
    }
    out.add(on_ref, on_inc, ref_is_a, p);
  }
}

/// Adds to `out` the points where the edges of `other` (a polygon or an edge, seen along n) cross
/// the rim of the cap `disc` (a feature with a disc_radius), both in A's frame: points of the
/// contact patch's boundary exactly on both surfaces, where the clipped rim polygon falls short
/// of the circle by up to 2 % of its radius (and misses a patch that lies only in that band).
/// Each is paired with the point of `other` straight along n, and kept when its depth is at least
/// min_depth. The planar coordinates of every point in `out` are then taken across n, one frame
/// for the points of both sources.
template <class S>
void add_rim_crossings(const SupportFeatureT<S>& disc, const SupportFeatureT<S>& other,
                       bool disc_is_a, const Vec3T<S>& n, S min_depth, ClippedPoints<S>& out) {
  const Vec3T<S>& m = disc.normal;
  const S mn = m.dot(n);
  if (!(std::abs(mn) > S(0.5)) || other.count < 2) return;
  // The other feature's points moved along n into the disc's plane: o + shift n.
  const S plane = m.dot(disc.disc_centre);
  Vec3T<S> moved[kMaxFeaturePoints];
  S shift[kMaxFeaturePoints];
  for (int i = 0; i < other.count; ++i) {
    shift[i] = (plane - m.dot(other.points[i])) / mn;
    moved[i] = other.points[i] + shift[i] * n;
  }
  const S r_sq = disc.disc_radius * disc.disc_radius;
  const int edges = other.count == 2 ? 1 : other.count;
  for (int i = 0; i < edges; ++i) {
    const int j = i + 1 == other.count ? 0 : i + 1;
    // |p + t e - c|^2 = r^2 for t in [0, 1]; the roots from the stable form of the quadratic.
    const Vec3T<S> e = moved[j] - moved[i], f = moved[i] - disc.disc_centre;
    const S ee = e.squaredNorm(), ef = e.dot(f), ff_r = f.squaredNorm() - r_sq;
    const S disc_sq = ef * ef - ee * ff_r;
    if (!(ee > S(0)) || !(disc_sq >= S(0))) continue;
    const S q = -(ef + std::copysign(std::sqrt(disc_sq), ef));
    const S roots[2] = {q / ee, q != S(0) ? ff_r / q : S(0)};
    for (const S t : roots) {
      if (!(t >= S(0) && t <= S(1)) || out.count >= kMaxClipPoints) continue;
      const Vec3T<S> on_disc = moved[i] + t * e;
      const S s = shift[i] + t * (shift[j] - shift[i]);
      const S depth = disc_is_a ? s : -s;
      if (!(depth >= min_depth)) continue;
      out.add(on_disc, on_disc - s * n, disc_is_a, PlanarPoint<S>{S(0), S(0), depth});
    }
  }
  Vec3T<S> u, v;
  plane_basis(n, u, v);
  for (int i = 0; i < out.count; ++i) {
    out.planar[i].x = u.dot(out.on_a[i]);
    out.planar[i].y = v.dot(out.on_a[i]);
  }
}

/// Steps 2 and 3 of manifold.hpp's outline, in A's frame: `rel` is B's pose in A's frame, `n` the
/// unit normal in A's frame, `min_depth` the least depth kept (negative: a gap), `slack` how far
/// outside a side plane a point still counts as inside (unit: length; see kSideSlack).
template <ConvexShape A, ConvexShape B>
void clip_features(const A& a, const B& b, const PoseT<typename A::Scalar>& rel,
                   const Vec3T<typename A::Scalar>& n, typename A::Scalar feature_tolerance,
                   typename A::Scalar min_depth, typename A::Scalar size, typename A::Scalar slack,
                   ClippedPoints<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  const Vec3T<S> nb = rel.inverse_rotate(-n);  // B's feature direction, in B's frame
  SupportFeatureT<S> fa, fb;
  support_feature_of(a, n, feature_tolerance * a.bounding_radius(), fa);
  support_feature_of(b, nb, feature_tolerance * b.bounding_radius(), fb);
  // The radius moves a face along its own normal and a vertex along the contact normal. An
  // edge tilted from the normal by t (within the tolerance) moves along the normal at its deeper
  // end, whose rounded end is deepest there, and across the edge at its other end: both are then
  // on the rounded surface, and the deepest point is exact. (Along the normal, the other end would
  // be inside by radius * t^2 / 2.) Points clipped between the ends lie on the chord, inside by
  // at most that.
  auto push = [](SupportFeatureT<S>& f, const Vec3T<S>& toward, S radius) {
    if (radius == S(0)) return;
    if (f.count >= 3) {
      for (int i = 0; i < f.count; ++i) f.points[i] += radius * f.normal;
      f.disc_centre += radius * f.normal;
      return;
    }
    if (f.count == 2) {
      push_rounded_edge(f.points[0], f.points[1], toward, radius);
      return;
    }
    f.points[0] += radius * toward;
  };
  push(fa, n, a.core_radius());
  push(fb, nb, b.core_radius());
  fb.normal = rel.rotate(fb.normal);
  for (int i = 0; i < fb.count; ++i) fb.points[i] = rel.apply(fb.points[i]);
  if (fb.disc_radius > S(0)) fb.disc_centre = rel.apply(fb.disc_centre);
  clip_feature_pair(a, b, rel, n, fa, fb, feature_tolerance, min_depth, size, slack, out);
  // A cap against a polygon or an edge: the clipped rim polygon stops short of the rim.
  if (fa.disc_radius > S(0) && fb.disc_radius == S(0))
    add_rim_crossings(fa, fb, true, n, min_depth, out);
  else if (fb.disc_radius > S(0) && fa.disc_radius == S(0))
    add_rim_crossings(fb, fa, false, n, min_depth, out);
}

}  // namespace mink::detail
