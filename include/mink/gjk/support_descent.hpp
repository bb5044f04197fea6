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

  /// Measures h along the unit n (one support call of `diff`, counted in `iterations`) and
  /// offers it.
  template <class Difference>
  void measure(const Difference& diff, const Vec3T<S>& n, int& iterations) {
    SimplexVertexT<S> w;
    diff.support(n, w);
    ++iterations;
    offer(n.dot(w.w), n, w);
  }

  /// The least so far of a search started at the unit n: its support point, one support call
  /// counted in `iterations`.
  template <class Difference>
  static SupportMinimum at(const Difference& diff, const Vec3T<S>& n, int& iterations) {
    SupportMinimum least;
    least.measure(diff, n, iterations);
    return least;
  }
};

/// Points a (of A's core) and b (of B's core) along the unit n moved so that a - b = depth n
/// (depth < 0: apart by -depth), what is left of a - b - depth n shared evenly between them.
/// Returns the length of that residual.
template <class S>
S share_residual(Vec3T<S>& a, Vec3T<S>& b, const Vec3T<S>& n, S depth) {
  const Vec3T<S> half = S(0.5) * (a - b - depth * n);
  a -= half;
  b += half;
  return S(2) * half.norm();
}

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
/// zigzag across. After a circle that ended on a smooth minimum the next one takes the conjugate
/// direction (nonlinear conjugate gradients, Polak-Ribiere), which steepest descent would also
/// only zigzag towards down a long smooth valley.
template <ConvexShape A, ConvexShape B>
bool descend_support(const CoreDifference<A, B>& diff, typename A::Scalar lower,
                     typename A::Scalar gain_tol, int max_iterations, int& iterations,
                     SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  bool have_other = false;  // a support point across the kink the last circle ended at
  Vec3T<S> other = Vec3T<S>::Zero();
  // smooth: the last circle gained and ended on a smooth minimum, not at a kink; its direction
  // and gradient, carried along it to its best point, then give the conjugate direction.
  bool smooth = false;
  Vec3T<S> previous_direction = Vec3T<S>::Zero(), previous_gradient = Vec3T<S>::Zero();
  while (iterations < max_iterations) {
    const Vec3T<S> u = best.normal;
    Vec3T<S> gradient = part_across(best.vertex.w, u);  // tangential part
    const bool bundled = have_other;
    if (have_other) {
      const Vec3T<S> across = part_across(other, u) - gradient;
      const S aa = across.squaredNorm();
      if (aa > S(0)) gradient += std::clamp(-gradient.dot(across) / aa, S(0), S(1)) * across;
    }
    if (!(gradient.squaredNorm() > S(0))) return true;
    // Steepest descent zigzags down a long valley (an ellipsoid's minimum, whose curvatures
    // differ 1e3-fold) and spent the whole budget there; the conjugate direction (Polak-Ribiere,
    // restarted at kinks and whenever it stops descending) walks down it in a few circles.
    Vec3T<S> direction = -gradient;
    if (smooth) {
      const S beta = std::max(
          S(0), gradient.dot(gradient - previous_gradient) / previous_gradient.squaredNorm());
      const Vec3T<S> conjugate = direction + beta * previous_direction;
      const Vec3T<S> tangent = part_across(conjugate, u);
      if (std::isfinite(beta) && tangent.dot(gradient) < S(0)) direction = tangent;
    }
    const S direction_length = direction.norm();
    const Vec3T<S> v = direction / direction_length;
    const S slope = -gradient.dot(v);  // > 0: h falls at this rate along v
    if (!(slope > S(0))) return true;
    // The minimum on the circle is within t = 2 (value - lower) / slope: at a kink h rises from
    // there at the slope at least, on a smooth minimum the drop is at most that.
    S lo = S(0), hi = std::min(S(2) * (best.value - lower) / slope, S(0.5));
    if (!(hi > S(0))) return true;
    Vec3T<S> s_lo = best.vertex.w, s_hi = Vec3T<S>::Zero();
    S slope_lo = -slope, slope_hi = S(0);
    bool bracketed = false;
    int trials = 0;
    const S start = best.value;
    S t_best = S(0), h_lo = start;
    // The bracket is narrowed until what is left of it could gain at most gain_tol; on a smooth
    // minimum (the slope changes little across the bracket) a thousandth of what the circle has
    // gained is enough, as the next circle goes on from there. A kink must be pinned down.
    auto narrow_enough = [&] {
      const S left = (hi - lo) * slope;
      return left <= gain_tol || (bracketed && slope_hi - slope_lo <= S(0.25) * slope &&
                                  left <= S(1e-3) * (start - best.value));
    };
    while (iterations < max_iterations && !narrow_enough()) {
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
      if (h < best.value) t_best = t;
      best.offer(h, d, w);
      const S slope_t = w.w.dot(std::cos(t) * v - std::sin(t) * u);
      // Still descending at t, and lower than at lo: else a minimum lies between them (h on a
      // circle is not convex: past a hump, a tiny slope's first step lands descending again).
      if (slope_t < S(0) && h < h_lo) {
        lo = t;
        h_lo = h;
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
    // The circle ended at a kink when the slope still jumps across its final bracket by a good
    // part of the starting slope, and by more than a smooth h allows: its second derivative along
    // a circle, the radius of curvature of A - B minus h, is at most the diameter of A - B, which
    // the support points bound (4 |w| with room to spare).
    const S jump = slope_hi - slope_lo;
    const S diameter = S(4) * std::sqrt(std::max(s_lo.squaredNorm(), s_hi.squaredNorm()));
    smooth = !(bracketed && jump > S(0.25) * slope && jump > diameter * (hi - lo));
    if (!(start - best.value > gain_tol)) {
      // Nothing gained: a minimum, unless the bundle has not been tried across the bracket yet.
      // (A point inside a cylinder, nearer its side: the minimum lies on the kink circle where
      // the support jumps from one rim to the other, and the first circle ends on it at once.)
      if (!have_other || bundled) return true;
      smooth = false;
      continue;
    }
    // Carried to the best point along the circle, v turns into cos t v - sin t u; the part of
    // the gradient across the circle stays as it is.
    const Vec3T<S> v_there = std::cos(t_best) * v - std::sin(t_best) * u;
    const S along = gradient.dot(v);
    previous_direction = direction_length * v_there;
    previous_gradient = gradient - along * v + along * v_there;
  }
  return true;
}

}  // namespace mink::detail
