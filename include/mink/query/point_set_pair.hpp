/// @file point_set_pair.hpp
/// Two small point sets (segments, triangles, boxes, polytopes of up to kPointSetMaxPoints
/// points, and their rounded versions) answered by enumeration of their features, where GJK and EPA
/// are unsure of the answer.
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
/// Cost: a segment against a triangle tries 4 axes (0.4 us), a triangle touching a box 13 (3 us
/// with GJK's and EPA's first try), two 4-point needles 44 (7 us), two 8-point polytopes 896
/// (160 us); the feature pairs are pruned by their heights along the best axis. The queries call
/// it only when GJK or EPA hit their caps, and where the cores are within kPointSetNearTouching
/// of touching (the normal ill-conditioned) for sets of at most kPointSetNearTouchingMaxAxes
/// candidate axes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include "mink/epa/epa.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/signed_volumes.hpp"
#include "mink/query/box_box.hpp"
#include "mink/shapes/box.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/polytope.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/shapes/triangle.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// Most points a core may have for point_set_pair(): two sets of 8 try 896 axes.
inline constexpr int kPointSetMaxPoints = 8;

/// How near touching (a fraction of the size, on the cores' signed distance) the queries hand a
/// pair of point sets to point_set_pair() even when GJK and EPA converged: every normal the
/// probes found off (stop 66: up to 3e-7 rad) was on cores within 5e-11 of the size of touching.
inline constexpr double kPointSetNearTouching = 1e-8;

/// Most candidate axes (point_set_axes()) of the pairs that the queries hand to point_set_pair()
/// where GJK or EPA converged and the cores only nearly touch: a segment against 8 points (a
/// triangle against a box takes 13, two needles of 4 points 44 and 7 us). Two 8-point polytopes
/// try 896 axes in 160 us (this machine), too much for every resting contact of two hulls whose
/// answer is already good. Pairs at a cap take any size.
inline constexpr int kPointSetNearTouchingMaxAxes = 84;

