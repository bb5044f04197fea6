/// @file inner_ball.hpp
/// A lower bound on the penetration depth from a ball inside A - B, which lets EPA stop on
/// cores that hold an ellipsoid, or meet at a cylinder's side, once Newton's steps have found the
/// normal. (Since stop 89 the balls need not touch at the support points: see balls() below.)
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

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/gjk/support_newton.hpp"
#include "mink/shapes/box.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"
#include "mink/support/shape.hpp"

namespace mink::detail {

/// A ball inside a core: its radius (unit: length; 0 for the point `centre` itself, a point of
/// the core) and its centre, in the core's frame.
template <class S>
struct CoreBall {
  S radius = S(0);
  Vec3T<S> centre = Vec3T<S>::Zero();
};

/// The balls a core offers the proof below. `radius()`: that of a ball that fits inside the core
/// touching each point of its boundary (0: a corner or an edge somewhere), which a sum of cores
/// adds up. `reach()`: the depth up to which its balls usually close the proof (the rolling
/// ball's radius; half the largest ball's, which fits only about the core's middle), beyond which
/// Newton's steps would be spent for nothing. `balls()` writes up to kMaxCoreBalls balls near the
/// boundary point `witness` whose outward unit normal is `normal` (core frame; `support` is the
/// support point along it) and returns their number. By default one, the rolling ball touching at
/// the support point. `touches()`: whether one of those balls may touch the core where its support
/// feature is `feature` and close a proof that EPA needs (a cylinder's side, any point of an
/// ellipsoid; not a corner, an edge or a rim, where the proof would fail after Newton's steps, nor
/// a face, where EPA closes on a facet by itself). Cores only: EPA runs on them, a rounded shape's
/// margin apart.
inline constexpr int kMaxCoreBalls = 3;

template <class T>
struct InnerBall {
  using S = typename T::Scalar;
  static constexpr bool kMay = false;
  static S radius(const T&) { return S(0); }
  static S reach(const T& core) { return radius(core); }
  static int balls(const T&, const Vec3T<S>&, const Vec3T<S>&, const Vec3T<S>&, CoreBall<S>*) {
    return 0;
  }
  static bool touches(const T&, const SupportFeatureT<S>&) { return false; }
};

/// Whether `core` holds a rolling ball (InnerBall::radius() > 0): one touching at each point of
/// its boundary, so at its support point along any normal.
template <class T>
bool rolls(const T& core) {
  return InnerBall<T>::radius(core) > typename T::Scalar(0);
}

/// The rolling ball of radius `r` touching at `support` with outward `normal`: one ball, or none.
template <class S>
int rolling_ball(S r, const Vec3T<S>& support, const Vec3T<S>& normal, CoreBall<S>* out) {
  if (!(r > S(0))) return 0;
  out[0] = {r, Vec3T<S>(support - r * normal)};
  return 1;
}

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
  static S reach(const EllipsoidT<S>& e) { return radius(e); }
  static int balls(const EllipsoidT<S>& e, const Vec3T<S>& support, const Vec3T<S>&,
                   const Vec3T<S>& normal, CoreBall<S>* out) {
    return rolling_ball(radius(e), support, normal, out);
  }
  static bool touches(const EllipsoidT<S>& e, const SupportFeatureT<S>&) {
    return radius(e) > S(0);
  }
};

/// A cylinder holds a ball of radius rho about every point of the cylinder of radius r - rho and
/// half height h - rho (rho <= min(r, h)); no ball touches its rims. Near a point of its side,
/// the ball as large as the caps let touch there; near a point of a cap, as large as the rim lets;
/// and the largest, its centre the point of that inner cylinder nearest to where it would touch.
/// Every centre is taken into its inner cylinder, so each ball lies inside, touching or not.
template <class S>
struct InnerBall<CylinderT<S>> {
  static constexpr bool kMay = true;
  static S radius(const CylinderT<S>&) { return S(0); }
  static S largest(const CylinderT<S>& c) { return std::min(c.radius, c.half_height); }
  static S reach(const CylinderT<S>& c) { return largest(c) / S(2); }
  static int balls(const CylinderT<S>& c, const Vec3T<S>&, const Vec3T<S>& witness,
                   const Vec3T<S>& normal, CoreBall<S>* out) {
    // Rounding of the centre's coordinates: the balls shrink by it.
    const S slack = S(8) * std::numeric_limits<S>::epsilon() * (c.radius + c.half_height);
    const S side = std::min(c.radius, c.half_height - std::abs(witness.z()));
    const S cap = std::min(c.half_height, c.radius - planar_length(witness.x(), witness.y()));
    int count = 0;
    for (const S rho : {largest(c), side, cap}) {
      if (!(rho > slack)) continue;
      Vec3T<S> centre = witness - rho * normal;
      const S lateral = c.radius - rho, axial = c.half_height - rho;
      centre.z() = std::clamp(centre.z(), -axial, axial);
      const S from_axis = planar_length(centre.x(), centre.y());
      if (from_axis > lateral) {
        const S shrink = lateral / from_axis;
        centre.x() *= shrink;
        centre.y() *= shrink;
      }
      out[count++] = {rho - slack, centre};
    }
    return count;
  }
  /// Its side (a segment along the axis): not a rim, nor a cap, where EPA closes on a facet.
  static bool touches(const CylinderT<S>&, const SupportFeatureT<S>& feature) {
    return feature.count == 2;
  }
};

