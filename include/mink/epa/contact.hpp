/// @file contact.hpp
/// The contact query: one call that answers whether two convex shapes intersect, their distance
/// when apart or their penetration depth when not, the normal, and the closest or deepest points.
///
/// Frames: shapes in their local frames with poses to the world; results in the world frame.
///
/// Normal: unit, from A towards B. Separated: point_b - point_a = distance * normal. Penetrating:
/// the direction in which B must move, by `depth`, to separate the shapes, and
/// point_b - point_a = -depth * normal (point_a is A's deepest point inside B, point_b B's deepest
/// point inside A). So in both cases moving B along the normal moves the shapes apart.
///
/// How: GJK on the cores (core + radius, see architecture.md). If the cores are apart, the shapes
/// are separated when the core distance exceeds the sum of the radii and penetrate by the
/// difference otherwise: exact for spheres and capsules, no EPA. Only when the cores themselves
/// meet does EPA (epa.hpp) run on them, and the radii are added to its depth. Two boxes (or
/// rounded boxes) whose cores overlap skip GJK and EPA: the separating axis test
/// (query/box_box.hpp) gives the same depth and normal to rounding, and `iterations` is 0; so
/// do boxes whose cores are apart with closest points that its best axis gives in closed form
/// (box_box_closest()). A sphere or point against a box or cylinder (or their rounded versions)
/// is a closed form throughout, inside the solid or not (query/point_solid.hpp); a capsule or
/// segment against a box while the cores are apart (query/segment_box.hpp). Small point sets
/// (segments, triangles, polytopes of up to 8 points) that GJK or EPA leave at their caps, or
/// whose cores are within 1e-8 of the size of touching, are answered by their features instead
/// (query/point_set_pair.hpp): a thin A - B there left the normal up to 3e-7 rad off.
///
/// Ties: when several normals are equally good the query returns one of them and sets
/// `normal_chosen`. That happens when A - B has no volume where it meets the origin: concentric
/// spheres (the line of centres if the centres differ by rounding, else A's local +z axis),
/// capsules whose segments cross (the common perpendicular of the segments, sign towards B's side
/// when it can be told; in closed form, meeting_segments_normal()) or overlap along a line (the
/// line of centres' orthogonal part), and solids of revolution on a common axis (coincident or
/// coaxial cylinders, cones, spheroids; a sphere on a cone's axis) whose way out is not along the
/// axis: the normal then leans towards orthogonal()'s direction across A's axis (A's local +x when
/// that axis is its z; query/axial_pair.hpp). Coincident boxes are not ties of this kind: their
/// Minkowski difference has volume, and the normal is the axis of a face of least depth (the first
/// in the order A's x, y, z, then B's, when several tie). A sphere's (or point's) centre inside a
/// box, as deep below two faces (on a diagonal plane of the box, or its centre plane) does set
/// `normal_chosen`: the normal is then the first such face axis in x, y, z order, on the side of
/// the centre, the + side on the centre plane.
///
/// Tolerances: distances within `tolerances.relative * size` of zero count as touching
/// (intersecting, depth 0); EPA stops when its bounds on the core depth are within
/// `tolerances.relative_depth * size`, and `error_bound` reports the gap it stopped at.
#pragma once

#include "mink/epa/epa.hpp"
#include "mink/gjk/distance.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/manifold/clip_box_pair.hpp"
#include "mink/query/axial_pair.hpp"
#include "mink/query/point_solid.hpp"
#include "mink/query/scale_range.hpp"
#include "mink/query/segment_box.hpp"

