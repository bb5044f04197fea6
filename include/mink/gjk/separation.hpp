/// @file separation.hpp
/// The answer for cores that GJK found apart: the normal and the closest points of the cores.
#pragma once

#include <algorithm>
#include <cmath>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"

namespace mink::detail {

template <class S>
struct CoreSeparation {
  Vec3T<S> normal;  ///< unit, A's frame, from A's core towards B's
  Vec3T<S> on_a;    ///< closest point of A's core (A's frame)
  Vec3T<S> on_b;    ///< closest point of B's core (A's frame); on_b - on_a = distance * normal
  S lower;          ///< proven lower bound on the core distance: the separation along `normal`
};

/// The normal and closest points for GJK's answer. A unit n proves the separation -h(n), h the
/// support function of A - B, so the normal is the candidate with the least h:
///   - -v / |v|, and its correction orthogonal to the final simplex (separation_direction()),
///     which removes the rounding tilt of a v that is tiny next to the points it came from;
///     exact when the simplex lies on a flat feature of A - B;
///   - the direction that proved GJK's lower bound, when an earlier v did: on a curved core the
///     final simplex mixes support points of A from different iterations, a chord whose
///     direction is tilted by its sag (1e-9 of the size in h against a flat face), while its
///     length is right to second order;
///   - when the best of these still leaves GJK's bounds apart by more than twice `touch` (curved
///     cores at the rounding floor), a descent on h from it (descend_support(), with at most
///     max_iterations / 4 support calls): the minimum of h is minus the distance, at the normal.
/// Only the first pair is free of support calls, and when it is the only candidate (the common
/// case: GJK converged on its last v) nothing is measured. Extra support calls are counted in
/// `iterations`. A normal other than the first pair's is taken only for a clear gain (see the
/// end); the points then keep GJK's midpoint and distance and line up with it.
template <ConvexShape A, ConvexShape B>
CoreSeparation<typename A::Scalar> separate_cores(const CoreDifference<A, B>& diff,
                                                  const GjkOutcome<typename A::Scalar>& gjk,
                                                  typename A::Scalar touch, int max_iterations,
                                                  int& iterations) {
  using S = typename A::Scalar;
  CoreSeparation<S> out;
  gjk.simplex.witness_points(out.on_a, out.on_b);
  out.normal = separation_direction(gjk.simplex, gjk.v);
  out.lower = gjk.lower;
  const S length = gjk.v.norm();
  const Vec3T<S> plain = length > S(0) ? Vec3T<S>(-gjk.v / length) : out.normal;
  const bool plain_differs = (out.normal - plain).squaredNorm() > S(1e-24);
  const S lower_length = gjk.lower_v.norm();
  const bool lower_differs = gjk.lower > S(0) && lower_length > S(0) && gjk.lower_v != gjk.v;
  const bool apart = gjk.upper - gjk.lower > S(2) * touch;
  if (!plain_differs && !lower_differs && !apart) return out;

  SupportMinimum<S> least;
  auto consider = [&](const Vec3T<S>& n) {
    SimplexVertexT<S> w;
    diff.support(n, w);
    ++iterations;
    const S h = n.dot(w.w);
    if (h < least.value) least = {h, n, w};
  };
  consider(out.normal);
  if (plain_differs) consider(plain);
  const S free_value = least.value;  // the best of the first pair
  const Vec3T<S> free_normal = least.normal;
  if (lower_differs && -gjk.lower < least.value)
    least = {-gjk.lower, Vec3T<S>(-gjk.lower_v / lower_length), gjk.lower_vertex};
  // The minimum of h is minus the distance, at least -gjk.upper. On non-finite arithmetic the
  // descent keeps its last finite answer, which is still a proven separation.
  if (gjk.upper + least.value > S(2) * touch)
    descend_support(diff, -gjk.upper, touch, iterations + max_iterations / 4, iterations, least);
  out.lower = std::max(out.lower, -least.value);
  out.normal = free_normal;
  // A new normal moves the points with it, by half the distance times the turn, off the exact
  // pair GJK's points are (their gap is -v); and near a smooth minimum of h the turn is the
  // square root of the gain. So a new normal only for a gain that counts: 16 times the touching
  // tolerance (a tilt across a kink of h, a flat face's edge, gains at first order).
  if (!(free_value - least.value > S(16) * touch)) return out;
  const Vec3T<S> middle = (out.on_a + out.on_b) / S(2);
  const S half = (out.on_b - out.on_a).norm() / S(2);
  out.normal = least.normal;
  out.on_a = middle - half * out.normal;
  out.on_b = middle + half * out.normal;
  return out;
}

}  // namespace mink::detail
