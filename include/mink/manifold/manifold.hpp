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
///     separating axis test (query/box_box.hpp), which gives the same answer for a fixed cost.
///  2. The support features (feature.hpp) of A along the normal and of B against it: a face, an
///     edge or a vertex of each core, pushed out by the core radius (so a capsule is its segment
///     moved out by its radius, a sphere one point). Two boxes read them off their axes
///     (clip_box_pair.hpp).
///  3. Reference = the face more aligned with the normal (the larger face on a near tie, A on a
///     tie: a box resting on a table is clipped against the table, so the points are the box's
///     corners); incident = the other feature. The incident feature is clipped against the
///     reference face's side planes (Sutherland–Hodgman; the planes contain the normal), and each
///     clipped point gets its own depth: its distance along the normal to the reference face's
///     plane. Parallel edges (to the tolerance) clip the shorter against the longer one's end
///     planes (capsule on capsule: 2 points). Edges that are not exactly parallel also get the
///     point where they cross, seen along the normal, the deepest one; and each point beside the
///     reference edge is paired with the point of the reference shape straight along the normal
///     (a ray cast by conservative advancement), since the plane through the edge is the shape's
///     surface only along the edge.
///  4. Points whose depth is below -max(margin, touching tolerance) are dropped, the rest reduced
///     to at most four (clip.hpp): the deepest point, the point farthest from it, the largest
///     triangle, the largest added area (points on a line: the deepest and both ends).
///  A vertex against anything, and two crossing edges, give one point: the contact's deepest (or
///  closest) points.
///
/// Tolerances: a feature is a face or edge when its points are within
/// `feature_tolerance * bounding_radius` of the support plane (feature.hpp); a generous value is
/// harmless because clipped points keep their own depths. Points are on both surfaces to rounding
/// for boxes and polytopes, and at the ends of rounded edges (capsules) and on rounded faces. A
/// rounded edge tilted from the normal by an angle t that the tolerance lets through is moved out
/// along the normal at its deeper end and across the edge at the other, so points clipped
/// between its ends lie on the chord, inside the surface by at most r t^2 / 2. Cylinder and cone
/// caps are polygons of 16 rim points, to which the points where the other feature's edges cross
/// the rim itself are added (exact, on both surfaces), so the patch reaches the rim even where it
/// lies only between that polygon and the rim; points where the polygon's own sides are clipped
/// lie on the cap up to 2 % of its radius inside the rim. Two caps against each other (cylinder
/// on cylinder) use the polygons alone.
///
/// Cost: no allocation. A box pair is about the price of one separating axis test plus clipping;
/// other pairs cost one contact() plus a scan of each polytope's points. Skew edges add one or
/// two distance() calls of a point per point beside the reference edge: little on boxes and
/// polytopes, several microseconds on a cylinder's or cone's side (a cylinder across a box's
/// edge: 3.4 us before, 6 to 12 us with them).
#pragma once

#include <array>
#include <type_traits>

#include "mink/epa/contact.hpp"
#include "mink/manifold/clip_box_pair.hpp"
#include "mink/query/scale_range.hpp"

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
  /// The deepest first. 16-byte aligned: the zeroing's paired stores then never straddle a cache
  /// line (on box pairs, one that did held half of manifold()'s own samples).
  alignas(16) std::array<ManifoldPointT<S>, 4> points = {};
  S error_bound = S(0);  ///< as contact(): bound on the error of distance or depth (unit: length)
  int iterations = 0;    ///< support evaluations of GJK and EPA (0 for two boxes)
  bool normal_chosen = false;   ///< as contact(): several normals were equally good
  const char* error = nullptr;  ///< reason for InvalidInput, else nullptr
};

using ManifoldOptions = ManifoldOptionsT<double>;
using ManifoldPoint = ManifoldPointT<double>;
using ManifoldResult = ManifoldResultT<double>;

