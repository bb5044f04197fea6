/// @file intersect.hpp
/// Boolean intersection test of two convex shapes by GJK with early exit.
///
/// Frames: each shape is given in its local frame with a pose mapping it to the world; the
/// computation runs in A's frame. Touching shapes (distance at most `tolerances.relative` times
/// the sum of the bounding radii) count as intersecting. Rounded shapes and sums run on their cores
/// and compare the core distance with the sum of the radii: exact, no sampling of curved surfaces.
///
/// Cost: no allocation, no global state, reentrant. Typically 1-6 support calls per shape; at most
/// `tolerances.max_iterations`. Pairs of spheres, capsules, points and segments (and their
/// Rounded versions) take a closed form instead (segment_cores.hpp) and report 0 iterations; so do
/// pairs of boxes (and rounded boxes) that the separating axis test decides
/// (query/box_box.hpp: when the cores overlap or are clearly apart, and no two edges are parallel
/// to within 1e-6 without being exactly parallel; a point of one core within reach of the other
/// also proves an overlap), spheres and points against boxes, cylinders and ellipsoids
/// (query/point_solid.hpp), and capsules and segments against boxes (query/segment_box.hpp). A
/// sphere or point against a core with no closed form (a polytope of 64 points or more, a hull, a
/// sum) first tries that core's support plane facing it, and GJK starts from that support point
/// when the plane does not decide (query/point_solid.hpp, PointSupportPlane).
#pragma once

#include "mink/epa/epa.hpp"
#include "mink/gjk/gjk.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/separation.hpp"
#include "mink/query/box_box.hpp"
#include "mink/query/point_set_pair.hpp"
#include "mink/query/point_solid.hpp"
#include "mink/query/polytope_pair.hpp"
#include "mink/query/scale_range.hpp"
#include "mink/query/segment_box.hpp"

