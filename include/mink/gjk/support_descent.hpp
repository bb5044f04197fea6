/// @file support_descent.hpp
/// Descent on the support function of A - B over unit directions, from a given start.
///
/// h(u), the support value of A - B along the unit u, has the same minimum for both answers a
/// query can give: minus the distance when the shapes are apart (the minimiser is the normal from
/// A to B) and the penetration depth when they overlap (the minimiser is the contact normal).
/// GJK and EPA bracket that minimum between a lower bound and the least h seen; where their
/// brackets stay open (curved cores at the rounding floor, a circle of equally good normals around
/// the axis of coaxial cones, cylinders or spheroids), this descent brings the upper end down.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/gjk/gjk.hpp"

namespace mink::detail {

/// The least support value seen, its unit direction and its support point.
template <class S>
struct SupportMinimum {
  S value = std::numeric_limits<S>::infinity();
  Vec3T<S> normal = Vec3T<S>::UnitZ();
  SimplexVertexT<S> vertex{Vec3T<S>::Zero(), Vec3T<S>::Zero(), Vec3T<S>::Zero(), Vec3T<S>::Zero()};

  /// Keeps h, measured along the unit n with support point w, when it is the least so far.
  void offer(S h, const Vec3T<S>& n, const SimplexVertexT<S>& w) {
    if (h < value) {
      value = h;
      normal = n;
      vertex = w;
    }
  }
};

/// Lowers `best` (its value must be h(best.normal), its vertex that support point) by descent
/// along great circles, stopping when a circle gains at most `gain_tol`, when `iterations`
/// reaches `max_iterations` (each support call counts one), or on non-finite arithmetic. `lower`
/// is a lower bound on min h; it sets the first step. Returns false on non-finite arithmetic
/// (`best` then holds the last finite answer).
///
/// h is convex and positively homogeneous, its gradient the support point s, so along
/// u(t) = cos t u + sin t v the slope is s(u(t)) . u'(t). The minimum on a circle is bracketed by
/// the sign of the slope and found where the support planes of the bracket's ends cross
/// (safeguarded by bisection), which is exact at a kink of h (a cone's rim, where its slope
/// jumps), alternating with the secant of the slope, which is fast on a smooth minimum. At a kink
/// the next circle follows the valley: its direction is minus the least combination of the
/// gradients on either side (a bundle of two), not the one-sided gradient, which would only
/// zigzag across.
template <ConvexShape A, ConvexShape B>
bool descend_support(const CoreDifference<A, B>& diff, typename A::Scalar lower,
                     typename A::Scalar gain_tol, int max_iterations, int& iterations,
                     SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  bool have_other = false;  // a support point across the kink the last circle ended at
  Vec3T<S> other = Vec3T<S>::Zero();
  while (iterations < max_iterations) {
    const Vec3T<S> u = best.normal;
    Vec3T<S> gradient = best.vertex.w - u.dot(best.vertex.w) * u;  // tangential part
    if (have_other) {
      const Vec3T<S> across = other - u.dot(other) * u - gradient;
      const S aa = across.squaredNorm();
      if (aa > S(0)) gradient += std::clamp(-gradient.dot(across) / aa, S(0), S(1)) * across;
    }
    const S slope = gradient.norm();
    if (!(slope > S(0))) return true;
    const Vec3T<S> v = -gradient / slope;
    // The minimum on the circle is within t = 2 (value - lower) / slope: at a kink h rises from
    // there at the slope at least, on a smooth minimum the drop is at most that.
    S lo = S(0), hi = std::min(S(2) * (best.value - lower) / slope, S(0.5));
    if (!(hi > S(0))) return true;
    Vec3T<S> s_lo = best.vertex.w, s_hi = Vec3T<S>::Zero();
    S slope_lo = -slope, slope_hi = S(0);
    bool bracketed = false;
    int trials = 0;
    const S start = best.value;
    while (iterations < max_iterations && (hi - lo) * slope > gain_tol) {
      S t = hi;
      if (bracketed) {
        // Alternately where the planes of s_lo and s_hi cross, (s_lo - s_hi) . u(t) = 0, and
        // where the slope's secant is zero; bisection when either falls near an end.
        if (++trials % 2) {
          const Vec3T<S> jump = s_lo - s_hi;
          t = std::atan2(-jump.dot(u), jump.dot(v));
        } else {
          t = lo + (hi - lo) * (-slope_lo / (slope_hi - slope_lo));
        }
        const S margin = (hi - lo) / S(16);
        if (!(t > lo + margin && t < hi - margin)) t = (lo + hi) / S(2);
      }
      // Normalised: when the gradient is tiny next to the support point (a needle touching a
      // face), its rounding tilts v off u by far more than eps, and |d| would drift from 1.
      const Vec3T<S> d = (std::cos(t) * u + std::sin(t) * v).normalized();
      SimplexVertexT<S> w;
      diff.support(d, w);
      ++iterations;
      const S h = d.dot(w.w);
      if (!(std::abs(h) <= std::numeric_limits<S>::max())) return false;
      best.offer(h, d, w);
      const S slope_t = w.w.dot(std::cos(t) * v - std::sin(t) * u);
      if (slope_t < S(0)) {  // still descending at t
        lo = t;
        s_lo = w.w;
        slope_lo = slope_t;
        if (!bracketed) hi = std::min(hi * S(4), S(1.5));
        if (!bracketed && hi >= S(1.5)) break;
      } else {
        hi = t;
        s_hi = w.w;
        slope_hi = slope_t;
        bracketed = true;
      }
    }
    // The bracket's end that is not the best point lies across the minimum from it.
    have_other = bracketed;
    other = best.vertex.w == s_hi ? s_lo : s_hi;
    if (!(start - best.value > gain_tol)) return true;  // this circle gained nothing: a minimum
  }
  return true;
}

}  // namespace mink::detail
