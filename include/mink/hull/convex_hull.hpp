/// @file convex_hull.hpp
/// The convex hull of a point set: vertices, polygonal faces and full adjacency, built by
/// Quickhull (Barber, Dobkin and Huhdanpaa, "The Quickhull algorithm for convex hulls", ACM TOMS
/// 1996) with conflict lists and a half-edge mesh.
///
/// How it is built, and why each step keeps the result right:
///   1. Frame. The points are translated and scaled without rounding: an axis is shifted by its
///      lower bound only when the whole box lies within a factor 2 of it on that axis, where the
///      subtraction is exact (Sterbenz), and the scale is a power of two. Otherwise the box
///      already contains coordinates near 0. So the hull is computed on an exact copy of the
///      input, with coordinates of about 1, whatever its size or distance from the origin.
///   2. Dimension. Two extreme points along the widest axis, the point farthest from their line
///      and the points farthest on either side of the plane of those three decide whether the
///      set is a point (bounding-box diagonal within `tolerance`), a segment (all points within
///      `tolerance` of that line), a flat polygon (all points in a slab of that thickness along
///      that plane) or a solid. A lower-dimensional answer is therefore
///      always a true statement about the input; an input that is only nearly flat under some
///      other plane is built as a (thin) solid, which is also correct.
///   3. Exact triangulated hull. First, points strictly inside a ball or a box inscribed in
///      the exact hull of a sample (every 16th point, filtered the same way) are dropped: the
///      test keeps a margin of 1e-9 M (M the largest local coordinate) over rounding errors
///      below 1e-13 M, so a dropped point is strictly inside the hull and never a vertex (in a ball
///      this removes over 90 % of the points, in a cube about 70 %; on a sphere it gives up
///      after the smallest sample). The rest is sorted along a Morton curve, for memory locality.
///      Quickhull then adds the point farthest beyond a face (the newest face first, or
///      furthest first over all faces when max_vertices may stop the build), removes the faces
///      it sees and joins it to their horizon. "Sees"
///      is the exact sign of an orientation determinant (hull/predicates.hpp: a floating-point
///      filter with a proven error bound, and an exact expansion evaluation when the filter
///      cannot decide). With exact signs the faces a point sees form a disk bounded by one
///      simple loop, the new faces are never degenerate, and a point of a removed face's
///      conflict list that is above none of the new faces is inside the new hull: the segment
///      from it to the interior of the removed face crosses the new boundary only where the new
///      faces are. So the triangulation is exactly the convex hull of the input: every input
///      point is inside or on it and no extreme point is lost. Points on a face's plane do not
///      see it, so duplicates and points on faces never become vertices twice. Floating-point
///      distances and the order of faces only choose the order in which points are added.
///   4. Faces. Triangles that are exactly coplanar (exact orientation 0) form facets: planar
///      convex polygons of the true hull, never split. From the largest facet left, a face
///      grows over neighbouring facets whose vertices all lie within `tolerance` below the
///      supporting plane of the seed's normal, that face that normal (exact sign), and keep the
///      face a disk without pinches. The face is accepted if its boundary turns left at every
///      vertex seen along the normal (exact signs); otherwise the facets at its reflex vertices
///      are excluded and it grows again, then it grows keeping every corner convex, and at
///      worst it is the seed facet alone. A face's normal is its area-weighted normal when the
///      face stays flat, front-facing and convex along it, else the seed's (rounded from its
///      exact value). Its offset is an upper bound of max normal . x over the hull: with the
///      seed's normal, the facet's own maximum plus a proven margin of 48 u M (u = 2^-53, M
///      the largest local coordinate; no margin when the normal is an axis); with another
///      normal, the exact maximum found by an exact hill climb over the convex triangulation.
///      Vertices where fewer than three faces meet (points inside a face or on an edge of it)
///      are left out of the face loops, unless a face would keep fewer than three, or the
///      boundary between two faces bends there: faces are flat only within `tolerance`, so two
///      of them can share a bent chain (the rim of a disc 1e-9 thick), and every vertex left
///      out of such a chain lies within `tolerance` of the chord between the kept ones.
///   5. Output. Offsets are converted to input units with exact arithmetic and rounded up.
///
/// Guarantees (complete builds; `tolerance` is ConvexHull::tolerance, in input units):
///   - every input point p satisfies normal . p <= offset for every face, up to the rounding of
///     evaluating normal . p in double (about 4 eps |p|);
///   - every vertex of a face lies within `tolerance` of its plane;
///   - each face's vertex loop is counter-clockwise seen from outside and convex when projected
///     along its normal (exact signs on the input points);
///   - the faces form a closed polyhedron: every half-edge has a twin in another face, V - E + F
///     = 2, every vertex is an input point shared by at least three faces (or two, when a face
///     would otherwise have fewer than three vertices, or at a bend of their common boundary);
///   - every point of the exact hull that is not a vertex (because it is not extreme, or because
///     it was dropped as above) lies within `tolerance` of a face plane.
/// Flat, segment and point results: see HullStatus.
///
/// The tolerance absorbs rounding and near-coplanar noise; it is not a simplification (use
/// max_vertices for small hulls): large tolerances merge fewer faces than they could, because
/// faces are grown greedily and must stay convex. Default: 1e-10 times the bounding-box
/// diagonal, plus 32 eps times the largest coordinate magnitude (always added: a double only
/// resolves positions to eps |x|, so points far from the origin cannot be flatter than that in
/// any output format, and the margins of step 4 stay below it).
///
/// Cost: O(n log n) expected on points in a ball or cube (in practice linear: the filter of
/// step 3 leaves few points), O(n h) in the worst case (h hull vertices). bench/hull_bench.cpp
/// measures it against Qhull, CGAL and Bullet (docs/benchmarks.md). Every loop is capped; hitting a
/// cap is an internal error reported through the Expected, never a silent wrong result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mink/expected.hpp"
#include "mink/math/vec.hpp"

