/// @file inner_ball.hpp
/// A lower bound on the penetration depth from a ball inside A - B, which lets EPA stop on
/// cores that hold an ellipsoid once Newton's steps have found the normal.
///
/// EPA's lower bound is its polytope's nearest face. On a curved A - B that bound closes
/// linearly, the polytope refining all round the minimum: two ellipsoids took 30-50 support calls
/// to 1e-10 of the size, after GJK, where Newton's steps find the minimum's normal in a handful.
/// Their support value is an upper bound only. A lower bound of another kind closes the bracket:
///
/// Let a ball of radius r_A fit inside core A touching its boundary at each of its points (an
/// ellipsoid's least radius of curvature, c^2 / a for semi-axes a >= b >= c: Blaschke's rolling
/// theorem), and likewise r_B in B. With a on A's support plane along the unit n, the ball of
/// radius r_A touching there lies in A; b on B's support plane along -n likewise; so A - B holds
/// the ball of radius R = r_A + r_B about c = a - b - R n, and every point of its boundary is
/// at least R - |c| from the origin: the depth is at least that. At the minimum, a - b = h n
/// with h = h(n) the support value along n, so R - |c| = R - |h - R| = h when h <= R, and the
/// bracket [R - |c|, h(n)] closes to rounding: the answer is exact. A core with no such ball
/// (a polytope's corner, a cylinder's rim) has r = 0 and needs only its point on the plane, any
/// point of it: the witness pair of Newton's steps. Shallow contacts, the common case, are within
/// R; deeper ones, and pairs without an ellipsoid, go on with EPA.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/gjk/support_newton.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"
#include "mink/support/shape.hpp"