/// A box of half extents h holds a ball of radius rho about every point of the box of half
/// extents h - rho (rho <= min h). Near a point of a face, the ball as large as the face's edges
/// let touch there; and the largest, its centre taken into its inner box.
template <class S>
struct InnerBall<BoxT<S>> {
  static constexpr bool kMay = true;
  static S radius(const BoxT<S>&) { return S(0); }
  static S largest(const BoxT<S>& box) { return box.half_extents.minCoeff(); }
  static S reach(const BoxT<S>& box) { return largest(box) / S(2); }
  static int balls(const BoxT<S>& box, const Vec3T<S>&, const Vec3T<S>& witness,
                   const Vec3T<S>& normal, CoreBall<S>* out) {
    const Vec3T<S>& h = box.half_extents;
    const S slack = S(8) * std::numeric_limits<S>::epsilon() * h.sum();
    int face;
    normal.cwiseAbs().maxCoeff(&face);
    S on_face = h[face];
    for (int k = 0; k < 3; ++k)
      if (k != face) on_face = std::min(on_face, h[k] - std::abs(witness[k]));
    int count = 0;
    for (const S rho : {largest(box), on_face}) {
      if (!(rho > slack)) continue;
      const Vec3T<S> inner = (h.array() - rho).matrix();
      const Vec3T<S> centre = Vec3T<S>(witness - rho * normal).cwiseMax(-inner).cwiseMin(inner);
      out[count++] = {rho - slack, centre};
    }
    return count;
  }
  /// Never where the proof is needed: against a face EPA closes on a facet. (Its balls still
  /// serve where the other core's touch.)
  static bool touches(const BoxT<S>&, const SupportFeatureT<S>&) { return false; }
};

template <class T>
struct InnerBall<Rounded<T>> {
  using S = typename T::Scalar;
  static constexpr bool kMay = InnerBall<T>::kMay;
  static S radius(const Rounded<T>& r) { return InnerBall<T>::radius(r.shape); }
  static S reach(const Rounded<T>& r) { return InnerBall<T>::reach(r.shape); }
  static int balls(const Rounded<T>& r, const Vec3T<S>& support, const Vec3T<S>& witness,
                   const Vec3T<S>& normal, CoreBall<S>* out) {
    return InnerBall<T>::balls(r.shape, support, witness, normal, out);
  }
  static bool touches(const Rounded<T>& r, const SupportFeatureT<S>& feature) {
    return InnerBall<T>::touches(r.shape, feature);
  }
};
/// A sum of cores holds the sum of their rolling balls, touching where their support points add
/// up. (Their other balls would need each term's own witness point.)
template <class X, class Y>
struct InnerBall<MinkowskiSum<X, Y>> {
  using S = typename X::Scalar;
  static constexpr bool kMay = InnerBall<X>::kMay || InnerBall<Y>::kMay;
  static S radius(const MinkowskiSum<X, Y>& s) {
    return InnerBall<X>::radius(s.a) + InnerBall<Y>::radius(s.b);
  }
  static S reach(const MinkowskiSum<X, Y>& s) { return radius(s); }
  static int balls(const MinkowskiSum<X, Y>& s, const Vec3T<S>& support, const Vec3T<S>&,
                   const Vec3T<S>& normal, CoreBall<S>* out) {
    return rolling_ball(radius(s), support, normal, out);
  }
  static bool touches(const MinkowskiSum<X, Y>& s, const SupportFeatureT<S>&) {
    return radius(s) > S(0);
  }
};
/// A run-time Shape here is a sum (a Shape of one core is queried as that core): the sum of its
/// terms' rolling balls.
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
  static double reach(const Shape& shape) { return radius(shape); }
  static int balls(const Shape& shape, const Vec3& support, const Vec3&, const Vec3& normal,
                   CoreBall<double>* out) {
    return rolling_ball(radius(shape), support, normal, out);
  }
  static bool touches(const Shape& shape, const SupportFeatureT<double>&) {
    return radius(shape) > 0;
  }
};

template <class A, class B>
inline constexpr bool kInnerBallPair = InnerBall<A>::kMay || InnerBall<B>::kMay;