namespace mink {

/// The dimension of the hull.
enum class HullStatus {
  Full,     ///< a solid: faces enclose a positive volume
  Flat,     ///< all points within `tolerance` of a plane: one convex polygon, given as two faces
            ///< with opposite normals and the same vertices (front counter-clockwise about the
            ///< normal, back reversed); volume 0; area counts both sides
  Segment,  ///< all points within `tolerance` of a line: the two extreme points, no faces
  Point,    ///< all points equal, or within `tolerance` of each other: one vertex (the first
            ///< point), no faces
};

constexpr const char* to_string(HullStatus status) {
  switch (status) {
    case HullStatus::Full:
      return "full";
    case HullStatus::Flat:
      return "flat";
    case HullStatus::Segment:
      return "segment";
    case HullStatus::Point:
      return "point";
  }
  return "unknown";
}

struct HullOptions {
  /// Faces are flat, and lower-dimensional input is recognised, within this times the diagonal
  /// of the input's bounding box (plus the rounding floor described above). In [0, 1e-2].
  double relative_tolerance = 1e-10;
  /// 0: no limit. Otherwise at least 4: points are added furthest first and the build stops when
  /// the hull has this many vertices; points left outside are reported by `max_outside`.
  std::size_t max_vertices = 0;
};

/// A vertex of the hull: one of the input points.
struct HullVertex {
  Vec3 position;              ///< the input point, bit for bit
  std::uint32_t input_index;  ///< its index in the input (one of them if it is repeated)
};

/// A face: a convex polygon, its plane and its loop of half-edges.
struct HullFace {
  Vec3 normal;          ///< unit, outward
  double offset;        ///< plane: normal . x = offset; the hull lies where normal . x <= offset
  std::uint32_t first;  ///< first half-edge of the loop
  std::uint32_t count;  ///< number of half-edges (= vertices) of the loop: first .. first+count-1
};

/// A directed edge of a face loop, from `vertex` to the next half-edge's vertex.
struct HullHalfEdge {
  std::uint32_t vertex;  ///< origin vertex (index into ConvexHull::vertices)
  std::uint32_t twin;    ///< the same edge in the neighbouring face, reversed
  std::uint32_t face;    ///< the face it bounds (on its left, seen from outside)
};

struct ConvexHull {
  HullStatus status = HullStatus::Point;
  std::vector<HullVertex> vertices;
  std::vector<HullFace> faces;
  /// Half-edges grouped by face: face f owns [faces[f].first, faces[f].first + faces[f].count),
  /// in counter-clockwise order seen from outside; the vertex loop of f is their `vertex`.
  std::vector<HullHalfEdge> half_edges;
  /// Neighbours of vertex v: neighbors[neighbor_offsets[v] .. neighbor_offsets[v + 1]), in
  /// counter-clockwise order seen from outside (Full); the two polygon neighbours (Flat); the
  /// other end (Segment). neighbor_offsets has vertices.size() + 1 entries.
  std::vector<std::uint32_t> neighbor_offsets;
  std::vector<std::uint32_t> neighbors;
  /// Volume of the polyhedron bounded by the face loops, and the sum of the face areas
  /// (computed at unit scale, then scaled: they underflow to 0 only for hulls smaller than
  /// about 1e-100, whose faces and adjacency are still exact).
  double volume = 0;
  double area = 0;
  /// Flatness tolerance used (input units): see the file comment.
  double tolerance = 0;
  /// False when max_vertices stopped the build early.
  bool complete = true;
  /// When !complete: the largest distance of a remaining input point beyond the plane of the
  /// face its conflict list ended on (what furthest-first keeps small); 0 when complete.
  double max_outside = 0;

  std::uint32_t face_vertex(std::size_t face, std::size_t k) const {
    return half_edges[faces[face].first + k].vertex;
  }
  /// The half-edge after h in its face loop.
  std::uint32_t next(std::uint32_t h) const {
    const HullFace& f = faces[half_edges[h].face];
    return h + 1 == f.first + f.count ? f.first : h + 1;
  }
  /// The neighbouring face across half-edge h.
  std::uint32_t neighbor_face(std::uint32_t h) const { return half_edges[half_edges[h].twin].face; }
};

/// The convex hull of `points`. Errors: no points, a NaN or infinite coordinate, a coordinate
/// above 1e100, more than 2^28 points, options out of range; and internal errors (a cap hit), which
/// would be bugs.
Expected<ConvexHull> build_convex_hull(std::span<const Vec3> points,
                                       const HullOptions& options = {});

}  // namespace mink