/// The `max_axes` the queries pass point_set_pair(): any number where GJK or EPA hit a cap, at
/// most kPointSetNearTouchingMaxAxes where the cores only nearly touch.
constexpr int point_set_max_axes(bool at_cap) {
  return at_cap ? std::numeric_limits<int>::max() : kPointSetNearTouchingMaxAxes;
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

/// A sphere's core, its centre, and a capsule's, the ends of its segment along z: the point sets
/// of a point and a segment. Without them a Shape's sphere or capsule (which holds these cores)
/// beside a needle triangle ended at GJK's cap where a rounded point or segment did not.
template <class S>
struct PointSetCore<SphereT<S>> : std::true_type {
  static int points(const SphereT<S>&, Vec3T<S>* out) {
    out[0] = Vec3T<S>::Zero();
    return 1;
  }
};

template <class S>
struct PointSetCore<CapsuleT<S>> : std::true_type {
  static int points(const CapsuleT<S>& c, Vec3T<S>* out) {
    out[0] = {S(0), S(0), -c.half_height};
    out[1] = {S(0), S(0), c.half_height};
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

/// A box as its 8 corners: a segment, triangle or small polytope beside a box face or edge, nearly
/// parallel, has the thin difference of the file's comment too (a triangle 8e-9 rad from a box
/// face hit GJK's cap; segments 5e-9 rad from an edge got normals 1.8e-9 of the size off).
template <class S>
struct PointSetCore<BoxT<S>> : std::true_type {
  // Corner i has bit 1 set for +x, 2 for +y, 4 for +z (PointSet::list_box()).
  static int points(const BoxT<S>& b, Vec3T<S>* out) {
    const Vec3T<S>& h = b.half_extents;
    for (int i = 0; i < 8; ++i)
      out[i] = {i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z()};
    return 8;
  }
};

template <class T>
struct PointSetCore<Rounded<T>> : std::bool_constant<PointSetCore<T>::value> {
  static int points(const Rounded<T>& r, Vec3T<typename T::Scalar>* out) {
    return PointSetCore<T>::points(r.shape, out);
  }
};

/// Most pairs and triples of points that a PointSet lists (every pair and triple of 8 points).
inline constexpr int kPointSetMaxEdges = kPointSetMaxPoints * (kPointSetMaxPoints - 1) / 2;
inline constexpr int kPointSetMaxTriangles =
    kPointSetMaxPoints * (kPointSetMaxPoints - 1) * (kPointSetMaxPoints - 2) / 6;

/// A core as point_set_pair() enumerates it: its points, the pairs of them that may be edges of
/// its hull and the triangles that may lie in its faces. A set of points alone lists every pair
/// and every triple; a box lists its 12 edges and the 2 triangles of each face (of its 8 corners'
/// 28 pairs and 56 triples: a segment touching a box took 11 us with them all).
template <class S>
struct PointSet {
  Vec3T<S> points[kPointSetMaxPoints];
  int count = 0;
  int edges[kPointSetMaxEdges][2];  ///< a set of one point lists one edge, (0, 0)
  int edge_count = 0;
  int triangles[kPointSetMaxTriangles][3];
  int triangle_count = 0;
  /// The first edges and triangles that give every direction of an edge and every normal of a
  /// face (the separating axis test's candidates): all of them unless the set knows better.
  int axis_edges = 0, axis_triangles = 0;

  std::span<const int[2]> edge_list() const { return {edges, std::size_t(edge_count)}; }
  std::span<const int[3]> triangle_list() const { return {triangles, std::size_t(triangle_count)}; }

  /// Every pair and every triple of the points.
  void list_all() {
    edge_count = triangle_count = 0;
    if (count == 1) {
      edges[0][0] = edges[0][1] = 0;
      edge_count = 1;
    }
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j) {
        edges[edge_count][0] = i;
        edges[edge_count++][1] = j;
        for (int k = j + 1; k < count; ++k) {
          triangles[triangle_count][0] = i;
          triangles[triangle_count][1] = j;
          triangles[triangle_count++][2] = k;
        }
      }
    axis_edges = edge_count;
    axis_triangles = triangle_count;
  }

  /// A box's 12 edges and the 2 triangles of each face, its corners in PointSetCore<BoxT>'s
  /// order. One edge and one triangle per axis come first: the separating axis test needs only
  /// those (3 directions and 3 face normals), the closest features all of them.
  void list_box() {
    edge_count = triangle_count = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (int axis = 1; axis <= 4; axis <<= 1) {
        // Along the axis: from each corner without its bit to the one with it.
        for (int i = 0; i < 8; ++i)
          if (!(i & axis) && (i == 0) == (pass == 0)) {
            edges[edge_count][0] = i;
            edges[edge_count++][1] = i | axis;
          }
        // The two faces across the axis, each cut along its diagonal c0-c3.
        const int u = axis == 1 ? 2 : 1, v = axis == 4 ? 2 : 4;
        for (const int side : {0, axis}) {
          const int c0 = side, c1 = side | u, c2 = side | v, c3 = side | u | v;
          const int cut[2][3] = {{c0, c1, c3}, {c0, c3, c2}};
          for (int c = 0; c < 2; ++c) {
            if ((side == 0 && c == 0) != (pass == 0)) continue;
            for (int k = 0; k < 3; ++k) triangles[triangle_count][k] = cut[c][k];
            ++triangle_count;
          }
        }
      }
    axis_edges = axis_triangles = 3;
  }
};

/// `core` as a PointSet; false when it has too many points.
template <class T>
bool point_set_of(const T& core, PointSet<typename T::Scalar>& set) {
  set.count = PointSetCore<T>::points(core, set.points);
  if constexpr (BoxCore<T>::value)
    set.list_box();
  else
    set.list_all();
  return set.count > 0;
}

/// The separating axis test's candidate axes for sets p and q: a normal of each triangle, and of
/// each pair of edges, one of each set.
template <class S>
int point_set_axes(const PointSet<S>& p, const PointSet<S>& q) {
  return p.axis_triangles + q.axis_triangles + p.axis_edges * q.axis_edges;
}

/// Both cores are point sets, and not two segments or points (closed form, segment_cores.hpp).
template <class A, class B>
inline constexpr bool kPointSetPair =
    PointSetCore<A>::value&& PointSetCore<B>::value && !kSegmentCores<A, B>;

/// Cores of at most three points: points, segments, triangles, spheres' and capsules' cores (and
/// their rounded versions).
template <class T>
struct FewPointsCore : std::false_type {};
template <class S>
struct FewPointsCore<PointT<S>> : std::true_type {};
template <class S>
struct FewPointsCore<SphereT<S>> : std::true_type {};
template <class S>
struct FewPointsCore<SegmentT<S>> : std::true_type {};
template <class S>
struct FewPointsCore<CapsuleT<S>> : std::true_type {};
template <class S>
struct FewPointsCore<TriangleT<S>> : std::true_type {};
template <class T>
struct FewPointsCore<Rounded<T>> : FewPointsCore<T> {};

/// Pairs that the queries hand to point_set_pair() where the cores only nearly touch: a box only
/// against a point, segment or triangle (the pairs whose normals and points the probes found
/// off). Two boxes have an exact separating axis test there already (query/box_box.hpp), and
/// through the point sets a box resting exactly on a box took 7.9 us a contact against 0.9 us, a
/// tetrahedron's corner on a box 9.3 us against 0.8. At a cap, every point set pair.
template <class A, class B>
inline constexpr bool kPointSetNearTouchingPair = kPointSetPair<A, B> &&
                                                  (!BoxCore<A>::value || FewPointsCore<B>::value) &&
                                                  (!BoxCore<B>::value || FewPointsCore<A>::value);

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

/// The closest points of the hulls of point sets p and q, over every point of one against every
/// triangle of the other and every edge of one against every edge of the other: their distance when
/// the hulls are apart (a vertex over a face, two edges, or less), and an upper bound otherwise (an
/// edge through a face has no such pair). A pair of features is skipped when their heights along
/// the unit `axis` are already further apart than the best pair (its distance is no less than
/// that), which leaves the features near the support planes of a separating or nearly separating
/// axis.
template <class S>
ClosestFeatures<S> closest_features(const PointSet<S>& set_p, const PointSet<S>& set_q,
                                    const Vec3T<S>& axis) {
  using V = Vec3T<S>;
  const V *p = set_p.points, *q = set_q.points;
  const int np = set_p.count, nq = set_q.count;
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
  for (const auto& [i, j] : set_p.edge_list())
    for (const auto& [k, l] : set_q.edge_list()) {
      if (beaten(std::min(height_q[k], height_q[l]) - std::max(height_p[i], height_p[j]))) continue;
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
  auto point_triangles = [&](const V& point, S height, const PointSet<S>& set, const S* heights,
                             bool point_in_p) {
    const V* x = set.points;
    for (const auto& [i, j, k] : set.triangle_list()) {
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
  for (int i = 0; i < np; ++i) point_triangles(p[i], height_p[i], set_q, height_q, true);
  for (int j = 0; j < nq; ++j) point_triangles(q[j], height_q[j], set_p, height_p, false);
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
/// value is not finite, or when the sets have more than `max_axes` candidate axes. `touch`
/// (unit: length): cores nearer than this count as touching.
template <ConvexShape A, ConvexShape B>
std::optional<PointSetAnswer<typename A::Scalar>> point_set_pair(
    const CoreDifference<A, B>& diff, typename A::Scalar touch,
    int max_axes = std::numeric_limits<int>::max()) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  PointSet<S> set_p, set_q;
  if (!point_set_of(diff.a, set_p) || !point_set_of(diff.b, set_q) ||
      point_set_axes(set_p, set_q) > max_axes)
    return std::nullopt;
  V* const p = set_p.points;
  V* const q = set_q.points;
  const int np = set_p.count, nq = set_q.count;
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
  for (const PointSet<S>* set : {&set_p, &set_q})
    for (const auto& [i, j, k] : set->triangle_list().first(set->axis_triangles))
      if (V n; sliver_normal(set->points[i], set->points[j], set->points[k], n)) offer(n);
  for (const auto& [i, j] : set_p.edge_list().first(set_p.axis_edges))
    for (const auto& [k, l] : set_q.edge_list().first(set_q.axis_edges))
      if (V n; edge_pair_normal(V(p[j] - p[i]), V(q[l] - q[k]), n) &&
               // Neither side's gap exceeds the edges' own offset along n.
               std::abs(n.dot(V(q[k] - p[i]))) > best_gap)
        offer(n);
  if (best_n == V::Zero()) {
    // Every edge on one line: any normal across it. The longest edge names the line.
    V line = V::Zero();
    for (const PointSet<S>* set : {&set_p, &set_q})
      for (const auto& [i, j] : set->edge_list())
        if (const V edge = set->points[j] - set->points[i]; edge.squaredNorm() > line.squaredNorm())
          line = edge;
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
      for (const PointSet<S>* set : {&set_p, &set_q})
        for (const auto& [i, j] : set->edge_list().first(set->axis_edges))
          if (V n; edge_pair_normal(m, V(set->points[j] - set->points[i]), n)) offer(n);
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
      if (const ClosestFeatures<S> closest = closest_features(set_p, set_q, best_n);
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
  const ClosestFeatures<S> closest = closest_features(set_p, set_q, best_n);
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
