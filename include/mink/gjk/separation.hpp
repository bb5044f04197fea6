/// @file separation.hpp
/// The answer for cores that GJK did not find meeting: the normal, the closest points of the cores
/// and the status of the full shapes (one rule for distance() and contact()).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mink/gjk/corner_solid.hpp"
#include "mink/gjk/gjk.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/gjk/support_newton.hpp"
#include "mink/support/core_terms.hpp"

namespace mink::detail {

template <class S>
struct CoreSeparation {
  Vec3T<S> normal;  ///< unit, A's frame, from A's core towards B's
  Vec3T<S> on_a;    ///< closest point of A's core (A's frame)
  Vec3T<S> on_b;    ///< closest point of B's core (A's frame); on_b - on_a = distance * normal
  S lower;          ///< proven lower bound on the core distance: the separation along `normal`
  /// The core distance answered: GJK's upper bound, or the distance of a witness pair that
  /// `normal` proves to be the closest (polytopes' nearly parallel faces), >= lower.
  S upper;
  /// What GJK's bracket [lower, upper] on the core distance says of the full shapes (radii
  /// added): Separated; Intersecting when they penetrate by the radii or touch (see
  /// separate_cores()); IterationLimit when GJK hit its cap or its bracket stayed open.
  Status status;
};

/// Makes on_a - on_b = v when GJK's v is the projection onto its triangle's plane rather than
/// the combination of its points (closest_on_triangle(): they differ when the weights' rounding
/// slides the combination along a long thin triangle, 1e8 for a box 1.8e13 long). The side whose
/// support points in the simplex lie closer together (a disk's single rim point against the box's
/// far corners) holds its point exactly; the other is placed from it.
template <class S>
void line_up_witness_points(const SimplexT<S>& simplex, const Vec3T<S>& v, Vec3T<S>& on_a,
                            Vec3T<S>& on_b) {
  const Vec3T<S> slide = on_a - on_b - v;
  const S scale = std::max(on_a.cwiseAbs().maxCoeff(), on_b.cwiseAbs().maxCoeff());
  const S rounding = S(64) * std::numeric_limits<S>::epsilon() * scale;
  if (!(slide.squaredNorm() > rounding * rounding)) return;
  S spread_a = S(0), spread_b = S(0);
  for (int i = 1; i < simplex.size; ++i) {
    spread_a = std::max(spread_a, (simplex.vertices[i].a - simplex.vertices[0].a).squaredNorm());
    spread_b = std::max(spread_b, (simplex.vertices[i].b - simplex.vertices[0].b).squaredNorm());
  }
  if (spread_a <= spread_b)
    on_b = on_a - v;
  else
    on_a = on_b + v;
}

/// distance()'s first test of the distance loop's answer, before separate_cores(): the shapes
/// intersect when GJK proved the cores overlap or its upper bound on their distance is within
/// `reach` (the radii plus the touching tolerance), where a distance of 0 is exact even if GJK hit
/// its cap. intersect() decides its stalled pairs by the same two steps, so the two never disagree.
template <class S>
bool cores_within_reach(const GjkOutcome<S>& gjk, S reach) {
  return gjk.status == Status::Intersecting || gjk.upper <= reach;
}

/// The normal, closest points and proven lower bound of separate_cores() (see there), without
/// the status.
template <ConvexShape A, ConvexShape B>
void find_separation(const CoreDifference<A, B>& diff, const GjkOutcome<typename A::Scalar>& gjk,
                     typename A::Scalar touch, int max_iterations, int& iterations,
                     CoreSeparation<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  gjk.simplex.witness_points(out.on_a, out.on_b);
  line_up_witness_points(gjk.simplex, gjk.v, out.on_a, out.on_b);
  out.normal = separation_direction(gjk.simplex, gjk.v);
  out.lower = gjk.lower;
  const S vv = gjk.v.squaredNorm(), length = length_of(gjk.v, vv);
  const Vec3T<S> plain = length > S(0) ? Vec3T<S>(-unit_of(gjk.v, vv, length)) : out.normal;
  const bool plain_differs = (out.normal - plain).squaredNorm() > S(1e-24);
  const S lower_sq = gjk.lower_v.squaredNorm(), lower_length = length_of(gjk.lower_v, lower_sq);
  const bool lower_differs = gjk.lower > S(0) && lower_length > S(0) && gjk.lower_v != gjk.v;
  const bool apart = gjk.upper - gjk.lower > S(2) * touch;
  if (!plain_differs && !lower_differs && !apart) return;

  SupportMinimum<S> least;
  least.measure(diff, out.normal, iterations);
  if (plain_differs) least.measure(diff, plain, iterations);
  const S free_value = least.value;  // the best of the first pair
  const Vec3T<S> free_normal = least.normal;
  // The minimum of h is minus the distance, at least -gjk.upper. The lower bound's direction
  // already proved its value; it is measured again for its support point (GJK keeps only the
  // direction), which starts the descent and places the points below. On non-finite arithmetic
  // the descent keeps its last finite answer, which is still a proven separation.
  if (lower_differs && -gjk.lower < least.value)
    least.measure(diff, Vec3T<S>(-unit_of(gjk.lower_v, lower_sq, lower_length)), iterations);
  if (gjk.upper + least.value > S(2) * touch)
    descend_support(diff, -gjk.upper, touch, iterations + max_iterations / 4, iterations, least);
  out.lower = std::max(out.lower, -least.value);
  out.normal = free_normal;
  // A new normal only for a gain that counts: 16 times the touching tolerance (a tilt across a
  // kink of h, a flat face's edge, gains at first order). Near a smooth minimum of h the turn is
  // the square root of the gain, and the points must turn with the normal.
  if (!(free_value - least.value > S(16) * touch)) return;
  out.normal = least.normal;
  // GJK's points are a pair `gap` apart, each in its core. The one that lies on its core's
  // support plane along the new normal (a vertex, a flat face: exact) stays; the other (a chord
  // of a curved core, sagging under its surface) is placed `gap` from it along the normal.
  // Turning both about their midpoint instead moved a polytope's vertex off the polytope by
  // half the gap times the turn (8e-8 for a turn of 8e-6).
  const Vec3T<S> offset = out.on_b - out.on_a;
  const S gap = length_of(offset);
  const S below_a = out.normal.dot(least.vertex.a - out.on_a);
  const S above_b = out.normal.dot(out.on_b - least.vertex.b);
  if (above_b <= below_a)
    out.on_a = out.on_b - gap * out.normal;
  else
    out.on_b = out.on_a + gap * out.normal;
}

/// The cores' support features along a unit normal (A's frame) when each is a point or a segment
/// (a cone's slant or apex, a cylinder's side line, a box's edge or corner), as segments in A's
/// frame, with their closest points: points of the cores, so their distance bounds the core
/// distance from above.
template <class S>
struct FeatureSegments {
  CoreSegment<S> p, q;
  Vec3T<S> on_a, on_b;
};

template <ConvexShape A, ConvexShape B>
std::optional<FeatureSegments<typename A::Scalar>> feature_segments(
    const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& normal,
    typename A::Scalar size) {
  using S = typename A::Scalar;
  SupportFeatureT<S> feature_a, feature_b;
  core_features(diff, normal, S(kFaceSnapReach) * size, feature_a, feature_b);
  if (feature_a.count > 2 || feature_b.count > 2) return std::nullopt;
  const Vec3T<S>&a0 = feature_a.points[0], &a1 = feature_a.points[feature_a.count - 1];
  const Vec3T<S> b0 = diff.rotation * feature_b.points[0] + diff.translation;
  const Vec3T<S> b1 = diff.rotation * feature_b.points[feature_b.count - 1] + diff.translation;
  FeatureSegments<S> out{
      {S(0.5) * (a0 + a1), S(0.5) * (a1 - a0)}, {S(0.5) * (b0 + b1), S(0.5) * (b1 - b0)}, {}, {}};
  closest_points_of_segments(out.p, out.q, out.on_a, out.on_b);
  if (!is_finite(out.on_a) || !is_finite(out.on_b)) return std::nullopt;
  return out;
}

/// Rounds of close_at_feature_segments(): Newton's steps restarted from a normal turned across
/// the features.
inline constexpr int kFeatureRounds = 3;

/// For curved cores whose bracket on the distance GJK left open although Newton's steps found
/// the normal: two cones' slants 1.3e-7 rad from parallel and 5e-12 apart span a thin
/// parallelogram of A - B, GJK's simplices on it are slivers, and it stopped 2.6e-8 apart (the
/// slants' distance 5e-12, which Newton's steps had proven from below). The features along
/// `best` (Newton's answer: its unit normal, A's frame, and h there) give points of the cores
/// (feature_segments()); where their distance, or GJK's upper bound if tighter, comes within
/// `tolerance` of the proven lower bound, the bracket is closed, and the closer pair is the answer.
/// Where it does not (Newton's steps started from GJK's normal 2.7e-3 rad off, beside a needle
/// cone, and stopped at a kink of h), the normal turned across both features (make_orthogonal():
/// the answer's normal is across a segment whose interior it meets, and two nearly parallel
/// segments are met so) starts the steps again, up to kFeatureRounds times, while h falls. Returns
/// whether the bracket closed (`out.upper` the closer pair's distance, `out.lower` and
/// `out.normal` the best proof); support calls are counted in `iterations`.
template <ConvexShape A, ConvexShape B>
bool close_at_feature_segments(const CoreDifference<A, B>& diff, typename A::Scalar size,
                               typename A::Scalar tolerance, typename A::Scalar reach,
                               SupportMinimum<typename A::Scalar> best, int& iterations,
                               CoreSeparation<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  for (int round = 0;; ++round) {
    const auto features = feature_segments(diff, best.normal, size);
    if (!features) return false;
    const S features_distance = length_of(Vec3T<S>(features->on_b - features->on_a));
    // The tighter of the two upper bounds: the features' pair may be looser than GJK's (a box
    // plus a cone against a cone, 2.8e-12 apart: the features 7.1e-11), and taking it then made
    // the verdict depend on the order of A and B.
    const S upper = std::min(out.upper, features_distance);
    const S lower = std::max(out.lower, -best.value);
    // Closed, and the verdict decided: apart beyond `reach` or within it.
    if (upper - lower <= tolerance && (lower > reach || upper <= reach)) {
      if (-best.value >= out.lower) {
        out.lower = -best.value;
        out.normal = best.normal;
      }
      if (features_distance < out.upper) {
        out.on_a = features->on_a;
        out.on_b = features->on_b;
        out.upper = features_distance;
      }
      return true;
    }
    if (round == kFeatureRounds) return false;
    // Across both features: their common normal, where their closest points are interior to
    // both (lines that cross, seen along the normal, or a parallelogram face of A - B), and the
    // normal made orthogonal to them, where one is an end (a point against a line: the
    // direction around the line is the normal's own); the lower support value.
    SupportMinimum<S> least;
    Vec3T<S> across = best.normal;
    if (make_orthogonal(across, features->p.half, features->q.half))
      least.measure(diff, across, iterations);
    if (const auto common = meeting_segments_normal(features->p, features->q))
      least.measure(diff, common->dot(best.normal) >= S(0) ? *common : Vec3T<S>(-*common),
                    iterations);
    if (!std::isfinite(least.value)) return false;
    newton_on_support(diff, size, tolerance, kNewtonMaxSteps, iterations, least);
    if (!(least.value < best.value)) return false;
    best = least;
  }
}

/// The bracket, relative to the size, at which GJK hands curved cores apart over to Newton's
/// steps (gjk_apart()). GJK closes its bracket on a curved core linearly, about 20 support calls
/// to 1e-12 of the size, half of them past 1e-6; there the normal is within about 1e-3 rad, from
/// which Newton's steps converge quadratically.
inline constexpr double kHandOffGap = 1e-6;

/// Primitive cores whose pairs gjk_apart() hands over to Newton's steps: all but a cone. A
/// cone's apex is a kink of h that Newton's steps from the loose run's normal (1e-3 rad off)
/// did not cross: 14 to 30 % of the pairs with a cone apart fell back to the full run, and the
/// pairs took 20-30 % more support calls than without the hand-off.
template <class T>
struct NewtonHandOffCore : std::true_type {};
template <class S>
struct NewtonHandOffCore<ConeT<S>> : std::false_type {};

/// Whether gjk_apart() hands the pair over to Newton's steps: every term of both cores allows it
/// (support/core_terms.hpp), and one of them is curved (kCurvedPair holds for every Shape, and a
/// sum of polytopes gains nothing).
template <ConvexShape A, ConvexShape B>
bool hands_off_to_newton(const A& a, const B& b) {
  return every_term<NewtonHandOffCore>(a) && every_term<NewtonHandOffCore>(b) &&
         (any_term<CurvedCore>(a) || any_term<CurvedCore>(b));
}

/// GJK's outcome on cores that may be apart, for distance() and contact(). Curved cores (with
/// refine_curved_normals, no cone: hands_off_to_newton()) run GJK to kHandOffGap only; where it
/// finds them apart beyond 16 touching tolerances, Newton's steps on h from its normal
/// (newton_on_support()) give a proven lower bound, -h, and a witness pair, two points of the cores
/// whose distance bounds it from above. When the two meet within `tol.relative * size` and the pair
/// is a witness pair along the normal (is_witness_pair()), that is the outcome: the pair as its
/// one-point simplex, marked `refined` for separate_cores(). Otherwise (cores within the radii or
/// touching, a minimum Newton's steps do not close: a flat face's support point is a corner of it)
/// GJK goes on from the loose run's simplex (its warm start) to its own tolerance; cores that meet
/// are told by the loose run. Other cores: run_gjk_distance().
template <EnclosePhase kPhase, ConvexShape A, ConvexShape B>
GjkOutcome<typename A::Scalar> gjk_apart(const CoreDifference<A, B>& diff,
                                         typename A::Scalar radius, typename A::Scalar size,
                                         const TolerancesT<typename A::Scalar>& tol,
                                         GjkCacheT<typename A::Scalar>* cache) {
  using S = typename A::Scalar;
  if constexpr (kCurvedPair<A, B>) {
    const S touch = tol.relative * size;
    if (tol.refine_curved_normals && S(kHandOffGap) > tol.relative &&
        hands_off_to_newton(diff.a, diff.b)) {
      GjkCacheT<S> local;
      GjkCacheT<S>* warm = cache ? cache : &local;
      auto loose = run_gjk_distance<kPhase>(diff, radius, size, tol, warm, S(kHandOffGap) * size);
      // Cores that meet, a cap or overflow: as the full run would say. Cores within the radii
      // but apart need their distance to the full tolerance (the depth is the radii less it).
      if (loose.status == Status::IterationLimit || loose.status == Status::InvalidInput ||
          (loose.status == Status::Intersecting && !(loose.upper > touch)))
        return loose;
      // The best lower bound proven on the way, which the full run keeps (below).
      S proven = loose.lower;
      Vec3T<S> proven_v = loose.lower_v;
      if (loose.status == Status::Separated && loose.lower > radius + S(16) * touch) {
        int iterations = loose.iterations;
        auto least = SupportMinimum<S>::at(diff, Vec3T<S>(-loose.v / loose.upper), iterations);
        newton_on_support(diff, size, tol.relative_depth * size, kNewtonMaxSteps, iterations,
                          least);
        loose.iterations = iterations;
        if (-least.value >= proven) {
          proven = -least.value;
          proven_v = -least.normal;
        }
        const S upper = length_of(least.vertex.w);
        // A witness pair too: the bracket's width is the square of the normal's error, and
        // the points need the normal itself converged.
        if (upper - proven <= touch && std::isfinite(upper) &&
            is_witness_pair(least, tol.relative_depth * size)) {
          loose.simplex.size = 1;
          loose.simplex.vertices[0] = least.vertex;
          loose.simplex.weights[0] = S(1);
          loose.v = least.vertex.w;
          loose.upper = upper;
          loose.lower = proven;
          loose.lower_v = proven_v;
          loose.refined = true;
          loose.refined_normal = least.normal;
          loose.refined_value = least.value;
          return loose;
        }
      }
      auto full = run_gjk_distance<kPhase>(diff, radius, size, tol, warm);
      full.iterations += loose.iterations;
      // The full run, warm, may not prove again what the loose run or Newton's steps proved:
      // contact() takes cores apart only on GJK's lower bound, and 37 pairs 1.03-1.63 touching
      // tolerances apart came out touching from contact() and apart from distance().
      if (full.upper > touch && proven > full.lower) {
        full.lower = proven;
        full.lower_v = proven_v;
      }
      return full;
    }
  }
  return run_gjk_distance<kPhase>(diff, radius, size, tol, cache);
}

/// The normal and closest points for GJK's answer on cores that GJK did not find meeting, and
/// the status of the full shapes; `radii` is the sum of the shapes' radii, `size` the sum of
/// their bounding radii. A unit n proves the separation -h(n), h the support function of A - B,
/// so the normal is the candidate with the least h:
///   - -v / |v|, and its correction orthogonal to the final simplex (separation_direction()),
///     which removes the rounding tilt of a v that is tiny next to the points it came from;
///     exact when the simplex lies on a flat feature of A - B;
///   - the direction that proved GJK's lower bound, when an earlier v did: on a curved core the
///     final simplex mixes support points of A from different iterations, a chord whose
///     direction is tilted by its sag (1e-9 of the size in h against a flat face), while its
///     length is right to second order;
///   - when the best of these still leaves GJK's bounds apart by more than twice the touching
///     tolerance (curved cores at the rounding floor), a descent on h from it
///     (descend_support(), with at most max_iterations / 4 support calls): the minimum of h is
///     minus the distance, at the normal.
/// Only the first pair is free of support calls, and when it is the only candidate (the common
/// case: GJK converged on its last v) nothing is measured. Extra support calls are counted in
/// `iterations`. A normal other than the first pair's is taken only for a clear gain (see the
/// end); the points then keep GJK's midpoint and distance and line up with it.
///
/// The status, one rule for distance() and contact() (touch = tolerances.relative * size):
///   - GJK's upper bound within radii + touch: the shapes penetrate by the radii, or touch;
///   - else, no direction proves the cores apart by more than radii + touch: they touch when
///     GJK's upper bound is within 16 touching tolerances of it (GJK on curved cores that touch
///     crawls, and its bounds meet only at the cap), else GJK stalled and the distance is only
///     bracketed (IterationLimit);
///   - else separated, unless GJK hit its cap or the bracket stayed open wider than curved cores
///     converge to (`relative_depth * size`, EPA's tolerance): IterationLimit.
template <ConvexShape A, ConvexShape B>
CoreSeparation<typename A::Scalar> separate_cores(const CoreDifference<A, B>& diff,
                                                  const GjkOutcome<typename A::Scalar>& gjk,
                                                  typename A::Scalar radii, typename A::Scalar size,
                                                  const TolerancesT<typename A::Scalar>& tolerances,
                                                  int& iterations) {
  using S = typename A::Scalar;
  const S touch = tolerances.relative * size;
  CoreSeparation<S> out;
  find_separation(diff, gjk, touch, tolerances.max_iterations, iterations, out);
  out.upper = gjk.upper;
  bool closed = false;  // by the features' points (close_at_feature_segments())
  if constexpr (kCurvedPair<A, B>) {
    // Curved cores apart or touching: the normal of a smooth minimum is good to the square root
    // of GJK's tolerance; Newton's steps (gjk/support_newton.hpp) take it to the rounding, and
    // the points become the support points along it, lined up at GJK's distance. Touching cores
    // too: where the minimum is sharp (a cone's slant against a cylinder's rim), GJK's normal
    // left the points 5e-7 of the size from the contact; where it is flat (a corner against a
    // rim), the steps leave the value within its rounding and the points where they were.
    if (tolerances.refine_curved_normals && std::isfinite(gjk.upper)) {
      // gjk_apart()'s steps, when they closed the bracket, or the steps from GJK's normal.
      SupportMinimum<S> least;
      if (gjk.refined) {
        least.value = gjk.refined_value;
        least.normal = gjk.refined_normal;
        least.vertex = gjk.simplex.vertices[0];
      } else {
        least = SupportMinimum<S>::at(diff, out.normal, iterations);
      }
      if (gjk.refined || newton_on_support(diff, size, tolerances.relative_depth * size,
                                           kNewtonMaxSteps, iterations, least) > 0) {
        out.normal = least.normal;
        out.lower = std::max(out.lower, -least.value);
        out.on_a = least.vertex.a;
        out.on_b = least.vertex.b;
        share_residual(out.on_a, out.on_b, out.normal, -gjk.upper);
      }
      // A corner against a solid: the corner and its nearest point on the solid, exact where
      // the steps stop beside a kink (gjk/corner_solid.hpp).
      if (const auto pair = corner_solid_pair(diff, least, gjk.upper, touch, iterations)) {
        out.normal = pair->normal;
        out.on_a = pair->on_a;
        out.on_b = pair->on_b;
        share_residual(out.on_a, out.on_b, out.normal, -gjk.upper);
      }
      // Where the status below would be IterationLimit: GJK capped, its bracket open, or the
      // cores neither proven apart nor within the touching tolerance.
      if (gjk.status == Status::IterationLimit ||
          gjk.upper - out.lower > tolerances.relative_depth * size ||
          (out.lower <= radii + touch && gjk.upper > radii + touch))
        closed = close_at_feature_segments(diff, size, tolerances.relative_depth * size,
                                           radii + touch, least, iterations, out);
    }
  }
  if constexpr (!kCurvedPair<A, B>) {
    // Polytopes: GJK's bracket closes on a face of A - B to rounding, except where two faces
    // are nearly parallel (a hull's face over a box's, tilted 1e-10 rad): its simplex may then
    // be any within its tolerance, and its points any of the overlap, 0.34 of the size from
    // the nearest corner. A face's normal and the features' witness pair (witness_at_face()):
    // two points of the shapes whose distance that normal proves the least, so it is the
    // answer (GJK's upper bound was above it by up to its tolerance).
    if (gjk.upper - out.lower > S(64) * std::numeric_limits<S>::epsilon() * size &&
        std::isfinite(gjk.upper)) {
      SupportMinimum<S> pair;
      if (witness_at_face(diff, out.normal, size, iterations, pair) &&
          pair_on_support_planes(pair) &&
          std::abs(pair.value + gjk.upper) <= tolerances.relative_depth * size) {
        out.normal = pair.normal;
        out.upper = std::min(gjk.upper, -pair.value);
        out.lower = std::max(out.lower, out.upper);
        out.on_a = pair.vertex.a;
        out.on_b = pair.vertex.b;
        share_residual(out.on_a, out.on_b, out.normal, -out.upper);
      }
    }
  }
  const bool capped = gjk.status == Status::IterationLimit && !closed;
  const bool open = out.upper - out.lower > tolerances.relative_depth * size;
  if (out.upper <= radii + touch)
    out.status = capped || open ? Status::IterationLimit : Status::Intersecting;
  else if (out.lower <= radii + touch)
    out.status = out.upper <= radii + S(16) * touch ? Status::Intersecting : Status::IterationLimit;
  else
    out.status = capped || open ? Status::IterationLimit : Status::Separated;
  return out;
}

}  // namespace mink::detail
