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

namespace mink::detail {

/// T's core is a polytope whose face planes SolidCore<T> reads (PolytopeT, Rounded<PolytopeT>).
template <class T>
constexpr bool has_face_planes() {
  if constexpr (SolidCore<T>::value)
    return std::is_same_v<typename SolidCore<T>::Core, FacePlanesT<typename T::Scalar>>;
  else
    return false;
}

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
/// face planes yet is never Intersecting here. Always inlined into intersect(), its only caller:
/// out of line, the first point and its direction went back through memory, and Clang took
/// 33.2 ns for a polytope8 pair apart against 25.5 ns inlined (GCC 34.0 -> 32.6 ns; overlapping
/// pairs 55.7 -> 53.7 ns under Clang, 63.7 -> 65.2 ns under GCC).
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline EncloseVerdict first_support_verdict(
    const CoreDifference<A, B>& diff, typename A::Scalar inside,
    PointAndDirection<typename A::Scalar>& first) {
  using S = typename A::Scalar;
  const Vec3T<S> d = first_direction(diff);
  const Vec3T<S> on_a = diff.a.support_core(d);
  const Vec3T<S> on_b =
      diff.rotation * diff.b.support_core(diff.direction_in_b(d)) + diff.translation;
  first.w = on_a - on_b;  // as CoreDifference::support_point() computes it
  first.dir = d;
  const S wd = first.w.dot(d);
  if (!(wd >= S(0)))
    return exceeds_times_length(-wd, inside, d, S(d.squaredNorm())) ? EncloseVerdict::Separated
                                                                    : EncloseVerdict::Unsure;
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
