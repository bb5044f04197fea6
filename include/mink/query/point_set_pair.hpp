/// @file point_set_pair.hpp
/// Two small point sets (segments, triangles, polytopes of up to kPointSetMaxPoints points, and
/// their rounded versions) answered by enumeration of their features, where GJK and EPA are
/// unsure of the answer.
///
/// Where the Minkowski difference A - B is thin for its length (a segment beside a needle
/// triangle 1e-12 wide, two needles 1e-8 rad from parallel) and the origin lies at or near its
/// boundary, GJK's simplices are too thin for their weights: it stops at its cap with the
/// distance open by up to 1e-10 of the size, and its normal (or EPA's) points up to 1e-7 rad off
/// along the long side, which costs that much of the support value times the length. Small
/// point sets need no iteration:
///   - the separating axis test over every candidate normal of a face of A - B: a plane through
///     three points of A or of B, and a pair of edges, one of each (and, where A - B is flat, the
///     normals of its edges within its plane). Its best axis decides the verdict and, when the
///     cores meet, is the depth's normal exactly;
///   - apart, the closest pair over every point of one set against every triangle of the other
///     and every edge (or point) against every edge (or point): the exact distance.
/// Each normal is computed along the longer of its two edges' lines first (sliver_normal() for a
/// triangle), so its tilt along that length, the costly one, is the rounding of its coordinates.
///
/// Cost: a segment against a triangle tries 5 axes (0.4 us), two 4-point needles 44 (7 us), two
/// 8-point polytopes 896 (160 us); the feature pairs are pruned by their heights along the best
/// axis. The queries call it only when GJK or EPA hit their caps, and where the cores are within
/// kPointSetNearTouching of touching (the normal ill-conditioned) for sets whose sizes multiply
/// to at most kPointSetNearTouchingMaxPairs.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mink/epa/epa.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/signed_volumes.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/polytope.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/triangle.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// Most points a core may have for point_set_pair(): two sets of 8 try 896 axes.
inline constexpr int kPointSetMaxPoints = 8;

/// How near touching (a fraction of the size, on the cores' signed distance) the queries hand a
/// pair of point sets to point_set_pair() even when GJK and EPA converged: every normal the
/// probes found off (stop 66: up to 3e-7 rad) was on cores within 5e-11 of the size of touching.
inline constexpr double kPointSetNearTouching = 1e-8;

/// Most products of the two sets' sizes that the queries hand to point_set_pair() where GJK or
/// EPA converged and the cores only nearly touch: a segment against a triangle costs 0.4 us
/// there, two needles of 4 points 7 us, two 8-point polytopes 160 us (this machine), too much for
/// every resting contact of two hulls whose answer is already good. Pairs at a cap take any size.
inline constexpr int kPointSetNearTouchingMaxPairs = 16;

/// The `max_pairs` the queries pass point_set_pair(): any size where GJK or EPA hit a cap, at
/// most kPointSetNearTouchingMaxPairs where the cores only nearly touch.
constexpr int point_set_max_pairs(bool at_cap) {
  return at_cap ? kPointSetMaxPoints * kPointSetMaxPoints : kPointSetNearTouchingMaxPairs;
}

/// GJK's support calls beyond which intersect() checks its verdict on small point sets by their
/// features: a tetrahedron of a difference flat to 1e-17 "enclosed" an origin 2e-11 off its
/// plane after 50 calls (two needles 1e-10 rad from parallel). Well-posed pairs of up to 8
/// points take 3 to 12.
inline constexpr int kPointSetSuspectIterations = 24;

/// The points of a core that is a small point set, in its frame: Points(shape, out) writes them
/// and returns their number (0: too many).
template <class T>
struct PointSetCore : std::false_type {};

template <class S>
struct PointSetCore<PointT<S>> : std::true_type {
  static int points(const PointT<S>& p, Vec3T<S>* out) {
    out[0] = p.position;
    return 1;
  }
};

template <class S>
struct PointSetCore<SegmentT<S>> : std::true_type {
  static int points(const SegmentT<S>& s, Vec3T<S>* out) {
    out[0] = s.a;
    out[1] = s.b;
    return 2;
  }
};

template <class S>
struct PointSetCore<TriangleT<S>> : std::true_type {
  static int points(const TriangleT<S>& t, Vec3T<S>* out) {
    out[0] = t.a;
    out[1] = t.b;
    out[2] = t.c;
    return 3;
  }
};

template <class S>
struct PointSetCore<PolytopeT<S>> : std::true_type {
  static int points(const PolytopeT<S>& p, Vec3T<S>* out) {
    if (p.size() > std::size_t(kPointSetMaxPoints)) return 0;
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = p.point(i);
    return int(p.size());
  }
};

