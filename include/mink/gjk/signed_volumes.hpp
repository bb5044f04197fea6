/// @file signed_volumes.hpp
/// The distance sub-algorithm of GJK: the point of a simplex closest to the origin.
///
/// We use the signed-volumes method of Montanari, Petrinic and Barbieri, "Improving the GJK
/// algorithm for faster and more reliable distance queries between convex objects" (ACM TOG
/// 2017), rather than Johnson's sub-algorithm. Johnson decides the Voronoi region from products of
/// cofactors that lose all their digits on nearly flat or nearly degenerate simplices, and its
/// "backup procedure" is then the only thing between GJK and a wrong or looping answer. Signed
/// volumes decide with the signs of the barycentric volumes of the simplex itself (which are
/// well conditioned) and recurse only into the faces that the origin lies outside of.
///
/// Departures from the paper: the projection onto a triangle's plane is returned only when it
/// agrees to rounding with the convex combination of the vertices (on a sliver triangle it can
/// undershoot the distance, and GJK then stops early); the recursion does not assume GJK's
/// vertex ordering (any simplex, including one rebuilt from a warm-start cache, is handled);
/// near-flat triangles and tetrahedra (relative size below kFlatness) are treated as their
/// boundary; barycentrics are normalised by the sum of the computed sub-volumes so they always
/// lie in [0, 1] and sum to 1; a triangle's sub-areas come from the edges at its largest angle,
/// the third as the rest of the whole, so that a sliver's weights along its length stay exact.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/gjk/simplex.hpp"
#include "mink/math/orthogonal.hpp"

