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
#include <type_traits>

#include "mink/gjk/flat_pair.hpp"
#include "mink/gjk/gjk.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/manifold/feature.hpp"
#include "mink/math/orthogonal.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/point.hpp"
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

/// Which cores' support points jump between `plus` and `minus`, taken on either side of a kink
/// of h: by more than `smooth`, what a smooth core's point moves by between the two directions.
template <class S>
struct KinkSides {
  bool a_jumps, b_jumps;
  KinkSides(const SimplexVertexT<S>& plus, const SimplexVertexT<S>& minus, S smooth)
      : a_jumps((plus.a - minus.a).norm() > smooth), b_jumps((plus.b - minus.b).norm() > smooth) {}
  bool one() const { return a_jumps != b_jumps; }
};

/// The edge of A - B that `plus` and `minus` straddle, oriented from minus to plus. When only
/// one core's point jumps, that core's own jump: A - B's also holds the other core's smooth
/// motion, which tilts the edge by that motion over the edge's length (6e-8 rad for an edge of
/// 2e-7 beside a core of 1e-6 turned by 1e-7 rad), and puts the circle of directions orthogonal
/// to it that far off.
template <class S>
Vec3T<S> kink_edge(const SimplexVertexT<S>& plus, const SimplexVertexT<S>& minus, S smooth) {
  const KinkSides<S> sides(plus, minus, smooth);
  // B's point is taken along the opposite direction: its jump runs against A - B's.
  if (sides.one()) return sides.a_jumps ? Vec3T<S>(plus.a - minus.a) : Vec3T<S>(minus.b - plus.b);
  return plus.w - minus.w;
}

/// The rounding of support values u . w at support point `w`: of its cores' points, from whose
/// difference w was rounded, not of w itself, which is small where the cores nearly touch or
/// overlap slightly: a Newton step whose value came out 2.8e-17 higher, within the 1e-16
/// rounding of its cores' points, was refused against w's own 3e-17, and the normal, its
/// witness pair refused in turn, left 6e-5 rad off.
template <class S>
S support_rounding(const SimplexVertexT<S>& w) {
  return S(16) * std::numeric_limits<S>::epsilon() *
         std::max(
             {w.a.cwiseAbs().maxCoeff(), w.b.cwiseAbs().maxCoeff(), w.w.cwiseAbs().maxCoeff()});
}

/// The weight t in [0, 1] of the point from + t (to - from) nearest `target` (from != to).
template <class S>
S nearest_weight(const Vec3T<S>& from, const Vec3T<S>& to, const Vec3T<S>& target) {
  const Vec3T<S> edge = to - from;
  return std::clamp((target - from).dot(edge) / edge.squaredNorm(), S(0), S(1));
}

/// The witness pair on the kink between `plus` and `minus`, taken on either side of it close
/// by: on the jumping core, the point of its edge where A - B's point has no part along the
/// edge (not either end); on a smooth core, the mean of its two points, its support point on
/// the kink to second order. Interpolating the smooth core's points with the edge's weight
/// instead moved them across the normal by that weight's distance from 1/2 times their
/// straddle (2.5e-10 for an ellipsoid's points 1.3e-9 apart, beyond the witness tolerance).
template <class S>
SimplexVertexT<S> kink_witness(const SimplexVertexT<S>& plus, const SimplexVertexT<S>& minus,
                               S smooth) {
  const KinkSides<S> sides(plus, minus, smooth);
  SimplexVertexT<S> out = minus;
  if (sides.one() && sides.a_jumps) {
    out.b = S(0.5) * (plus.b + minus.b);
    out.a = minus.a + nearest_weight(minus.a, plus.a, out.b) * (plus.a - minus.a);
  } else if (sides.one()) {
    out.a = S(0.5) * (plus.a + minus.a);
    out.b = minus.b + nearest_weight(minus.b, plus.b, out.a) * (plus.b - minus.b);
  } else {
    // Both jump: the point of A - B's edge nearest the origin, and each core's at its weight.
    const S t = nearest_weight(minus.w, plus.w, Vec3T<S>::Zero().eval());
    out.a = minus.a + t * (plus.a - minus.a);
    out.b = minus.b + t * (plus.b - minus.b);
  }
  out.w = out.a - out.b;
  return out;
}

