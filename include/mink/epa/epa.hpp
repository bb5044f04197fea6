/// @file epa.hpp
/// The Expanding Polytope Algorithm (van den Bergen 2001): penetration depth and direction of two
/// intersecting cores, seeded by GJK's final simplex.
///
/// The penetration depth of A and B is the distance from the origin to the boundary of A - B, and
/// the direction B must move to separate is the outward normal of A - B there. EPA keeps a convex
/// polytope P inside A - B (a triangle mesh of support points) and repeatedly pushes out its face
/// nearest the origin by the support point of A - B along that face's normal, until the push
/// gains less than the tolerance. Two bounds bracket the answer at every step: the nearest face's
/// distance d (P lies inside A - B) and the smallest support value h(n) = max over A - B of n.x
/// seen along a face normal (every direction's support bounds the depth from above). The result
/// reports both, so a capped run says how far it can be off.
///
/// Robustness, in the order the failures show up in other libraries:
///   - GJK often ends with fewer than 4 points (touching, flat or needle shapes). The seed grows
///     the simplex with support points along directions orthogonal to it into a tetrahedron;
///     when no direction leaves a plane, a line or a point, A - B is flat there, the core depth is
///     0 and the normal is a direction of that degenerate set (the choice is documented in
///     contact.hpp).
///   - Face distances are signed, so an origin on the boundary of P, or just outside it (touching
///     within tolerance), needs no special case: the face it lies beyond has d <= 0 and is pushed
///     out first.
///   - Every expansion is checked before it is committed: the visible region must have a single
///     loop for its horizon, and every new face must have a normal and keep P convex. A horizon
///     face the new point lies in the plane of (a reflex, degenerate or folded new face) joins the
///     visible region and the expansion is tried again; if that does not help, the expansion is
///     undone and EPA stops with the bracket it has.
///   - Every loop is capped (tolerances.max_epa_iterations support calls), and the cap is a status.
///     A run that stops with its bracket open answers with the upper end (the least support
///     value seen and its direction), which always separates the shapes; the nearest face is only
///     a lower bound and its normal can be far from the answer.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "mink/epa/inner_ball.hpp"
#include "mink/gjk/gjk.hpp"
#include "mink/gjk/segment_cores.hpp"
#include "mink/gjk/separation.hpp"
#include "mink/gjk/support_descent.hpp"
#include "mink/math/least_index.hpp"
#include "mink/math/orthogonal.hpp"

namespace mink::detail {

template <class S>
struct EpaFace {
  /// Leaves the fields unset: make_epa_face() sets every one, and the zeroing that
  /// `emplace_back()` otherwise does was a tenth of the cost of a face.
  EpaFace() {}

  int v[3];         ///< vertex indices, counter-clockwise seen from outside P
  int adj[3];       ///< face across edge i (from v[i] to v[(i + 1) % 3])
  int adj_edge[3];  ///< index of that edge in the neighbour
  Vec3T<S> n;       ///< outward normal, not normalised (the square root waits until needed)
  S nn;             ///< |n|^2
  S offset;         ///< n . v[0]: the plane is n . x = offset
  int slot;         ///< position in the workspace's open list, while live
  bool live;

  /// Signed distance of the origin below the face's plane (> 0: the origin is inside).
  /// length_of() and unit_of(): on shapes of 1e-80, nn is a product of four such coordinates,
  /// subnormal, and its plain root left the normal 5e-8 off unit.
  S distance() const { return offset / length_of(n, nn); }
  Vec3T<S> unit_normal() const { return unit_of(n, nn, length_of(n, nn)); }
};

/// Scratch memory of one EPA run, kept per thread so that queries do not allocate once warm.
template <class S>
struct EpaWorkspace {
  std::vector<SimplexVertexT<S>> vertices;
  std::vector<EpaFace<S>> faces;
  struct Horizon {
    int face, edge;
  };
  // The scratch of one expansion. make_room() sizes it for the worst case, and the expansion
  // writes it through raw pointers with counts of its own: with push_back() and the vectors'
  // own indexing, every store into a face made the compiler reload the vectors' pointers, and
  // the bookkeeping cost more than the arithmetic of the faces.
  std::vector<int> removed;  ///< faces removed by the current expansion
  std::vector<int> stack;
  std::vector<Horizon> horizon;
  std::vector<int> forced;  ///< faces taken into the visible region to keep P convex
  /// Vertex -> the new face of the current expansion that starts there, or -1 (all -1 between
  /// expansions).
  std::vector<int> starting_at;
  /// The live faces of P, packed: their keys (the signed squared distance of the origin below
  /// the face's plane, d |d|, which orders them as d does with no square root) and indices, in
  /// the same order.
  /// The nearest face is found by a scan with no branch on the keys: a binary heap's sifts
  /// mispredicted about 150 branches per query on hull pairs. The first `open_count` entries are
  /// the list; clear() and make_room() size the vectors for it, so that a face joins and leaves
  /// it without push_back()'s check of the capacity (a twentieth of EPA's time on pairs of
  /// 8-point polytopes).
  std::vector<S> open_keys;
  std::vector<int> open_faces;
  int open_count = 0;

  /// Empties P; room for the seed's four open faces.
  void clear() {
    vertices.clear();
    faces.clear();
    open_count = 0;
    if (open_keys.size() < 4) {
      open_keys.resize(64);
      open_faces.resize(64);
    }
  }

  /// Sizes the scratch for an expansion of the current P: its region holds at most every face,
  /// its horizon at most three edges of each (so at most that many new faces join the open
  /// list), and every vertex may start a new face.
  void make_room() {
    const std::size_t face_count = faces.size();
    if (removed.size() < face_count) {
      removed.resize(2 * face_count);
      stack.resize(2 * face_count);
    }
    if (horizon.size() < 3 * face_count) horizon.resize(6 * face_count);
    if (open_keys.size() < 4 * face_count) {
      open_keys.resize(8 * face_count);
      open_faces.resize(8 * face_count);
    }
    if (starting_at.size() < vertices.size()) starting_at.resize(2 * vertices.size(), -1);
  }

  void enqueue(int face) {
    EpaFace<S>& open = faces[face];
    open.slot = open_count;
    open_keys[open_count] = open.offset * std::abs(open.offset) / open.nn;
    open_faces[open_count] = face;
    ++open_count;
  }

