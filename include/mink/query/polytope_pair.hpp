/// @file polytope_pair.hpp
/// Two small polytopes in the boolean test: a common point from GJK's first support call.
///
/// GJK's first support point of A - B, along the line of centres, is A's point farthest towards B
/// minus B's point farthest towards A. When the shapes overlap, one of those two points often lies
/// inside the other polytope (in five of six of the benchmark's overlapping pairs of 8-point
/// polytopes, and in nineteen of twenty of 32-point ones). It is then a point of both cores: the
/// shapes intersect, proven by one support call and a scan of the face planes, where GJK needs
/// three to five support calls and its simplex steps to enclose the origin. Otherwise the support
/// point goes on to GJK's first phase, which starts from it, so nothing is computed twice.
///
/// Polytopes of 4 to 63 points with face planes only (face_planes.hpp; PolytopeT builds them after
/// kPolytopePlanesAfterQueries queries), and cores with no radius: the test is whether the point
/// is below every face plane of the other polytope, the rule by which query/point_solid.hpp calls a
/// point inside (the planes are flat to 256 eps of the coordinates, within the touching
/// tolerance).
#pragma once

#include <limits>
#include <type_traits>

#include "mink/gjk/gjk.hpp"
#include "mink/query/point_solid.hpp"
#include "mink/shapes/face_planes.hpp"
#include "mink/shapes/polytope.hpp"
#include "mink/support/polytope_core.hpp"