/// A minimum on a kink of h: where one core's support point jumps across an edge of A - B (a
/// capsule or cylinder lying on its side: the support jumps from one end of its axis to the
/// other), the minimum lies on the circle of directions orthogonal to that edge, and h is smooth
/// along it. `edge`: the jump's direction, first estimate (kink_edge()); the start is first
/// moved onto its circle, as the kink may lie further from it than the straddle below. The edge
/// is measured again at each point by two support calls straddling the circle by 1e-9 rad, the
/// point is moved onto the circle, and secant steps on the slope of h along the circle find its
/// zero; 3 support calls a step. `best` only improves; returns whether it did.
template <ConvexShape A, ConvexShape B>
bool secant_on_kink(const CoreDifference<A, B>& diff, Vec3T<typename A::Scalar> edge,
                    typename A::Scalar size, int& iterations,
                    SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  const S straddle = std::max(S(1e-9), S(64) * kEps);
  edge = unit_of(edge);
  V u = unit_of(V(best.normal - best.normal.dot(edge) * edge));
  if (!is_finite(u)) return false;
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
    edge = unit_of(kink_edge(plus, minus, S(4) * straddle * size));
    u = unit_of(V(u - u.dot(edge) * edge));
    const V along = unit_of(V(edge.cross(u)));
    // On the circle both sides give the same value and slope (along is orthogonal to the jump).
    const V mean = S(0.5) * (plus.w + minus.w);
    const S slope = along.dot(mean);
    const S rounding = support_rounding(plus);
    // The value is measured at u itself: on a kink it is the sides' common one, but where the
    // jump crossed a face of A - B rather than an edge (a curved core against a polytope's face)
    // u . mean is a point inside the face, below h(u) by the tilt of u off the face's normal
    // times the face's width (9e-12 of a depth taken as the contact's), and no kink is here.
    SimplexVertexT<S> at;
    diff.support(u, at);
    ++iterations;
    const S h = u.dot(at.w);
    if (!(h <= u.dot(mean) + rounding)) break;
    if (std::isfinite(h) && h <= best.value + rounding) {
      best.value = h;
      best.normal = u;
      best.vertex = kink_witness(plus, minus, S(4) * straddle * size);
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

/// A kink of h ahead of `best` along the unit tangent `ahead`: the normal turned that way by
/// 1e-6 rad, then ten times as far up to `reach`, until the support point jumps further than a
/// smooth core's turns (kink_edge()); secant_on_kink() then finds the minimum on it. Returns
/// whether `best` improved.
template <ConvexShape A, ConvexShape B>
bool kink_ahead(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& ahead,
                typename A::Scalar reach, typename A::Scalar size, int& iterations,
                SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  for (S turn = S(1e-6); turn <= reach; turn *= S(10)) {
    SimplexVertexT<S> w;
    diff.support(unit_of(Vec3T<S>(best.normal + turn * ahead)), w);
    ++iterations;
    if ((w.w - best.vertex.w).norm() > S(4) * turn * size)
      return secant_on_kink(diff, kink_edge(w, best.vertex, S(4) * turn * size), size, iterations,
                            best);
  }
  return false;
}

/// How far in from the rim, as a fraction of its radius, the other core's point may be seen along
/// a cap's axis for newton_about_axis() to look for a rim contact. Not only beyond the rim: with
/// the normal 3e-7 rad off, that point moves by as much times its core's radius, and a cylinder's
/// cap tilted 2.9e-9 rad from the normal, whose rim point 0.087 away was the contact, was seen
/// 2.4e-8 inside its rim and left alone (the points 1.9e-7 of the size off; stop 62's curved
/// probe, c11_1521). The answer must be a witness pair no higher, so a wider reach only costs
/// support calls.
inline constexpr double kRimContactReach = 0.5;

/// The most Newton steps newton_about_axis() takes: each squares the error near the minimum, and
/// three take the azimuth from 1e-1 off to rounding; a start 1e3 times too near or far from the
/// axis takes three more.
inline constexpr int kAxisNewtonMaxSteps = 12;

/// Newton's method on h in polar coordinates about the unit `axis` of a cap (a cylinder's or
/// cone's flat face, of radius `rim_radius`, whose rim holds one core's support point):
/// u = cos(psi) axis + sin(psi) (cos(phi) e1 + sin(phi) e2). Seen from psi off its axis the rim's
/// point turns 1 / sin(psi) as fast as the normal, and h's Hessian in Cartesian steps changes
/// across a step itself: from 1e-7 rad off the axis, eight steps converged linearly and left the
/// normal 8e-7 rad off, the rim point 1e-7 of the size off the contact (a flat rounded cylinder's
/// rim against a cone's at 1e6; stop 62's curved probe, c11_2416). In (phi, psi) the rim's point
/// moves with phi alone, at the rim's radius, and h is smooth: the slopes of h along phi (over
/// sin(psi)) and psi are the parts of the support point w across u, w . t and w . e_psi, whose
/// zero is the minimum. The start: phi where the rim faces `toward` (the other core's point from
/// the cap's centre, seen along the axis; over the cap's inner part, kRimContactReach, there is
/// no rim contact), psi as
/// `best.normal` has it (within 0.1 rad of the axis). Each step solves the slopes' Jacobian by
/// forward differences (1e-7 in phi, at most psi / 16 in psi, that side of the axis; float's
/// sqrt(eps) for 1e-7), and takes them to rounding in two or three steps near the minimum. `best`
/// moves only to a witness pair (its points' offset across the normal within `witness_gap`, unit:
/// length) whose value is no higher; 4 to 9 support calls a step (counted in `iterations`).
/// Returns whether `best` moved.
template <ConvexShape A, ConvexShape B>
bool newton_about_axis(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& axis,
                       const Vec3T<typename A::Scalar>& toward, typename A::Scalar rim_radius,
                       typename A::Scalar witness_gap, int& iterations,
                       SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  V e1, e2;
  plane_basis(axis, e1, e2);
  const S x = best.normal.dot(e1), y = best.normal.dot(e2);
  S psi = std::atan2(std::hypot(x, y), best.normal.dot(axis));
  if (!(psi <= S(0.1))) return false;
  // The other core's point seen along the axis well inside the rim: a face contact, no rim's.
  const S tx = toward.dot(e1), ty = toward.dot(e2);
  if (!(std::hypot(tx, ty) > (S(1) - S(kRimContactReach)) * rim_radius)) return false;
  S phi = std::atan2(ty, tx);
  psi = std::max(psi, S(1e-9));
  struct Polar {
    V u;
    SimplexVertexT<S> w;
    S along_phi, along_psi;  // w . t, w . e_psi: h's slopes, the first over sin(psi)
  };
  const auto at = [&](S phi_at, S psi_at) {
    const S c = std::cos(phi_at), s = std::sin(phi_at);
    const V radial = c * e1 + s * e2;
    Polar p;
    p.u = unit_of(V(std::cos(psi_at) * axis + std::sin(psi_at) * radial));
    diff.support(p.u, p.w);
    ++iterations;
    p.along_phi = p.w.w.dot(V(c * e2 - s * e1));
    p.along_psi = p.w.w.dot(V(std::cos(psi_at) * radial - std::sin(psi_at) * axis));
    return p;
  };
  const auto slope = [](const Polar& p) { return std::hypot(p.along_phi, p.along_psi); };
  // The forward differences' step, as newton_steps()'s: 1e-7 in double, sqrt(eps) in float.
  const S delta = std::max(S(1e-7), std::sqrt(std::numeric_limits<S>::epsilon()));
  Polar here = at(phi, psi);
  for (int step = 0; step < kAxisNewtonMaxSteps; ++step) {
    if (!(slope(here) > support_rounding(here.w))) break;
    const S d_phi = delta, d_psi = std::min(delta, psi / S(16));
    const Polar turned = at(phi + d_phi, psi), tilted = at(phi, psi + d_psi);
    const S j11 = (turned.along_phi - here.along_phi) / d_phi,
            j21 = (turned.along_psi - here.along_psi) / d_phi;
    const S j12 = (tilted.along_phi - here.along_phi) / d_psi,
            j22 = (tilted.along_psi - here.along_psi) / d_psi;
    const S det = j11 * j22 - j12 * j21;
    const S step_phi = -(j22 * here.along_phi - j12 * here.along_psi) / det;
    const S step_psi = -(j11 * here.along_psi - j21 * here.along_phi) / det;
    if (!std::isfinite(step_phi) || !std::isfinite(step_psi)) break;
    // psi changes by at most 16 times a step, taken as it comes: where the step would take it
    // further, the model holds at the scale of psi only (the minimum, say 2e-6 rad off the axis,
    // is reached from 3e-9 or 5e-3 rad in three steps). Else the step is halved until the slopes
    // shrink.
    const S ratio = S(1) + step_psi / psi;
    if (!(ratio >= S(1) / S(16) && ratio <= S(16))) {
      psi = std::min(psi * std::clamp(ratio, S(1) / S(16), S(16)), S(0.1));
      phi += step_phi;
      here = at(phi, psi);
      continue;
    }
    bool moved = false;
    for (S part = S(1); !moved && part >= S(1) / S(32); part *= S(0.5)) {
      const S next_psi = std::min(psi + part * step_psi, S(0.1));
      const Polar next = at(phi + part * step_phi, next_psi);
      if (slope(next) < slope(here)) {
        phi += part * step_phi;
        psi = next_psi;
        here = next;
        moved = true;
      }
    }
    if (!moved) break;
  }
  const S h = here.u.dot(here.w.w);
  if (!(std::isfinite(h) && h <= best.value + support_rounding(here.w) &&
        (here.w.w - h * here.u).norm() <= witness_gap))
    return false;
  best.value = h;
  best.normal = here.u;
  best.vertex = here.w;
  best.vertex.dir = here.u;
  return true;
}

/// Newton steps that distance() and contact() allow (newton_on_support()). One or two reach the
/// rounding from GJK's or EPA's normal where h is curved alike all round, and the steps stop
/// there. Where one core's point turns 1e5 times faster than the normal (a rim seen from 1e-5 rad
/// off its axis), the Hessian changes along the step itself and the steps converge linearly at
/// first: five to seven from 1e-5 rad (three had left the rim point up to 7e-6 of the size off).
inline constexpr int kNewtonMaxSteps = 8;

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
    V t1, t2;
    plane_basis(u, t1, t2);
    const S g1 = t1.dot(s), g2 = t2.dot(s);
    const S rounding = support_rounding(best.vertex);
    const S gradient = std::hypot(g1, g2);
    if (!(gradient > rounding)) break;
    SimplexVertexT<S> w1, w2;
    diff.support(unit_of(V(u + delta * t1)), w1);
    diff.support(unit_of(V(u + delta * t2)), w2);
    iterations += 2;
    // A smooth h moves the support point by at most delta times the diameter of A - B.
    const V jump1 = w1.w - s, jump2 = w2.w - s;
    const S smooth = S(4) * delta * size;
    // The support point's derivative along t_j, for the Hessian below.
    V d1 = jump1 / delta, d2 = jump2 / delta;
    bool stiff = false;  // the point turns much faster than the normal (see below)
    if (jump1.norm() > smooth || jump2.norm() > smooth) {
      // A kink's jump keeps its length as the turn shrinks; a smooth core's shrinks with it. Its
      // radius of curvature may well exceed the size: a cylinder's rim seen from 0.07 rad off its
      // axis curves with r / 0.07 along the rim, and was taken for a kink, which left the normal
      // at EPA's 1e-5 rad.
      const bool first = jump1.norm() >= jump2.norm();
      const SimplexVertexT<S>& across = first ? w1 : w2;
      const S central = delta / S(16);
      SimplexVertexT<S> closer;
      diff.support(unit_of(V(u + central * (first ? t1 : t2))), closer);
      ++iterations;
      if ((closer.w - s).norm() > S(0.25) * (across.w - s).norm()) {
        if (secant_on_kink(diff, kink_edge(across, best.vertex, smooth), size, iterations, best))
          ++kept;
        break;
      }
      // Smooth, but curved far more tightly than the size: a rim seen from near its cap's
      // normal (6e-6 rad off it, its radius of curvature r / 6e-6), whose point turns as fast as
      // the normal does over its distance from the axis. A forward difference then measures the
      // Hessian delta / 6e-6 off, in the direction along the rim as well as in size, where the
      // Hessian is nearly singular (the other core's curvature is 1e-4 of the rim's): the error
      // made it indefinite, no step was taken, and the rim point stayed 4e-8 of the size off the
      // contact. Central differences leave the square of their spacing over that angle instead.
      // The two jumps measure the angle: over delta the derivative changes by delta / angle of
      // itself, so the long jump differs from 16 short ones by that much. A spacing of 1e-4 of
      // the angle (delta / 16 was still too coarse below 1e-5 rad from the axis) rounds to 1e-12
      // of the derivative, the support points' rounding over a jump of r / angle times it.
      const S bend = (S(16) * (closer.w - s) - (across.w - s)).norm() / (across.w - s).norm();
      // A short jump far from a sixteenth of the long one is no such curve: a kink between the
      // two (a capsule's side against a sum's slant 2e-7 rad from parallel, whose short jump was
      // 0), which the forward difference's step handles as before.
      if (bend <= S(0.5)) {
        const S spacing = std::min(central, S(1e-4) * delta / bend);
        SimplexVertexT<S> ahead1, back1, ahead2, back2;
        diff.support(unit_of(V(u + spacing * t1)), ahead1);
        diff.support(unit_of(V(u - spacing * t1)), back1);
        diff.support(unit_of(V(u + spacing * t2)), ahead2);
        diff.support(unit_of(V(u - spacing * t2)), back2);
        iterations += 4;
        d1 = (ahead1.w - back1.w) / (S(2) * spacing);
        d2 = (ahead2.w - back2.w) / (S(2) * spacing);
        stiff = true;
      }
    }
    // The Hessian, symmetrised.
    const S h11 = t1.dot(d1) - best.value, h22 = t2.dot(d2) - best.value;
    const S h12 = S(0.5) * (t1.dot(d2) + t2.dot(d1));
    const S det = h11 * h22 - h12 * h12;
    // A minimum has a positive definite Hessian, and a Newton step from near it is short. Else
    // (a capsule on its side: h is smooth here, the minimum is on the kink where the capsule's
    // support jumps to its other end, 1e-5 rad on, where EPA's tolerance left the normal) the
    // kink is looked for downhill, at 1e-6 to 1e-3 rad.
    const S x1 = -(h22 * g1 - h12 * g2) / det, x2 = -(h11 * g2 - h12 * g1) / det;
    if (!(h11 > S(0) && det > S(0) && std::isfinite(det) && std::hypot(x1, x2) <= S(1e-2))) {
      if (kink_ahead(diff, V(-(g1 * t1 + g2 * t2) / gradient), S(1e-3), size, iterations, best))
        ++kept;
      break;
    }
    const S turn = std::hypot(x1, x2);
    SimplexVertexT<S> full, w;
    V n;
    S h = S(0), gradient_after = S(0);
    const auto try_step = [&](S part) {
      n = unit_of(V(u + part * (x1 * t1 + x2 * t2)));
      diff.support(n, w);
      ++iterations;
      h = n.dot(w.w);
      gradient_after = (w.w - h * n).norm();
      return std::isfinite(h) && h <= best.value + rounding && gradient_after < gradient;
    };
    bool improved = try_step(S(1));
    full = w;
    // Where the support point turns fast, the Hessian holds over a fraction of the angle to the
    // rim's axis only, and a step can overshoot past the axis (1.5e-6 rad from a rim 1e-6 rad
    // off its axis): shorter steps in the same direction.
    for (S part = S(0.25); stiff && !improved && part >= S(1) / S(256); part *= S(0.25))
      improved = try_step(part);
    if (!improved) {
      // The step crossed a kink: the Hessian was one side's, whose minimum lies beyond the kink,
      // and the minimum is on the kink itself (a curved core against a polyhedral one's edge).
      // Where the support point jumped further than the turn moves a smooth one, the jump shows
      // the kink; else it is looked for along the step: a cylinder's side line (3.6e3 long, at
      // 1.8e6) against a capsule's end, 6e-7 rad beyond GJK's normal, drew a step of 5e-3 rad
      // whose jump was no longer than a smooth core's over that turn, and the normal stayed 6e-7
      // rad off, the points 2.4e-7 of the size off the contact.
      if (is_finite(full.w) && (full.w - s).norm() > S(4) * turn * size) {
        if (secant_on_kink(diff, kink_edge(full, best.vertex, S(4) * turn * size), size, iterations,
                           best))
          ++kept;
      } else if (kink_ahead(diff, V((x1 * t1 + x2 * t2) / turn), turn, size, iterations, best)) {
        ++kept;
      }
      break;
    }
    best.value = h;
    best.normal = n;
    best.vertex = w;
    ++kept;
  }
  return kept;
}