  /// Takes a face out of the open list: the last one moves into its slot.
  void retire(int face) {
    const int slot = faces[face].slot;
    const int last = --open_count;
    const int moved = open_faces[last];
    open_keys[slot] = open_keys[last];
    open_faces[slot] = moved;
    faces[moved].slot = slot;
  }

  /// The live face nearest the origin.
  int nearest() const {
    return open_faces[least_index(open_keys.data(), static_cast<std::size_t>(open_count))];
  }
};

template <class S>
EpaWorkspace<S>& epa_workspace() {
  thread_local EpaWorkspace<S> workspace;
  return workspace;
}

template <class S>
struct EpaOutcome {
  /// Intersecting: converged, the bracket [lower, upper] within the tolerance; IterationLimit:
  /// the cap was hit or an expansion failed with the bracket open, and depth, normal and points
  /// are the upper end's (see run_epa); InvalidInput: the arithmetic overflowed.
  Status status = Status::Intersecting;
  S depth = S(0);  ///< the core depth: the lower bound when converged (may be slightly < 0)
  S lower = S(0);  ///< lower bound on the core depth
  S upper = S(0);  ///< upper bound on the core depth
  Vec3T<S> normal = Vec3T<S>::UnitZ();  ///< unit, A's frame: the direction B moves to separate
  Vec3T<S> a = Vec3T<S>::Zero();        ///< deepest point of A's core (A's frame)
  Vec3T<S> b = Vec3T<S>::Zero();        ///< deepest point of B's core (A's frame)
  int iterations = 0;                   ///< support calls
  bool degenerate = false;  ///< A - B is flat, a segment or a point: the normal was chosen
  /// Converged on a facet of A - B (on_facet(), below): depth and normal are exact to rounding,
  /// and contact() takes the features' witness pair along the normal instead of Newton's steps.
  bool on_facet = false;
  /// Closed by Newton's steps and the cores' inner ball (inner_ball.hpp): depth, normal and
  /// points are exact to rounding.
  bool proven_by_ball = false;
  /// Where Newton's steps ran for the balls, kept steps, and the balls did not prove them: their
  /// answer (support value, unit normal, witness pair), for contact()'s refinement.
  std::optional<SupportMinimum<S>> newton;
};

/// How far inside its face of P (relative to the size) the origin's projection must lie for
/// on_facet() to call that face part of a facet of A - B.
inline constexpr double kFacetInset = 1e-3;

/// Whether EPA's answer lies on a facet of A - B, a flat part of its boundary, where it is exact:
/// the bracket closed to rounding (`upper - lower`, 64 eps of the size), and the origin's
/// projection p lies inside the face of P that holds it (barycentrics `lambda` of its corners
/// `w`), at least kFacetInset of the size from each edge. The face's plane then supports A - B
/// to rounding, so the three corners lie on one facet with p among them, and any normal tilted
/// by t from the face's raises the support value by t times p's distance to the edges: within
/// the bracket only by 64 eps / 1e-3, 1.4e-11 rad. A face that tiny steps have made on a curved
/// part of A - B also closes to rounding (its sag is below it once it is 3e-7 of the size
/// across) but is far narrower than the inset, and there the normal is only as good as the
/// square root of the bracket, which is what contact()'s Newton steps are for. On curved pairs
/// this spared those steps (12-17 support calls) on a fifth to a half of the penetrating pairs of
/// a box or cylinder with a cylinder or cone (a box's face against a rim).
template <class S>
bool on_facet(S upper, S lower, S size, const Vec3T<S> (&w)[3], const S (&lambda)[3],
              S twice_area) {
  if (!(upper - lower <= S(64) * std::numeric_limits<S>::epsilon() * size)) return false;
  const S inset = S(kFacetInset) * size;
  for (int k = 0; k < 3; ++k) {
    // p's distance to the edge opposite corner k is lambda_k times the altitude onto it,
    // twice_area / |edge|.
    const S edge = (w[kCornerAfterNext[k]] - w[kNextCorner[k]]).norm();
    if (!(lambda[k] * twice_area >= inset * edge)) return false;
  }
  return true;
}

/// EPA's bracket, relative to the size, at which cores with an inner ball try Newton's steps and
/// the ball (inner_ball.hpp), once. Newton's steps from its nearest face's normal converge there
/// (1e-2 rad off at most); EPA took 4-8 support calls to it on two ellipsoids, and 30-50 to
/// 1e-10 of the size.
inline constexpr double kInnerBallHandOff = 1e-4;

/// Tries per expansion before EPA gives up on keeping P convex and stops with its bracket.
inline constexpr int kMaxExpansionAttempts = 8;

/// Unit normal of the triangle (p, q, r), counter-clockwise; false when it has no area to
/// rounding.
template <class S>
bool triangle_normal(const Vec3T<S>& p, const Vec3T<S>& q, const Vec3T<S>& r, Vec3T<S>& n) {
  S nn;
  if (!triangle_cross(p, q, r, n, nn)) return false;
  n = unit_of(n, nn, length_of(n, nn));
  return true;
}

/// The unit normal of triangle (p, q, r) from its longest edge, along unit u, and the part of the
/// third vertex's offset across it, f: u x f. For a sliver, the cross product of two edges is off
/// by eps times its length over its width in every direction (1e-9 rad across a sliver 12 long and
/// 3e-6 wide, which, levered by the length, put its ends 4e-10 off the plane); this one is off by
/// that much only about u, where the lever is the width. False when the triangle has no width.
template <class S>
bool sliver_normal(const Vec3T<S>& p, const Vec3T<S>& q, const Vec3T<S>& r, Vec3T<S>& n) {
  // triangle_cross() names the longest edge by the vertex opposite it; its flatness verdict is
  // not wanted here.
  Vec3T<S> unused;
  S unused_sq;
  int apex = 0;
  triangle_cross(p, q, r, unused, unused_sq, &apex);
  const Vec3T<S>* corners[3] = {&p, &q, &r};
  const Vec3T<S>& start = *corners[kNextCorner[apex]];
  const Vec3T<S> u = unit_of(Vec3T<S>(*corners[kCornerAfterNext[apex]] - start));
  if (!is_finite(u)) return false;
  const Vec3T<S> cross = u.cross(part_across(Vec3T<S>(*corners[apex] - start), u));
  if (!(cross.squaredNorm() > S(0))) return false;
  n = unit_of(cross);
  return is_finite(n);
}

/// Of n and -n, the one along which A - B's support value is smaller (n . up against -n . down,
/// `up` and `down` its support points along n and -n): a flat A - B's better normal.
template <class S>
Vec3T<S> side_of_smaller_support(const Vec3T<S>& n, const Vec3T<S>& up, const Vec3T<S>& down) {
  return n.dot(up) <= -n.dot(down) ? n : Vec3T<S>(-n);
}

/// Builds face (i, j, k) of `vertices` in `face`, or returns false if it is degenerate. Its
/// neighbours are the caller's to link. Built in place: a face assembled on the stack and copied
/// in costs a store-forwarding stall per field, which was a sixth of EPA's time.
template <class S>
[[gnu::always_inline]] inline bool make_epa_face(EpaFace<S>& face,
                                                 const SimplexVertexT<S>* vertices, int i, int j,
                                                 int k) {
  const Vec3T<S>& p = vertices[i].w;
  const Vec3T<S>& q = vertices[j].w;
  const Vec3T<S>& r = vertices[k].w;
  Vec3T<S> n;
  S nn;
  if (!triangle_cross(p, q, r, n, nn)) return false;
  face.n = n;
  face.nn = nn;
  face.v[0] = i;
  face.v[1] = j;
  face.v[2] = k;
  // The plane's offset from all three vertices: less sensitive to which one is farthest.
  face.offset = n.dot(p + q + r) / S(3);
  face.live = true;
  return true;
}

/// The seed tetrahedron over vertices 0..3 as a mesh: its faces, counter-clockwise seen from
/// outside, and across each face's edge e (from v[e] to v[e + 1]) the neighbour and the index of
/// the shared edge there. Fixed tables, one per orientation: linking faces by searching for
/// shared edges cost a dozen mispredicted branches per query.
struct TetrahedronMesh {
  int v[4][3];
  int adj[4][3];
  int adj_edge[4][3];
};

/// `flip`: whether (0, 1, 2) faces vertex 3 (a positive volume), so every face turns over.
constexpr TetrahedronMesh tetrahedron_mesh(bool flip) {
  constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  TetrahedronMesh m{};
  for (int f = 0; f < 4; ++f) {
    m.v[f][0] = kFaces[f][0];
    m.v[f][1] = kFaces[f][flip ? 2 : 1];
    m.v[f][2] = kFaces[f][flip ? 1 : 2];
  }
  for (int f = 0; f < 4; ++f)
    for (int e = 0; e < 3; ++e) {
      m.adj[f][e] = -1;
      const int from = m.v[f][e], to = m.v[f][(e + 1) % 3];
      for (int g = 0; g < 4; ++g)
        for (int k = 0; k < 3; ++k)
          if (g != f && m.v[g][k] == to && m.v[g][(k + 1) % 3] == from) {
            m.adj[f][e] = g;
            m.adj_edge[f][e] = k;
          }
    }
  return m;
}

inline constexpr TetrahedronMesh kTetrahedron[2] = {tetrahedron_mesh(false),
                                                    tetrahedron_mesh(true)};

constexpr bool closed_mesh(const TetrahedronMesh& m) {
  for (int f = 0; f < 4; ++f)
    for (int e = 0; e < 3; ++e)
      if (m.adj[f][e] < 0 || m.adj[m.adj[f][e]][m.adj_edge[f][e]] != f) return false;
  return true;
}
static_assert(closed_mesh(kTetrahedron[0]) && closed_mesh(kTetrahedron[1]));

/// Removes, of the three points of a sliver triangle, the one nearest the segment of the other two
/// (the middle one), leaving the segment to grow from.
template <class S>
void drop_middle_point(std::vector<SimplexVertexT<S>>& vertices) {
  int middle = 0;
  S nearest = std::numeric_limits<S>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Vec3T<S>& p = vertices[i].w;
    const Vec3T<S>& q = vertices[(i + 1) % 3].w;
    const Vec3T<S>& r = vertices[(i + 2) % 3].w;
    const Vec3T<S> e = r - q;
    const S ee = e.squaredNorm();
    const S t = ee > S(0) ? std::clamp((p - q).dot(e) / ee, S(0), S(1)) : S(0);
    const S gap = (p - q - t * e).squaredNorm();
    if (gap < nearest) {
      nearest = gap;
      middle = i;
    }
  }
  vertices.erase(vertices.begin() + middle);
}