template <class T>
struct PointSetCore<Rounded<T>> : std::bool_constant<PointSetCore<T>::value> {
  static int points(const Rounded<T>& r, Vec3T<typename T::Scalar>* out) {
    return PointSetCore<T>::points(r.shape, out);
  }
};

/// Both cores are point sets, and not two segments or points (closed form, segment_cores.hpp).
template <class A, class B>
inline constexpr bool kPointSetPair =
    PointSetCore<A>::value&& PointSetCore<B>::value && !kSegmentCores<A, B>;

/// point_set_pair()'s answer, in A's frame.
template <class S>
struct PointSetAnswer {
  bool apart = false;  ///< the cores are apart by more than the touching tolerance
  S value = S(0);      ///< apart: the cores' distance; else their depth (>= 0) (unit: length)
  Vec3T<S> normal = Vec3T<S>::UnitZ();  ///< unit, from A's core towards B's
  Vec3T<S> on_a = Vec3T<S>::Zero();     ///< apart: the closest points of the cores
  Vec3T<S> on_b = Vec3T<S>::Zero();
};

/// The unit normal of the plane of edges e and f (arbitrary lengths), taken across the longer
/// one first: e x f tilts by eps / sin(angle) in every direction, and a tilt along an edge costs
/// its length times the tilt of support value; this one tilts only about the longer edge.
/// False when the edges are parallel or either is a point.
template <class S>
bool edge_pair_normal(const Vec3T<S>& e, const Vec3T<S>& f, Vec3T<S>& n) {
  const bool e_longer = e.squaredNorm() >= f.squaredNorm();
  const Vec3T<S> along = unit_of(e_longer ? e : f);
  if (!is_finite(along)) return false;
  const Vec3T<S> across = part_across(e_longer ? f : e, along);
  const Vec3T<S> cross = along.cross(across);
  if (!(cross.squaredNorm() > S(0))) return false;
  n = unit_of(cross);
  return is_finite(n);
}

/// closest_features()'s answer: the closest points of two point sets' hulls, and when they come
/// from two edges (or points), those edges and the points' parameters on them.
template <class S>
struct ClosestFeatures {
  S distance = std::numeric_limits<S>::infinity();
  Vec3T<S> on_p = Vec3T<S>::Zero(), on_q = Vec3T<S>::Zero();
  bool edges = false;
  CoreSegment<S> edge_p{Vec3T<S>::Zero(), Vec3T<S>::Zero()},
      edge_q{Vec3T<S>::Zero(), Vec3T<S>::Zero()};
  S u = S(0), v = S(0);

  /// The squared terms the pair's difference is computed from (segment_gap_direction()).
  S terms_sq() const {
    return edge_p.centre.squaredNorm() + edge_p.half.squaredNorm() + edge_q.centre.squaredNorm() +
           edge_q.half.squaredNorm();
  }
};