namespace mink::detail {

/// The radius of a ball that fits inside the core touching each point of its boundary (0: a
/// corner or an edge somewhere). Cores only: EPA runs on them, a rounded shape's margin apart.
template <class T>
struct InnerBall {
  static constexpr bool kMay = false;
  static typename T::Scalar radius(const T&) { return typename T::Scalar(0); }
};
template <class S>
struct InnerBall<EllipsoidT<S>> {
  static constexpr bool kMay = true;
  /// The least radius of curvature, c^2 / a, shrunk by a few roundings of its own arithmetic so
  /// that it never exceeds the true one.
  static S radius(const EllipsoidT<S>& e) {
    const S least = e.radii.minCoeff(), most = e.radii.maxCoeff();
    if (!(most > S(0))) return S(0);
    return least * least / most * (S(1) - S(8) * std::numeric_limits<S>::epsilon());
  }
};
template <class T>
struct InnerBall<Rounded<T>> {
  static constexpr bool kMay = InnerBall<T>::kMay;
  static typename T::Scalar radius(const Rounded<T>& r) { return InnerBall<T>::radius(r.shape); }
};
/// A sum of cores holds the sum of their balls, touching where their support points add up.
template <class X, class Y>
struct InnerBall<MinkowskiSum<X, Y>> {
  static constexpr bool kMay = InnerBall<X>::kMay || InnerBall<Y>::kMay;
  static typename X::Scalar radius(const MinkowskiSum<X, Y>& s) {
    return InnerBall<X>::radius(s.a) + InnerBall<Y>::radius(s.b);
  }
};
/// A run-time Shape: the sum of its terms' balls.
template <>
struct InnerBall<Shape> {
  static constexpr bool kMay = true;
  static double radius(const Shape& shape) {
    double sum = 0;
    for (const Core& term : shape.cores())
      sum += visit_core(
          term, [](const auto& c) { return InnerBall<std::decay_t<decltype(c)>>::radius(c); });
    return sum;
  }
};

template <class A, class B>
inline constexpr bool kInnerBallPair = InnerBall<A>::kMay || InnerBall<B>::kMay;

/// Whether the inner balls of the cores (radii `ball_a`, `ball_b`) prove the depth along the
/// unit normal of `least` (Newton's answer: its vertex a witness pair) within `tolerance` (unit:
/// length), with the points' offset across the normal within `witness_gap` (unit: length). One
/// support call along the normal (counted in `iterations`) gives h(n), the upper bound, and the
/// points where the balls touch; a core without a ball keeps the pair's point. On success
/// `least` holds that support value, the normal and the points, and `lower` the proven lower
/// bound. The bracket alone allows an offset t with t^2 <= 2 (R - h) tolerance (6e-7 of the
/// size on a probe's box and ellipsoid 0.03 across, though Newton's steps left 2e-12), and the
/// points, shared along the normal, move by t / 2: on a box's edge, off the box at first order.
/// The gap is what Newton's witness pairs keep elsewhere (is_witness_pair()).
template <ConvexShape A, ConvexShape B>
bool inner_ball_proves_depth(const CoreDifference<A, B>& diff, typename A::Scalar ball_a,
                             typename A::Scalar ball_b, typename A::Scalar tolerance,
                             typename A::Scalar witness_gap, int& iterations,
                             SupportMinimum<typename A::Scalar>& least, typename A::Scalar& lower) {
  using S = typename A::Scalar;
  const Vec3T<S> n = least.normal;
  SimplexVertexT<S> along;
  diff.support(n, along);
  ++iterations;
  const S upper = n.dot(along.w);
  const Vec3T<S> a = ball_a > S(0) ? along.a : least.vertex.a;
  const Vec3T<S> b = ball_b > S(0) ? along.b : least.vertex.b;
  const S ball = ball_a + ball_b;
  const Vec3T<S> offset = a - b;
  const S proven = ball - length_of(Vec3T<S>(offset - ball * n));
  if (!(std::isfinite(upper) && proven > S(0) && upper - proven <= tolerance &&
        length_of(Vec3T<S>(offset - n.dot(offset) * n)) <= witness_gap))
    return false;
  least.value = upper;
  least.vertex.a = a;
  least.vertex.b = b;
  least.vertex.w = a - b;
  least.vertex.dir = n;
  lower = proven;
  return true;
}

/// How far below the support plane (a fraction of the size) a face may lie for
/// newton_proves_depth() to try its normal: EPA hands over with its normal up to about 1e-2 rad
/// off, and snap_to_face()'s own reach (1e-5) missed a box's face against an ellipsoid from
/// 3e-5 rad off.
inline constexpr double kInnerBallFaceReach = 1e-2;

/// The normal of `least` (h along it and that support point) made exact, then proven by the
/// inner balls (inner_ball_proves_depth()). First a face's normal within kInnerBallFaceReach and
/// the features' witness pair along it (snap_to_face(), feature_witness()): a face's normal is a
/// kink of h in every direction, where Newton's steps spent all their budget (8 steps, 24-32
/// support calls) on a box's face against an ellipsoid without reaching it. Else Newton's steps
/// (newton_on_support()). Support calls are counted in `iterations`; `least` and `lower` are
/// set on success.
template <ConvexShape A, ConvexShape B>
bool newton_proves_depth(const CoreDifference<A, B>& diff, typename A::Scalar size,
                         const TolerancesT<typename A::Scalar>& tol, typename A::Scalar ball_a,
                         typename A::Scalar ball_b, int& iterations,
                         SupportMinimum<typename A::Scalar>& least, typename A::Scalar& lower) {
  using S = typename A::Scalar;
  const S bracket = tol.relative * size, witness_gap = tol.relative_depth * size;
  SupportFeatureT<S> feature_a, feature_b;
  core_features(diff, least.normal, S(kInnerBallFaceReach) * size, feature_a, feature_b);
  SupportMinimum<S> at_face = least;
  if (snap_to_face(diff, feature_a, feature_b, iterations, at_face) &&
      feature_witness(diff, size, iterations, at_face) &&
      inner_ball_proves_depth(diff, ball_a, ball_b, bracket, witness_gap, iterations, at_face,
                              lower)) {
    least = at_face;
    return true;
  }
  newton_on_support(diff, size, tol.relative_depth * size, kNewtonMaxSteps, iterations, least);
  return inner_ball_proves_depth(diff, ball_a, ball_b, bracket, witness_gap, iterations, least,
                                 lower);
}

}  // namespace mink::detail