/// Removes one point of the closest pair among the seed's four (the later one), leaving a
/// triangle to grow from.
template <class S>
void drop_closest_pair_point(std::vector<SimplexVertexT<S>>& vertices) {
  int drop = 3;
  S closest = std::numeric_limits<S>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const S gap = (vertices[i].w - vertices[j].w).squaredNorm();
      if (gap < closest) {
        closest = gap;
        drop = j;
      }
    }
  vertices.erase(vertices.begin() + drop);
}

/// Builds P as the tetrahedron of the 4 points of the workspace. Returns false on degeneracy.
template <class S>
bool seed_polytope(EpaWorkspace<S>& ws) {
  // Orient all faces by one decision, the sign of the volume: testing each face against the
  // centroid is unreliable on a sliver (a needle 1e-9 thick), where rounding of a face normal
  // moves it by more than the centroid's distance to the face, and one flipped face breaks the
  // mesh.
  // The sign is taken in S when the volume clears its rounding error (16 eps |e1| |e2| |e3|
  // bounds it generously), else in long double: on such a sliver the volume is ~1e-17 while
  // double rounding of the triple product is ~1e-16 (the seed's vertices are 1e-12 of the size
  // off each other's planes at least, which long double resolves).
  const Vec3T<S>& w0 = ws.vertices[0].w;
  const Vec3T<S> e1 = ws.vertices[1].w - w0, e2 = ws.vertices[2].w - w0, e3 = ws.vertices[3].w - w0;
  const S volume = e1.dot(e2.cross(e3));
  const S rounding = S(16) * std::numeric_limits<S>::epsilon();
  bool flip = volume > S(0);  // then (0, 1, 2) faces vertex 3: inwards
  if (!(volume * volume >
        rounding * rounding * e1.squaredNorm() * e2.squaredNorm() * e3.squaredNorm())) {
    using Wide = long double;
    const Vec3T<Wide> wide0 = w0.template cast<Wide>();
    flip = (ws.vertices[1].w.template cast<Wide>() - wide0)
               .dot((ws.vertices[2].w.template cast<Wide>() - wide0)
                        .cross(ws.vertices[3].w.template cast<Wide>() - wide0)) > Wide(0);
  }
  const TetrahedronMesh& mesh = kTetrahedron[flip ? 1 : 0];
  const int first = static_cast<int>(ws.faces.size());
  ws.faces.resize(first + 4);
  for (int f = 0; f < 4; ++f)
    if (!make_epa_face(ws.faces[first + f], ws.vertices.data(), mesh.v[f][0], mesh.v[f][1],
                       mesh.v[f][2])) {
      ws.faces.resize(first);
      return false;
    }
  for (int f = 0; f < 4; ++f) {
    EpaFace<S>& face = ws.faces[first + f];
    for (int e = 0; e < 3; ++e) {
      face.adj[e] = first + mesh.adj[f][e];
      face.adj_edge[e] = mesh.adj_edge[f][e];
    }
    ws.enqueue(first + f);
  }
  return true;
}

