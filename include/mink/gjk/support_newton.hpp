/// @file support_newton.hpp
/// Newton's method on the support function of A - B over unit directions, for the normal of a
/// smooth minimum.
///
/// Why: on curved cores GJK and EPA stop when the value h(u) of the support function of A - B is
/// within their tolerance of its minimum (the distance's negative, or the depth). Near a smooth
/// minimum h rises as the square of the angle, so the normal, and with it the support points that
/// are the witness points, is then known only to the square root of that tolerance: 1e-6 to 1e-5
/// rad, the points off the exact ones by that times the radius of curvature.
///
/// How: in the plane tangent to the sphere of directions at u (unit t1, t2), h(u + x1 t1 + x2 t2)
/// normalised has gradient g_i = t_i . s(u) (s the support point) and Hessian
/// H_ij = t_i . ds/dx_j - h(u) delta_ij, where ds/dx_j is taken by a forward difference of the
/// support point along t_j. The step -H^{-1} g lands within the Hessian's relative error of the
/// minimiser (a forward difference of 1e-7 rad: about 1e-7), so one or two steps bring the normal
/// from 1e-5 rad to the rounding. Where the minimum lies on a kink of h (a capsule or cylinder on
/// its side, where its support point jumps from one end of its axis to the other) the difference
/// is no Hessian; secant steps along the kink take over (secant_on_kink()). A step is kept only
/// when it leaves h within its rounding or lowers it, and the answer only when its points are a
/// witness pair (newton_on_support()), so it never makes the answer worse.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/math/orthogonal.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"

namespace mink {
class Shape;
}