/// How far below the support plane a point of the other core's feature may lie when the witness
/// is placed in it (a fraction of the size): the bar of the answers' accuracy, so a placed point
/// lies within it of the face's plane.
inline constexpr double kFeatureWitnessTolerance = 1e-9;

/// Whether `target` lies in the support feature `f` (in a core's frame, mapped to A's by
/// `rotation`, `translation`) seen along unit `u`, to `tolerance` (unit: length): inside its face
/// (a cap's whole disc), on its edge or at its corner. The features (manifold/feature.hpp) are
/// every core's exact face, edge or corner, the sum of its parts' for a sum: their points are
/// points of the core, so containment proves that `target`, on the support plane, is one too.
template <class S>
bool in_feature(const SupportFeatureT<S>& f, const Mat3T<S>& rotation, const Vec3T<S>& translation,
                const Vec3T<S>& u, const Vec3T<S>& target, S tolerance) {
  using V = Vec3T<S>;
  if (f.count < 1) return false;
  V points[kMaxFeaturePoints];
  for (int i = 0; i < f.count; ++i) points[i] = rotation * f.points[i] + translation;
  if (f.count == 1) return part_across(V(target - points[0]), u).norm() <= tolerance;
  if (f.count == 2) {
    const V edge = part_across(V(points[1] - points[0]), u),
            to = part_across(V(target - points[0]), u);
    if (!(edge.squaredNorm() > S(0))) return to.norm() <= tolerance;
    return (to - nearest_weight<S>(V::Zero(), edge, to) * edge).norm() <= tolerance;
  }
  const V normal = rotation * f.normal;
  if (f.is_cap()) {
    // A cap: the target moved along u onto the cap's plane lies within the rim.
    const V centre = rotation * f.disc_centre + translation;
    const S along = normal.dot(u);
    if (!(std::abs(along) > S(0.5))) return false;
    const V on_plane = target + (normal.dot(V(centre - target)) / along) * u;
    return (on_plane - centre).norm() <= f.disc_radius + tolerance;
  }
  if (f.is_stadium()) {
    // A cap swept along a segment: likewise, within its radius of the segment. Its polygon
    // cuts the round ends' chords: a point on them lay outside it, and an ellipsoid touching a
    // cone's base swept by a segment kept EPA's points, 1e-6 of the size off.
    const V from = rotation * f.stadium_ends[0] + translation;
    const V to = rotation * f.stadium_ends[1] + translation;
    const S along = normal.dot(u);
    if (!(std::abs(along) > S(0.5))) return false;
    const V on_plane = target + (normal.dot(V(from - target)) / along) * u;
    const V segment = to - from, offset = on_plane - from;
    const S t = segment.squaredNorm() > S(0) ? nearest_weight<S>(V::Zero(), segment, offset) : S(0);
    return (offset - t * segment).norm() <= f.stadium_radius + tolerance;
  }
  // The polygon runs counter-clockwise about its normal: the target is on the inner side of
  // every edge, seen along u.
  const S side = normal.dot(u) >= S(0) ? S(1) : S(-1);
  for (int i = 0; i < f.count; ++i) {
    const V edge = points[i + 1 == f.count ? 0 : i + 1] - points[i];
    if (side * edge.cross(V(target - points[i])).dot(u) < -tolerance * edge.norm()) return false;
  }
  return true;
}

/// The support features of both cores along unit `u` (A's frame; B's is along -u), each within
/// `tolerance` (unit: length) of its support plane, in the cores' own frames.
template <ConvexShape A, ConvexShape B>
void core_features(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& u,
                   typename A::Scalar tolerance, SupportFeatureT<typename A::Scalar>& feature_a,
                   SupportFeatureT<typename A::Scalar>& feature_b) {
  support_feature_of(diff.a, u, tolerance, feature_a);
  support_feature_of(diff.b, Vec3T<typename A::Scalar>(diff.rotation.transpose() * -u), tolerance,
                     feature_b);
}

/// How far below the support plane a face may lie to be tried as the normal by snap_to_face()
/// (a fraction of the size): what EPA's or GJK's normal, good to the square root of their
/// tolerance (1e-5 rad), tilts a face of the size's width by.
inline constexpr double kFaceSnapReach = 1e-5;

/// How far below the support plane (a fraction of the size) a cap or stadium may lie for
/// newton_on_support() to try its rim when the steps end short of a witness pair: where h is
/// flat along such a rim (to 1e-15 over 2e-4 rad), GJK's normal and the steps end up to 1e-3
/// rad off, and the face lies that much below the plane.
inline constexpr double kFaceFacingReach = 1e-3;