namespace detail {

/// Manifold points closer than this times the size are one point (reduce_to_four()).
inline constexpr double kRepeatLength = 1e-9;

/// Step 4 and the world frame: reduces `clipped` to at most four points of `result`, whose
/// normal is set.
template <class S>
void keep_four(const ClippedPoints<S>& clipped, const PoseT<S>& pose_a, S size,
               ManifoldResultT<S>& result) {
  int keep[4];
  const int kept =
      detail::reduce_to_four(clipped.planar, clipped.count, S(kRepeatLength) * size, keep);
  result.count = kept;
  for (int i = 0; i < kept; ++i) {
    const S depth = clipped.planar[keep[i]].depth;
    ManifoldPointT<S>& point = result.points[i];
    point.point_a = pose_a.apply(clipped.on_a[keep[i]]);
    // point_b follows from point_a along the normal (one transform a point instead of two),
    // unless the pair is not apart along it: the closest points of two crossing edges clamped to
    // an edge's end, each of which must stay on its surface.
    point.point_b = clipped.pairs_along_normal ? Vec3T<S>(point.point_a - depth * result.normal)
                                               : pose_a.apply(clipped.on_b[keep[i]]);
    point.depth = depth;
  }
}

/// Adds the contact's own pair (`c`, computed with A at the identity: its points and normal `n`
/// are in A's frame) to `clipped` (count > 0) when it is deeper than every clipped point
/// by more than `margin` (the touching tolerance): the features clipped need not hold the deepest
/// point (a rounded cylinder deep in a sum of a polytope and a segment gave one point 0.1
/// shallower than the depth, 3 % of the size; with A and B swapped, the full depth; a cylinder's
/// 16-point rim polygon, tilted 1e-6 rad, fell 3.9e-9 short), and the manifold's deepest point
/// must be the contact's. The pair goes first, as the reduction takes the first of the points
/// within its tolerance of the deepest (a full set gives up its shallowest point). The points'
/// planar coordinates are then taken again, all in one basis across the normal (the clipping's
/// may be a face's own, an affine image of it), for the reduction to keep.
///
/// A clipped point that is the pair's own corner, rounded the face's way, gives the pair its
/// slot: a face of a rounded core moves by the radius r along its own normal, tilted from the
/// contact's, so its corner lies apart from the corner's deepest point and a little shallower
/// (1.2e-5 apart for a rounded triangle tilted 8e-5 rad, which kept both, 4 points for 3). Both
/// lie on the sphere of radius r about the pair's core point: a point of A within r_a (plus
/// `min_length`, the reduction's repeat distance) of point_a - r_a n, or of B within r_b of
/// point_b + r_b n, is that corner. Any other point of the rounded surface is farther from the
/// core point (a reach of sqrt(2 r (depth - its depth)) from the pair, used before, took a base's
/// rim point 0.2 away for the corner of a cone-and-capsule sum, and which one depended on the
/// order of the shapes).
template <class S>
void add_deepest_pair(const ContactResultT<S>& c, const Vec3T<S>& n, S margin, S radius_a,
                      S radius_b, S min_length, ClippedPoints<S>& clipped) {
  const S depth = c.intersect ? c.depth : -c.distance;
  const Vec3T<S> core_a = c.point_a - radius_a * n, core_b = c.point_b + radius_b * n;
  int shallowest = 0, same_corner = -1;
  S deepest = -std::numeric_limits<S>::infinity();
  for (int i = 0; i < clipped.count; ++i) {
    deepest = std::max(deepest, clipped.planar[i].depth);
    if (clipped.planar[i].depth < clipped.planar[shallowest].depth) shallowest = i;
    if (same_corner < 0 && ((clipped.on_a[i] - core_a).norm() <= radius_a + min_length ||
                            (clipped.on_b[i] - core_b).norm() <= radius_b + min_length))
      same_corner = i;
  }
  if (!(depth > deepest + margin)) return;
  // Entries before the free slot (the corner's, the end, or the shallowest point's) move up by
  // one.
  const int free_slot = same_corner >= 0                 ? same_corner
                        : clipped.count < kMaxClipPoints ? clipped.count++
                                                         : shallowest;
  for (int i = free_slot; i > 0; --i) {
    clipped.on_a[i] = clipped.on_a[i - 1];
    clipped.on_b[i] = clipped.on_b[i - 1];
    clipped.planar[i] = clipped.planar[i - 1];
  }
  clipped.on_a[0] = c.point_a;
  clipped.on_b[0] = c.point_b;
  clipped.planar[0].depth = depth;
  Vec3T<S> u, v;
  plane_basis(n, u, v);
  for (int i = 0; i < clipped.count; ++i)
    set_planar(clipped.planar[i], u.dot(clipped.on_a[i]), v.dot(clipped.on_a[i]),
               clipped.planar[i].depth);
}

/// The manifold of shapes whose normal and depth come from contact(), into `result` (default
/// constructed). contact() runs in A's frame (A at the identity, B at the relative pose), where
/// the features are clipped: it computes in that frame anyway, and its points taken to the world
/// and back lost the world's rounding (1e-8 at 8e7 from the origin, 6e-9 of a unit pair's size),
/// which set the contact's pair apart from the same clipped point by more than the reduction's
/// 1e-9 of the size, and kept both. The input must have been checked (query_input_error()).
template <ConvexShape A, ConvexShape B>
void manifold_from_contact(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
                           const PoseT<typename A::Scalar>& pose_b,
                           const ManifoldOptionsT<typename A::Scalar>& options,
                           ManifoldResultT<typename A::Scalar>& result) {
  using S = typename A::Scalar;
  const PoseT<S> relative = pose_a.relative(pose_b);
  const ContactResultT<S> c = contact(a, PoseT<S>::identity(), b, relative, options.tolerances);
  result.status = c.status;
  result.error = c.error;
  result.intersect = c.intersect;
  result.distance = c.distance;
  result.depth = c.depth;
  result.normal = pose_a.rotate(c.normal);
  result.error_bound = c.error_bound;
  result.iterations = c.iterations;
  result.normal_chosen = c.normal_chosen;
  if (c.status == Status::InvalidInput || (!c.intersect && !(c.distance <= options.margin))) return;
  const S size = a.bounding_radius() + b.bounding_radius();
  const S min_depth = -std::max(options.margin, options.tolerances.relative * size);
  ClippedPoints<S> clipped;
  clip_features(a, b, relative, c.normal, options.feature_tolerance, min_depth, size,
                S(kSideSlack) * size, clipped);
  if (clipped.count > 0)
    add_deepest_pair(c, c.normal, options.tolerances.relative * size, a.core_radius(),
                     b.core_radius(), S(kRepeatLength) * size, clipped);
  if (clipped.count > 0) {
    keep_four(clipped, pose_a, size, result);
  } else {
    // A vertex, crossing edges, or features that the clipping could not match: the contact's
    // deepest (or closest) points.
    result.count = 1;
    result.points[0].point_a = pose_a.apply(c.point_a);
    result.points[0].point_b = pose_a.apply(c.point_b);
    result.points[0].depth = c.intersect ? c.depth : -c.distance;
  }
}

/// The manifold of two boxes (Box or Rounded<Box>) whose cores overlap, into `result` (default
/// constructed): the separating axis test gives EPA's depth and normal, and the boxes' axes give
/// their features. Returns false, `result` untouched, when the cores are apart or touching (the
/// axis test gives no distance) or the clipping finds no points: the general path answers then.
template <ConvexShape A, ConvexShape B>
bool box_manifold(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
                  const PoseT<typename A::Scalar>& pose_b,
                  const ManifoldOptionsT<typename A::Scalar>& options,
                  ManifoldResultT<typename A::Scalar>& result) {
  using S = typename A::Scalar;
  // The radii first: every tolerance below waits on them.
  S bound_a, bound_b;
  box_bounding_radii(a, b, bound_a, bound_b);
  const S size = bound_a + bound_b;
  const PoseT<S> rel = pose_a.relative(pose_b);
  const auto axis = box_box_axis(BoxCore<A>::half_extents(a), BoxCore<B>::half_extents(b),
                                 rel.rotation, rel.translation, S(1e-9) * size);
  if (!(axis.overlap > options.tolerances.relative * size)) return false;
  const S min_depth = -std::max(options.margin, options.tolerances.relative * size);
  ClippedPoints<S> clipped;
  clip_box_pair(a, b, rel, axis.normal, options.feature_tolerance, min_depth, bound_a, bound_b,
                S(kSideSlack) * size, clipped);
  if (clipped.count == 0) return false;
  result.status = Status::Intersecting;
  result.intersect = true;
  result.depth = axis.overlap + a.core_radius() + b.core_radius();
  result.normal = pose_a.rotate(axis.normal);
  keep_four(clipped, pose_a, size, result);
  return true;
}

/// The margin is a length: scaled with the pair (query/scale_range.hpp); feature_tolerance is
/// relative.
template <class S>
struct OptionsAtScale<ManifoldOptionsT<S>> {
  static ManifoldOptionsT<S> scaled(const ManifoldOptionsT<S>& options, S factor) {
    ManifoldOptionsT<S> scaled = options;
    scaled.margin *= factor;
    return scaled;
  }
};

/// manifold()'s work, for pairs within the range of lengths (query/scale_range.hpp). Inlined:
/// it is a few checks and a call, and an outlined call cost a box pair 20 instructions.
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline ManifoldResultT<typename A::Scalar> manifold_in_range(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const ManifoldOptionsT<typename A::Scalar>& options) {
  using S = typename A::Scalar;
  // One result object for every path, returned by name: a second one moved out would copy its
  // 300 bytes (a few percent of a box pair's time).
  ManifoldResultT<S> result;
  if (!(options.margin >= S(0)) || !(options.feature_tolerance >= S(0))) {
    result.error = "manifold margin and feature_tolerance must be >= 0";
    return result;
  }
  // Checked here in the world frame, once for every path: contact() below sees only the
  // relative pose, whose error message would name the wrong pose.
  if ((result.error = detail::query_input_error(a, pose_a, b, pose_b))) return result;
  if constexpr (detail::BoxCore<A>::value && detail::BoxCore<B>::value) {
    if (detail::box_manifold(a, pose_a, b, pose_b, options, result)) return result;
  }
  detail::manifold_from_contact(a, pose_a, b, pose_b, options, result);
  return result;
}

}  // namespace detail

/// Contact manifold between a (at pose_a) and b (at pose_b); see the file comment.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar> ManifoldResultT<typename A::Scalar>
manifold(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
         const PoseT<typename A::Scalar>& pose_b,
         const ManifoldOptionsT<typename A::Scalar>& options = {}) {
  return detail::solve_in_scale_range<&detail::manifold_in_range<A, B>>(a, pose_a, b, pose_b,
                                                                        options);
}

}  // namespace mink