/// Whether balls inside the cores (InnerBall<A>, InnerBall<B>) prove the depth along the unit
/// normal of `least` (Newton's answer: its vertex a witness pair) within `tolerance` (unit:
/// length), with the points' offset across the normal within `witness_gap` (unit: length). One
/// support call along the normal (counted in `iterations`) gives h(n), the upper bound. Each core
/// offers its balls near its witness point, and the point itself (a ball of radius 0); a ball of
/// radius r_A about c_A in A and one of r_B about c_B in B put the ball of radius r_A + r_B about
/// c_A - c_B in A - B, which proves the depth at least r_A + r_B - |c_A - c_B|. The best pair is
/// the lower bound. On success `least` holds that support value, the normal and the points (a
/// rolling ball's core its support point, any other its witness point), and `lower` the proven
/// lower bound. The bracket alone allows an offset t with t^2 <= 2 (R - h) tolerance (6e-7 of the
/// size on a probe's box and ellipsoid 0.03 across, though Newton's steps left 2e-12), and the
/// points, shared along the normal, move by t / 2: on a box's edge, off the box at first order.
/// The gap is what Newton's witness pairs keep elsewhere (is_witness_pair()).
template <ConvexShape A, ConvexShape B>
bool inner_ball_proves_depth(const CoreDifference<A, B>& diff, typename A::Scalar tolerance,
                             typename A::Scalar witness_gap, int& iterations,
                             SupportMinimum<typename A::Scalar>& least, typename A::Scalar& lower) {
  using S = typename A::Scalar;
  const Vec3T<S> n = least.normal;
  SimplexVertexT<S> along;
  diff.support(n, along);
  ++iterations;
  const S upper = n.dot(along.w);
  // A's balls in A's frame; B's in B's, where its outward normal is -n, then taken to A's.
  CoreBall<S> balls_a[kMaxCoreBalls + 1], balls_b[kMaxCoreBalls + 1];
  const int count_a = InnerBall<A>::balls(diff.a, along.a, least.vertex.a, n, balls_a);
  const Mat3T<S>& r = diff.rotation;
  const int count_b =
      InnerBall<B>::balls(diff.b, Vec3T<S>(r.transpose() * (along.b - diff.translation)),
                          Vec3T<S>(r.transpose() * (least.vertex.b - diff.translation)),
                          diff.direction_in_b(n), balls_b);
  for (int i = 0; i < count_b; ++i) balls_b[i].centre = r * balls_b[i].centre + diff.translation;
  const Vec3T<S> a = rolls(diff.a) ? along.a : least.vertex.a;
  const Vec3T<S> b = rolls(diff.b) ? along.b : least.vertex.b;
  balls_a[count_a] = {S(0), a};
  balls_b[count_b] = {S(0), b};
  S proven = -std::numeric_limits<S>::infinity();
  for (int i = 0; i <= count_a; ++i)
    for (int j = 0; j <= count_b; ++j)
      proven = std::max(proven, balls_a[i].radius + balls_b[j].radius -
                                    length_of(Vec3T<S>(balls_a[i].centre - balls_b[j].centre)));
  const Vec3T<S> offset = a - b;
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
/// set on success. `newton_kept` receives the steps Newton's search kept (0: none ran or none
/// kept): on failure `least` then holds its answer, which contact() takes instead of searching
/// again from EPA's final normal when it is as deep as EPA's upper end.
template <ConvexShape A, ConvexShape B>
bool newton_proves_depth(const CoreDifference<A, B>& diff, typename A::Scalar size,
                         const TolerancesT<typename A::Scalar>& tol, int& iterations,
                         SupportMinimum<typename A::Scalar>& least, typename A::Scalar& lower,
                         int& newton_kept) {
  using S = typename A::Scalar;
  const S bracket = tol.relative * size, witness_gap = tol.relative_depth * size;
  SupportFeatureT<S> feature_a, feature_b;
  core_features(diff, least.normal, S(kInnerBallFaceReach) * size, feature_a, feature_b);
  // The balls that may touch there must reach as deep as EPA's upper end; else no proof. A
  // cylinder's side against a face (a cap's, a box's) is a facet of A - B, which EPA closes
  // exactly by itself; an ellipsoid's rolling ball proves it sooner.
  const auto touching = [](bool touches, bool rolling, const SupportFeatureT<S>& other) {
    return touches && (rolling || other.count < 3);
  };
  const bool touch_a = touching(InnerBall<A>::touches(diff.a, feature_a), rolls(diff.a), feature_b);
  const bool touch_b = touching(InnerBall<B>::touches(diff.b, feature_b), rolls(diff.b), feature_a);
  const S reach = (touch_a ? InnerBall<A>::reach(diff.a) : S(0)) +
                  (touch_b ? InnerBall<B>::reach(diff.b) : S(0));
  newton_kept = 0;
  if (!(least.value < reach)) return false;
  SupportMinimum<S> at_face = least;
  if (snap_to_face(diff, feature_a, feature_b, iterations, at_face) &&
      feature_witness(diff, size, iterations, at_face) &&
      inner_ball_proves_depth(diff, bracket, witness_gap, iterations, at_face, lower)) {
    least = at_face;
    return true;
  }
  newton_kept = newton_on_support(diff, size, tol.relative_depth * size, kNewtonMaxSteps,
                                  iterations, least, false);
  return inner_ball_proves_depth(diff, bracket, witness_gap, iterations, least, lower);
}

}  // namespace mink::detail