/// Pushes `face` of P out to the support point w beyond it: removes the faces w sees (a
/// connected region grown from `face`) and closes the hole with new faces from its horizon to w.
/// A neighbour that w does not see but that would meet the new faces at a reflex angle, with no
/// area or folded back (w lies within rounding of its plane: a curved core near convergence, a
/// flat facet sampled at several points) is added to the region and the expansion tried again.
/// Returns false, with P unchanged, if that does not give a valid convex P. `size` is EPA's (the
/// sum of the bounding radii), `flat_tol` its flatness tolerance (unit: length).
template <class S>
bool expand_polytope(EpaWorkspace<S>& ws, int face, const SimplexVertexT<S>& w, S size,
                     S flat_tol) {
  const int wi = static_cast<int>(ws.vertices.size());
  ws.vertices.push_back(w);
  ws.forced.clear();
  ws.make_room();
  // The new faces take the slots from `first_new` on, in horizon order.
  const int first_new = static_cast<int>(ws.faces.size());
  const SimplexVertexT<S>* const vertices = ws.vertices.data();
  int* const removed = ws.removed.data();
  int* const stack = ws.stack.data();
  typename EpaWorkspace<S>::Horizon* const horizon = ws.horizon.data();
  int* const starting_at = ws.starting_at.data();
  // `face` is the nearest: when the origin is below it, it is inside P (every face's signed
  // distance is at least this one's), unless rounding has already bent P. Not so when the cores
  // only touch or are just apart and EPA decides (contact.hpp): the origin may then lie outside P,
  // and faces of needles 1e-7 thick are bent by rounding at 1e-10 of the size. So only an origin
  // deeper than 1e-7 of the size counts as held.
  const S held_depth = S(1e-7) * size;
  const S nearest_offset = ws.faces[face].offset;
  const bool holds_origin =
      nearest_offset > S(0) &&
      nearest_offset * nearest_offset > held_depth * held_depth * ws.faces[face].nn;
  bool valid = false;
  int created_count = 0, removed_count = 0;
  for (int attempt = 0; attempt < kMaxExpansionAttempts; ++attempt) {
    EpaFace<S>* faces = ws.faces.data();
    int stack_count = 0, horizon_count = 0;
    removed_count = 0;
    faces[face].live = false;
    removed[removed_count++] = face;
    stack[stack_count++] = face;
    while (stack_count > 0) {
      const int f = stack[--stack_count];
      for (int e = 0; e < 3; ++e) {
        const int g = faces[f].adj[e];
        if (!faces[g].live) continue;
        const bool forced = !ws.forced.empty() &&
                            std::find(ws.forced.begin(), ws.forced.end(), g) != ws.forced.end();
        if (forced || faces[g].n.dot(w.w) - faces[g].offset > S(0)) {
          faces[g].live = false;
          removed[removed_count++] = g;
          stack[stack_count++] = g;
        } else {
          horizon[horizon_count++] = {g, faces[f].adj_edge[e]};
        }
      }
    }
    // New faces over the horizon, checked before anything is linked.
    valid = horizon_count >= 3;
    int reflex = -1;
    ws.faces.resize(first_new + horizon_count);
    faces = ws.faces.data();
    created_count = 0;
    for (int h_i = 0; valid && h_i < horizon_count; ++h_i) {
      const auto [g, k] = horizon[h_i];
      const int from = faces[g].v[kNextCorner[k]], to = faces[g].v[k];
      const int far = faces[g].v[kCornerAfterNext[k]];
      EpaFace<S>& created = faces[first_new + created_count];
      if (!make_epa_face(created, vertices, from, to, wi)) {
        // w lies on the line of the horizon edge, so in the plane of g: a flat face of A - B
        // sampled at an interior point (the centre of a cylinder's cap) and then at two rim
        // points on either side of it. Taking g into the region retriangulates that plane.
        valid = false;
        reflex = g;
        break;
      }
      ++created_count;
      created.adj[0] = g;
      created.adj_edge[0] = k;
      // Convexity across the horizon edge: the neighbour's far vertex is below the new face.
      // When it lies in the new face's plane (w is in g's plane: a flat facet of A - B sampled
      // at several points), the two faces must also face the same way: opposite normals mean
      // the new face folds back over g, and P would turn inside out there.
      const S above = created.n.dot(vertices[far].w) - created.offset;
      const bool off_plane = above * above > flat_tol * flat_tol * created.nn;
      // And the origin below the new face, when P holds it: P only grows, so a face with the
      // origin beyond it by more than rounding says that P has stopped being convex (w nearly in
      // the plane of a large flat facet of A - B, sampled again and again, made new faces over a
      // horizon that folds). The neighbour joins the region, and the fan is built over a wider
      // horizon. Rounding here is the plane's: a sliver's normal is off by about eps over the
      // sine of its angle (1e-8 across a needle's width), which moves the plane at the origin by
      // eps size / sine, i.e. eps size |e1| |e2| / |n|.
      auto beyond_rounding = [&] {
        if (!holds_origin || !(created.offset < S(0)) ||
            !(created.offset * created.offset > flat_tol * flat_tol * created.nn))
          return false;
        const Vec3T<S>& w0 = vertices[created.v[0]].w;
        const S plane_error = S(64) * std::numeric_limits<S>::epsilon() * size;
        return created.offset * created.offset > plane_error * plane_error *
                                                     (vertices[created.v[1]].w - w0).squaredNorm() *
                                                     (vertices[created.v[2]].w - w0).squaredNorm();
      };
      if ((off_plane ? above > S(0) : created.n.dot(faces[g].n) < S(0)) || beyond_rounding()) {
        valid = false;
        reflex = g;
        break;
      }
    }
    // The horizon must be one simple loop: each new face's edge 1 (to -> w) meets exactly one
    // other new face's edge 2 (w -> from), i.e. every horizon vertex starts exactly one new
    // face. Found through a table from vertex to the new face that starts there: comparing
    // all pairs cost about fifty mispredicted branches per query. A simple loop links every new
    // face on both sides, so make_epa_face() need not mark the links unset.
    for (int c = first_new; valid && c < first_new + created_count; ++c) {
      int& slot = starting_at[faces[c].v[0]];
      if (slot >= 0) valid = false;  // two new faces start at one vertex: not a simple loop
      slot = c;
    }
    for (int c = first_new; valid && c < first_new + created_count; ++c) {
      const int match = starting_at[faces[c].v[1]];
      if (match < 0) {
        valid = false;
        break;
      }
      faces[c].adj[1] = match;
      faces[c].adj_edge[1] = 2;
      faces[match].adj[2] = c;
      faces[match].adj_edge[2] = 1;
    }
    for (int c = first_new; c < first_new + created_count; ++c) starting_at[faces[c].v[0]] = -1;
    if (valid) break;
    // Undo this attempt: drop the new faces, revive the removed ones.
    ws.faces.resize(first_new);
    for (int r = 0; r < removed_count; ++r) faces[removed[r]].live = true;
    if (reflex < 0) break;
    ws.forced.push_back(reflex);
  }
  if (!valid) {
    ws.vertices.pop_back();
    return false;
  }
  for (int r = 0; r < removed_count; ++r) ws.retire(removed[r]);
  EpaFace<S>* const faces = ws.faces.data();
  for (int c = first_new; c < first_new + created_count; ++c) {
    const EpaFace<S>& created = faces[c];
    EpaFace<S>& neighbour = faces[created.adj[0]];
    neighbour.adj[created.adj_edge[0]] = c;
    neighbour.adj_edge[created.adj_edge[0]] = 0;
    ws.enqueue(c);
  }
  return true;
}