namespace mink {

template <class S>
struct IntersectResultT {
  /// Separated or Intersecting when decided; IterationLimit when the cap was hit (then
  /// `intersect` is the best guess: the upper bound on the distance was within touching range)
  /// or when GJK's bounds stayed on both sides of the touching range (then as distance() says);
  /// InvalidInput when a shape or pose is invalid (then `intersect` is false and `error` says why).
  Status status = Status::InvalidInput;
  bool intersect = false;       ///< the shapes share a point (touching within tolerance counts)
  int iterations = 0;           ///< support evaluations of the Minkowski difference
  const char* error = nullptr;  ///< reason for InvalidInput, else nullptr
};

using IntersectResult = IntersectResultT<double>;

namespace detail {

/// The answer of a closed form's GapVerdict (not Unsure): within reach, the shapes intersect.
template <class S>
[[gnu::always_inline]] inline void intersect_from_verdict(GapVerdict verdict,
                                                          IntersectResultT<S>& result) {
  if (verdict == GapVerdict::Overflow) {
    result.error = kOverflowError;
    return;
  }
  result.intersect = verdict == GapVerdict::Within;
  result.status = result.intersect ? Status::Intersecting : Status::Separated;
}

/// The direction of a PointSupportPlane (point core A or B) in A's frame, as GJK's direction that
/// finds that support point (support of A along it minus support of B against it): for the warm
/// start, which stores it.
template <class A, class S>
Vec3T<S> plane_direction_in_a(const PointSupportPlane<S>& plane, const PoseT<S>& pose_a,
                              const PoseT<S>& pose_b) {
  if constexpr (PointCore<A>::value)
    return -pose_a.inverse_rotate(pose_b.rotate(plane.d));  // B's support along d, its frame
  else
    return plane.d;
}

/// The support call of a PointSupportPlane as a point of A - B in A's frame with its direction,
/// for run_gjk_boolean()'s `first`: written as CoreDifference::support_point() computes B's
/// points (B's support mapped by diff's pose), so that GJK's later points round alike.
template <class A, class B, class S>
PointAndDirection<S> plane_in_difference(const PointSupportPlane<S>& plane,
                                         const CoreDifference<A, B>& diff) {
  if constexpr (PointCore<A>::value) {
    const Vec3T<S> dir = -(diff.rotation * plane.d);
    return {Vec3T<S>(diff.a.support_core(dir) - (diff.rotation * plane.support + diff.translation)),
            dir};
  } else {
    return {
        Vec3T<S>(plane.support - (diff.rotation * diff.b.support_core(plane.d) + diff.translation)),
        plane.d};
  }
}

/// intersect()'s work, for pairs within the range of lengths (query/scale_range.hpp).
template <ConvexShape A, ConvexShape B>
IntersectResultT<typename A::Scalar> intersect_in_range(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const TolerancesT<typename A::Scalar>& tolerances,
    GjkCacheT<typename A::Scalar>* cache) {
  using S = typename A::Scalar;
  IntersectResultT<S> result;
  if ((result.error = detail::query_input_error(a, pose_a, b, pose_b))) return result;
  const S radius = a.core_radius() + b.core_radius();
  if constexpr (detail::BoxCore<A>::value && detail::BoxCore<B>::value) {
    // Two boxes: a point of B within reach of A, or the separating axis test, decides in a few
    // flops unless the axes' largest gap lies about the radii plus the touching tolerance (a
    // corner near a corner: the distance is then larger than any axis's gap) or an edge axis is
    // nearly degenerate; GJK decides then, on the reach itself. The test takes bounds on the
    // reach instead, with no root: a box's bounding radius |h| lies between |h|_1 / sqrt(3) and
    // |h|_1 (box boolean apart 5 % faster, its instructions a fifth of them the query's set-up).
    const S lengths = detail::BoxCore<A>::half_extents(a).sum() +
                      detail::BoxCore<B>::half_extents(b).sum() + radius;
    const S low = tolerances.relative * (S(0.577) * lengths);
    const S high = tolerances.relative * (S(1.001) * lengths);
    const PoseT<S> rel = pose_a.relative(pose_b);
    const auto verdict = detail::box_box_verdict(
        detail::BoxCore<A>::half_extents(a), detail::BoxCore<B>::half_extents(b), rel.rotation,
        rel.translation, radius + std::min(low, high), radius + std::max(low, high));
    if (verdict != detail::BoxBoxVerdict::Unsure) {
      result.intersect = verdict == detail::BoxBoxVerdict::Overlapping;
      result.status = result.intersect ? Status::Intersecting : Status::Separated;
      return result;
    }
  }
  S bound_a, bound_b;
  detail::bounding_radii(a, b, bound_a, bound_b);
  const S size = bound_a + bound_b;
  const S reach = radius + tolerances.relative * size;  // core distances that count as touching
  if constexpr (detail::kSegmentCores<A, B>) {
    // Spheres, capsules, points, segments: closed form, no iteration.
    // Shifted to A's origin, like GJK, so far-away pairs keep their precision.
    const auto p = detail::SegmentCore<A>::world(a, pose_a, pose_a.translation);
    const auto q = detail::SegmentCore<B>::world(b, pose_b, pose_a.translation);
    if (detail::line_of_centres_separates(p, q, reach)) {
      result.status = Status::Separated;
      return result;
    }
    Vec3T<S> on_a, on_b;
    detail::closest_points_of_segments(p, q, on_a, on_b);
    detail::intersect_from_verdict(detail::gap_verdict(Vec3T<S>(on_b - on_a), reach), result);
    return result;
  }
  bool point_closed_form = false;  // a point core against a solid with a closed form
  if constexpr (detail::kPointSolid<A, B>) {
    // A sphere or point against a box, cylinder, cone, ellipsoid or small polytope: closed form, no
    // iteration. Asked once: a polytope counts the asks towards building its planes.
    if (const auto* solid = detail::solid_of(a, b)) {
      point_closed_form = true;
      const auto verdict = detail::point_solid_verdict(*solid, a, pose_a, b, pose_b, reach);
      if (verdict != detail::GapVerdict::Unsure) {
        detail::intersect_from_verdict(verdict, result);
        return result;
      }
    }
  }
  if constexpr (detail::kSegmentBox<A, B>) {
    // A capsule or segment against a box: closed form (query/segment_box.hpp).
    if (const auto local = detail::segment_box_pair_local(a, pose_a, b, pose_b)) {
      detail::intersect_from_verdict(detail::gap_verdict(local->gap, reach), result);
      return result;
    }
  }
  // A point core against a core with no closed form: that core's support plane facing the point
  // decides most pairs apart for less than GJK's set-up, and GJK starts from it otherwise
  // (query/point_solid.hpp). Not with a usable cache, whose warm start serves instead.
  detail::PointSupportPlane<S> plane;
  if constexpr (detail::kPointCorePair<A, B>) {
    if (!point_closed_form && !detail::cache_is_usable(cache)) {
      plane = detail::point_support_plane(a, pose_a, b, pose_b);
      if (plane.beyond(reach)) {
        result.status = Status::Separated;
        result.iterations = 1;
        detail::save_cache(
            cache, 1, [&](int) { return detail::plane_direction_in_a<A>(plane, pose_a, pose_b); },
            Vec3T<S>(Vec3T<S>::Zero()));
        return result;
      }
    }
  }
  // B's pose in A's frame, whose rotation two small polytopes form only when their first support
  // values leave them undecided (query/polytope_pair.hpp).
  detail::CoreDifference<A, B> diff{a, b, {}, pose_a.relative_translation(pose_b), nullptr};
  bool rotation_formed = false;
  detail::PointAndDirection<S> first;
  const detail::PointAndDirection<S>* first_computed = nullptr;
  if constexpr (detail::kPolytopePair<A, B>) {
    // Two small polytopes: the first support call's values may prove the gap, its points the
    // overlap (query/polytope_pair.hpp); else GJK's first phase starts from that support point.
    if (radius == S(0) && !detail::cache_is_usable(cache)) {
      rotation_formed = true;
      const detail::EncloseVerdict verdict =
          detail::first_support_verdict(diff, pose_a, pose_b, reach, bound_b, first);
      if (verdict != detail::EncloseVerdict::Unsure) {
        result.intersect = verdict == detail::EncloseVerdict::Intersecting;
        result.status = result.intersect ? Status::Intersecting : Status::Separated;
        result.iterations = 1;
        detail::save_cache(
            cache, 1, [&first](int) { return first.dir; }, Vec3T<S>(Vec3T<S>::Zero()));
        return result;
      }
      first_computed = &first;
    }
  }
  if (!rotation_formed) pose_a.relative_rotation(pose_b, diff.rotation);
  if constexpr (detail::kPointCorePair<A, B>) {
    if (plane.d_sq > S(0)) {
      first = detail::plane_in_difference(plane, diff);
      first_computed = &first;
    }
  }
  const auto gjk = detail::run_gjk_boolean(diff, radius, size, tolerances, cache, first_computed);
  // Small point sets that GJK left unsure (a segment beside a needle triangle), or decided only
  // after more support calls than a well-posed pair takes: their features decide
  // (query/point_set_pair.hpp), as in distance() and contact().
  auto decide_by_point_sets = [&] {
    if constexpr (detail::kPointSetPair<A, B>) {
      if (result.status != Status::IterationLimit &&
          result.iterations <= detail::kPointSetSuspectIterations)
        return;
      if (const auto sets = detail::point_set_pair(diff, tolerances.relative * size)) {
        result.intersect = !sets->apart || sets->value <= reach;
        result.status = result.intersect ? Status::Intersecting : Status::Separated;
      }
    }
  };
  if (gjk.stalled) [[unlikely]] {
    // The distance loop and distance()'s rule decide, so that the two never disagree: the
    // distance loop's own Separated is not a proof (a needle 1e-8 thick that a box penetrated by
    // 3e-9 came out Separated here, and IterationLimit from distance()).
    const auto full = detail::run_gjk_distance(diff, radius, size, tolerances, nullptr);
    result.iterations = gjk.iterations + full.iterations;
    if (full.status == Status::InvalidInput) {
      result.error = detail::kOverflowError;
      return result;
    }
    if (detail::cores_within_reach(full, reach)) {
      result.status = Status::Intersecting;
    } else {
      result.status =
          detail::settle_cores(diff, full, radius, size, tolerances, result.iterations).status;
    }
    result.intersect = result.status == Status::Intersecting;
    decide_by_point_sets();
    return result;
  }
  result.status = gjk.status;
  result.iterations = gjk.iterations;
  if (gjk.status == Status::InvalidInput) {
    result.error = detail::kOverflowError;
    return result;
  }
  result.intersect = gjk.status == Status::Intersecting ||
                     (gjk.status == Status::IterationLimit && gjk.upper <= reach);
  decide_by_point_sets();
  return result;
}

}  // namespace detail

/// Do a (at pose_a) and b (at pose_b) intersect? `cache` (optional, in/out) warm-starts GJK from
/// the previous query of the same pair.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar> IntersectResultT<typename A::Scalar>
intersect(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
          const PoseT<typename A::Scalar>& pose_b,
          const TolerancesT<typename A::Scalar>& tolerances = {},
          GjkCacheT<typename A::Scalar>* cache = nullptr) {
  return detail::solve_in_scale_range<&detail::intersect_in_range<A, B>>(a, pose_a, b, pose_b,
                                                                         tolerances, cache);
}

}  // namespace mink