/// Moves `best` to the normal of a face of either core near it (within kFaceSnapReach of the
/// size of the support plane) when the support value there is no higher, to rounding. A face's
/// normal is a kink of h in every direction, which neither Newton's steps nor the secant along
/// one kink reach: a cylinder's rim pressed into a cone's base (at 1e6) kept EPA's normal,
/// 2.1e-8 rad off the base's, where the base no longer counts as a face to 1e-9 of the size, and
/// the points 3.5e-8 of the size off the contact. Two edges, one on each core (a cone's side line
/// across a box's edge), are tried the same way at their common normal, where h has kinks
/// across both: EPA's normal stayed 1e-9 rad off it, and its points up to 1.3e-5 of the size
/// off the crossing. `feature_a` and `feature_b` are the cores' features along best.normal
/// within kFaceSnapReach of the size (core_features()). Up to two support calls (counted in
/// `iterations`); returns whether `best` moved.
template <ConvexShape A, ConvexShape B>
bool snap_to_face(const CoreDifference<A, B>& diff,
                  const SupportFeatureT<typename A::Scalar>& feature_a,
                  const SupportFeatureT<typename A::Scalar>& feature_b, int& iterations,
                  SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const V u = best.normal;
  V faces[2];
  int count = 0;
  if (feature_a.count >= 3) faces[count++] = unit_of(feature_a.normal);
  if (feature_b.count >= 3) faces[count++] = unit_of(V(-(diff.rotation * feature_b.normal)));
  if (feature_a.count == 2 && feature_b.count == 2) {
    const V across = (feature_a.points[1] - feature_a.points[0])
                         .cross(V(diff.rotation * (feature_b.points[1] - feature_b.points[0])));
    // Parallel edges have no common normal of their own: any normal of the pair's plane is one.
    const S sq = across.squaredNorm();
    if (sq > S(0)) {
      const V n = unit_of(across, sq, length_of(across, sq));
      faces[count++] = n.dot(u) < S(0) ? V(-n) : n;
    }
  }
  bool moved = false;
  for (int i = 0; i < count; ++i) {
    const V& n = faces[i];
    if (!is_finite(n) || !(n.dot(u) > S(0)) || n == best.normal) continue;
    SimplexVertexT<S> at;
    diff.support(n, at);
    ++iterations;
    const S h = n.dot(at.w);
    if (std::isfinite(h) && h <= best.value + support_rounding(at)) {
      best.value = h;
      best.normal = n;
      best.vertex = at;
      best.vertex.dir = n;
      moved = true;
    }
  }
  return moved;
}

/// snap_to_face() with the features taken here.
template <ConvexShape A, ConvexShape B>
bool snap_to_face(const CoreDifference<A, B>& diff, typename A::Scalar size, int& iterations,
                  SupportMinimum<typename A::Scalar>& best) {
  SupportFeatureT<typename A::Scalar> feature_a, feature_b;
  core_features(diff, best.normal, typename A::Scalar(kFaceSnapReach) * size, feature_a, feature_b);
  return snap_to_face(diff, feature_a, feature_b, iterations, best);
}

/// How far the normal may turn (rad) when witness_beside_single_point() keeps a curved core's
/// point just outside the other's feature.
inline constexpr double kOutsideTurn = 1e-11;

/// The radius of curvature (unit: length) of the core that has a single point on its support
/// plane along unit `u` (A when `single_a`; `at` is that support pair), along the unit `away`
/// across u: how far its support point moves along `away` for a turn of the direction towards
/// it, measured by two turns, of 2^-20 and 2^-19 rad (two support calls, counted in
/// `iterations`). 0 where the point does not move in proportion to the turn: a corner or an
/// edge's end, which stays or jumps.
template <ConvexShape A, ConvexShape B>
typename A::Scalar curvature_radius_along(const CoreDifference<A, B>& diff, bool single_a,
                                          const Vec3T<typename A::Scalar>& u,
                                          const Vec3T<typename A::Scalar>& away,
                                          const SimplexVertexT<typename A::Scalar>& at,
                                          int& iterations) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  // B's support point is taken along -u: it moves towards `away` as -u turns towards it.
  const S turn = std::ldexp(S(1), -20) * (single_a ? S(1) : S(-1));
  SimplexVertexT<S> once, twice;
  diff.support(unit_of(V(u + turn * away)), once);
  diff.support(unit_of(V(u + S(2) * turn * away)), twice);
  iterations += 2;
  const V base = single_a ? at.a : at.b;
  const S moved_once = away.dot(V((single_a ? once.a : once.b) - base));
  const S moved_twice = away.dot(V((single_a ? twice.a : twice.b) - base));
  if (!(moved_once > S(0)) || !(std::abs(moved_twice - S(2) * moved_once) <= S(0.25) * moved_once))
    return S(0);
  return moved_once / std::abs(turn);
}

/// feature_witness()'s pair where one core has a single point on its support plane along unit
/// `u` (smooth or strictly convex there, or a corner) and the other does not (a face or an edge,
/// whose support point is one of its corners, not the point of contact): `pair` (the support
/// point along u, `value` its support value) keeps the single point, and the other core's point
/// is placed from it by the value along u, onto that core's support plane, and kept only where
/// it lies in that core's support feature there (in_feature()), a proof that it is a point of
/// that core. `size`: the sum of the bounding radii. Returns whether `pair` holds the witness
/// pair.
///
/// A curved single point just outside the feature (by less than its radius of curvature along
/// the way out, curvature_radius_along(), times kOutsideTurn; two support calls, counted in
/// `iterations`) is kept: were the contact truly beyond the outline, at its rim or edge, the
/// normal would turn by that distance over the radius, at most kOutsideTurn, and the points
/// move by at most that distance. Far from the origin the inputs' rounding alone puts such a
/// point out: 1e-13 outside a swept cone's base at 1.7e3, where the points fell back to EPA's,
/// 1e-6 of the size off. A corner, whose radius is 0, gets no such slack: beside a face's edge
/// the normal may turn by any angle.
template <ConvexShape A, ConvexShape B>
bool witness_beside_single_point(const CoreDifference<A, B>& diff,
                                 const SupportFeatureT<typename A::Scalar>& feature_a,
                                 const SupportFeatureT<typename A::Scalar>& feature_b,
                                 const Vec3T<typename A::Scalar>& u, typename A::Scalar value,
                                 typename A::Scalar size, int& iterations,
                                 SimplexVertexT<typename A::Scalar>& pair) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const S tolerance = S(4) * support_rounding(pair);
  const bool single_a = feature_a.count == 1;
  if (single_a)
    pair.b = pair.a - value * u;
  else
    pair.a = pair.b + value * u;
  const auto inside = [&](S within) {
    return single_a
               ? in_feature<S>(feature_b, diff.rotation, diff.translation, u, V(pair.b), within)
               : in_feature<S>(feature_a, Mat3T<S>::Identity(), V::Zero(), u, V(pair.a), within);
  };
  if (inside(tolerance)) return true;
  // No radius of curvature above 64 sizes (an ellipsoid's reaches its radii's ratio squared
  // times its size) is counted: most points that miss, miss by more, and cost no support call.
  const S most = S(64) * size;
  if (!inside(tolerance + S(kOutsideTurn) * most)) return false;
  // Towards the placed point from the middle of the feature it missed: the way out.
  const SupportFeatureT<S>& missed = single_a ? feature_b : feature_a;
  V middle = V::Zero();
  for (int i = 0; i < missed.count; ++i) middle += missed.points[i];
  middle /= S(missed.count);
  if (single_a) middle = diff.rotation * middle + diff.translation;
  const V out = part_across(V((single_a ? pair.b : pair.a) - middle), u);
  const S out_length = out.norm();
  if (!(out_length > S(0))) return false;
  const S radius = curvature_radius_along(diff, single_a, u, V(out / out_length), pair, iterations);
  const S slack = S(kOutsideTurn) * std::min(radius, most);
  return slack > S(0) && inside(tolerance + slack);
}

