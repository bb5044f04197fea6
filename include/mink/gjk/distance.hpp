/// @file distance.hpp
/// Distance and closest points of two separated convex shapes by GJK with the signed-volumes
/// sub-algorithm (see signed_volumes.hpp for why not Johnson's).
///
/// Frames: each shape is given in its local frame with a pose mapping it to the world; the
/// computation runs in A's frame (shifted to A's origin, which keeps shapes far from the world
/// origin accurate) and the results are in the **world frame**.
///
/// Normal: unit, from A's closest point towards B's: point_b - point_a = distance * normal.
///
/// Accuracy: GJK stops when its upper and lower bounds on the core distance differ by at most
/// `tolerances.relative * size` (size: the sum of the shapes' bounding radii), or at
/// the rounding floor. Polytopes, boxes, points, segments and triangles converge exactly in a few
/// iterations; spheres and capsules are points and segments with a radius, so they are exact too.
/// On curved cores GJK ends at the rounding floor with a simplex that is a chord of the surface;
/// the normal is then the best proven one (separation.hpp: the least support value of A - B among
/// GJK's directions, refined by a descent when GJK's bounds stay apart). Touching shapes (distance
/// <= `tolerances.relative * size`) count as intersecting; so do curved cores that no direction
/// proves apart by more than that while GJK's upper bound is within 16 times it. When no
/// direction proves them apart and GJK's upper bound is farther, GJK stalled: IterationLimit, with
/// the distance bracketed by `error_bound`.
///
/// Penetrating shapes: the result says Intersecting with distance 0; depth, normal and deepest
/// points are the job of EPA (a separate query).
///
/// Pairs of spheres, capsules, points and segments (and their Rounded versions) take a closed form
/// instead of GJK (segment_cores.hpp): exact to rounding, 0 iterations; so do spheres and points
/// against boxes, cylinders and ellipsoids (query/point_solid.hpp), and capsules and segments
/// against boxes (query/segment_box.hpp). Pairs of boxes (and
/// rounded boxes) report 0 iterations too when the separating axis test proves them overlapping,
/// or when its best axis gives their closest points in closed form (a vertex, edge or face over a
/// face, or two crossing edges: box_box_closest() in query/box_box.hpp). For other cores with no
/// radius, overlapping pairs are mostly proved by the boolean test's first phase (gjk.hpp,
/// enclose_origin()).
///
/// Cost: no allocation, no global state, reentrant.
#pragma once

#include <optional>

#include "mink/epa/epa.hpp"
#include "mink/gjk/gjk.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/separation.hpp"
#include "mink/query/box_box.hpp"
#include "mink/query/point_set_pair.hpp"
#include "mink/query/point_solid.hpp"
#include "mink/query/scale_range.hpp"
#include "mink/query/segment_box.hpp"