namespace mink {

template <class S>
struct ContactResultT {
  /// Separated or Intersecting (penetrating or touching): every field is valid. IterationLimit:
  /// GJK or EPA hit the cap, or EPA stopped before its bounds met; the fields are the best
  /// estimate and `error_bound` bounds the error of the distance or depth (a penetrating
  /// estimate is then the upper bound: moving B by `depth` along `normal` separates the shapes).
  /// InvalidInput: nothing was computed and `error` says why.
  Status status = Status::InvalidInput;
  bool intersect = false;               ///< the shapes share a point (touching counts)
  S distance = S(0);                    ///< >= 0 (unit: length); 0 when intersecting
  S depth = S(0);                       ///< >= 0 (unit: length); 0 when separated or touching
  Vec3T<S> normal = Vec3T<S>::UnitZ();  ///< unit, world frame, from A towards B (see above)
  Vec3T<S> point_a = Vec3T<S>::Zero();  ///< closest (separated) or deepest point of A, world
  Vec3T<S> point_b = Vec3T<S>::Zero();  ///< closest (separated) or deepest point of B, world
  S error_bound = S(0);         ///< bound on the error of distance or depth (unit: length), >= 0
  int iterations = 0;           ///< support evaluations of A - B, GJK and EPA together
  bool normal_chosen = false;   ///< several normals were equally good; this is one of them
  const char* error = nullptr;  ///< reason for InvalidInput, else nullptr
};

using ContactResult = ContactResultT<double>;

namespace detail {

/// Fills the distance or depth, normal and points of `result` from the closest points of the
/// cores, on_a and on_b, in the world frame (or shifted from it; see separated_from_cores() in
/// gjk/distance.hpp for why callers map them first), and
/// `normal`, the unit direction from on_a to on_b: `core_distance` is the distance of the cores
/// (B's core minus A's along the normal), `inside` the sum of the radii plus the touching
/// tolerance. `origin` (optional): on_a and on_b are about it, not the world's origin; the points
/// are moved out by the radii and then by `origin`, written once (a point written and then
/// shifted in place is read back whole from its parts' stores, which stalls).
template <class S>
[[gnu::always_inline]] inline void contact_from_cores(const Vec3T<S>& on_a, const Vec3T<S>& on_b,
                                                      const Vec3T<S>& normal, S core_distance,
                                                      S radius_a, S radius_b, S inside,
                                                      ContactResultT<S>& result,
                                                      const Vec3T<S>* origin = nullptr) {
  const S radius = radius_a + radius_b;
  result.intersect = core_distance <= inside;
  result.distance = result.intersect ? S(0) : core_distance - radius;
  result.depth = std::max(S(0), radius - core_distance);
  result.normal = normal;
  surface_points(on_a, on_b, normal, radius_a, radius_b, origin, result.point_a, result.point_b);
}

/// contact()'s work, for pairs within the range of lengths (query/scale_range.hpp).
template <ConvexShape A, ConvexShape B>
ContactResultT<typename A::Scalar> contact_in_range(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const TolerancesT<typename A::Scalar>& tolerances,
    GjkCacheT<typename A::Scalar>* cache) {
  using S = typename A::Scalar;
  ContactResultT<S> result;
  if ((result.error = detail::query_input_error(a, pose_a, b, pose_b))) return result;
  const S radius_a = a.core_radius(), radius_b = b.core_radius();
  const S bound_a = a.bounding_radius(), bound_b = b.bounding_radius();
  const S size = bound_a + bound_b;
  const S touch = tolerances.relative * size;
  const S inside = radius_a + radius_b + touch;
  if constexpr (detail::kSegmentCores<A, B>) {
    // Spheres, capsules, points, segments: closed form while the cores are apart.
    Vec3T<S> on_a, on_b, normal = Vec3T<S>::UnitZ();
    const S core_distance = detail::closest_core_points(a, pose_a, b, pose_b, on_a, on_b, &normal);
    if (!(core_distance <= std::numeric_limits<S>::max())) {
      result.error = detail::kOverflowError;
      return result;
    }
    if (core_distance > touch) {
      // on_a, on_b are world points shifted to A's origin: shift them back.
      detail::contact_from_cores(on_a, on_b, normal, core_distance, radius_a, radius_b, inside,
                                 result, &pose_a.translation);
      result.status = result.intersect ? Status::Intersecting : Status::Separated;
      return result;
    }
    // Segments that meet and are not parallel: their difference is flat, and the common
    // perpendicular is a best normal (either sign when they cross). The cores touch: both points
    // at the midpoint of the closest points, and the depth the radii, as EPA's touching cores.
    const auto core_a = detail::SegmentCore<A>::world(a, pose_a, pose_a.translation);
    const auto core_b = detail::SegmentCore<B>::world(b, pose_b, pose_a.translation);
    if (const auto n = detail::meeting_segments_normal(core_a, core_b)) {
      const Vec3T<S> midpoint = S(0.5) * (on_a + on_b);
      detail::contact_from_cores(midpoint, midpoint, *n, S(0), radius_a, radius_b, inside, result,
                                 &pose_a.translation);
      result.normal_chosen = true;
      result.status = Status::Intersecting;
      return result;
    }
  }
  if constexpr (detail::kPointSolid<A, B>) {
    // A sphere or point against a box, cylinder, cone, ellipsoid or small polytope, inside it or
    // not: closed form, no GJK or EPA.
    if (const auto local = detail::point_solid_local(a, pose_a, b, pose_b)) {
      if (!(std::abs(local->signed_distance) <= std::numeric_limits<S>::max())) {
        result.error = detail::kOverflowError;
        return result;
      }
      const auto cores = detail::point_solid_world<A, B>(*local, pose_a, pose_b);
      detail::contact_from_cores(cores.on_a, cores.on_b, cores.normal, cores.distance, radius_a,
                                 radius_b, inside, result);
      result.normal_chosen = cores.tie;
      result.status = result.intersect ? Status::Intersecting : Status::Separated;
      return result;
    }
  }
  if constexpr (detail::kSegmentBox<A, B>) {
    // A capsule or segment against a box while the cores are apart: closed form
    // (query/segment_box.hpp), exact where GJK on two needles stalled. Cores that meet: EPA.
    if (const auto cores = detail::segment_box_world(a, pose_a, b, pose_b);
        cores && cores->distance > touch) {
      detail::contact_from_cores(cores->on_a, cores->on_b, cores->normal, cores->distance, radius_a,
                                 radius_b, inside, result);
      result.status = result.intersect ? Status::Intersecting : Status::Separated;
      return result;
    }
  }
  if constexpr (detail::BoxCore<A>::value && detail::BoxCore<B>::value) {
    // Two boxes whose cores overlap: the separating axis test is EPA's depth and normal, exact
    // and in a fixed number of flops, and the deepest point of the manifold's clipping gives the
    // witness points (a point of B's deepest feature that lies over A's face, or the reverse, or
    // the closest points of two crossing edges). Cores apart: the same axis gives most pairs
    // their closest points in closed form (box_box_closest()).
    const PoseT<S> rel = pose_a.relative(pose_b);
    const Vec3T<S>&ha = detail::BoxCore<A>::half_extents(a),
          &hb = detail::BoxCore<B>::half_extents(b);
    // No bias towards face axes (the manifold's, for stable normals): the least overlap, exact.
    const auto axes = detail::box_pair_axes(ha, hb, rel.rotation, rel.translation);
    const auto axis = detail::box_best_axis(axes, rel.rotation, rel.translation, S(0));
    Vec3T<S> on_a, on_b, normal;
    S core_distance;
    if (axis.overlap < -touch &&
        detail::box_box_closest(ha, hb, rel.rotation, rel.translation, axes, axis, true, on_a, on_b,
                                normal, core_distance)) {
      detail::contact_from_cores(pose_a.apply(on_a), pose_a.apply(on_b), pose_a.rotate(normal),
                                 core_distance, radius_a, radius_b, inside, result);
      // The axis warm-starts GJK the next time, should the pair move out of closed form.
      detail::save_cache(
          cache, 1, [&normal](int) { return normal; }, normal);
      result.status = result.intersect ? Status::Intersecting : Status::Separated;
      return result;
    }
    if (axis.overlap > touch &&
        detail::box_box_closest(ha, hb, rel.rotation, rel.translation, axes, axis, false, on_a,
                                on_b, normal, core_distance)) {
      // The deepest point of one box over the other's face, or two crossing edges: no clipping.
      detail::contact_from_cores(pose_a.apply(on_a), pose_a.apply(on_b), pose_a.rotate(normal),
                                 core_distance, radius_a, radius_b, inside, result);
      result.status = Status::Intersecting;
      return result;
    }
    if (axis.overlap > touch) {
      // Features only where flat to rounding (1e-9): a rounded face tilted within a coarser
      // tolerance is moved out along its own normal, off the surface by up to r t^2 / 2, and
      // the witnesses must be exact; and no slack at the side planes, so the points stay on the
      // faces. The true support point is always among the clipped ones.
      detail::ClippedPoints<S> clipped;
      detail::clip_box_pair(a, b, rel, axis.normal, S(1e-9), -touch, bound_a, bound_b, S(0),
                            clipped);
      if (clipped.count > 0) {
        int deepest = 0;
        for (int i = 1; i < clipped.count; ++i)
          if (clipped.planar[i].depth > clipped.planar[deepest].depth) deepest = i;
        result.status = Status::Intersecting;
        result.intersect = true;
        result.depth = axis.overlap + radius_a + radius_b;
        result.normal = pose_a.rotate(axis.normal);
        result.point_a = pose_a.apply(clipped.on_a[deepest]);
        result.point_b = pose_a.apply(clipped.on_b[deepest]);
        return result;
      }
    }
    // Touching or apart: GJK below.
  }
  auto diff = detail::make_core_difference(a, pose_a, b, pose_b);
  detail::FramedPointsT<S> b_points;  // a small polytope B's points in A's frame
  detail::frame_points_of_b(diff, b_points);
  // Overlapping cores with no radius: the boolean test's first phase encloses the origin in a
  // tetrahedron for less than the distance loop, and EPA starts from it; boxes come here only
  // touching or apart, where it would prove nothing.
  constexpr bool kBoxes = detail::BoxCore<A>::value && detail::BoxCore<B>::value;
  constexpr auto kPhase = kBoxes ? detail::EnclosePhase::Off : detail::EnclosePhase::Simplex;
  const auto gjk = detail::gjk_apart<kPhase>(diff, radius_a + radius_b, size, tolerances, cache);
  result.iterations = gjk.iterations;
  if (gjk.status == Status::InvalidInput) {
    result.error = detail::kOverflowError;
    return result;
  }
  // Fills `result` rather than returning a copy of it: every return must name `result`, or the
  // compiler builds the answer apart and copies it out (no named return value optimisation),
  // and the copy's loads straddle the stores that built it and stall (10 ns of a sphere-box
  // contact).
  const S radii = radius_a + radius_b;
  auto separate = [&] {
    return detail::separate_cores(diff, gjk, radii, size, tolerances, result.iterations);
  };
  // Separated, penetrating by the radii only, or touching: the status by the rule distance()
  // shares (separate_cores()).
  auto answer_apart = [&](const detail::CoreSeparation<S>& cores) {
    detail::contact_from_cores(pose_a.apply(cores.on_a), pose_a.apply(cores.on_b),
                               pose_a.rotate(cores.normal), cores.upper, radius_a, radius_b, inside,
                               result);
    if (cores.status == Status::Intersecting) {
      // Curved cores that touch, beyond `inside` by GJK's crawl only: depth and distance 0.
      result.intersect = true;
      result.distance = S(0);
    }
    result.error_bound = std::max(S(0), cores.upper - cores.lower);
    result.status = cores.status;
  };
  // Small point sets that GJK or EPA left unsure, or whose cores nearly touch, where the normal
  // is ill-conditioned (a segment beside a needle triangle, 1e-8 rad from parallel: the normal
  // 1e-7 rad off along the needle): by their features (query/point_set_pair.hpp).
  auto answer_by_point_sets = [&] {
    if constexpr (detail::kPointSetPair<A, B>) {
      const S core_value = result.distance + radii - result.depth;
      if (result.status != Status::IterationLimit &&
          !(detail::kPointSetNearTouchingPair<A, B> &&
            std::abs(core_value) <= S(detail::kPointSetNearTouching) * size))
        return;
      const auto sets = detail::point_set_pair(
          diff, touch, detail::point_set_max_axes(result.status == Status::IterationLimit));
      if (!sets) return;
      result.error_bound = S(0);
      result.normal_chosen = false;
      if (sets->apart) {
        detail::contact_from_cores(pose_a.apply(sets->on_a), pose_a.apply(sets->on_b),
                                   pose_a.rotate(sets->normal), sets->value, radius_a, radius_b,
                                   inside, result);
        result.status = result.intersect ? Status::Intersecting : Status::Separated;
        return;
      }
      const Vec3T<S> n = sets->normal;
      result.point_a = pose_a.apply(Vec3T<S>(sets->on_a + radius_a * n));
      result.point_b = pose_a.apply(Vec3T<S>(sets->on_b - radius_b * n));
      result.intersect = true;
      result.distance = S(0);
      result.depth = sets->value + radii;
      result.normal = pose_a.rotate(n);
      result.status = Status::Intersecting;
    }
  };
  // GJK proves the cores apart only with a separating plane (lower bound > touch). Without one
  // (a point inside a needle 1e-7 as thick as it is long: GJK's simplex there is too thin to
  // enclose the origin), EPA decides.
  if (gjk.upper > touch && gjk.lower > touch) {
    answer_apart(separate());
    answer_by_point_sets();
    return result;
  }
  // Solids of revolution about parallel or nearly parallel axes: EPA in planes through an axis
  // (query/axial_pair.hpp), where EPA in space would refine a whole circle of equally good
  // normals. False (result untouched) when that path does not apply or does not answer; shapes
  // so large that the answer overflows are left to EPA, whose rules report it.
  // Generic, so that pairs without axes never instantiate it.
  // `ceiling`: when finite, the answer is taken only if it converged and is no deeper than that.
  [[maybe_unused]] auto axial_answer = [&](const auto& axes, auto min_tilt, auto max_tilt,
                                           S ceiling) {
    const auto axial = detail::axial_depth(diff, axes, size, tolerances, max_tilt, min_tilt);
    const bool checked = std::isfinite(ceiling);
    if (!axial || (checked && axial->status != Status::Intersecting)) return false;
    // Flat features nearly parallel (a cone's base on a cylinder's cap tilted 4e-7 rad): the
    // planes' normal is good to 1e-13 rad and their points are any of the overlap, 1e-4 of the
    // size off the deepest one. A face's normal nearby, and the features' own witness pair
    // along it, as Newton's steps end (witness_at_face()). Not on a tie, whose normal is the
    // one chosen.
    Vec3T<S> n = axial->normal, on_a = axial->on_a, on_b = axial->on_b;
    int witness_calls = 0;
    if (tolerances.refine_curved_normals && !axial->normal_chosen) {
      detail::SupportMinimum<S> pair;
      if (detail::witness_at_face(diff, n, size, witness_calls, pair) &&
          std::abs(pair.value - axial->depth) <= tolerances.relative_depth * size) {
        n = pair.normal;
        on_a = pair.vertex.a;
        on_b = pair.vertex.b;
        detail::share_residual(on_a, on_b, n, axial->depth);
      }
    }
    const Vec3T<S> axial_a = pose_a.apply(Vec3T<S>(on_a + radius_a * n));
    const Vec3T<S> axial_b = pose_a.apply(Vec3T<S>(on_b - radius_b * n));
    const S axial_depth = axial->depth + radius_a + radius_b;
    if (!(is_finite(axial_a) && is_finite(axial_b) && std::isfinite(axial_depth) &&
          std::isfinite(axial->error_bound)))
      return false;
    if (checked && !(axial_depth <= ceiling)) return false;
    result.iterations += axial->iterations + witness_calls;
    result.intersect = true;
    result.depth = axial_depth;
    result.error_bound = axial->error_bound;
    result.normal = pose_a.rotate(n);
    result.point_a = axial_a;
    result.point_b = axial_b;
    result.normal_chosen = axial->normal_chosen;
    result.status = axial->status;
    return true;
  };
  constexpr bool kAxial = detail::kAxialPair<A, B> && !detail::kSegmentCores<A, B>;
  // Parallel within the tolerance, or a point on an axis: one plane answers. Axes tilted further,
  // by at most kAxialMaxTilt: EPA in space first, within kAxialEpaBudget support calls, where it
  // suits them (detail::epa_suits_tilted_axes()), and the planes where it stops at that cap;
  // elsewhere the planes first.
  bool epa_first = false;
  TolerancesT<S> epa_tolerances = tolerances;
  if constexpr (kAxial) {
    const auto axes = detail::pair_axes(diff);
    epa_first = axes.tilt <= S(detail::kAxialMaxTilt) &&
                !detail::axes_count_as_parallel(diff, axes, size, tolerances) &&
                detail::epa_suits_tilted_axes(diff, axes, result.iterations);
    if (!epa_first &&
        axial_answer(axes, S(-1), S(detail::kAxialMaxTilt), std::numeric_limits<S>::infinity()))
      return result;
    if (epa_first)
      epa_tolerances.max_epa_iterations =
          std::min(tolerances.max_epa_iterations, detail::kAxialEpaBudget);
  }
  // The cores meet (or may): EPA on the cores, then add the radii.
  const auto epa =
      detail::run_epa(diff, gjk.simplex, size, epa_tolerances, detail::epa_fallback(diff));
  result.iterations += epa.iterations;
  if (epa.status == Status::InvalidInput) {
    result.error = detail::kOverflowError;
    return result;
  }
  // A direction n with support value h(n) < -touch proves A - B lies beyond the origin: the cores
  // are apart after all, and GJK's closest points are the answer. So does a flat A - B (two
  // coplanar flat boxes side by side) that GJK's upper bound keeps the origin off: it has no
  // interior, and separate_cores() tells apart from touching by the rule distance() uses.
  if (gjk.upper > touch && (epa.upper < -touch || epa.degenerate)) {
    answer_apart(separate());
    answer_by_point_sets();
    return result;
  }
  // EPA's own depth below -touch, with GJK's upper bound also keeping the origin off, proves
  // nothing (EPA's polytope need not enclose the origin), but separate_cores() may settle it by
  // distance()'s rule: two needles 1e-12 thick, nearly parallel and 3.2e-8 apart, whose
  // difference GJK's first phase took to enclose the origin, had EPA's bracket [-2.5e-6, 2.2e-5]
  // hold 0, and contact() said touching where distance() said apart; 4e-14 apart, EPA's points
  // lay 0.04 of the size off the needles. Not when that rule is unsure too (IterationLimit)
  // without a proven separation: a cylinder grazing a box's edge 3e-12 deep had EPA's depth
  // below -touch, and EPA settles it, as it does for distance(). A proven one is taken whatever
  // the status (needles 1.1e-8 apart, where the rule hit its cap, were said touching).
  if (gjk.upper > touch && epa.depth < -touch) {
    const auto cores = separate();
    if (cores.lower > touch || cores.status != Status::IterationLimit) {
      answer_apart(cores);
      answer_by_point_sets();
      return result;
    }
  }
  Vec3T<S> n = epa.normal;
  if (!(std::abs(n.squaredNorm() - S(1)) <= S(1e-6))) {
    // EPA's face normals are products of four coordinates: beyond about 1e77 they overflow, and
    // the normal comes out zero. Say so rather than answer with it.
    result.error = detail::kOverflowError;
    return result;
  }
  S core_depth = std::max(S(0), epa.depth);
  Vec3T<S> on_a = epa.a, on_b = epa.b;
  bool refined = epa.proven_by_ball;  // Newton's steps have run, and the ball proved them
  // A face's normal near n and the features' witness pair along it (detail::witness_at_face()),
  // taken when its points lie on their support planes and its value is EPA's depth within EPA's
  // tolerance; whether it was.
  const auto take_witness_at_face = [&] {
    detail::SupportMinimum<S> pair;
    if (!detail::witness_at_face(diff, n, size, result.iterations, pair) ||
        !detail::pair_on_support_planes(pair) ||
        !(std::abs(pair.value - core_depth) <= tolerances.relative_depth * size))
      return false;
    n = pair.normal;
    core_depth = std::max(S(0), pair.value);
    on_a = pair.vertex.a;
    on_b = pair.vertex.b;
    detail::share_residual(on_a, on_b, n, core_depth);
    return true;
  };
  if constexpr (!detail::kCurvedPair<A, B>) {
    // Polytopes: EPA's normal is a face of A - B, exact, but where two faces are nearly parallel
    // (a hull's face on a box's, tilted 1e-9 rad) its nearest face may be any within its
    // tolerance, and its points any of the overlap: up to 0.64 of the size from the deepest
    // corner. Only there is its bracket left open beyond rounding (never in the benchmark's
    // random pairs); a face's normal and the features' witness pair (witness_at_face()).
    if (!epa.degenerate && epa.status == Status::Intersecting &&
        epa.upper - epa.lower > S(64) * std::numeric_limits<S>::epsilon() * size)
      take_witness_at_face();
  }
  if constexpr (detail::kCurvedPair<A, B>) {
    // Curved cores: EPA's normal of a smooth minimum is good to the square root of its tolerance
    // (1e-5 rad); Newton's steps (gjk/support_newton.hpp) take it, and the points (the support
    // points along it), to the rounding. Kept only as deep as EPA's upper end, to rounding. Cores
    // that touch too (see separate_cores()). Both values are rounded by their support points'
    // coordinates, B's also by its offset from A, not by their difference w: on cores that
    // touch, w is 1e-14 long, and a face's exact normal, its value 1e-15 above EPA's upper end,
    // was refused for EPA's normal, 3e-8 rad off.
    // On a facet of A - B (detail::on_facet()) EPA's depth and normal are exact, but not its
    // points: its face's corners come from support points along nearby normals, which on a
    // curved core lie up to the square root of the rounding (3e-7 of the size) from the one
    // along the normal. There the polytopes' answer: a face's normal within reach and the
    // features' witness pair along it (witness_at_face()), when one of them is a single point or
    // two edges cross; otherwise Newton's steps as elsewhere.
    bool witnessed = false;
    if (tolerances.refine_curved_normals && epa.on_facet)
      refined = witnessed = take_witness_at_face();
    if (tolerances.refine_curved_normals && !epa.degenerate && !witnessed && !refined) {
      const auto rounding = [&](const detail::SupportMinimum<S>& least) {
        return S(2) * std::max(detail::support_rounding(least.vertex),
                               S(16) * std::numeric_limits<S>::epsilon() *
                                   diff.translation.cwiseAbs().maxCoeff());
      };
      // Newton's answer from EPA's hand-off to the balls (epa.hpp), when as deep as EPA's upper
      // end, with the edges' ends the hand-off left (newton_at_end()); else the steps from EPA's
      // final normal.
      const bool early = epa.newton && epa.newton->value <= epa.upper + rounding(*epa.newton);
      auto least = early ? *epa.newton : detail::SupportMinimum<S>::at(diff, n, result.iterations);
      const int kept =
          detail::newton_on_support(diff, size, tolerances.relative_depth * size,
                                    early ? 0 : detail::kNewtonMaxSteps, result.iterations, least);
      if ((early || kept > 0) && least.value <= epa.upper + rounding(least)) {
        n = least.normal;
        core_depth = std::max(S(0), least.value);
        on_a = least.vertex.a;
        on_b = least.vertex.b;
        detail::share_residual(on_a, on_b, n, core_depth);
        refined = true;
      }
    }
  }
  result.intersect = true;
  result.depth = core_depth + radius_a + radius_b;
  result.error_bound = std::max(S(0), epa.upper - epa.lower);
  result.normal = pose_a.rotate(n);
  if (gjk.upper <= touch && !(epa.depth > touch)) {
    // Cores that touch: both points at the midpoint of GJK's closest points, which are points of
    // the two cores within `touch` of each other up to the rounding of the simplex's weights
    // (a few 1e-9 of a needle's length). EPA's come from its nearest face, which for a plate
    // touching a wall 1e5 times its size is a sliver that the origin lies beside: its points
    // were split across the gap, and A's landed 5 % of A's size off A. (GJK's points lined up
    // as distance() does, one held and the other placed by v, moved a point touching a needle
    // off its shape by the whole rounding.)
    // A tetrahedron (the cores enclose the origin) gives its face nearest the origin instead.
    // Curved cores: Newton's points above, else from the normal where one core has a single
    // point (detail::touching_witness()).
    bool placed = refined;
    if constexpr (detail::kCurvedPair<A, B>)
      placed = placed || (tolerances.refine_curved_normals &&
                          detail::touching_witness(diff, n, size, S(16) * touch, result.iterations,
                                                   on_a, on_b));
    if (!placed) {
      SimplexT<S> touching = gjk.simplex;
      if (touching.size == 4) detail::reduce_to_nearest_face(touching);
      touching.witness_points(on_a, on_b);
    }
    const Vec3T<S> midpoint = S(0.5) * (on_a + on_b);
    on_a = on_b = midpoint;
  }
  result.point_a = pose_a.apply(on_a + radius_a * n);
  result.point_b = pose_a.apply(on_b - radius_b * n);
  result.normal_chosen = epa.degenerate;
  result.status =
      epa.status == Status::IterationLimit ? Status::IterationLimit : Status::Intersecting;
  if constexpr (kAxial) {
    // EPA stopped at its cap: a band of nearly equal normals. Nearly parallel axes that EPA had
    // the first try on: the planes answer. Tilted further (a spheroid against a cone,
    // capsule or spheroid): EPA's polished depth is a support value of A - B, so no less than the
    // true depth, and so is each plane's converged depth: the planes through A's axis answer when
    // they converge no deeper than EPA (within its tolerance). A scan that missed the least plane
    // comes out deeper and is ignored.
    const auto axes = detail::pair_axes(diff);
    if (result.status == Status::IterationLimit && epa_first)
      axial_answer(axes, S(-1), S(detail::kAxialMaxTilt), std::numeric_limits<S>::infinity());
    else if (result.status == Status::IterationLimit)
      axial_answer(axes, S(detail::kAxialMaxTilt), S(detail::kAxialFallbackTilt),
                   result.depth + tolerances.relative_depth * size);
  }
  answer_by_point_sets();
  return result;
}

}  // namespace detail

/// Contact between a (at pose_a) and b (at pose_b). `cache` (optional, in/out) warm-starts GJK
/// from the previous query of the same pair.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar> ContactResultT<typename A::Scalar>
contact(const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
        const PoseT<typename A::Scalar>& pose_b,
        const TolerancesT<typename A::Scalar>& tolerances = {},
        GjkCacheT<typename A::Scalar>* cache = nullptr) {
  return detail::solve_in_scale_range<&detail::contact_in_range<A, B>>(a, pose_a, b, pose_b,
                                                                       tolerances, cache);
}

}  // namespace mink