/// feature_witness()'s pair where both cores show an edge on their support planes along unit
/// `u` (a cone's side line across a box's edge) and the edges cross seen along u: the point of
/// each edge at the crossing, kept only when the two lie on one line along u and their offset
/// along it is `value`, the support value there, both to the rounding of their coordinates: a
/// proof that they are points of their cores' edges on the support planes. Returns whether
/// `pair` holds the witness pair.
template <ConvexShape A, ConvexShape B>
bool witness_at_crossing(const CoreDifference<A, B>& diff,
                         const SupportFeatureT<typename A::Scalar>& feature_a,
                         const SupportFeatureT<typename A::Scalar>& feature_b,
                         const Vec3T<typename A::Scalar>& u, typename A::Scalar value,
                         SimplexVertexT<typename A::Scalar>& pair) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const CoreSegment<S> edge_a{S(0.5) * (feature_a.points[0] + feature_a.points[1]),
                              S(0.5) * (feature_a.points[1] - feature_a.points[0])};
  const CoreSegment<S> edge_b{
      diff.rotation * (S(0.5) * (feature_b.points[0] + feature_b.points[1])) + diff.translation,
      diff.rotation * (S(0.5) * (feature_b.points[1] - feature_b.points[0]))};
  // The edges seen along u: the closest points of their shadows are at the crossing, and their
  // parameters place the points on the edges themselves.
  const CoreSegment<S> shadow_a{part_across(edge_a.centre, u), part_across(edge_a.half, u)};
  const CoreSegment<S> shadow_b{part_across(edge_b.centre, u), part_across(edge_b.half, u)};
  V seen_a, seen_b;
  S s = S(0), t = S(0);
  closest_points_of_segments(shadow_a, shadow_b, seen_a, seen_b, &s, &t);
  pair.a = edge_a.centre + s * edge_a.half;
  pair.b = edge_b.centre + t * edge_b.half;
  pair.w = pair.a - pair.b;
  const S tolerance = S(4) * support_rounding(pair);
  // And the edges themselves must lie along their planes, u orthogonal to both: a capsule's
  // axis tilted 4e-9 rad off its plane, crossing a cylinder's side line 3e-7 from its end, put
  // its point there only 1e-15 below the plane, though the minimum lies at the end, in its own
  // directions (newton_at_end()), and the points were 3e-9 of the size off.
  const S level = S(1e4) * std::numeric_limits<S>::epsilon();
  return is_finite(pair.w) && part_across(pair.w, u).norm() <= tolerance &&
         std::abs(u.dot(pair.w) - value) <= tolerance &&
         std::abs(u.dot(edge_a.half)) <= level * edge_a.half.norm() &&
         std::abs(u.dot(edge_b.half)) <= level * edge_b.half.norm();
}

/// The witness pair along `best.normal` from the cores' exact support features there
/// (manifold/feature.hpp, within kFeatureWitnessTolerance of the size of the support plane):
///   - one core has a single point there and the other does not: that point and its shift onto
///     the other's plane (witness_beside_single_point()). Probes turning the normal by 1e-7 rad
///     six ways (used before the features) took a rim seen within 1e-7 rad of its axis for a
///     face, its support point jumping round the rim;
///   - both show an edge (a cone's or cylinder's side line across a box's edge or another side
///     line): where the edges cross (witness_at_crossing());
///   - both show a face or an edge, nearly parallel (a cylinder's cap on a box, tilted 1e-9 rad):
///     the deepest point of their overlap (gjk/flat_pair.hpp), when the depth varies over it by
///     more than rounding.
/// GJK's and EPA's points are combinations of support points from several directions: beside a
/// face, the curved core's are a chord below its surface, and the face's point lay off the
/// contact by the chord's tilt (2e-7 of the size, with the normal exact to 1e-13); at crossing
/// edges, combinations of the edges' ends, up to 1.3e-5 of the size off. One support call
/// (counted in `iterations`) and two features; returns whether `best.vertex` changed.
template <ConvexShape A, ConvexShape B>
bool feature_witness(const CoreDifference<A, B>& diff, typename A::Scalar size, int& iterations,
                     SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  const Vec3T<S> u = best.normal;
  SupportFeatureT<S> feature_a, feature_b;
  core_features(diff, u, S(kFeatureWitnessTolerance) * size, feature_a, feature_b);
  const bool single = (feature_a.count == 1) != (feature_b.count == 1);
  const bool flat = feature_a.count >= 2 && feature_b.count >= 2;
  if (!single && !flat) return false;
  SimplexVertexT<S> pair;
  diff.support(u, pair);
  ++iterations;
  const S value = u.dot(pair.w);
  if (!std::isfinite(value) || !is_finite(pair.w)) return false;
  if (single) {
    if (!witness_beside_single_point(diff, feature_a, feature_b, u, value, size, iterations, pair))
      return false;
  } else if (!(feature_a.count == 2 && feature_b.count == 2 &&
               witness_at_crossing(diff, feature_a, feature_b, u, value, pair))) {
    // Faces or edges nearly parallel: the deepest point of their overlap, when the depth
    // varies over it by more than rounding and that point is within the features' tolerance of
    // the support value (with an exact normal, it is the value).
    SimplexVertexT<S> deepest = pair;
    if (!flat_pair_witness<S>(feature_a, feature_b, diff.rotation, diff.translation, u,
                              S(4) * support_rounding(pair), deepest.a, deepest.b) ||
        !(value - u.dot(Vec3T<S>(deepest.a - deepest.b)) <= S(kFeatureWitnessTolerance) * size))
      return false;
    pair = deepest;
  }
  pair.w = pair.a - pair.b;
  pair.dir = u;
  best.value = value;
  best.vertex = pair;
  return true;
}

/// Where two faces are nearly parallel and the normal came without Newton's steps (polytopes
/// after EPA or GJK, the axial planes): a face's normal within reach (snap_to_face()) and the
/// features' witness pair along it (feature_witness()). `best` starts at the unit `normal` (one
/// support call, and those of the two; counted in `iterations`). Returns whether `best` holds
/// the pair.
template <ConvexShape A, ConvexShape B>
bool witness_at_face(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& normal,
                     typename A::Scalar size, int& iterations,
                     SupportMinimum<typename A::Scalar>& best) {
  best = SupportMinimum<typename A::Scalar>::at(diff, normal, iterations);
  snap_to_face(diff, size, iterations, best);
  return feature_witness(diff, size, iterations, best);
}

/// Whether the points of `best` are a witness pair: their offset vertex.w - value normal across
/// the normal within `gap` (unit: length).
template <class S>
bool is_witness_pair(const SupportMinimum<S>& best, S gap) {
  return (best.vertex.w - best.value * best.normal).norm() <= gap;
}

/// Whether the pair of `best` lies its support value apart along its normal to rounding, so
/// that both points are on their surfaces: what polytopes ask of witness_at_face()'s pair.
template <class S>
bool pair_on_support_planes(const SupportMinimum<S>& best) {
  return is_witness_pair(best, S(4) * support_rounding(best.vertex));
}

/// Whether `candidate` (a pair, its unit normal and its value along it, found on a part of the
/// cores) may replace `best`: a witness pair within `witness_gap`, whose value is the full cores'
/// support value along its normal and no higher than best's, both to 4 roundings of that
/// support point. A pair on a part can sit below the full cores' support plane, where that part
/// is not the support along the normal. `full` gets the full support point (one support call,
/// counted in `iterations`, made only once the pair is a witness pair).
template <ConvexShape A, ConvexShape B>
bool is_full_support_witness(const CoreDifference<A, B>& diff,
                             const SupportMinimum<typename A::Scalar>& candidate,
                             typename A::Scalar witness_gap,
                             const SupportMinimum<typename A::Scalar>& best, int& iterations,
                             SimplexVertexT<typename A::Scalar>& full) {
  using S = typename A::Scalar;
  if (!is_witness_pair(candidate, witness_gap)) return false;
  diff.support(candidate.normal, full);
  ++iterations;
  const S tolerance = S(4) * support_rounding(full);
  const S h = candidate.normal.dot(full.w);
  return std::isfinite(h) && std::isfinite(candidate.value) &&
         std::abs(candidate.value - h) <= tolerance && candidate.value <= best.value + tolerance;
}

/// The witness pair along the unit `normal` where the cores touch or nearly do, which Newton's
/// steps leave alone (the normal is ill-conditioned there): when one core has a single point on
/// its support plane, that point and its shift onto the other core's plane, proved a point of it;
/// when both show an edge there, the edges' crossing (feature_witness()). Kept when they are
/// within `gap_limit` of each other along the normal (plus the rounding of their coordinates:
/// 3e-12 at 1e3 from the origin).
/// GJK's closest points are combinations of support points from several directions: beside a
/// face, a chord of the curved core 4e-7 of the size off the contact. Returns whether `on_a` and
/// `on_b` were set.
template <ConvexShape A, ConvexShape B>
bool touching_witness(const CoreDifference<A, B>& diff, const Vec3T<typename A::Scalar>& normal,
                      typename A::Scalar size, typename A::Scalar gap_limit, int& iterations,
                      Vec3T<typename A::Scalar>& on_a, Vec3T<typename A::Scalar>& on_b) {
  using S = typename A::Scalar;
  SupportMinimum<S> best;
  best.normal = normal;
  if (!feature_witness(diff, size, iterations, best) ||
      !(std::abs(best.value) <= gap_limit + S(4) * support_rounding(best.vertex)))
    return false;
  on_a = best.vertex.a;
  on_b = best.vertex.b;
  return true;
}