namespace mink {

template <class S>
struct DistanceResultT {
  /// Separated: every field is valid. Intersecting: distance is 0 and the normal and points are
  /// zero (undefined). IterationLimit: the fields are the best estimate so far and `error_bound`
  /// bounds the distance error. InvalidInput: nothing was computed and `error` says why.
  Status status = Status::InvalidInput;
  bool intersect = false;  ///< the shapes share a point (touching within tolerance counts)
  S distance = S(0);       ///< Euclidean distance, >= 0 (unit: length); 0 when intersecting
  Vec3T<S> normal = Vec3T<S>::Zero();   ///< unit, world frame, from point_a towards point_b
  Vec3T<S> point_a = Vec3T<S>::Zero();  ///< closest point on A (world frame)
  Vec3T<S> point_b = Vec3T<S>::Zero();  ///< closest point on B (world frame)
  S error_bound = S(0);         ///< distance minus GJK's proven lower bound (unit: length), >= 0
  int iterations = 0;           ///< support evaluations of the Minkowski difference
  const char* error = nullptr;  ///< reason for InvalidInput, else nullptr
};

using DistanceResult = DistanceResultT<double>;

namespace detail {

/// The shapes' points from their cores' closest points on_a and on_b: pushed out by the radii
/// along `normal` (from A to B) and, when `origin` is given, shifted from it to the world in the
/// same expression. Two forms of moved_along() rather than a zero origin: adding a zero origin
/// would turn a -0 coordinate into +0.
template <class S>
[[gnu::always_inline]] inline void surface_points(const Vec3T<S>& on_a, const Vec3T<S>& on_b,
                                                  const Vec3T<S>& normal, S radius_a, S radius_b,
                                                  const Vec3T<S>* origin, Vec3T<S>& point_a,
                                                  Vec3T<S>& point_b) {
  if (origin) {
    point_a = moved_along(on_a, radius_a, normal, *origin);
    point_b = moved_along(on_b, -radius_b, normal, *origin);
  } else {
    point_a = moved_along(on_a, radius_a, normal);
    point_b = moved_along(on_b, -radius_b, normal);
  }
}

/// Fills the separated answer of `result` from the closest points of the cores, on_a and on_b, in
/// the world frame (or shifted from it: the caller shifts the points back), `normal`, the unit
/// direction from on_a to on_b, and `core_distance`, the cores' distance: the shapes' closest
/// points are the cores' pushed out by the radii. Points computed in A's frame are mapped to the
/// world before the call, not in the result afterwards: a mapping in place reads the fields just
/// written, and the packed load of a vector stored in parts stalls on store forwarding (6 ns a
/// query on box contact). contact_from_cores() (epa/contact.hpp) is its contact twin.
/// `origin` (optional) as in contact_from_cores(): on_a and on_b are about it, and the points are
/// shifted to the world in the same expression.
template <class S>
[[gnu::always_inline]] inline void separated_from_cores(const Vec3T<S>& on_a, const Vec3T<S>& on_b,
                                                        const Vec3T<S>& normal, S core_distance,
                                                        S radius_a, S radius_b,
                                                        DistanceResultT<S>& result,
                                                        const Vec3T<S>* origin = nullptr) {
  result.status = Status::Separated;
  result.distance = std::max(S(0), core_distance - radius_a - radius_b);
  result.normal = normal;
  surface_points(on_a, on_b, normal, radius_a, radius_b, origin, result.point_a, result.point_b);
}

/// distance()'s work, for pairs within the range of lengths (query/scale_range.hpp).
template <ConvexShape A, ConvexShape B>
DistanceResultT<typename A::Scalar> distance_in_range(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const TolerancesT<typename A::Scalar>& tolerances,
    GjkCacheT<typename A::Scalar>* cache) {
  using S = typename A::Scalar;
  DistanceResultT<S> result;
  if ((result.error = detail::query_input_error(a, pose_a, b, pose_b))) return result;
  if constexpr (detail::kSegmentCores<A, B>) {
    // Spheres, capsules, points, segments: closed form, no iteration. Computed in the world frame
    // shifted to A's origin, like GJK, so far-away pairs keep their precision.
    // Cores within reach are decided on the square of their gap, as intersect() decides them,
    // before the root and the direction, which are not reported there.
    Vec3T<S> on_a, on_b, normal = Vec3T<S>::UnitZ();
    const S radius_a = a.core_radius(), radius_b = b.core_radius();
    const S touch = tolerances.relative * (a.bounding_radius() + b.bounding_radius());
    const std::optional<S> core_distance = detail::closest_core_points_until<true>(
        a, pose_a, b, pose_b, radius_a + radius_b + touch, on_a, on_b, &normal);
    if (!core_distance) {
      result.status = Status::Intersecting;
      result.intersect = true;
      return result;
    }
    if (!(*core_distance <= std::numeric_limits<S>::max())) {
      result.error = detail::kOverflowError;
      return result;
    }
    // on_a, on_b are world points shifted to A's origin: shift them back.
    detail::separated_from_cores(on_a, on_b, normal, *core_distance, radius_a, radius_b, result,
                                 &pose_a.translation);
    return result;
  }
  if constexpr (detail::kPointSolid<A, B>) {
    // A sphere or point against a box, cylinder, cone, ellipsoid or small polytope: closed form, no
    // iteration.
    if (const auto local = detail::point_solid_local(a, pose_a, b, pose_b)) {
      const S radius_a = a.core_radius(), radius_b = b.core_radius();
      if (!(std::abs(local->signed_distance) <= std::numeric_limits<S>::max())) {
        result.error = detail::kOverflowError;
        return result;
      }
      const S touch = tolerances.relative * (a.bounding_radius() + b.bounding_radius());
      if (local->signed_distance <= radius_a + radius_b + touch) {
        result.status = Status::Intersecting;
        result.intersect = true;
        return result;
      }
      const auto cores = detail::point_solid_world<A, B>(*local, pose_a, pose_b);
      detail::separated_from_cores(cores.on_a, cores.on_b, cores.normal, cores.distance, radius_a,
                                   radius_b, result);
      return result;
    }
  }
  if constexpr (detail::kSegmentBox<A, B>) {
    // A capsule or segment against a box: closed form (query/segment_box.hpp).
    if (const auto cores = detail::segment_box_world(a, pose_a, b, pose_b)) {
      const S radius_a = a.core_radius(), radius_b = b.core_radius();
      const S touch = tolerances.relative * (a.bounding_radius() + b.bounding_radius());
      if (cores->distance <= radius_a + radius_b + touch) {
        result.status = Status::Intersecting;
        result.intersect = true;
        return result;
      }
      detail::separated_from_cores(cores->on_a, cores->on_b, cores->normal, cores->distance,
                                   radius_a, radius_b, result);
      return result;
    }
  }
  auto diff = detail::make_core_difference(a, pose_a, b, pose_b);
  const S radius_a = a.core_radius(), radius_b = b.core_radius();
  const S size = a.bounding_radius() + b.bounding_radius();
  constexpr bool kBoxes = detail::BoxCore<A>::value && detail::BoxCore<B>::value;
  if constexpr (kBoxes) {
    // Two boxes: the separating axis test proves most overlapping pairs in a few flops, as in
    // intersect(), and its best axis gives most separated pairs their closest points in closed
    // form (box_box_closest()); the rest go to GJK.
    const Vec3T<S>&ha = detail::BoxCore<A>::half_extents(a),
          &hb = detail::BoxCore<B>::half_extents(b);
    // One pass over the 15 axes: separated pairs need the best one as well as the verdict.
    const auto axes = detail::box_pair_axes(ha, hb, diff.rotation, diff.translation);
    const auto verdict =
        detail::box_box_verdict(axes, radius_a + radius_b + tolerances.relative * size);
    if (verdict == detail::BoxBoxVerdict::Overlapping) {
      result.status = Status::Intersecting;
      result.intersect = true;
      return result;
    }
    if (verdict == detail::BoxBoxVerdict::Separated) {
      const auto axis = detail::box_best_axis(axes, diff.rotation, diff.translation, S(0));
      Vec3T<S> on_a, on_b, normal;
      S core_distance;
      if (detail::box_box_closest(ha, hb, diff.rotation, diff.translation, axes, axis, true, on_a,
                                  on_b, normal, core_distance)) {
        detail::separated_from_cores(pose_a.apply(on_a), pose_a.apply(on_b), pose_a.rotate(normal),
                                     core_distance, radius_a, radius_b, result);
        // The axis warm-starts GJK the next time, should the pair move out of closed form.
        detail::save_cache(
            cache, 1, [&normal](int) { return normal; }, normal);
        return result;
      }
    }
  }
  // Overlapping cores with no radius: the boolean test's first phase proves most of them enclosed
  // for less than the distance loop (run_gjk_distance()); boxes have had the test above.
  constexpr auto kPhase = kBoxes ? detail::EnclosePhase::Off : detail::EnclosePhase::Verdict;
  detail::FramedPointsT<S> b_points;  // a small polytope B's points in A's frame
  detail::frame_points_of_b(diff, b_points);
  const auto gjk = detail::gjk_apart<kPhase>(diff, radius_a + radius_b, size, tolerances, cache);
  result.status = gjk.status;
  result.iterations = gjk.iterations;
  if (gjk.status == Status::InvalidInput) {
    result.error = detail::kOverflowError;
    return result;
  }
  const S touch = tolerances.relative * size;
  const S radii = radius_a + radius_b;
  if (detail::cores_within_reach(gjk, radii + touch)) {
    result.status = Status::Intersecting;
    result.intersect = true;
    return result;
  }
  // Cores apart, or touching within tolerance (curved cores that touch, whose GJK crawls), or
  // GJK stalled: settle_cores() tells, by the rule contact() shares (and where GJK's bracket
  // straddles touching, by contact()'s EPA).
  const auto cores = detail::settle_cores(diff, gjk, radii, size, tolerances, result.iterations);
  if constexpr (detail::kPointSetPair<A, B>) {
    // Small point sets that GJK left unsure, or nearly touching, where its normal is
    // ill-conditioned (a segment beside a needle triangle): by their features.
    if (cores.status == Status::IterationLimit ||
        (detail::kPointSetNearTouchingPair<A, B> &&
         cores.upper <= S(detail::kPointSetNearTouching) * size)) {
      if (const auto sets = detail::point_set_pair(
              diff, touch, detail::point_set_max_axes(cores.status == Status::IterationLimit))) {
        result.error_bound = S(0);
        if (!sets->apart || sets->value <= radii + touch) {
          result.status = Status::Intersecting;
          result.intersect = true;
          return result;
        }
        detail::separated_from_cores(pose_a.apply(sets->on_a), pose_a.apply(sets->on_b),
                                     pose_a.rotate(sets->normal), sets->value, radius_a, radius_b,
                                     result);
        return result;
      }
    }
  }
  result.status = cores.status;
  if (cores.status == Status::Intersecting) {
    result.intersect = true;
    return result;
  }
  detail::separated_from_cores(pose_a.apply(cores.on_a), pose_a.apply(cores.on_b),
                               pose_a.rotate(cores.normal), cores.upper, radius_a, radius_b,
                               result);
  result.status = cores.status;
  result.error_bound = std::max(S(0), cores.upper - cores.lower);
  return result;
}

}  // namespace detail

/// Distance between a (at pose_a) and b (at pose_b), with closest points and the normal.
/// `cache` (optional, in/out) warm-starts GJK from the previous query of the same pair.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar> DistanceResultT<typename A::Scalar>
distance(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
         const PoseT<typename A::Scalar>& pose_b,
         const TolerancesT<typename A::Scalar>& tolerances = {},
         GjkCacheT<typename A::Scalar>* cache = nullptr) {
  return detail::solve_in_scale_range<&detail::distance_in_range<A, B>>(a, pose_a, b, pose_b,
                                                                        tolerances, cache);
}

}  // namespace mink