/// The closest points of the hulls of point sets p and q (np, nq points), over every point of one
/// against every triangle of the other and every edge (or point) of one against every edge (or
/// point) of the other: their distance when the hulls are apart (a vertex over a face, two edges,
/// or less), and an upper bound otherwise (an edge through a face has no such pair). A pair of
/// features is skipped when their heights along the unit `axis` are already further apart than
/// the best pair (its distance is no less than that), which leaves the features near the support
/// planes of a separating or nearly separating axis.
template <class S>
ClosestFeatures<S> closest_features(const Vec3T<S>* p, int np, const Vec3T<S>* q, int nq,
                                    const Vec3T<S>& axis) {
  using V = Vec3T<S>;
  S height_p[kPointSetMaxPoints], height_q[kPointSetMaxPoints];
  int top = 0, low = 0;
  for (int i = 0; i < np; ++i) {
    height_p[i] = axis.dot(p[i]);
    if (height_p[i] > height_p[top]) top = i;
  }
  for (int j = 0; j < nq; ++j) {
    height_q[j] = axis.dot(q[j]);
    if (height_q[j] < height_q[low]) low = j;
  }
  // The support points along the axis are a pair: the bound to beat.
  ClosestFeatures<S> best;
  best.on_p = p[top];
  best.on_q = q[low];
  S best_sq = (best.on_q - best.on_p).squaredNorm();
  auto beaten = [&best_sq](S gap) { return gap > S(0) && gap * gap >= best_sq; };
  for (int i = 0; i < np; ++i)
    for (int j = i; j < np; ++j)
      for (int k = 0; k < nq; ++k)
        for (int l = k; l < nq; ++l) {
          if (beaten(std::min(height_q[k], height_q[l]) - std::max(height_p[i], height_p[j])))
            continue;
          const CoreSegment<S> edge_p{S(0.5) * (p[i] + p[j]), S(0.5) * (p[j] - p[i])};
          const CoreSegment<S> edge_q{S(0.5) * (q[k] + q[l]), S(0.5) * (q[l] - q[k])};
          V on_p, on_q;
          S u, v;
          closest_points_of_segments(edge_p, edge_q, on_p, on_q, &u, &v);
          const S sq = (on_q - on_p).squaredNorm();
          if (!(sq < best_sq)) continue;
          best_sq = sq;
          best.on_p = on_p;
          best.on_q = on_q;
          best.edges = true;
          best.edge_p = edge_p;
          best.edge_q = edge_q;
          best.u = u;
          best.v = v;
        }
  // A point against a triangle of the other set, as the origin against their difference; the
  // triangle's set lies beyond the point along the axis when the point is p's.
  auto point_triangles = [&](const V& point, S height, const V* x, const S* heights, int count,
                             bool point_in_p) {
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j)
        for (int k = j + 1; k < count; ++k) {
          const S gap = point_in_p ? std::min({heights[i], heights[j], heights[k]}) - height
                                   : height - std::max({heights[i], heights[j], heights[k]});
          if (beaten(gap)) continue;
          const V w[3] = {x[i] - point, x[j] - point, x[k] - point};
          const SubSimplex<S> nearest = closest_on_triangle(w, 0, 1, 2);
          if (!(nearest.dist_sq < best_sq)) continue;
          best_sq = nearest.dist_sq;
          const V on_x = point + nearest.v;
          best.on_p = point_in_p ? point : on_x;
          best.on_q = point_in_p ? on_x : point;
          // Inside the triangle or on an edge, the pair's direction is orthogonal to the longest
          // edge among the corners it uses: kept as an edge pair (the point a segment of no
          // length), so that the direction can be made so (a needle's face, whose long edge
          // carries the costly tilt).
          const int corner[3] = {i, j, k};
          int from = -1, to = -1;
          for (int c = 0; c < 3; ++c)
            for (int e = c + 1; e < 3; ++e)
              if ((nearest.mask >> c & 1u) && (nearest.mask >> e & 1u) &&
                  (from < 0 ||
                   (x[corner[e]] - x[corner[c]]).squaredNorm() > (x[to] - x[from]).squaredNorm())) {
                from = corner[c];
                to = corner[e];
              }
          best.edges = from >= 0;
          if (!best.edges) continue;
          const CoreSegment<S> at_point{point, V::Zero()};
          const CoreSegment<S> edge{S(0.5) * (x[from] + x[to]), S(0.5) * (x[to] - x[from])};
          const S along = edge.half.squaredNorm();
          const S t = along > S(0)
                          ? std::clamp(edge.half.dot(V(on_x - edge.centre)) / along, S(-1), S(1))
                          : S(1);
          best.edge_p = point_in_p ? at_point : edge;
          best.edge_q = point_in_p ? edge : at_point;
          best.u = point_in_p ? S(1) : t;
          best.v = point_in_p ? t : S(1);
        }
  };
  for (int i = 0; i < np; ++i) point_triangles(p[i], height_p[i], q, height_q, nq, true);
  for (int j = 0; j < nq; ++j) point_triangles(q[j], height_q[j], p, height_p, np, false);
  best.distance = (best.on_q - best.on_p).norm();
  return best;
}

/// Most points of A - B that face_witness() takes on a face: four points of A's face against
/// four of B's.
inline constexpr int kPointSetMaxFacePoints = 16;