/// A flat disc about `centre` with unit `normal` (a cylinder's cap), in its core's frame: what a
/// side line's end on a rim stands for among that end's own directions (newton_at_end()).
template <class S>
struct DiscCore {
  using Scalar = S;
  Vec3T<S> centre, normal;
  S radius;
  Vec3T<S> support_core(const Vec3T<S>& d) const {
    const Vec3T<S> across = d - d.dot(normal) * normal;
    const S length = across.norm();
    return length > S(0) ? Vec3T<S>(centre + (radius / length) * across) : centre;
  }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return length_of(centre) + radius; }
  const char* error() const { return nullptr; }
};

/// Where a core's feature along the normal is an edge and the minimum lies just beyond one of
/// its ends, among the directions whose support is that end (a capsule's end beside a cone's
/// side line, their lines crossing 1e-6 beyond it): there h is flat to second order, the
/// support values' rounding let a pair 3.6e-8 rad off pass as one at the edges' crossing, and
/// the points stayed 5e-7 of the size off the contact (stop 62's curved probe, c11_2). Each end
/// is taken as a point against the other core, and where the end lies on the rim of a cap along
/// the edge (a cylinder's side line tilted 3e-8 rad off its plane, c11_521), as that cap: a
/// problem that Newton's steps solve to rounding. Its answer is kept only where the full core's
/// support along it is the reduced core's (a vertex, or the cap's rim point), the pair a witness
/// pair within `witness_gap` and h no higher than at `best`. `feature_a` and `feature_b` are
/// the cores' features along best.normal (core_features()). Support calls are counted in
/// `iterations`; returns whether `best` moved.
template <ConvexShape A, ConvexShape B>
bool newton_at_end(const CoreDifference<A, B>& diff,
                   const SupportFeatureT<typename A::Scalar>& feature_a,
                   const SupportFeatureT<typename A::Scalar>& feature_b, typename A::Scalar size,
                   typename A::Scalar witness_gap, int& iterations,
                   SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const S near = S(kFeatureWitnessTolerance) * size;
  // The full core's support must be the reduced core's point, not another beside it: to
  // rounding on a first pass over the ends, and to the answers' accuracy bar on a second pass
  // when none passed. An edge tilted 2.3e-6 rad from the support plane at 1e6 has support points
  // 1e-3 apart (6e-10 of the size) within its values' rounding, and its end, the exact contact,
  // was refused (stop 62's curved probe, c12_1172); a side line rising 1.5e-9 rad to its rim's
  // cap takes the cap on the first pass, whose normal the point's, 1.2e-9 rad off, would beat.
  bool strict = true;
  // The reduced problem keeps A's frame, so its pair is the full one's.
  const auto solve = [&](const auto& reduced, bool end_of_a) {
    SupportMinimum<S> r = SupportMinimum<S>::at(reduced, best.normal, iterations);
    newton_steps(reduced, size, kNewtonMaxSteps, iterations, r);
    SimplexVertexT<S> full, own;
    if (!is_full_support_witness(diff, r, witness_gap, best, iterations, full)) return false;
    reduced.support(r.normal, own);
    ++iterations;
    const S rounding = S(4) * support_rounding(full);
    if (!(V(end_of_a ? V(full.a - own.a) : V(full.b - own.b)).norm() <=
          (strict ? rounding : std::max(rounding, near))))
      return false;
    best = r;
    return true;
  };
  // The cap along the edge from `from` to the end `to` (the core's frame), when `to` is on its
  // rim: a cylinder's side line ends on its caps' rims; a cone's slant on its base's, which
  // does not lie along the slant and is left.
  const auto cap_at = [&](const auto& core, const V& from, const V& to, DiscCore<S>& disc) {
    SupportFeatureT<S> cap;
    support_feature_of(core, V(unit_of(V(to - from))), near, cap);
    if (!cap.is_cap()) return false;
    disc = {cap.disc_centre, unit_of(cap.normal), cap.disc_radius};
    const V offset = to - disc.centre;
    return std::abs(offset.norm() - disc.radius) <= near &&
           std::abs(offset.dot(disc.normal)) <= near;
  };
  // One core's ends at a time: `with` builds the reduced problem, a core in that one's place.
  const auto ends_of = [&](const SupportFeatureT<S>& feature, const auto& core, bool end_of_a,
                           const auto& with) {
    bool moved = false;
    for (int i = 0; feature.count == 2 && i < 2; ++i) {
      const V& end = feature.points[i];
      DiscCore<S> disc;
      if (solve(with(PointT<S>{end}), end_of_a) ||
          (cap_at(core, feature.points[1 - i], end, disc) && solve(with(disc), end_of_a)))
        moved = true;
    }
    return moved;
  };
  const auto both_cores = [&] {
    const bool moved_a = ends_of(feature_a, diff.a, true, [&](const auto& core) {
      return CoreDifference<std::decay_t<decltype(core)>, B>{core, diff.b, diff.rotation,
                                                             diff.translation};
    });
    const bool moved_b = ends_of(feature_b, diff.b, false, [&](const auto& core) {
      return CoreDifference<A, std::decay_t<decltype(core)>>{diff.a, core, diff.rotation,
                                                             diff.translation};
    });
    return moved_a || moved_b;
  };
  if (both_cores()) return true;
  strict = false;
  return both_cores();
}

/// Most Newton steps of rim_against_edge() on the rim's angle: each squares the error, and a start
/// where the edge's shadow crosses the rim is within the tilt's lever of the root.
inline constexpr int kRimEdgeMaxSteps = 16;

/// Most times rim_against_edge() takes the features again along its normal: a side line's place
/// round its core moves with the normal, by the normal's error times the core's radius (GJK's
/// normal put a cylinder's side line 5e-6 of the size off, and the rim's point with it). A rim
/// running nearly along the edge settles slowly: of 6,000 rim points against side lines
/// (CurvedKink.RimPointAgainstASideLine at 20 times its scenes), 47 failed with 6 rounds, 32 with
/// 16, and 15 once a nearly settled last round was tried too.
inline constexpr int kRimEdgeMaxRounds = 16;