/// EPA on the cores of `diff`, seeded by GJK's final `simplex` (the cores intersect or touch
/// within tolerance). `size` is the sum of the bounding radii; the expansion stops when a push
/// gains at most `tol.relative_depth * size`. `fallback` is the normal to use when A - B is a
/// point (any direction is as good): the line of centres, or any unit vector.
template <ConvexShape A, ConvexShape B>
EpaOutcome<typename A::Scalar> run_epa(const CoreDifference<A, B>& diff,
                                       const SimplexT<typename A::Scalar>& simplex,
                                       typename A::Scalar size,
                                       const TolerancesT<typename A::Scalar>& tol,
                                       const Vec3T<typename A::Scalar>& fallback) {
  using S = typename A::Scalar;
  EpaOutcome<S> out;
  EpaWorkspace<S>& ws = epa_workspace<S>();
  ws.clear();
  ws.faces.reserve(128);
  const S gain_tol = tol.relative_depth * size;
  // A support point adds volume only if it leaves the current affine hull by more than this.
  const S flat_tol = tol.relative * size;

  for (int i = 0; i < simplex.size; ++i) ws.vertices.push_back(simplex.vertices[i]);
  // Witness points of the degenerate answers: the point of GJK's simplex nearest the origin.
  Vec3T<S> gjk_a, gjk_b;
  simplex.witness_points(gjk_a, gjk_b);
  // EPA's directions jump from face to face: scans find their index with no branch.
  auto support = [&](const Vec3T<S>& d) {
    SimplexVertexT<S> vertex;
    diff.template support<SupportPattern::Scattered>(d, vertex);
    ++out.iterations;
    return vertex;
  };
  // A - B has no volume near the origin: the core depth is its support value along `normal`
  // (about 0), the points GJK's.
  auto degenerate = [&](const Vec3T<S>& normal) {
    out.degenerate = true;
    out.normal = normal;
    out.a = gjk_a;
    out.b = gjk_b;
    const S h = normal.dot(support(normal).w);
    out.depth = out.lower = std::min(S(0), h);
    out.upper = std::max(S(0), h);
    return out;
  };

  // 1. Grow GJK's simplex to a full-dimensional seed.
  if (ws.vertices.empty()) ws.vertices.push_back(support(fallback));
  if (ws.vertices.size() == 4) {
    const Vec3T<S> e1 = ws.vertices[1].w - ws.vertices[0].w;
    const Vec3T<S> e2 = ws.vertices[2].w - ws.vertices[0].w;
    const Vec3T<S> e3 = ws.vertices[3].w - ws.vertices[0].w;
    const S det = e1.dot(e2.cross(e3));
    if (!(det * det > kFlatness<S> * e1.squaredNorm() * e2.squaredNorm() * e3.squaredNorm())) {
      // Flat tetrahedron: keep the triangle with the largest area and grow it again.
      int drop = 0;
      S best = S(-1);
      for (int skip = 0; skip < 4; ++skip) {
        int idx[3], m = 0;
        for (int i = 0; i < 4; ++i)
          if (i != skip) idx[m++] = i;
        const S area = (ws.vertices[idx[1]].w - ws.vertices[idx[0]].w)
                           .cross(ws.vertices[idx[2]].w - ws.vertices[idx[0]].w)
                           .squaredNorm();
        if (area > best) {
          best = area;
          drop = skip;
        }
      }
      ws.vertices.erase(ws.vertices.begin() + drop);
    }
  }
  // Each stage adds the support point that leaves the current affine hull the most. A seed that
  // still has a face too thin to orient (a triangle 1e-12 of the size across: a box 1e8 long whose
  // GJK simplex put two points 2e-4 apart) is grown again without the nearer of its closest pair,
  // up to kMaxRegrows times; giving up instead answered depth 0 for a disk sunk 0.33 into it.
  constexpr int kMaxRegrows = 2;
  int regrows = 0;
  // The last triangle tried, and whether there was one: its plane is the answer when no seed can
  // be built.
  Vec3T<S> last_triangle[3];
  bool have_plane = false;
  while (true) {
    if (ws.vertices.size() == 1) {
      // A point: the farthest support point along the six axis directions.
      SimplexVertexT<S> best_vertex;
      S best = S(-1);
      for (int axis = 0; axis < 6; ++axis) {
        Vec3T<S> d = Vec3T<S>::Zero();
        d[axis / 2] = axis % 2 ? S(-1) : S(1);
        const SimplexVertexT<S> vertex = support(d);
        const S dist = (vertex.w - ws.vertices[0].w).norm();
        if (dist > best) {
          best = dist;
          best_vertex = vertex;
        }
      }
      if (!(best > flat_tol)) {
        const Vec3T<S> normal = fallback;
        return degenerate(normal);
      }
      ws.vertices.push_back(best_vertex);
    }
    if (ws.vertices.size() == 2) {
      // A segment: the support point farthest from its line, along four orthogonal directions.
      const Vec3T<S> e = ws.vertices[1].w - ws.vertices[0].w;
      // unit_of(), not normalized(): a segment of 1e-158 has a subnormal square, and its
      // normalised directions came out 7e-9 off unit.
      const Vec3T<S> u1 = unit_of(Vec3T<S>(orthogonal(e)));
      const Vec3T<S> u2 = unit_of(Vec3T<S>(e.cross(u1)));
      SimplexVertexT<S> best_vertex;
      S best = S(-1);
      for (const Vec3T<S>& d : {u1, Vec3T<S>(-u1), u2, Vec3T<S>(-u2)}) {
        const SimplexVertexT<S> vertex = support(d);
        const S dist = (vertex.w - ws.vertices[0].w).cross(e).norm() / e.norm();
        if (dist > best) {
          best = dist;
          best_vertex = vertex;
        }
      }
      if (!(best > flat_tol)) {
        // A - B is a segment: any direction orthogonal to it; prefer the line of centres'
        // component orthogonal to it, which separates concentric-looking pairs the expected way.
        // Projected out twice: when the line of centres runs nearly along the segment (a sphere's
        // centre on a capsule's axis, off its middle), one projection leaves a component along it,
        // and every unit of it costs the segment's length in depth.
        Vec3T<S> normal = fallback;
        if (!make_orthogonal(normal, e, e)) normal = u1;
        return degenerate(normal);
      }
      ws.vertices.push_back(best_vertex);
    }
    if (ws.vertices.size() == 3) {
      Vec3T<S> n;
      if (!triangle_normal(ws.vertices[0].w, ws.vertices[1].w, ws.vertices[2].w, n)) {
        // A sliver: drop its middle point (the one nearest the segment of the other two) and
        // grow again from the segment.
        if (regrows++ < kMaxRegrows) {
          drop_middle_point(ws.vertices);
          continue;
        }
        const Vec3T<S> e = ws.vertices[1].w - ws.vertices[0].w;
        return degenerate(unit_of(Vec3T<S>(orthogonal(e))));
      }
      const SimplexVertexT<S> up = support(n);
      const SimplexVertexT<S> down = support(-n);
      const S plane = n.dot(ws.vertices[0].w);
      const S rise = n.dot(up.w) - plane, fall = plane - n.dot(down.w);
      if (!(rise > flat_tol) && !(fall > flat_tol)) {
        // A - B is flat: the side with the smaller support value is the better normal.
        return degenerate(side_of_smaller_support(n, up.w, down.w));
      }
      for (int i = 0; i < 3; ++i) last_triangle[i] = ws.vertices[i].w;
      have_plane = true;
      // A tetrahedron with the farther apex. The origin lies within the touching tolerance of the
      // triangle, so it may sit just outside it, on the other side: signed face distances make the
      // first expansion push that face out towards the other apex. (A double pyramid with both
      // apexes is not convex when the segment between them misses the triangle.)
      ws.vertices.push_back(rise >= fall ? up : down);
    }
    if (seed_polytope(ws)) break;
    // No seed: A - B is flat to the rounding of its triangles' normals. A sliver's normal is good
    // to about eps over the sine of its angle, so a flat A - B can rise off its plane by more than
    // the flatness tolerance (a triangle and a segment in one plane, 12 long and 3e-6 wide: 4e-10),
    // while the tetrahedra on it are too flat to seed. The last triangle's plane, its normal taken
    // again with care (sliver_normal()), on the side of the smaller support value, is then the
    // answer; the fallback, the line of centres, was any direction (0.67 of the size too deep).
    if (regrows++ >= kMaxRegrows) {
      Vec3T<S> n;
      if (!have_plane || !sliver_normal(last_triangle[0], last_triangle[1], last_triangle[2], n))
        return degenerate(fallback);
      return degenerate(side_of_smaller_support(n, support(n).w, support(Vec3T<S>(-n)).w));
    }
    ws.faces.clear();
    drop_closest_pair_point(ws.vertices);
  }

  // 2. Expand the face nearest the origin, until the bracket closes.
  // The least support value seen, its direction and support point: slots[least_slot]. A step
  // writes its own into the other slot and keeps the lesser of the two by a select, not a branch:
  // the support values of EPA's steps rise and fall with no pattern, and a mispredicted branch
  // waited on the root and the division that give h.
  SupportMinimum<S> slots[2];
  int least_slot = 0;
  enum class Step { Expanded, Closed, Stuck, Overflow, ProvenByBall };
  // Cores that hold balls (an ellipsoid, a cylinder): Newton's steps and the balls may close the
  // bracket once EPA's is within kInnerBallHandOff of the size (inner_ball.hpp), for depths within
  // their reach. Only where contact() would refine the normal with Newton's steps anyway, and
  // they refine (no cone: hands_off_to_newton()).
  S ball_reach = S(0), ball_lower = S(0);
  if constexpr (kInnerBallPair<A, B>) {
    if (tol.refine_curved_normals && hands_off_to_newton(diff.a, diff.b))
      ball_reach = InnerBall<A>::reach(diff.a) + InnerBall<B>::reach(diff.b);
  }
  bool try_ball = ball_reach > S(0);
  // Samples A - B along face f's normal, keeps the least support value seen, and pushes f out
  // unless it already lies on the boundary of A - B.
  auto step = [&](int f) {
    const EpaFace<S>& face = ws.faces[f];
    SupportMinimum<S>& here = slots[least_slot ^ 1];
    here.vertex = support(face.n);
    const SimplexVertexT<S>& w = here.vertex;
    const S length = length_of(face.n, face.nn);
    const S h = face.n.dot(w.w) / length;
    if (!(std::abs(h) <= std::numeric_limits<S>::max())) return Step::Overflow;
    here.value = h;
    here.normal = unit_of(face.n, face.nn, length);
    least_slot = h < slots[least_slot].value ? least_slot ^ 1 : least_slot;
    if constexpr (kInnerBallPair<A, B>) {
      SupportMinimum<S>& least = slots[least_slot];
      // The ball proves depths up to its radius only: deeper (EPA's lower bound beyond it), no
      // try.
      if (try_ball && least.value - face.offset / length <= S(kInnerBallHandOff) * size) {
        try_ball = false;
        if (face.offset / length < ball_reach) {
          SupportMinimum<S> trial = least;
          int newton_kept = 0;
          if (newton_proves_depth(diff, size, tol, out.iterations, trial, ball_lower,
                                  newton_kept)) {
            least = trial;
            return Step::ProvenByBall;
          }
          if (newton_kept > 0) out.newton = trial;
        }
      }
    }
    if (h - face.offset / length <= gain_tol) return Step::Closed;
    // w is a vertex of the face: h is its distance, to rounding.
    for (int k = 0; k < 3; ++k)
      if (ws.vertices[face.v[k]].w == w.w) return Step::Closed;
    return expand_polytope(ws, f, w, size, flat_tol) ? Step::Expanded : Step::Stuck;
  };
  // The last quarter of the support calls is kept for the polish below.
  const int global_budget = tol.max_epa_iterations - tol.max_epa_iterations / 4;
  int best = ws.nearest();
  Step last = Step::Expanded;
  while (out.iterations < global_budget && (last = step(best)) == Step::Expanded)
    best = ws.nearest();
  if (last == Step::Overflow) {
    out.status = Status::InvalidInput;
    return out;
  }
  SupportMinimum<S>& least = slots[least_slot];
  if (last == Step::ProvenByBall) {
    out.normal = least.normal;
    out.depth = out.upper = least.value;
    out.lower = ball_lower;
    out.a = least.vertex.a;
    out.b = least.vertex.b;
    share_residual(out.a, out.b, out.normal, out.depth);
    out.proven_by_ball = true;
    return out;
  }
  const bool converged = last == Step::Closed;

  // 3. Polish. The bracket stays open when many normals are about as good: a circle of them
  // around the axis of coaxial cones, cylinders or spheroids, where P would need refining all
  // along the circle (thousands of faces) before its nearest face is within the tolerance. The
  // answer is then the upper end, which only needs the least support value near one of those
  // normals: descend_support() from the best normal seen. The upper end can only go down.
  best = ws.nearest();
  const bool polished = !converged && least.value < std::numeric_limits<S>::infinity();
  if (polished && !descend_support(diff, ws.faces[best].distance(), gain_tol,
                                   tol.max_epa_iterations, out.iterations, least)) {
    out.status = Status::InvalidInput;
    return out;
  }

  // 4. Witness points: the origin's projection p = d n in barycentric coordinates. p lies in the
  // facet of A - B that the nearest face belongs to, but that facet may be split into several
  // coplanar faces of P (a box face, or the parallelogram of an edge of A and an edge of B, is two
  // triangles) and the heap may have surfaced a coplanar neighbour of the face holding p. So take,
  // among the faces coplanar with the nearest one, the one whose coordinates of p are least
  // negative; depth and normal stay those of the nearest face.
  const Vec3T<S> normal = ws.faces[best].unit_normal();
  const S depth = ws.faces[best].distance();
  const Vec3T<S> p = normal * depth;
  auto coordinates = [&](const EpaFace<S>& f, S lambda[3]) {
    const Vec3T<S>& w0 = ws.vertices[f.v[0]].w;
    const S area = normal.dot((ws.vertices[f.v[1]].w - w0).cross(ws.vertices[f.v[2]].w - w0));
    if (!(area > S(0))) return -std::numeric_limits<S>::infinity();
    S smallest = std::numeric_limits<S>::infinity();
    for (int k = 0; k < 3; ++k) {
      const Vec3T<S>& q = ws.vertices[f.v[(k + 1) % 3]].w;
      const Vec3T<S>& r = ws.vertices[f.v[(k + 2) % 3]].w;
      lambda[k] = normal.dot((q - p).cross(r - p)) / area;
      smallest = std::min(smallest, lambda[k]);
    }
    return smallest;
  };
  S lambda[3] = {S(1), S(1), S(1)};
  int holder = best;
  S score = coordinates(ws.faces[best], lambda);
  constexpr S kCoplanar = S(1) - S(1e-8);  // cosine of the angle between coplanar normals
  if (!(score >= S(0))) {
    for (int g = 0; g < static_cast<int>(ws.faces.size()); ++g) {
      if (g == best || !ws.faces[g].live) continue;
      // Coplanar: the same normal, and a plane through p (within EPA's tolerance).
      const S length = length_of(ws.faces[g].n, ws.faces[g].nn);
      if (ws.faces[g].n.dot(normal) < kCoplanar * length ||
          std::abs(ws.faces[g].n.dot(p) - ws.faces[g].offset) > (gain_tol + flat_tol) * length)
        continue;
      S trial[3] = {S(0), S(0), S(0)};
      const S trial_score = coordinates(ws.faces[g], trial);
      if (trial_score > score) {
        score = trial_score;
        holder = g;
        for (int k = 0; k < 3; ++k) lambda[k] = trial[k];
      }
    }
  }
  const int* holder_v = ws.faces[holder].v;
  if (converged && score >= S(0)) {
    const EpaFace<S>& face = ws.faces[holder];
    const Vec3T<S> corners[3] = {ws.vertices[holder_v[0]].w, ws.vertices[holder_v[1]].w,
                                 ws.vertices[holder_v[2]].w};
    out.on_facet = on_facet(std::max(depth, least.value), depth, size, corners, lambda,
                            length_of(face.n, face.nn));
  }
  if (!(score >= S(0))) {
    // p lies outside every such face, beyond rounding when the face is a sliver (a needle's edge
    // against a vertex: its width is the needle's thickness, and a normal off by rounding moves p
    // across it). Clamped coordinates would then land anywhere along the sliver; the face's point
    // nearest p does not.
    Vec3T<S> from_p[3];
    for (int k = 0; k < 3; ++k) from_p[k] = ws.vertices[holder_v[k]].w - p;
    const SubSimplex<S> nearest = closest_on_triangle_cold(from_p, 0, 1, 2);
    for (int k = 0; k < 3; ++k) lambda[k] = nearest.weights[k];
  }
  S total = S(0);
  for (int k = 0; k < 3; ++k) total += (lambda[k] = std::max(S(0), lambda[k]));
  out.a = Vec3T<S>::Zero();
  out.b = Vec3T<S>::Zero();
  for (int k = 0; k < 3; ++k) {
    const S weight = total > S(0) ? lambda[k] / total : S(1) / S(3);
    out.a += weight * ws.vertices[holder_v[k]].a;
    out.b += weight * ws.vertices[holder_v[k]].b;
  }
  // What is left of a - b - p (rounding, or the distance from p to that nearest point, in the
  // face's plane) is split between the two points, so that b - a = -depth * normal holds as the
  // result promises, each point moves by half of it, and swapping A and B mirrors the answer.
  const Vec3T<S> residual = S(0.5) * (out.a - out.b - p);
  out.a -= residual;
  out.b += residual;
  out.normal = normal;
  out.depth = out.lower = depth;
  out.upper = std::max(depth, least.value);
  if (polished) {
    // EPA did not close the bracket on a face (the cap, the polish, an expansion that rounding
    // would not allow): the nearest face is only a lower bound, and its normal may be far from
    // the answer even when the polish brought the upper end down to it, while moving B by h(n)
    // along the normal n of the least support value h seen always separates the shapes. That is
    // the answer; `upper - depth` (error_bound) says how good, and decides the status.
    out.normal = least.normal;
    // The witness points: a pair of the two support features along the normal, depth apart along
    // it. A feature may be a segment (a cylinder's side across its axis, a capsule's core) or a
    // face, where the support point alone can be any of its points: a sphere's point placed from
    // a cylinder's rim point landed 0.85 off the sphere, and two coaxial cylinders' points 0.37
    // off. So the features are sampled by the support along the normal tilted by 1e-9 rad four
    // ways (a flat feature shows its ends, a curved surface moves by 1e-9 of its radius), each
    // taken as the segment between its two samples farthest apart, B's shifted by the depth,
    // and the pair is their closest points: the same point twice where the features overlap
    // seen along the normal (every tie above), else split between them.
    const Vec3T<S>& n = least.normal;
    Vec3T<S> t1, t2;
    plane_basis(n, t1, t2);
    const S kTilt = std::max(S(1e-9), S(64) * std::numeric_limits<S>::epsilon());  // float: 8e-6
    Vec3T<S> on_a[5] = {least.vertex.a}, on_b[5] = {least.vertex.b};
    for (int k = 0; k < 4; ++k) {
      SimplexVertexT<S> v;
      diff.support(n + kTilt * (k < 2 ? t1 : t2) * (k % 2 ? S(-1) : S(1)), v);
      on_a[k + 1] = v.a;
      on_b[k + 1] = v.b;
    }
    out.iterations += 4;
    auto farthest_pair = [](const Vec3T<S>(&samples)[5], Vec3T<S>& p0, Vec3T<S>& p1) {
      S widest = S(-1);
      for (int i = 0; i < 5; ++i)
        for (int j = i + 1; j < 5; ++j)
          if (const S d = (samples[i] - samples[j]).squaredNorm(); d > widest) {
            widest = d;
            p0 = samples[i];
            p1 = samples[j];
          }
    };
    Vec3T<S> a0 = on_a[0], a1 = on_a[0], b0 = on_b[0], b1 = on_b[0];
    Vec3T<S> on_a_feature = on_a[0], on_b_shifted = on_b[0];
    farthest_pair(on_a, a0, a1);
    farthest_pair(on_b, b0, b1);
    const Vec3T<S> shift = least.value * n;
    closest_points_of_segments(a0, a1, Vec3T<S>(b0 + shift), Vec3T<S>(b1 + shift), on_a_feature,
                               on_b_shifted);
    const Vec3T<S> split = S(0.5) * (on_a_feature - on_b_shifted);
    out.a = on_a_feature - split;
    out.b = on_b_shifted + split - shift;
    if (least.value - depth > gain_tol && out.status == Status::Intersecting)
      out.status = Status::IterationLimit;
    out.depth = least.value;
  }
  return out;
}