/// The witness pair of point sets p (A's) and q (B's) that meet, along the unit axis n of their
/// least overlap `depth` (h of A - B along n): the point of A - B's face there nearest the origin
/// (the origin's projection onto it, when the depth is exact), as weights of the differences
/// p_i - q_j on the face, and the same weights of the p_i and of the q_j. So each point is a
/// convex combination of its own set's points, on its core whatever the weights' rounding (a
/// needle's face 1e-12 wide has weights good to 1e-4 only; the pair's gap along n is then off
/// by that times the width). False when the face has more than kPointSetMaxFacePoints points or a
/// value is not finite.
template <class S>
bool face_witness(const Vec3T<S>* p, int np, const Vec3T<S>* q, int nq, const Vec3T<S>& n, S depth,
                  Vec3T<S>& on_a, Vec3T<S>& on_b) {
  using V = Vec3T<S>;
  // On the face: within the rounding of the points' heights along n.
  S magnitude = S(0);
  for (int i = 0; i < np; ++i) magnitude = std::max(magnitude, p[i].cwiseAbs().maxCoeff());
  for (int j = 0; j < nq; ++j) magnitude = std::max(magnitude, q[j].cwiseAbs().maxCoeff());
  const S slack = S(256) * std::numeric_limits<S>::epsilon() * magnitude;
  V w[kPointSetMaxFacePoints];
  int of_p[kPointSetMaxFacePoints], of_q[kPointSetMaxFacePoints], count = 0;
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < nq; ++j) {
      const V d = p[i] - q[j];
      if (!(n.dot(d) >= depth - slack)) continue;
      if (count == kPointSetMaxFacePoints) return false;
      w[count] = d;
      of_p[count] = i;
      of_q[count] = j;
      ++count;
    }
  if (count == 0) return false;
  // The face's point nearest the origin, over its triangles (each with its edges and corners).
  SubSimplex<S> best;
  int corners[3] = {0, 0, 0};
  auto offer = [&](int i, int j, int k) {
    const V t[3] = {w[i], w[j], w[k]};
    const SubSimplex<S> candidate = closest_on_triangle(t, 0, 1, 2);
    if (candidate.dist_sq < best.dist_sq) {
      best = candidate;
      corners[0] = i;
      corners[1] = j;
      corners[2] = k;
    }
  };
  if (count < 3) offer(0, count - 1, count - 1);
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j)
      for (int k = j + 1; k < count; ++k) offer(i, j, k);
  on_a = on_b = V::Zero();
  for (int c = 0; c < 3; ++c) {
    if (!(best.mask & (1u << c))) continue;
    on_a += best.weights[c] * p[of_p[corners[c]]];
    on_b += best.weights[c] * q[of_q[corners[c]]];
  }
  return is_finite(on_a) && is_finite(on_b);
}