/// Where one core's support feature along `best.normal` is a cap (or a single point on a cap's
/// rim: SupportFeatureT::rim_radius) and the other's an edge, and the contact is the rim against
/// the edge: a cap tilted
/// 1.5e-7 rad from a cylinder's side line, whose rim point is its support, left Newton's steps on
/// h at GJK's normal (h has kinks across both the edge and the cap's normal there) and the points
/// 7e-6 of the size off (stop 62's curved probe, c11_2318). The contact is a stationary pair of
/// the rim's point q(phi) and the edge's line: their offset d is normal to the edge and to the
/// rim's tangent t, so the normal is edge x t, and phi solves G(phi) = d . t = 0 (d the part of
/// the line's point minus q across the edge), by Newton's method with
/// G' = -r (1 - (t . edge)^2) - d . radial. A cap nearly parallel to the edge starts where the
/// edge's shadow along its axis crosses the rim (each crossing is tried), or where the rim is
/// nearest that shadow; a rim point starts at its own angle. The features are taken again along
/// each normal found (core_features(), within kFaceSnapReach of the size), up to
/// kRimEdgeMaxRounds times, until they stay; from the second round on, the next angle is the
/// secant's root of the round trip's change in angle. Kept only where the line's point
/// lies on the edge, the pair is a witness pair within `witness_gap` along edge x t, and the full
/// cores' support value there is the pair's, no higher than at `best`, all to rounding.
/// `disc_on_a`: the cap is A's (`feature_a`, the edge `feature_b`), else the reverse. Support
/// calls are counted in `iterations`; returns whether `best` moved.
template <ConvexShape A, ConvexShape B>
bool rim_against_edge(const CoreDifference<A, B>& diff,
                      const SupportFeatureT<typename A::Scalar>& feature_a,
                      const SupportFeatureT<typename A::Scalar>& feature_b, bool disc_on_a,
                      typename A::Scalar size, typename A::Scalar witness_gap, int& iterations,
                      SupportMinimum<typename A::Scalar>& best) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const S eps = std::numeric_limits<S>::epsilon();
  // The cap and the edge in A's frame.
  struct CapAndEdge {
    V centre, axis, e1, e2, p0, along;
    S radius, length;
    bool rim_point;  // the rim is known by one point on it (its cap does not face the normal)
    V point;         // that point
    int end;         // a stadium's round end whose rim this is (0 or 1)
  };
  const auto to_a = [&](const V& p, bool on_a) {
    return on_a ? p : V(diff.rotation * p + diff.translation);
  };
  // A stadium's round ends are half rims, each tried as a whole rim: the answer's acceptance
  // below (the full cores' support there) drops a point on the inner half.
  const auto take = [&](const SupportFeatureT<S>& disc, const SupportFeatureT<S>& edge, int end,
                        CapAndEdge& f) {
    const bool cap = disc.is_cap(), stadium = disc.is_stadium();
    f.rim_point = disc.is_rim_point();
    f.end = end;
    if (!(cap || stadium || f.rim_point) || edge.count != 2) return false;
    f.centre = to_a(cap       ? disc.disc_centre
                    : stadium ? disc.stadium_ends[end]
                              : disc.rim_centre,
                    disc_on_a);
    const V axis = cap || stadium ? disc.normal : disc.rim_axis;
    f.axis = unit_of(disc_on_a ? axis : V(diff.rotation * axis));
    f.radius = cap ? disc.disc_radius : stadium ? disc.stadium_radius : disc.rim_radius;
    f.point = to_a(disc.points[0], disc_on_a);
    f.p0 = to_a(edge.points[0], !disc_on_a);
    const V p1 = to_a(edge.points[1], !disc_on_a);
    f.length = (p1 - f.p0).norm();
    f.along = unit_of(V(p1 - f.p0));
    if (!(f.length > S(0)) || !is_finite(f.axis) || !is_finite(f.along)) return false;
    plane_basis(f.axis, f.e1, f.e2);
    return true;
  };
  const auto features = [&](const SupportFeatureT<S>& fa, const SupportFeatureT<S>& fb, int end,
                            CapAndEdge& f) {
    return disc_on_a ? take(fa, fb, end, f) : take(fb, fa, end, f);
  };
  const SupportFeatureT<S>& disc = disc_on_a ? feature_a : feature_b;
  const int rims = disc.is_stadium() ? 2 : 1;
  CapAndEdge firsts[2];
  V starts[4];  // rim directions, in A's frame, on the rim firsts[start_rim[i]]
  int start_rim[4];
  int start_count = 0;
  for (int rim = 0; rim < rims; ++rim) {
    CapAndEdge& first = firsts[rim];
    if (!features(feature_a, feature_b, rim, first)) return false;
    if (first.rim_point) {
      start_rim[start_count] = rim;
      starts[start_count++] = first.point - first.centre;
      continue;
    }
    // The edge's shadow on the cap's plane, about the centre: o + s k.
    const V from_centre = first.p0 - first.centre;
    const S ox = from_centre.dot(first.e1), oy = from_centre.dot(first.e2);
    const S kx = first.along.dot(first.e1), ky = first.along.dot(first.e2);
    const S kk = kx * kx + ky * ky;
    if (!(kk > S(0.25))) return false;  // the edge is not nearly parallel to the cap
    // Its nearest point to the centre, and where it crosses the rim.
    const S s_near = -(ox * kx + oy * ky) / kk;
    const S nx = ox + s_near * kx, ny = oy + s_near * ky;
    const S miss_sq = nx * nx + ny * ny;
    const S radius = first.radius;
    if (miss_sq < radius * radius) {
      const S half_chord = std::sqrt((radius * radius - miss_sq) / kk);
      for (const S sign : {S(-1), S(1)}) {
        const S s = s_near + sign * half_chord;
        start_rim[start_count] = rim;
        starts[start_count++] = (ox + s * kx) * first.e1 + (oy + s * ky) * first.e2;
      }
    } else {
      start_rim[start_count] = rim;
      starts[start_count++] = nx * first.e1 + ny * first.e2;
    }
  }
  // Newton's steps on phi for the features `f`, from the rim's angle `phi`; the root phi, the
  // rim's point q, its tangent t and the line's parameter s there.
  const auto solve = [&](const CapAndEdge& f, S& phi, V& q, V& t, S& s) {
    V radial, d;
    const auto at = [&](S angle) {
      radial = std::cos(angle) * f.e1 + std::sin(angle) * f.e2;
      t = f.axis.cross(radial);
      q = f.centre + f.radius * radial;
      const V to_line = f.p0 - q;
      d = to_line - to_line.dot(f.along) * f.along;
    };
    at(phi);
    for (int step = 0; step < kRimEdgeMaxSteps; ++step) {
      const S along_t = t.dot(f.along);
      const S slope = -f.radius * (S(1) - along_t * along_t) - d.dot(radial);
      const S change = d.dot(t) / slope;
      if (!std::isfinite(change)) return false;
      phi -= change;
      at(phi);
      if (std::abs(change) <= S(4) * eps) break;
    }
    s = (q - f.p0).dot(f.along);
    return true;
  };
  // The rim's tangent at its angle phi.
  const auto tangent_at = [](const CapAndEdge& f, S phi) {
    return V(f.axis.cross(V(std::cos(phi) * f.e1 + std::sin(phi) * f.e2)));
  };
  // The normal edge x t for the rim's tangent t, towards best's side, and the features along it.
  const auto features_at = [&](const CapAndEdge& f, const V& t, V& u, CapAndEdge& next) {
    u = unit_of(V(f.along.cross(t)));
    if (!is_finite(u)) return false;
    if (u.dot(best.normal) < S(0)) u = -u;
    SupportFeatureT<S> fa, fb;
    core_features(diff, u, S(kFaceSnapReach) * size, fa, fb);
    return features(fa, fb, f.end, next);
  };
  bool moved = false;
  for (int i = 0; i < start_count; ++i) {
    const CapAndEdge& first = firsts[start_rim[i]];
    CapAndEdge f = first;
    S phi_in = std::atan2(starts[i].dot(first.e2), starts[i].dot(first.e1));
    // The rim's angle phi_in gives the edge (along the normal there), the edge the root phi_out:
    // a fixed point phi_out(phi) = phi, which the plain round trip approaches by a factor that
    // can be near -1 (a cap turned 2.6e-3 rad from a side line: 0.9), so the next phi_in is the
    // secant's root of g = phi_out - phi_in through the last two rounds.
    S previous_in = S(0), previous_g = S(0);
    V q, t, u;
    S s = S(0);
    bool settled = false, nearly_settled = false;
    CapAndEdge solved_on = f;  // the features q, t, s and u belong to
    for (int round = 0; round < kRimEdgeMaxRounds && !settled; ++round) {
      S phi_out = phi_in;
      nearly_settled = false;
      if (!solve(f, phi_out, q, t, s)) break;
      CapAndEdge next;
      if (!features_at(f, t, u, next)) break;
      solved_on = f;
      const S reach = S(64) * eps *
                      std::max({f.centre.cwiseAbs().maxCoeff(), f.p0.cwiseAbs().maxCoeff(), size});
      const bool same_rim =
          (next.centre - f.centre).norm() <= reach && (next.axis - f.axis).norm() <= S(64) * eps;
      settled = same_rim && (next.p0 - f.p0).norm() <= reach &&
                (next.along - f.along).norm() <= S(64) * eps;
      // The root is known to G's rounding over its slope, small where the rim runs nearly along
      // the edge: a cap turned 3e-3 rad from a cone's side line gave roots 1e-12 rad apart from
      // round to round, the line turning with them, never within 64 eps. Where the rounds run
      // out, a last round that moved the line's point at the root by under 64 times that reach
      // is tried too (the acceptance below still decides); lines that jump by 4e-9 from round
      // to round (a rim rising 4e-3 rad from a side line) left normals 3e-9 rad off.
      const V moved_line = (next.p0 + s * next.along) - (f.p0 + s * f.along);
      nearly_settled = same_rim && moved_line.norm() <= S(64) * reach;
      if (settled) break;
      const S g = phi_out - phi_in;
      const S secant = round > 0 ? phi_in - g * (phi_in - previous_in) / (g - previous_g) : phi_out;
      previous_in = phi_in;
      previous_g = g;
      phi_in = phi_out;
      f = next;
      if (std::isfinite(secant) && secant != phi_out) {
        V along_secant;
        if (!features_at(next, tangent_at(next, secant), along_secant, f)) break;
        phi_in = secant;
      }
    }
    if (!settled && !nearly_settled) continue;
    f = solved_on;
    const S reach =
        S(64) * eps * std::max({q.cwiseAbs().maxCoeff(), f.p0.cwiseAbs().maxCoeff(), f.length});
    if (!(s >= -reach && s <= f.length + reach)) continue;
    const V on_line = f.p0 + std::clamp(s, S(0), f.length) * f.along;
    SupportMinimum<S> found;
    found.vertex.a = disc_on_a ? q : on_line;
    found.vertex.b = disc_on_a ? on_line : q;
    found.vertex.w = found.vertex.a - found.vertex.b;
    found.vertex.dir = u;
    found.normal = u;
    found.value = u.dot(found.vertex.w);
    SimplexVertexT<S> full;
    if (!is_full_support_witness(diff, found, witness_gap, best, iterations, full)) continue;
    best = found;
    moved = true;
  }
  return moved;
}