/// run_epa()'s `fallback` for a pair: the line of centres, or +z when they coincide. unit_of():
/// two spheres' centres 5e-159 apart have a subnormal square, and the plain quotient was 2e-8 off
/// unit.
template <ConvexShape A, ConvexShape B>
Vec3T<typename A::Scalar> epa_fallback(const CoreDifference<A, B>& diff) {
  using S = typename A::Scalar;
  return diff.translation != Vec3T<S>::Zero() ? unit_of(diff.translation) : Vec3T<S>::UnitZ();
}

/// separate_cores() for distance() and intersect(), with contact()'s word on cores that GJK
/// neither proved apart nor found meeting: its bracket on their distance straddles the touching
/// tolerance (curved cores grazing a thin plate, whose GJK crawls to its cap). contact() runs EPA
/// on them there; where EPA converges on cores that enclose the origin (not flat, and no
/// direction proving them apart), they meet, and so the three queries give one verdict.
template <ConvexShape A, ConvexShape B>
CoreSeparation<typename A::Scalar> settle_cores(const CoreDifference<A, B>& diff,
                                                const GjkOutcome<typename A::Scalar>& gjk,
                                                typename A::Scalar radii, typename A::Scalar size,
                                                const TolerancesT<typename A::Scalar>& tolerances,
                                                int& iterations) {
  using S = typename A::Scalar;
  auto cores = separate_cores(diff, gjk, radii, size, tolerances, iterations);
  const S touch = tolerances.relative * size;
  if (cores.status != Status::IterationLimit || !(cores.lower <= touch)) return cores;
  const auto epa = run_epa(diff, gjk.simplex, size, tolerances, epa_fallback(diff));
  iterations += epa.iterations;
  if (epa.status == Status::Intersecting && !epa.degenerate && !(epa.upper < -touch))
    cores.status = Status::Intersecting;
  return cores;
}

}  // namespace mink::detail