/// The cores of `diff` as point sets (PointSetCore), by enumeration of their features (see the
/// file's comment): nullopt when either has more than kPointSetMaxPoints points, when no
/// candidate axis exists (all points on one line and every pair of lines parallel) or when a
/// value is not finite, or when the product of the sets' sizes exceeds `max_pairs`. `touch`
/// (unit: length): cores nearer than this count as touching.
template <ConvexShape A, ConvexShape B>
std::optional<PointSetAnswer<typename A::Scalar>> point_set_pair(
    const CoreDifference<A, B>& diff, typename A::Scalar touch,
    int max_pairs = kPointSetMaxPoints * kPointSetMaxPoints) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  V p[kPointSetMaxPoints], q[kPointSetMaxPoints];
  const int np = PointSetCore<A>::points(diff.a, p);
  const int nq = PointSetCore<B>::points(diff.b, q);
  if (np == 0 || nq == 0 || np * nq > max_pairs) return std::nullopt;
  for (int j = 0; j < nq; ++j) q[j] = diff.rotation * q[j] + diff.translation;

  // The separating axis test: the largest gap over the candidate axes, on either side.
  S best_gap = -std::numeric_limits<S>::infinity();
  V best_n = V::Zero();
  // The gap of B beyond A along n: the least of B's heights less the largest of A's.
  auto gap_along = [&](const V& n) {
    S top_p = -std::numeric_limits<S>::infinity(), low_q = std::numeric_limits<S>::infinity();
    for (int i = 0; i < np; ++i) top_p = std::max(top_p, n.dot(p[i]));
    for (int j = 0; j < nq; ++j) low_q = std::min(low_q, n.dot(q[j]));
    return low_q - top_p;
  };
  // One scan gives the gaps on both sides of n: along -n each height only changes its sign.
  auto offer = [&](const V& n) {
    S top_p = -std::numeric_limits<S>::infinity(), low_p = -top_p;
    S top_q = top_p, low_q = low_p;
    for (int i = 0; i < np; ++i) {
      const S h = n.dot(p[i]);
      top_p = std::max(top_p, h);
      low_p = std::min(low_p, h);
    }
    for (int j = 0; j < nq; ++j) {
      const S h = n.dot(q[j]);
      top_q = std::max(top_q, h);
      low_q = std::min(low_q, h);
    }
    if (const S gap = low_q - top_p; gap > best_gap) {
      best_gap = gap;
      best_n = n;
    }
    if (const S gap = low_p - top_q; gap > best_gap) {
      best_gap = gap;
      best_n = -n;
    }
  };
  auto offer_faces = [&](const V* x, int count) {
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j)
        for (int k = j + 1; k < count; ++k)
          if (V n; sliver_normal(x[i], x[j], x[k], n)) offer(n);
  };
  offer_faces(p, np);
  offer_faces(q, nq);
  for (int i = 0; i < np; ++i)
    for (int j = i + 1; j < np; ++j)
      for (int k = 0; k < nq; ++k)
        for (int l = k + 1; l < nq; ++l)
          if (V n; edge_pair_normal(V(p[j] - p[i]), V(q[l] - q[k]), n) &&
                   // Neither side's gap exceeds the edges' own offset along n.
                   std::abs(n.dot(V(q[k] - p[i]))) > best_gap)
            offer(n);
  if (best_n == V::Zero()) {
    // Every edge on one line: any normal across it. The longest edge names the line.
    V line = V::Zero();
    for (const V* x : {p, q})
      for (int i = 0, count = x == p ? np : nq; i < count; ++i)
        for (int j = i + 1; j < count; ++j)
          if ((x[j] - x[i]).squaredNorm() > line.squaredNorm()) line = x[j] - x[i];
    if (!(line.squaredNorm() > S(0))) return std::nullopt;  // two points: the closed form's
    offer(unit_of(orthogonal(line)));
  }
  {
    // A - B flat along the best axis (both sets in one plane): its faces are then its edges
    // within that plane, whose normals no three points or pair of edges give.
    const V m = best_n;
    S top = -std::numeric_limits<S>::infinity(), low = -top;
    for (int i = 0; i < np; ++i)
      for (int j = 0; j < nq; ++j) {
        const S h = m.dot(V(p[i] - q[j]));
        top = std::max(top, h);
        low = std::min(low, h);
      }
    if (top - low <= touch) {
      auto offer_in_plane = [&](const V* x, int count) {
        for (int i = 0; i < count; ++i)
          for (int j = i + 1; j < count; ++j)
            if (V n; edge_pair_normal(m, V(x[j] - x[i]), n)) offer(n);
      };
      offer_in_plane(p, np);
      offer_in_plane(q, nq);
    }
  }
  if (!std::isfinite(best_gap) || !is_finite(best_n)) return std::nullopt;

  PointSetAnswer<S> answer;
  if (!(best_gap > touch)) {
    // The cores meet: the least overlap over the faces of A - B is the depth, along its axis.
    // Touching, a common point: the closest pair of features (within the tolerance of each
    // other), else the point of the face nearest the origin. Deeper, that point's pair.
    answer.value = std::max(S(0), -best_gap);
    answer.normal = best_n;
    if (answer.value <= touch) {
      if (const ClosestFeatures<S> closest = closest_features(p, np, q, nq, best_n);
          closest.distance <= touch) {
        answer.on_a = answer.on_b = S(0.5) * (closest.on_p + closest.on_q);
        return answer;
      }
    }
    if (!face_witness(p, np, q, nq, best_n, -best_gap, answer.on_a, answer.on_b))
      return std::nullopt;
    if (answer.value <= touch) answer.on_a = answer.on_b = S(0.5) * (answer.on_a + answer.on_b);
    return answer;
  }
  // Apart: the closest pair of features; the best axis proves the gap.
  const ClosestFeatures<S> closest = closest_features(p, np, q, nq, best_n);
  const S distance = closest.distance;
  if (!std::isfinite(distance) || !(distance > S(0))) return std::nullopt;
  answer.on_a = closest.on_p;
  answer.on_b = closest.on_q;
  const V gap = answer.on_b - answer.on_a;
  answer.apart = true;
  answer.value = distance;
  // The normal: of the best axis and the pair's direction, the one that proves the larger gap.
  // The axis is exact where the pair is a point over a face or crossing edges; the pair's
  // direction carries the rounding of its points over the distance (2e-8 rad for needles 5e-9
  // apart), less where it is made orthogonal to the edges it meets inside. Only to an edge no
  // shorter than the gap: its direction carries the same rounding over its own length (a
  // needle's end edge 1e-13 long, met inside by a pair 3.8e-8 apart, turned the direction 0.4
  // rad, and the axis, which proved less, was kept).
  auto inside_of = [distance](const CoreSegment<S>& edge, S parameter) {
    return S(2) * edge.half.norm() >= distance ? parameter : S(1);
  };
  const V along_pair = closest.edges ? segment_gap_direction(closest.edge_p, closest.edge_q,
                                                             inside_of(closest.edge_p, closest.u),
                                                             inside_of(closest.edge_q, closest.v),
                                                             gap, closest.terms_sq())
                                     : unit_of(gap);
  answer.normal = best_n;
  if (is_finite(along_pair) && gap_along(along_pair) > best_gap) answer.normal = along_pair;
  if (!is_finite(answer.normal)) return std::nullopt;
  return answer;
}

}  // namespace mink::detail