namespace mink::detail {

/// T's core is a polytope whose face planes SolidCore<T> reads (PolytopeT, Rounded<PolytopeT>).
template <class T>
constexpr bool has_face_planes() {
  if constexpr (SolidCore<T>::value)
    return std::is_same_v<typename SolidCore<T>::Core, FacePlanesT<typename T::Scalar>>;
  else
    return false;
}

/// Every core with face planes is a PolytopeCore (support/polytope_core.hpp).
template <class A, class B>
inline constexpr bool kPolytopePair = has_face_planes<A>() && has_face_planes<B>();

/// Whether `p` (in the polytope's frame) is below every face plane of `planes` by at least
/// `margin`: a point of the polytope. The scan stops at the first block of planes that p is
/// above by more than -margin.
template <class S>
[[gnu::always_inline]] inline bool below_face_planes(const FacePlanesT<S>& planes,
                                                     const Vec3T<S>& p, S margin) {
  const std::optional<S> largest =
      SolidCore<PolytopeT<S>>::plane_distances(planes, p, nullptr, -margin);
  return largest && *largest <= -margin;
}

/// A's point is taken to B's frame by the transpose of B's rotation, which is its inverse only to
/// the rotation's own error: pose_error() allows 1e-6, and the point moves by up to about twice
/// that times its offset. It must be inside B by more than that. (B's point goes to A's frame by
/// the rotation itself, as GJK maps B's support points, and needs no margin.)
inline constexpr double kTransposeSlack = 4e-6;

/// GJK's first support point of `diff` (along first_direction(), as enclose_origin() takes it)
/// into `first`, and what it shows: Separated when its support plane passes the origin with room
/// for `inside` (as enclose_origin() would decide on it), Intersecting when either of its two
/// parts lies inside the other polytope, else Unsure (GJK goes on from `first`). A pair without
/// face planes yet is never Intersecting here. `diff` comes with its translation; its rotation is
/// formed here (relative_rotation()) unless the support values alone tell the pair apart. Always
/// inlined into intersect(), its only caller: out of line, the first point and its direction went
/// back through memory, and Clang took 33.2 ns for a polytope8 pair apart against 25.5 ns inlined
/// (GCC 34.0 -> 32.6 ns; overlapping pairs 55.7 -> 53.7 ns under Clang, 63.7 -> 65.2 ns under
/// GCC).
///
/// The separating plane is tested first on the two scans' support values: the gap along d is
/// t.d - h_A(d) - h_B(-R^T d), (R, t) B's pose in A's frame. The values are ready before either
/// support point is loaded and B's is moved to A's frame, so a pair apart is told so without
/// waiting on that chain (polytope8 pairs apart: 33.5 -> 27.3 ns in gjk_bench, 40.7 -> 30.8 ns
/// in a driver). Nor does it find the support points' indices: SupportHit::index() reads them
/// off the scans' lanes only for a pair the values leave undecided (polytope8 pairs apart 4 %
/// faster, stop 96). Nor does it wait on R: B scans along the world's direction, -R_B^T (t_B -
/// t_A) for d = t, which is -R^T d = -R_B^T R_A R_A^T (t_B - t_A) but for R_A's error (within
/// pose_error()'s 1e-6, so within kTransposeSlack |d| |p| for B's points p; rounding is far below
/// that for any d whose square is not 0). The gap must clear that slack too, and R is formed only
/// for a pair the values leave undecided: one product before B's scan where there were two in a
/// row, and none of R's for a pair apart (polytope8 pairs apart 20 % faster, 32- to 512-point
/// ones 4-7 %, paired; stop 100). A pair left undecided goes on with the points, as before;
/// their own product decides the same but for rounding, and B's point is taken again along -R^T d
/// itself (as GJK takes it) before it may tell the pair apart.
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline EncloseVerdict first_support_verdict(
    CoreDifference<A, B>& diff, const PoseT<typename A::Scalar>& pose_a,
    const PoseT<typename A::Scalar>& pose_b, typename A::Scalar inside, typename A::Scalar bound_b,
    PointAndDirection<typename A::Scalar>& first) {
  using S = typename A::Scalar;
  S d_sq = diff.translation.squaredNorm();
  Vec3T<S> d = diff.translation;
  Vec3T<S> d_world = pose_a.translation - pose_b.translation;  // -R_A d: B scans against d
  if (!(d_sq > S(0))) {  // as first_direction(): +x, exact in the world as A's first column
    d = Vec3T<S>::UnitX();
    d_sq = S(1);
    d_world = -pose_a.rotation.col(0);
  }
  first.dir = d;
  const auto& polytope_a = PolytopeCore<A>::of(diff.a);
  const auto& polytope_b = PolytopeCore<B>::of(diff.b);
  const SupportHit<S> hit_a = polytope_a.support_core_hit(d);
  const SupportHit<S> hit_b = polytope_b.support_core_hit(pose_b.inverse_rotate(d_world));
  // (B's point, moved) . d = its value along -R^T d, negated, plus the offset along d; within the
  // slack, with B's bounding radius for |p|. A NaN or an infinite gap leaves the verdict to the
  // points.
  const S value_gap = diff.translation.dot(d) - hit_a.value - hit_b.value;
  if (value_gap <= std::numeric_limits<S>::max() &&
      exceeds_times_length(value_gap, inside + S(kTransposeSlack) * bound_b, d, d_sq))
    return EncloseVerdict::Separated;
  pose_a.relative_rotation(pose_b, diff.rotation);
  const Vec3T<S> on_a = polytope_a.point(hit_a.index());
  Vec3T<S> on_b = diff.rotation * polytope_b.point(hit_b.index()) + diff.translation;
  first.w = on_a - on_b;  // as CoreDifference::support_point() computes it
  S wd = first.w.dot(d);
  if (!(wd >= S(0))) [[unlikely]] {
    // Apart by less than the values' slack, or not finite: B's point along -R^T d itself, as
    // CoreDifference::support_point() takes it, so that this verdict is GJK's.
    on_b = diff.rotation * polytope_b.support_core(diff.direction_in_b(d)) + diff.translation;
    first.w = on_a - on_b;
    wd = first.w.dot(d);
    if (!(wd >= S(0)))
      return exceeds_times_length(-wd, inside, d, d_sq) ? EncloseVerdict::Separated
                                                        : EncloseVerdict::Unsure;
  }
  if (const FacePlanesT<S>* planes_a = SolidCore<A>::core(diff.a))
    if (below_face_planes(*planes_a, on_b, S(0))) return EncloseVerdict::Intersecting;
  if (const FacePlanesT<S>* planes_b = SolidCore<B>::core(diff.b)) {
    const Vec3T<S> offset = on_a - diff.translation;
    if (below_face_planes(*planes_b, Vec3T<S>(diff.rotation.transpose() * offset),
                          S(kTransposeSlack) * offset.cwiseAbs().maxCoeff()))
      return EncloseVerdict::Intersecting;
  }
  return EncloseVerdict::Unsure;
}

}  // namespace mink::detail
