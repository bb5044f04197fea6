/// @file corner_solid.hpp
/// The witness points of separated cores where one core's closest point is a corner (of a box, a
/// polytope, a sum of them, a cone's apex) and the other core has a closed-form nearest point
/// (query/point_solid.hpp: a box, cylinder, cone, ellipsoid, or a polytope with its face planes):
/// the corner and its nearest point on the solid, exact to rounding. Newton's steps on h leave the
/// normal 1e-6 rad off where the minimum lies a little beside a kink of h that they cannot cross:
/// a corner 2e-5 rad off a cone's base normal, beyond its rim by 7.5e-7 of the size, kept the
/// rim point 1.9e-8 of the size off the contact.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "mink/gjk/gjk.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/gjk/support_newton.hpp"
#include "mink/math/orthogonal.hpp"
#include "mink/query/point_solid.hpp"
#include "mink/support/core_terms.hpp"
#include "mink/support/shape.hpp"

namespace mink::detail {

/// How far (rad) the normal turns, four ways, in the test that a support point is a corner: the
/// point stays the support point over a disc of half that radius about the normal, which holds the
/// true normal when Newton's steps left it within 7e-4 rad of it.
inline constexpr double kCornerTurn = 1e-3;

/// The support points of `core` along `d` (unit, the core's frame) turned by kCornerTurn
/// towards each of +-u and +-v (u, v orthogonal to d) that differ from `point`, its support point
/// along d, each once, into `others`; returns how many. None: `point` is a corner whose normal
/// cone holds those four directions, and so the disc between them. A smooth or curved core's
/// point (an ellipsoid's, a rim's) moves; an edge's end point, whose edge is within the turn of
/// the support plane, changes to the other end; a face nearly facing d shows its other corners,
/// the one across from `point` only along the diagonals +-u +-v, which are asked too when the
/// first four found another point. Four support calls, or eight.
template <ConvexShape T>
int turned_support_points(const T& core, const Vec3T<typename T::Scalar>& d,
                          const Vec3T<typename T::Scalar>& point,
                          Vec3T<typename T::Scalar> (&others)[8]) {
  using S = typename T::Scalar;
  Vec3T<S> u, v;
  plane_basis(d, u, v);
  const S turn = S(kCornerTurn);
  const Vec3T<S> sides[8] = {turn * u,       -turn * u,      turn * v,        -turn * v,
                             turn * (u + v), turn * (u - v), turn * (-u + v), -turn * (u + v)};
  int count = 0;
  for (int i = 0; i < 8 && (i < 4 || count > 0); ++i) {
    const Vec3T<S> p = core.support_core(Vec3T<S>(d + sides[i]));
    if (p != point && std::find(others, others + count, p) == others + count) others[count++] = p;
  }
  return count;
}

/// Calls fn(std::type_identity<SolidCore<C>>{}, solid) with the closed-form solid of `shape`'s
/// core, where it has one: a SolidCore shape, or a run-time Shape of one such core (`mink query`
/// passes sums and whatever they meet as Shapes). Returns whether it did.
template <ConvexShape T, class Fn>
bool with_solid(const T& shape, Fn&& fn) {
  if constexpr (SolidCore<T>::value) {
    if (const auto* solid = SolidCore<T>::core(shape)) {
      fn(std::type_identity<SolidCore<T>>{}, *solid);
      return true;
    }
  } else if constexpr (std::is_same_v<T, Shape>) {
    if (shape.cores().size() == 1)
      return visit_core(shape.cores().front(),
                        [&](const auto& core) { return with_solid(core, fn); });
  }
  return false;
}

/// Primitive cores that may have a corner: a point whose normal cone has an inside. An
/// ellipsoid's normal cones are rays, a cylinder's rays or (on a rim) flat wedges, and a sum's are
/// the meets of its terms', so a sum with one of them has none either (every_term(),
/// support/core_terms.hpp): corner_solid_pair() does not look for a corner on them (for two
/// ellipsoids, that look was a third of distance()'s time, all of it in the nearest points of the
/// turned support points).
template <class T>
struct CornerCore : std::true_type {};
template <class S>
struct CornerCore<CylinderT<S>> : std::false_type {};
template <class S>
struct CornerCore<EllipsoidT<S>> : std::false_type {};

/// A corner of one core and its nearest point on the other, a solid, as witness points of cores
/// apart: A's point, B's point and the unit normal from A to B, in A's frame.
template <class S>
struct CornerSolidPair {
  Vec3T<S> on_a, on_b, normal;
  S distance;
};

/// `pair`, unless h, the support function of A - B, is higher along its normal than along
/// `at_normal`'s beyond rounding: the pair's direction is rounded when its points are a tiny gap
/// apart (a triangle's corner a tiny gap from a cone's slant turned the slant's exact normal by
/// 3e-7 rad, and h by 5e-8 of the size). One support call, counted in `iterations`.
template <ConvexShape A, ConvexShape B>
std::optional<CornerSolidPair<typename A::Scalar>> no_higher(
    const CoreDifference<A, B>& diff, const SupportMinimum<typename A::Scalar>& at_normal,
    std::optional<CornerSolidPair<typename A::Scalar>> pair, int& iterations) {
  using S = typename A::Scalar;
  SimplexVertexT<S> along_pair;
  diff.support(pair->normal, along_pair);
  ++iterations;
  const S h_pair = pair->normal.dot(along_pair.w);
  if (!(h_pair <= at_normal.value + support_rounding(along_pair))) return std::nullopt;
  return pair;
}

/// The witness pair of separated cores from `at_normal`, Newton's answer (its unit normal, A's
/// frame, from A to B, within 7e-4 rad of the true one, and h of A - B there, which no_higher()
/// compares with), when one core's support point along the normal is a corner
/// (turned_support_points() finds no other) and the other core is a solid with a closed-form
/// nearest point (with_solid()): the corner and its nearest point on the solid. Kept only when the
/// pair's direction stays within half kCornerTurn of the normal (so the corner is still the one
/// support point along it, and the pair proves its own distance: the corner's support plane and the
/// solid's, both normal to it, are that distance apart) and its distance is at most `upper` (GJK's
/// upper bound on the core distance) plus `slack`, and h along it is no higher than along the
/// normal (no_higher()). A support point that fails the corner test is tried too, and so are the
/// other points that the test's turned directions found (a face nearly facing the normal shows its
/// corners): a point's pair is kept when the core's support point along the pair's own direction is
/// that point (one more support call), the pair's direction within kCornerTurn of the normal: a
/// proof of its own, the point on its core's support plane and the solid's point on the solid's. A
/// box's face tilted 4e-7 rad from facing an ellipsoid has a corner as its support point, with the
/// face's normal 4e-7 rad from that corner's normal cone's edge: the test's disc does not fit,
/// Newton's normal may lie beside another corner, and the points stayed Newton's, 8e-8 of the size
/// off. Five support calls of a core for each side tried (nine where the point is no corner), one
/// more for each point tried without the corner test, one of A - B for a pair found, counted in
/// `iterations`. Nothing when no core is a solid facing one that may have a corner
/// (every_term<CornerCore>()), when no point tried is outside the solid, or when no pair is kept.
template <ConvexShape A, ConvexShape B>
std::optional<CornerSolidPair<typename A::Scalar>> corner_solid_pair(
    const CoreDifference<A, B>& diff, const SupportMinimum<typename A::Scalar>& at_normal,
    typename A::Scalar upper, typename A::Scalar slack, int& iterations) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  const V& normal = at_normal.normal;
  std::optional<CornerSolidPair<S>> out;
  // Whether a pair of direction `n` (A's frame) and `distance` may be kept, its direction
  // within `reach` of the normal.
  auto fits = [&](const V& n, S distance, S reach) {
    return distance > S(0) && distance <= upper + slack && (n - normal).norm() <= reach;
  };
  // The pair of each candidate point of `core` (its frame; the support point along `d` first,
  // then the turned ones that differ) and its nearest point on the solid, from
  // `pair_of(point, pair, pair_d)`, which fills the pair (A's frame) and its direction in the
  // core's frame. A corner by the test keeps its pair within half the test's turn; else a
  // candidate keeps its pair, within the whole turn, when it is the core's support point along
  // the pair's direction (one more support call each).
  auto try_core = [&](const auto& core, const V& d, auto&& pair_of) {
    const V point = core.support_core(d);
    V others[8];
    const int turned = turned_support_points(core, d, point, others);
    iterations += turned > 0 ? 9 : 5;
    CornerSolidPair<S> pair;
    V pair_d;
    if (turned == 0) {
      if (pair_of(point, pair, pair_d) && fits(pair.normal, pair.distance, S(0.5 * kCornerTurn)))
        out = pair;
      return;
    }
    for (int i = -1; i < turned && !out; ++i) {
      const V& candidate = i < 0 ? point : others[i];
      if (!pair_of(candidate, pair, pair_d) || !fits(pair.normal, pair.distance, S(kCornerTurn)))
        continue;
      ++iterations;
      if (core.support_core(pair_d) == candidate) out = pair;
    }
  };
  // B a solid, A's support point a corner. Taken again, not from `at_normal`: Newton's witness
  // there may be a point placed from B's (feature_witness()), which the turned support
  // points would never equal.
  if (every_term<CornerCore>(diff.a))
    with_solid(diff.b, [&](auto solid_core, const auto& solid) {
      using Solid = typename decltype(solid_core)::type;
      try_core(diff.a, normal, [&](const V& corner, CornerSolidPair<S>& pair, V& pair_d) {
        const auto local =
            Solid::local(solid, V(diff.rotation.transpose() * (corner - diff.translation)));
        if (!local) return false;
        pair_d = -(diff.rotation * local->out_of_solid);
        pair = {corner, V(diff.rotation * local->on_solid + diff.translation), pair_d,
                local->signed_distance};
        return true;
      });
    });
  if (out) return no_higher(diff, at_normal, std::move(out), iterations);
  // A a solid, B's support point a corner.
  if (every_term<CornerCore>(diff.b))
    with_solid(diff.a, [&](auto solid_core, const auto& solid) {
      using Solid = typename decltype(solid_core)::type;
      try_core(diff.b, V(diff.rotation.transpose() * -normal),
               [&](const V& corner_b, CornerSolidPair<S>& pair, V& pair_d) {
                 const V corner = diff.rotation * corner_b + diff.translation;
                 const auto local = Solid::local(solid, corner);
                 if (!local) return false;
                 pair_d = diff.rotation.transpose() * -local->out_of_solid;
                 pair = {local->on_solid, corner, local->out_of_solid, local->signed_distance};
                 return true;
               });
    });
  return out ? no_higher(diff, at_normal, std::move(out), iterations) : out;
}

}  // namespace mink::detail