namespace mink::detail {

/// Cores whose support function is smooth somewhere (cylinders, cones, ellipsoids, and sums and
/// rounded shapes holding one; a run-time Shape may be such a sum): the pairs whose normals the
/// Newton steps below refine. Polytopes, boxes, segments and points converge exactly already.
template <class T>
struct CurvedCore : std::false_type {};
template <class S>
struct CurvedCore<CylinderT<S>> : std::true_type {};
template <class S>
struct CurvedCore<ConeT<S>> : std::true_type {};
template <class S>
struct CurvedCore<EllipsoidT<S>> : std::true_type {};
template <class T>
struct CurvedCore<Rounded<T>> : std::bool_constant<CurvedCore<T>::value> {};
template <class X, class Y>
struct CurvedCore<MinkowskiSum<X, Y>>
    : std::bool_constant<CurvedCore<X>::value || CurvedCore<Y>::value> {};
template <>
struct CurvedCore<Shape> : std::true_type {};

template <class A, class B>
inline constexpr bool kCurvedPair = CurvedCore<A>::value || CurvedCore<B>::value;

/// A minimum on a kink of h: where one core's support point jumps across an edge of A - B (a
/// capsule or cylinder lying on its side: the support jumps from one end of its axis to the
/// other), the minimum lies on the circle of directions orthogonal to that edge, and h is smooth
/// along it. `edge`: the jump's direction, first estimate. The edge is measured again at each
/// point by two support calls straddling the circle by 1e-9 rad, the point is moved onto the
/// circle, and secant steps on the slope of h along the circle find its zero. `best` only
/// improves; returns whether it did.
template <ConvexShape A, ConvexShape B>
bool secant_on_kink(const CoreDifference<A, B>& diff, Vec3T<typename A::Scalar> edge,
                    typename A::Scalar size, int& iterations,
                    SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  const S straddle = std::max(S(1e-9), S(64) * kEps);
  V u = best.normal;
  bool have_previous = false, improved = false;
  S previous_slope = S(0);
  V previous_u = u;
  for (int step = 0; step < 6; ++step) {
    SimplexVertexT<S> plus, minus;
    diff.support(unit_of(V(u + straddle * edge)), plus);
    diff.support(unit_of(V(u - straddle * edge)), minus);
    iterations += 2;
    const V jump = plus.w - minus.w;
    // No jump left across the circle (its length against what a smooth h moves by): no kink.
    if (!(jump.norm() > S(64) * straddle * size)) break;
    edge = unit_of(jump);
    u = unit_of(V(u - u.dot(edge) * edge));
    const V along = unit_of(V(edge.cross(u)));
    // On the circle both sides give the same value and slope (along is orthogonal to the jump).
    const V mean = S(0.5) * (plus.w + minus.w);
    const S h = u.dot(mean), slope = along.dot(mean);
    const S rounding = S(16) * kEps * mean.cwiseAbs().maxCoeff();
    if (std::isfinite(h) && h <= best.value + rounding) {
      // The witness pair is on the edge between the two sides' support points, where A - B's
      // point lies along u (its part along the edge is 0): not either end.
      const S along_edge = std::clamp(-jump.dot(minus.w) / jump.squaredNorm(), S(0), S(1));
      best.value = h;
      best.normal = u;
      best.vertex.a = minus.a + along_edge * (plus.a - minus.a);
      best.vertex.b = minus.b + along_edge * (plus.b - minus.b);
      best.vertex.w = best.vertex.a - best.vertex.b;
      best.vertex.dir = u;
      improved = true;
    }
    if (!(std::abs(slope) > rounding)) break;
    // The next point: by the secant of the slope along the circle, or a first probe of 1e-7 rad.
    S turn = slope > S(0) ? S(-1e-7) : S(1e-7);
    if (have_previous) {
      const S moved = (u - previous_u).dot(along);
      const S change = slope - previous_slope;
      if (std::abs(change) > S(0) && std::abs(moved) > S(0)) turn = -slope * moved / change;
    }
    if (!(std::abs(turn) <= S(1e-2))) break;
    previous_u = u;
    previous_slope = slope;
    have_previous = true;
    u = unit_of(V(std::cos(turn) * u + std::sin(turn) * along));
  }
  return improved;
}

/// The steps of newton_on_support(), without its check of the witness pair.
template <ConvexShape A, ConvexShape B>
int newton_steps(const CoreDifference<A, B>& diff, typename A::Scalar size, int max_steps,
                 int& iterations, SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  // The forward difference's step (radians): its error is about the step, its rounding
  // eps / step; 1e-7 in double balances them at a relative 1e-7, the square root of eps in float.
  const S delta = std::max(S(1e-7), std::sqrt(kEps));
  int kept = 0;
  for (int step = 0; step < max_steps; ++step) {
    const V u = best.normal;
    const V& s = best.vertex.w;
    const V t1 = unit_of(V(orthogonal(u).cross(u)));
    const V t2 = u.cross(t1);
    const S g1 = t1.dot(s), g2 = t2.dot(s);
    const S rounding = S(16) * kEps * s.cwiseAbs().maxCoeff();
    const S gradient = std::hypot(g1, g2);
    if (!(gradient > rounding)) break;
    SimplexVertexT<S> w1, w2;
    diff.support(unit_of(V(u + delta * t1)), w1);
    diff.support(unit_of(V(u + delta * t2)), w2);
    iterations += 2;
    // A smooth h moves the support point by at most delta times the diameter of A - B.
    const V jump1 = w1.w - s, jump2 = w2.w - s;
    const S smooth = S(4) * delta * size;
    if (jump1.norm() > smooth || jump2.norm() > smooth) {
      if (secant_on_kink(diff, jump1.norm() >= jump2.norm() ? jump1 : jump2, size, iterations,
                         best))
        ++kept;
      break;
    }
    // The support point's derivative along t_j, and the Hessian, symmetrised.
    const V d1 = jump1 / delta, d2 = jump2 / delta;
    const S h11 = t1.dot(d1) - best.value, h22 = t2.dot(d2) - best.value;
    const S h12 = S(0.5) * (t1.dot(d2) + t2.dot(d1));
    const S det = h11 * h22 - h12 * h12;
    // A minimum has a positive definite Hessian, and a Newton step from near it is short. Else
    // (a capsule on its side: h is smooth here, the minimum is on the kink where the capsule's
    // support jumps to its other end, 1e-5 rad on, where EPA's tolerance left the normal) the
    // kink is looked for downhill, at 1e-6 to 1e-3 rad.
    const S x1 = -(h22 * g1 - h12 * g2) / det, x2 = -(h11 * g2 - h12 * g1) / det;
    if (!(h11 > S(0) && det > S(0) && std::isfinite(det) && std::hypot(x1, x2) <= S(1e-2))) {
      const V downhill = -(g1 * t1 + g2 * t2) / gradient;
      for (S reach = S(1e-6); reach <= S(1e-3); reach *= S(10)) {
        SimplexVertexT<S> w;
        diff.support(unit_of(V(u + reach * downhill)), w);
        ++iterations;
        if ((w.w - s).norm() > S(4) * reach * size) {
          if (secant_on_kink(diff, V(w.w - s), size, iterations, best)) ++kept;
          break;
        }
      }
      break;
    }
    const V n = unit_of(V(u + x1 * t1 + x2 * t2));
    SimplexVertexT<S> w;
    diff.support(n, w);
    ++iterations;
    const S h = n.dot(w.w);
    const S gradient_after = (w.w - h * n).norm();
    if (!std::isfinite(h) || !(h <= best.value + rounding) || !(gradient_after < gradient)) break;
    best.value = h;
    best.normal = n;
    best.vertex = w;
    ++kept;
  }
  return kept;
}

/// Newton steps on h from `best` (its value must be h(best.normal), its vertex that support
/// point), at most `max_steps`, each 3 support calls (counted in `iterations`); `size` bounds
/// the radii of curvature of A - B (the sum of the bounding radii). A step across a kink (the
/// support point jumps by more than a smooth h allows) hands over to secant_on_kink(). `best`
/// only improves, and only to a vertex that is a witness pair: its points' offset
/// vertex.w - value normal across the normal within `witness_gap` (unit: length). A flat face's
/// support point is one corner of it, not the point of contact: such an answer is dropped and
/// `best` left as it came. Returns the number of steps kept (0 when dropped).
template <ConvexShape A, ConvexShape B>
int newton_on_support(const CoreDifference<A, B>& diff, typename A::Scalar size,
                      typename A::Scalar witness_gap, int max_steps, int& iterations,
                      SupportMinimum<typename A::Scalar>& best) {
  const SupportMinimum<typename A::Scalar> start = best;
  const int kept = newton_steps(diff, size, max_steps, iterations, best);
  if (kept > 0 && !((best.vertex.w - best.value * best.normal).norm() <= witness_gap)) {
    best = start;
    return 0;
  }
  return kept;
}

}  // namespace mink::detail