namespace mink::detail {

/// Closest point of a sub-simplex with its support: `mask` bit i set means vertex i is used.
template <class S>
struct SubSimplex {
  Vec3T<S> v;
  S weights[4] = {};
  unsigned mask = 0;
  S dist_sq = std::numeric_limits<S>::infinity();
};

/// A triangle or tetrahedron whose squared sine (the relative size of its area or volume against
/// its edges) is below this is treated as flat: its barycentrics would be noise. (1e4 eps)^2, so
/// about 5e-24 in double.
template <class S>
constexpr S kFlatness =
    S(1e8) * std::numeric_limits<S>::epsilon() * std::numeric_limits<S>::epsilon();

/// Counter-clockwise normal n of the triangle (p, q, r), n = (q - p) x (r - p) up to rounding,
/// and nn = |n|^2; false when the triangle has no area to rounding (the sine of its largest angle
/// below sqrt(kFlatness)). Taken from the two edges at the largest angle (the apex opposite the
/// longest edge), in cyclic order: a cross product is good to eps |e1| |e2|, so from the two long
/// edges of a triangle 2e5 long and 2 wide the normal was off by 3e-11 rad, which moved the plane
/// by 6e-6 at the origin 2e5 away (GJK then searched past the closest face); from the short edge
/// and a long one it is good to eps. `apex` (optional) receives the apex: 0 for p, 1 for q, 2 for
/// r.
template <class S>
[[gnu::always_inline]] inline bool triangle_cross(const Vec3T<S>& p, const Vec3T<S>& q,
                                                  const Vec3T<S>& r, Vec3T<S>& n, S& nn,
                                                  int* apex = nullptr) {
  const Vec3T<S> pq = q - p, qr = r - q, rp = p - r;
  const S pq_sq = pq.squaredNorm(), qr_sq = qr.squaredNorm(), rp_sq = rp.squaredNorm();
  if (pq_sq > qr_sq && pq_sq >= rp_sq) {  // apex r: (p - r) x (q - r)
    n = rp.cross(Vec3T<S>(-qr));
    nn = n.squaredNorm();
    if (apex) *apex = 2;
    return nn > kFlatness<S> * rp_sq * qr_sq && nn > S(0);
  }
  if (rp_sq > qr_sq && rp_sq > pq_sq) {  // apex q: (r - q) x (p - q)
    n = qr.cross(Vec3T<S>(-pq));
    nn = n.squaredNorm();
    if (apex) *apex = 1;
    return nn > kFlatness<S> * qr_sq * pq_sq && nn > S(0);
  }
  n = pq.cross(Vec3T<S>(-rp));  // apex p
  nn = n.squaredNorm();
  if (apex) *apex = 0;
  return nn > kFlatness<S> * pq_sq * rp_sq && nn > S(0);
}

/// The corner after corner k of a triangle, and the one after that: (k + 1) % 3 and (k + 2) % 3
/// without the division (here and in EPA's horizon).
inline constexpr int kNextCorner[3] = {1, 2, 0}, kCornerAfterNext[3] = {2, 0, 1};

/// `best` becomes the candidate v with squared distance `dist_sq` on the vertices in `mask`, every
/// weight 0 until the caller sets those of `mask`.
template <class S>
[[gnu::always_inline]] inline void take_candidate(SubSimplex<S>& best, const Vec3T<S>& v, S dist_sq,
                                                  unsigned mask) {
  best.v = v;
  best.weights[0] = best.weights[1] = best.weights[2] = best.weights[3] = S(0);
  best.mask = mask;
  best.dist_sq = dist_sq;
}

/// Offers vertex i as the closest point: `best` takes it when it is strictly closer (as every
/// offer_* below, so that among equal candidates the first offered stays). Returns whether the
/// candidate has a finite distance. A candidate is written into `best` in place and only when it
/// wins: each used to be built as a struct of its own and the winners copied, 390 instructions
/// of a polytope pair's distance query with the in-place reduction in gjk.hpp (6.8 %).
template <class S>
[[gnu::always_inline]] inline bool offer_vertex(const Vec3T<S>* w, int i, SubSimplex<S>& best) {
  const S dist_sq = w[i].squaredNorm();
  if (dist_sq < best.dist_sq) {
    take_candidate(best, w[i], dist_sq, 1u << i);
    best.weights[i] = S(1);
  }
  return dist_sq < std::numeric_limits<S>::infinity();
}

/// Offers the point of segment (w[i], w[j]) closest to the origin.
template <class S>
[[gnu::always_inline]] inline bool offer_segment(const Vec3T<S>* w, int i, int j,
                                                 SubSimplex<S>& best) {
  const Vec3T<S> t = w[j] - w[i];
  const S tt = t.squaredNorm();
  const S proj = -w[i].dot(t);  // (0 - w_i).t: where the origin projects, times tt
  if (!(tt > S(0)) || proj <= S(0)) return offer_vertex(w, i, best);
  if (proj >= tt) return offer_vertex(w, j, best);
  const S s = proj / tt;
  const Vec3T<S> v = w[i] + s * t;
  const S dist_sq = v.squaredNorm();
  if (dist_sq < best.dist_sq) {
    take_candidate(best, v, dist_sq, (1u << i) | (1u << j));
    best.weights[i] = S(1) - s;
    best.weights[j] = s;
  }
  return dist_sq < std::numeric_limits<S>::infinity();
}

template <class S>
[[gnu::always_inline]] inline SubSimplex<S> closest_on_vertex(const Vec3T<S>* w, int i) {
  SubSimplex<S> best;
  offer_vertex(w, i, best);
  return best;
}

template <class S>
[[gnu::always_inline]] inline SubSimplex<S> closest_on_segment(const Vec3T<S>* w, int i, int j) {
  SubSimplex<S> best;
  offer_segment(w, i, j, best);
  return best;
}

template <class S>
bool same_sign_or_zero(S x, S reference) {
  return reference > S(0) ? x >= S(0) : x <= S(0);
}

/// What offer_triangle() found: whether its candidates had a finite distance, and whether the
/// origin projects into the triangle (its candidate is then that projection, to rounding; in a
/// convex body whose face this is, with the origin beyond the face, no point is closer).
struct TriangleOffer {
  bool finite;
  bool interior;
};

/// Offers the point of triangle (w[i], w[j], w[k]) closest to the origin.
template <class S>
[[gnu::always_inline]] inline TriangleOffer offer_triangle(const Vec3T<S>* w, int i, int j, int k,
                                                           SubSimplex<S>& best) {
  Vec3T<S> n;
  S nn;
  int apex;
  if (!triangle_cross(w[i], w[j], w[k], n, nn, &apex)) {
    bool finite = offer_segment(w, i, j, best);
    finite |= offer_segment(w, j, k, best);
    finite |= offer_segment(w, k, i, best);
    return {finite, false};
  }
  // Projection of the origin onto the plane: exact up to rounding of the plane's offset.
  const S offset = w[i].dot(n);
  const Vec3T<S> p = n * (offset / nn);
  // Signed areas in the coordinate plane where the triangle's projection is largest; (x, y, z)
  // taken cyclically so the areas carry the sign of n[axis].
  int axis = 0;
  if (std::abs(n.y()) > std::abs(n[axis])) axis = 1;
  if (std::abs(n.z()) > std::abs(n[axis])) axis = 2;
  const int x = kNextCorner[axis], y = kCornerAfterNext[axis];
  // Barycentric areas from the apex (a, b, c in cyclic order, a at the largest angle): the
  // sub-area of b (b replaced by p) and of c each from an edge at the apex, the two shorter
  // edges; a's as the rest of the whole area n[axis], which triangle_cross() took from those same
  // edges. Each sub-area of a sliver taken from its longest edge, and their sum as the whole,
  // carried an error of eps |w| times that edge: on a triangle 7e16 long and 4e5 wide (a needle
  // box against a segment) the weights were off by 2e-5, and the witness point on the segment by
  // 1e11. From the apex, only the split between the two near vertices is that uncertain.
  const int order[3] = {i, j, k};
  const int a = order[apex], b = order[kNextCorner[apex]], c = order[kCornerAfterNext[apex]];
  const S px = p[x], py = p[y];
  const S ax = w[a][x], ay = w[a][y], bx = w[b][x], by = w[b][y], cx = w[c][x], cy = w[c][y];
  // (u - p) x (v - u) in the coordinate plane: the area of (p, u, v).
  const S whole = n[axis];
  const S area_b = (cx - px) * (ay - cy) - (cy - py) * (ax - cx);
  const S area_c = (ax - px) * (by - ay) - (ay - py) * (bx - ax);
  const S area_a = whole - area_b - area_c;
  // Back in the order i, j, k, in which the sums below run whatever the apex.
  S area[3];
  area[apex] = area_a;
  area[kNextCorner[apex]] = area_b;
  area[kCornerAfterNext[apex]] = area_c;
  const bool in_i = same_sign_or_zero(area[0], whole);
  const bool in_j = same_sign_or_zero(area[1], whole);
  const bool in_k = same_sign_or_zero(area[2], whole);
  const S sum = area[0] + area[1] + area[2];
  if (in_i && in_j && in_k && sum != S(0)) {
    const S weight_i = area[0] / sum, weight_j = area[1] / sum, weight_k = area[2] / sum;
    // Two candidates for the closest point: the projection p onto the plane, whose direction is
    // the plane's normal (the best normal when the shapes nearly touch and the point is tiny),
    // and the convex combination q, which is a point of A - B by construction. On a sliver
    // triangle the plane can be off by far more than rounding, and p may then lie nearer the
    // origin than any point of A - B; GJK needs |v| to stay an upper bound on the distance or
    // it stops early, too small. So take p where q lies in p's plane to rounding. Not where
    // |q| = |p| to rounding: on a long thin triangle (a box 2e5 long against a segment) the
    // weights' rounding slides q along the plane by 1e-5, which tilts q by 4e-5 rad while
    // changing |q| at second order only; searching along that q found a vertex already in the
    // simplex, and GJK stopped 0.17 short of the closest face.
    const Vec3T<S> q = weight_i * w[i] + weight_j * w[j] + weight_k * w[k];
    const S scale = std::max(
        {w[i].cwiseAbs().maxCoeff(), w[j].cwiseAbs().maxCoeff(), w[k].cwiseAbs().maxCoeff()});
    // |(q - p).n| <= 32 eps scale |n|, squared: no square root on this hot path.
    const S off_plane = q.dot(n) - offset;
    const S bound = S(32) * std::numeric_limits<S>::epsilon() * scale;
    const bool p_agrees = off_plane * off_plane <= bound * bound * nn;
    // A branch, not a select: p agrees but on slivers, and GJK's next support call waits on v,
    // which as a select waited on q's divisions and dot product as well (pairs of 8- and
    // 32-point polytopes apart: distance and contact 1.5-3 % faster).
    Vec3T<S> v;
    if (p_agrees) [[likely]]
      v = p;
    else
      v = q;
    const S dist_sq = v.squaredNorm();
    if (dist_sq < best.dist_sq) {
      take_candidate(best, v, dist_sq, (1u << i) | (1u << j) | (1u << k));
      best.weights[i] = weight_i;
      best.weights[j] = weight_j;
      best.weights[k] = weight_k;
    }
    return {dist_sq < std::numeric_limits<S>::infinity(), true};
  }
  // Outside: the closest point lies on an edge whose line has the origin's projection beyond it.
  bool finite = false;
  if (!in_i) finite |= offer_segment(w, j, k, best);
  if (!in_j) finite |= offer_segment(w, k, i, best);
  if (!in_k) finite |= offer_segment(w, i, j, best);
  if (!finite) {
    finite |= offer_segment(w, i, j, best);
    finite |= offer_segment(w, j, k, best);
    finite |= offer_segment(w, k, i, best);
  }
  return {finite, false};
}

template <class S>
[[gnu::always_inline]] inline SubSimplex<S> closest_on_triangle(const Vec3T<S>* w, int i, int j,
                                                                int k) {
  SubSimplex<S> best;
  offer_triangle(w, i, j, k, best);
  return best;
}

/// closest_on_triangle() out of line, for the rare paths: inlined everywhere, it made the GJK
/// loop's function 37 KB, larger than the instruction cache, and its speed changed by 10-25 %
/// with unrelated edits as the hot part moved about in it.
template <class S>
[[gnu::noinline]] SubSimplex<S> closest_on_triangle_cold(const Vec3T<S>* w, int i, int j, int k) {
  return closest_on_triangle(w, i, j, k);
}

/// The faces of a tetrahedron (w0, w1, w2, w3): face i leaves out vertex i.
inline constexpr int kTetrahedronFaces[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// Offers the closest point of each face of the tetrahedron w[0..4) (see offer_vertex()).
template <class S>
void offer_tetrahedron_faces(const Vec3T<S>* w, SubSimplex<S>& best) {
  for (const auto& face : kTetrahedronFaces) {
    const SubSimplex<S> candidate = closest_on_triangle_cold(w, face[0], face[1], face[2]);
    if (candidate.dist_sq < best.dist_sq) best = candidate;
  }
}

template <class S>
SubSimplex<S> closest_on_tetrahedron(const Vec3T<S>* w) {
  const Vec3T<S> e1 = w[1] - w[0], e2 = w[2] - w[0], e3 = w[3] - w[0];
  const S det = triple_product(e1, e2, e3);
  // Barycentric volumes: c[i] is the volume with w[i] replaced by the origin. Each is written as
  // a vertex dotted with a cross product of *edges*, never as a triple product of the raw
  // points: near convergence on a curved surface the points crowd within 1e-5 of each other
  // some distance from the origin, their tetrahedron's volume is ~1e-15, and w1.(w2 x w3) would
  // carry an absolute error (eps |w|^3) larger than that. The edge form keeps the error relative
  // to the (small) face areas, so the signs that pick the faces stay right.
  const Vec3T<S> f2 = w[2] - w[1], f3 = w[3] - w[1];
  const S c[4] = {triple_product(w[1], f2, f3), -triple_product(w[0], e2, e3),
                  -triple_product(w[0], e3, e1), -triple_product(w[0], e1, e2)};
  const auto& kFace = kTetrahedronFaces;
  SubSimplex<S> best;
  const bool flat =
      !(det * det > kFlatness<S> * e1.squaredNorm() * e2.squaredNorm() * e3.squaredNorm());
  if (!flat) {
    // beyond[i]: the origin lies beyond face i (its volume has the other sign).
    bool beyond[4];
    for (int i = 0; i < 4; ++i) beyond[i] = !same_sign_or_zero(c[i], det);
    const bool inside = !(beyond[0] | beyond[1] | beyond[2] | beyond[3]);
    const S sum = c[0] + c[1] + c[2] + c[3];
    if (inside && sum != S(0)) {
      best.v = Vec3T<S>::Zero();
      for (int i = 0; i < 4; ++i) best.weights[i] = c[i] / sum;
      best.mask = 0xF;
      best.dist_sq = S(0);
      return best;
    }
    // The origin lies beyond the faces whose volume has the other sign. A face it projects into
    // holds the answer: the tetrahedron lies below that face's plane, the origin above it, so no
    // point of the tetrahedron is nearer than the projection, and the other faces need no look.
    // That face is the one whose plane lies farthest from the origin (each plane's distance
    // bounds the distance to the tetrahedron from below, and that face's meets it), so it is
    // offered first. On GJK's tetrahedra of 8-point polytopes apart, index order offered 1.8
    // faces a tetrahedron; this order 1.2, the first one the answer in 85 % of them (the rest
    // are answered by an edge).
    int first = -1;
    S best_c_sq = S(0), best_nn = S(1);
    for (int i = 0; i < 4; ++i) {
      if (!beyond[i]) continue;
      // The plane's distance is |c_i| / |n_i| up to a common factor, compared squared and by
      // cross products: no root or division on the way to the face. An overflow or underflow
      // only leaves the order as it was.
      const Vec3T<S>& p = w[kFace[i][0]];
      const S nn = Vec3T<S>(w[kFace[i][1]] - p).cross(Vec3T<S>(w[kFace[i][2]] - p)).squaredNorm();
      const S c_sq = c[i] * c[i];
      if (first < 0 || c_sq * best_nn > best_c_sq * nn) {
        first = i;
        best_c_sq = c_sq;
        best_nn = nn;
      }
    }
    if (first >= 0 &&
        offer_triangle(w, kFace[first][0], kFace[first][1], kFace[first][2], best).interior &&
        best.mask != 0)
      return best;
    for (int i = 0; i < 4; ++i)
      if (beyond[i] && i != first &&
          offer_triangle(w, kFace[i][0], kFace[i][1], kFace[i][2], best).interior && best.mask != 0)
        return best;
    if (best.mask != 0) return best;
  }
  offer_tetrahedron_faces(w, best);
  return best;
}

/// The point of the simplex w[0..size) closest to the origin, with the sub-simplex that holds it.
template <class S>
[[gnu::always_inline]] inline SubSimplex<S> closest_of_simplex(const Vec3T<S>* w, int size) {
  switch (size) {
    case 1:
      return closest_on_vertex(w, 0);
    case 2:
      return closest_on_segment(w, 0, 1);
    case 3:
      return closest_on_triangle(w, 0, 1, 2);
    default:
      return closest_on_tetrahedron(w);
  }
}

/// The vertices of a simplex of `n` points `w` that the closest point to the origin needs: their
/// indices in increasing order with their weights, and the point. When every weight rounded to
/// zero, the vertex closest to the origin alone.
template <class S>
struct KeptVertices {
  int index[4];
  S weight[4];
  int count = 0;
  Vec3T<S> v;
};

template <class S>
[[gnu::always_inline]] inline KeptVertices<S> vertices_to_keep(const SubSimplex<S>& r,
                                                               const Vec3T<S>* w, int n) {
  KeptVertices<S> kept;
  for (int i = 0; i < n; ++i) {
    if ((r.mask >> i & 1u) && r.weights[i] > S(0)) {
      kept.index[kept.count] = i;
      kept.weight[kept.count] = r.weights[i];
      ++kept.count;
    }
  }
  kept.v = r.v;
  if (kept.count == 0) {
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (w[i].squaredNorm() < w[best].squaredNorm()) best = i;
    kept.index[0] = best;
    kept.weight[0] = S(1);
    kept.count = 1;
    kept.v = w[best];
  }
  return kept;
}

/// The unit direction of -v, where v (|v| > 0) is the point of the reduced simplex closest to the
/// origin: the direction from A's closest point to B's. v is computed from support points some L
/// from the origin, so it carries rounding of eps L in every direction, which tilts it by
/// eps L / |v| when the cores nearly meet; a tilt out of the closest feature's normal plane costs
/// the feature's extent times the tilt (a sphere centre 1e-10 above a rounded box's core face).
/// But the closest point is interior to the reduced simplex, so -v is exactly orthogonal to it:
/// a segment's direction is projected out, and a triangle's normal comes from its edges' cross
/// product (make_orthogonal).
template <class S>
Vec3T<S> separation_direction(const SimplexT<S>& simplex, const Vec3T<S>& v) {
  if (v == Vec3T<S>::Zero()) return Vec3T<S>::UnitZ();  // no simplex: any unit vector
  Vec3T<S> n = -v;
  const Vec3T<S> zero = Vec3T<S>::Zero();
  const Vec3T<S> e1 =
      simplex.size >= 2 ? Vec3T<S>(simplex.vertices[1].w - simplex.vertices[0].w) : zero;
  const Vec3T<S> e2 =
      simplex.size >= 3 ? Vec3T<S>(simplex.vertices[2].w - simplex.vertices[0].w) : zero;
  // Nothing left but rounding (v was rounding itself): keep -v.
  if (simplex.size == 4 || !make_orthogonal(n, e1, e2)) {
    n = -unit_of(v);  // (tiny or huge v: unit_of() keeps n unit)
  }
  return n;
}

/// closest_vertices() below for a count known at compile time: the copies and
/// vertices_to_keep()'s loops then unroll for the case at hand (pairs of 8-point polytopes apart:
/// 3 % fewer instructions a distance or contact query, and 2.5-3 % faster in a driver).
template <int kCount, class S>
[[gnu::always_inline]] inline KeptVertices<S> closest_vertices_of(const SimplexT<S>& in) {
  Vec3T<S> w[4];
  for (int i = 0; i < kCount; ++i) w[i] = in.vertices[i].w;
  return vertices_to_keep(closest_of_simplex(w, kCount), w, kCount);
}

/// The vertices of the first `n` points of `in` that hold the point of their hull closest to the
/// origin, with their weights, and that point. `n` may be in.size + 1: the point stored past the
/// end, which the GJK loop appends there until it knows the step makes progress.
template <class S>
[[gnu::always_inline]] inline KeptVertices<S> closest_vertices(const SimplexT<S>& in, int n) {
  switch (n) {
    case 1:
      return closest_vertices_of<1>(in);
    case 2:
      return closest_vertices_of<2>(in);
    case 3:
      return closest_vertices_of<3>(in);
    default:
      return closest_vertices_of<4>(in);
  }
}

/// Writes the vertices `kept` of `in` with their weights to `out`, which may be `in`: indices
/// increase and index[j] >= j, so copying in place is safe, and moves only the vertices whose
/// place changes.
template <class S>
[[gnu::always_inline]] inline void keep_vertices(const SimplexT<S>& in, const KeptVertices<S>& kept,
                                                 SimplexT<S>& out) {
  for (int j = 0; j < kept.count; ++j) {
    if (&out != &in || kept.index[j] != j) out.vertices[j] = in.vertices[kept.index[j]];
    out.weights[j] = kept.weight[j];
  }
  out.size = kept.count;
}

/// Writes to `out` the smallest sub-simplex of `in` whose hull holds the point of `in` closest to
/// the origin, with its weights, and returns that point. `in` and `out` may be the same simplex.
template <class S>
[[gnu::always_inline]] inline Vec3T<S> reduce_to_closest(const SimplexT<S>& in, SimplexT<S>& out) {
  const KeptVertices<S> kept = closest_vertices(in, in.size);
  keep_vertices(in, kept, out);
  return kept.v;
}

/// Reduces the tetrahedron `simplex` (size 4) to the closest point of its face nearest the origin,
/// with that face's weights. For a tetrahedron that holds the origin
/// (GJK's last simplex for cores that touch), so that its witness points lie on the touching
/// features: touching puts the four points on the plane of contact, and the origin's weights
/// in so thin a tetrahedron carry the rounding divided by its thickness (they put a cylinder's
/// point 6e-4 of the size along a box's face from the box's point, and their midpoint 4e-9 of
/// the size off the cylinder). A face's weights are the origin's projection into that plane.
template <class S>
[[gnu::noinline]] void reduce_to_nearest_face(SimplexT<S>& simplex) {
  Vec3T<S> w[4];
  for (int i = 0; i < 4; ++i) w[i] = simplex.vertices[i].w;
  SubSimplex<S> best;
  best.v.setZero();  // read only when no face offers a finite point: the nearest vertex then
  offer_tetrahedron_faces(w, best);
  keep_vertices(simplex, vertices_to_keep(best, w, 4), simplex);
}

/// reduce_to_closest() out of line, for the rare paths of the GJK loop (warm start,
/// recombination): see closest_on_triangle_cold().
template <class S>
[[gnu::noinline]] Vec3T<S> reduce_to_closest_cold(const SimplexT<S>& in, SimplexT<S>& out) {
  return reduce_to_closest(in, out);
}

}  // namespace mink::detail