/// Newton steps on h from `best` (its value must be h(best.normal), its vertex that support
/// point), at most `max_steps`, each 3 or 4 support calls, up to 12 where the support point turns
/// much faster than the normal (counted in `iterations`); `size` is the sum of the bounding radii.
/// A step across a kink (the support point jumps, and by as much for a turn 16 times smaller)
/// hands over to secant_on_kink(). Steps that end without a witness pair beside one core's cap go
/// on about its axis (newton_about_axis()), and keep what they reach when it is one. Else a
/// face's normal nearby is tried (snap_to_face()), kept only with a witness pair along it. The
/// points come from the normal where one core is smooth and the other not, or where both show
/// edges that cross (feature_witness(), one support call and two features). `best` only
/// improves, and only to a vertex that is a witness pair: its points' offset vertex.w - value
/// normal across the normal within `witness_gap` (unit: length). A flat face's support point is
/// one corner of it, not the point of contact: an answer that keeps one is dropped; last, an
/// edge's end beside the minimum is tried as a point (newton_at_end(), up to 16 reduced
/// problems: not when `at_ends` is false), else `best` is left as it came (with its points from
/// its normal, as above). Returns the number of steps kept, the points' placing counting one (0
/// when nothing changed).
template <ConvexShape A, ConvexShape B>
int newton_on_support(const CoreDifference<A, B>& diff, typename A::Scalar size,
                      typename A::Scalar witness_gap, int max_steps, int& iterations,
                      SupportMinimum<typename A::Scalar>& best, bool at_ends = true) {
  using S = typename A::Scalar;
  const SupportMinimum<S> start = best;
  int kept = newton_steps(diff, size, max_steps, iterations, best);
  SupportFeatureT<S> feature_a, feature_b;
  core_features(diff, best.normal, S(kFaceSnapReach) * size, feature_a, feature_b);
  const bool cap_a = feature_a.is_cap() && feature_b.count < 3;
  const bool cap_b = feature_b.is_cap() && feature_a.count < 3;
  const bool stepped_to_witness = is_witness_pair(best, witness_gap);
  if (!stepped_to_witness) {
    // Short of the minimum beside one core's cap, its rim seen from near its axis
    // (newton_about_axis(); the rim's point at the minimum faces the other core's point seen
    // along the axis). A stadium's round end likewise (a cone's base swept by a segment, tilted
    // 9e-8 rad from a disc's rim point: EPA's points stayed 7e-5 of the size off). Both faces
    // nearly parallel are flat_pair_witness()'s; a polytope's face has no rim, and its corner
    // jumps with the azimuth.
    bool disc_tried = false;  // about_disc() reached newton_about_axis()
    const auto about_disc = [&](const SupportFeatureT<S>& fa, const SupportFeatureT<S>& fb,
                                SupportMinimum<S>& from) {
      Vec3T<S> centre;
      S radius;
      if (fb.count < 3 && fa.disc_towards(from.vertex.b, centre, radius)) {
        disc_tried = true;
        return newton_about_axis(diff, fa.normal, Vec3T<S>(from.vertex.b - centre), radius,
                                 witness_gap, iterations, from);
      }
      if (fa.count >= 3) return false;
      // In B's frame, where the cap's axis and the rim's point are exact: turned into A's, the
      // normal's rounding across the axis (1e-16) turned the rim's point by 1e-16 / psi and kept
      // the slopes from rounding 1e-7 rad off the axis.
      const Mat3T<S> back = diff.rotation.transpose();
      const CoreDifference<B, A> reversed{diff.b, diff.a, back, -(back * diff.translation)};
      SupportMinimum<S> mirrored = from;
      mirrored.normal = -(back * from.normal);
      mirrored.vertex.a = back * (from.vertex.b - diff.translation);
      mirrored.vertex.b = back * (from.vertex.a - diff.translation);
      mirrored.vertex.w = mirrored.vertex.a - mirrored.vertex.b;
      if (!fb.disc_towards(mirrored.vertex.b, centre, radius)) return false;
      disc_tried = true;
      if (!newton_about_axis(reversed, fb.normal, Vec3T<S>(mirrored.vertex.b - centre), radius,
                             witness_gap, iterations, mirrored))
        return false;
      from.value = mirrored.value;
      from.normal = unit_of(Vec3T<S>(-(diff.rotation * mirrored.normal)));
      from.vertex.a = diff.rotation * mirrored.vertex.b + diff.translation;
      from.vertex.b = diff.rotation * mirrored.vertex.a + diff.translation;
      from.vertex.w = from.vertex.a - from.vertex.b;
      from.vertex.dir = from.normal;
      return true;
    };
    if (about_disc(feature_a, feature_b, best)) return kept + 1;
    // A cap or stadium that faces the normal to within more than kFaceSnapReach: a rim's point
    // against a swept cone's round end tilted 7e-7 rad, where h is flat to 1e-15 over 2e-4 rad
    // and GJK's normal and Newton's steps stayed that far off, with the stadium's straight side
    // as its feature.
    // Only when the narrow features gave no disc to try: one that failed above fails again.
    if (!disc_tried) {
      SupportFeatureT<S> wide_a, wide_b;
      core_features(diff, best.normal, S(kFaceFacingReach) * size, wide_a, wide_b);
      if ((wide_a.count >= 3 || wide_b.count >= 3) && about_disc(wide_a, wide_b, best))
        return kept + 1;
    }
  }
  // A cap's rim, or a point on it, against the other core's edge (rim_against_edge()): its
  // answer is exact, where Newton's steps, at a witness pair too, leave the normal to the
  // square root of the rounding of h, flat to second order along the edge's kink (a cap turned
  // 2.6e-3 rad from a side line kept a normal 1.2e-9 rad off, the points 2.7e-8 of the size).
  const bool rim_a = cap_a || feature_a.is_rim_point() || feature_a.is_stadium();
  const bool rim_b = cap_b || feature_b.is_rim_point() || feature_b.is_stadium();
  if ((rim_a && feature_b.count == 2 &&
       rim_against_edge(diff, feature_a, feature_b, true, size, witness_gap, iterations, best)) ||
      (rim_b && feature_a.count == 2 &&
       rim_against_edge(diff, feature_a, feature_b, false, size, witness_gap, iterations, best)))
    return kept + 1;
  const bool beside_edge =
      !stepped_to_witness && !cap_a && !cap_b && (feature_a.count == 2 || feature_b.count == 2);
  // A face's normal (or two edges') is kept only with a witness pair along it: h is flat to
  // second order about a minimum, and two edges' common normal 6.6e-9 rad off it (a capsule's
  // axis rising that much from a cylinder's side line) came out no higher to rounding, where
  // their crossing lay beyond the capsule's end. The answer fell back to GJK's normal, 4e-9 rad
  // off, though Newton's steps had reached the minimum.
  const SupportMinimum<S> stepped = best;
  // best is still where the features were taken (newton_about_axis() and rim_against_edge()
  // move it only when they succeed).
  if (snap_to_face(diff, feature_a, feature_b, iterations, best)) {
    const bool placed = feature_witness(diff, size, iterations, best);
    if (is_witness_pair(best, witness_gap)) return kept + 1 + (placed ? 1 : 0);
    best = stepped;
  }
  if (feature_witness(diff, size, iterations, best)) ++kept;
  if (is_witness_pair(best, witness_gap)) return kept;
  // Last, from Newton's normal beside an edge, its ends as points (newton_at_end()).
  SupportMinimum<S> at_end = stepped;
  if (at_ends && beside_edge &&
      newton_at_end(diff, feature_a, feature_b, size, witness_gap, iterations, at_end)) {
    best = at_end;
    return kept + 1;
  }
  if (kept > 0) {
    best = start;
    return feature_witness(diff, size, iterations, best) ? 1 : 0;
  }
  return kept;
}

}  // namespace mink::detail
