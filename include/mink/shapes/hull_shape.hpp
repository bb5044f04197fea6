/// @file hull_shape.hpp
/// ConvexHullShape: a convex polytope given by its hull (vertices and vertex adjacency), whose
/// support climbs the vertex graph from the previous answer instead of scanning every point.
///
/// Support by hill climbing. From a start vertex, move to the neighbour with the largest dot
/// product with d as long as it is strictly larger; stop when no neighbour is. On the vertex-edge
/// graph of a convex polytope a vertex that no neighbour beats is a global maximum (the polytope
/// lies in the cone spanned by the edges leaving that vertex), so the climb ends on a support
/// point. Only strictly better moves are taken, so the dot product grows at every step: no vertex
/// is visited twice and the climb cannot cycle on a plateau (equal dot products). The number of
/// moves is still capped at the vertex count, and a climb that hits the cap falls back to the scan.
///
/// Accuracy. The hull's faces are flat within ConvexHull::tolerance (nearly coplanar facets are
/// merged), so the graph is the edge graph of a polytope within that tolerance of the exact hull
/// of the vertices: the climb's support value is within `tolerance * |d|` (plus the rounding of a
/// dot product, a few eps |p| |d|) of the maximum over the input points, and equal to it when
/// the merged faces are exactly coplanar (the usual case for points in general position and for
/// exact lattices). Input points that are not hull vertices are never returned.
///
/// Ties. The answer depends on d only, not on where the climb started: when the climb stops on a
/// vertex with neighbours of equal dot product (a face or edge facing d), it collects that
/// plateau (up to kHullPlateauLimit vertices, then it scans) and returns its lowest vertex index.
/// So warm starts, and races on the hint below, change the cost of a query but not its result.
///
/// Start vertex. Two candidates: the previous answer (the hint), right for a shape queried along
/// slowly turning directions (the next simulation step), and a direction table's seed (6 k^2
/// cells of the cube of directions, each holding its centre's answer, k about sqrt(2 n / 3): some
/// four cells per vertex), which is a random direction's answer three times in four and next to
/// it otherwise. The directions of one query jump (GJK's first direction is a new pose's, its
/// next ones turn by large angles; a shape shared by many bodies, or queried as A and as B, sees
/// each pair's), so both are read on every query and the climb starts from the higher.
///
/// Measured against reading the table only once the hint's neighbours show that the hint is not
/// the answer (and, for tables over 32 KB, after two moves), bench/hull_support_bench.cpp, median
/// ns per support: on directions turning 0.02 rad per query the seed's lookup is pure cost, 6.4 ->
/// 10.7 at 128 vertices and 19.9 -> 23.4 at 4,096; on random directions 34.6 -> 24.0 at 128,
/// 94 -> 41 at 4,096 and 243 -> 126 at 100,000. In GJK's own sequence of directions the seed
/// wins: distance of two 4,096-vertex hulls 870 -> 812; gjk_bench's intersect of two 128-vertex
/// polytopes apart 138 -> 108, their distance 1.96 -> 1.68 us (docs/benchmarks.md, stop 44).
///
/// The hint lives in the shape as a relaxed `std::atomic<std::uint32_t>` on its own cache line:
/// support is `const` and shapes are shared between threads, any start is correct (see Ties) so a
/// race between threads only changes a start, and a relaxed 32-bit load and store compile to
/// plain moves. The store is skipped when the answer equals the hint. Alternatives rejected: a
/// `thread_local` map from shape to hint costs a lookup as long as the climb itself; a hint held by
/// the caller (for instance in GjkCache) would be best, but needs the support concept to take it
/// (climb_index(d, start) is that entry point, ready for it).
///
/// Layout. Positions twice: three arrays for the scan, and per vertex a 64-byte record (position,
/// edge range, and up to eight neighbours' indices inline) for the climb, whose step reads its
/// vertex's record and then the neighbours' records, all at once; a vertex of higher degree reads
/// its neighbours from the CSR edge list. About 130 bytes per vertex in double, all told. Until
/// stop 97 the edges carried their end's position and range inline (a step read one run of
/// 40-byte edges; about 300 bytes per vertex). gjk_bench's 32 hulls of 512 vertices did not fit
/// the 1 MB second-level cache that way; the compact records cut contact of their overlapping
/// pairs by 9 %, and cold support calls on 100,000 vertices by 27 % (docs/benchmarks.md).
///
/// Small hulls scan. Below kHullClimbMinVertices vertices the vectorised scan of
/// shapes/support_scan.hpp is faster than climbing (measured in bench/hull_support_bench.cpp,
/// table below), and it keeps the same tie rule (lowest index among the farthest), so the shape
/// scans its vertices there.
///
/// Lower-dimensional hulls (HullStatus): Flat hulls climb their polygon (each vertex's two
/// neighbours), Segment hulls their two ends, a Point hull has one vertex: the same loop serves
/// all.
///
/// Units: positions in the caller's length unit, in the shape's local frame; radius 0.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/expected.hpp"
// HullStatus's enumerators Point and Segment trip GCC's -Wshadow against the shape aliases of
// the same names when this header comes after shapes/point.hpp: harmless (a scoped enum), so the
// warning is silenced for that one include.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#endif
#include "mink/hull/convex_hull.hpp"
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#include "mink/shapes/shape_common.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {

/// Hulls with fewer vertices than this scan them (shapes/support_scan.hpp); larger ones climb.
/// Measured with bench/hull_support_bench.cpp (Release, SSE2, points on a sphere, every point a
/// vertex; ns per query, CPU time, median of 5, quiet 2-core machine): warm = the direction turns
/// 0.02 rad per query, cold = random directions; support_index (hint, then table) from 64
/// vertices, climb_index from the previous answer below (support_index scans there).
///
///   vertices      16    24    32    48    64    96   128   256  1024  4096
///   scan         8.9  10.2  12.2  16.2  21.0  33.2  53.5  93.9   301  1113
///   climb warm  10.3   8.0   7.0   7.7   7.3   7.2   5.5  10.9   8.0  16.8
///   climb cold     -     -     -     -  45.6  49.3  55.3  64.3  76.1  92.6
///
/// Warm climbing wins from about 24 vertices, cold from about 128; at 64 warm queries are 3x
/// faster than the scan and cold ones at most 2.2x slower. Full table: docs/architecture.md.
inline constexpr std::size_t kHullClimbMinVertices = 64;
/// A polytope's support calls with scattered directions (EPA's; SupportPattern in
/// support_scan.hpp) scan up to this many points instead of climbing (PolytopeT::support_core).
inline constexpr std::size_t kScatteredScanMaxPoints = 128;

/// The largest plateau (vertices of equal support value) the climb collects to break a tie; a
/// larger one is resolved by the scan, with the same answer.
inline constexpr std::size_t kHullPlateauLimit = 32;

template <class S>
class ConvexHullShapeT {
 public:
  using Scalar = S;

  /// The shape of a hull built by build_convex_hull (any status; an incomplete hull, built with
  /// max_vertices, gives the shape of the vertices it kept). Error when the hull has no vertex or
  /// its adjacency is inconsistent (which would be a bug of the hull builder).
  static Expected<ConvexHullShapeT> make(const ConvexHull& hull) {
    using Result = Expected<ConvexHullShapeT>;
    const std::size_t n = hull.vertices.size();
    if (n == 0) return Result::failure("convex hull has no vertices");
    const auto& offsets = hull.neighbor_offsets;
    if (n > std::numeric_limits<std::uint32_t>::max() / 2 || offsets.size() != n + 1 ||
        offsets.front() != 0 || offsets.back() != hull.neighbors.size())
      return Result::failure("convex hull adjacency is inconsistent");
    ConvexHullShapeT shape;
    shape.status_ = hull.status;
    shape.tolerance_ = S(hull.tolerance);
    shape.x_.resize(n);
    shape.y_.resize(n);
    shape.z_.resize(n);
    shape.nodes_.resize(n);
    shape.input_indices_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3T<S> p = hull.vertices[i].position.template cast<S>();
      if (!is_finite(p)) return Result::failure("convex hull vertex is not finite");
      if (offsets[i + 1] < offsets[i])
        return Result::failure("convex hull adjacency is inconsistent");
      shape.x_[i] = p.x();
      shape.y_[i] = p.y();
      shape.z_[i] = p.z();
      shape.input_indices_[i] = hull.vertices[i].input_index;
      shape.nodes_[i] = Node{{p.x(), p.y(), p.z()}, offsets[i], offsets[i + 1], {}};
      shape.bounding_radius_ = std::max(shape.bounding_radius_, detail::length_of(p));
      shape.centre_ += p / S(n);  // divided first: no overflow near the largest doubles
    }
    shape.edges_.resize(hull.neighbors.size());
    for (std::size_t k = 0; k < hull.neighbors.size(); ++k) {
      const std::uint32_t u = hull.neighbors[k];
      if (u >= n) return Result::failure("convex hull adjacency is inconsistent");
      shape.edges_[k] = u;
    }
    for (Node& node : shape.nodes_)
      if (node.end - node.begin <= kInlineNeighbors)
        std::copy(shape.edges_.begin() + node.begin, shape.edges_.begin() + node.end, node.near);
    if (!shape.copy_faces(hull)) return Result::failure("convex hull faces are inconsistent");
    shape.climbs_ = n >= kHullClimbMinVertices;
    if (shape.climbs_) shape.build_seeds();
    return shape;
  }

  /// The shape of the convex hull of `points` (see build_convex_hull for the errors and options).
  static Expected<ConvexHullShapeT> make(std::span<const Vec3T<S>> points,
                                         const HullOptions& options = {}) {
    Expected<ConvexHull> hull = [&] {
      if constexpr (std::is_same_v<S, double>) {
        return build_convex_hull(points, options);
      } else {
        std::vector<Vec3> wide(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) wide[i] = points[i].template cast<double>();
        return build_convex_hull(wide, options);
      }
    }();
    if (!hull) return Expected<ConvexHullShapeT>::failure(hull.error());
    return make(*hull);
  }

  // The atomic hint is neither copyable nor movable: copy its value with the rest.
  ConvexHullShapeT(const ConvexHullShapeT& o) { *this = o; }
  ConvexHullShapeT(ConvexHullShapeT&& o) noexcept { *this = std::move(o); }
  ConvexHullShapeT& operator=(const ConvexHullShapeT& o) {
    if (this != &o) {
      x_ = o.x_;
      y_ = o.y_;
      z_ = o.z_;
      nodes_ = o.nodes_;
      input_indices_ = o.input_indices_;
      edges_ = o.edges_;
      seeds_ = o.seeds_;
      face_normals_ = o.face_normals_;
      face_begin_ = o.face_begin_;
      face_loops_ = o.face_loops_;
      vertex_face_begin_ = o.vertex_face_begin_;
      vertex_faces_ = o.vertex_faces_;
      copy_scalars(o);
    }
    return *this;
  }
  ConvexHullShapeT& operator=(ConvexHullShapeT&& o) noexcept {
    if (this != &o) {
      x_ = std::move(o.x_);
      y_ = std::move(o.y_);
      z_ = std::move(o.z_);
      nodes_ = std::move(o.nodes_);
      input_indices_ = std::move(o.input_indices_);
      edges_ = std::move(o.edges_);
      seeds_ = std::move(o.seeds_);
      face_normals_ = std::move(o.face_normals_);
      face_begin_ = std::move(o.face_begin_);
      face_loops_ = std::move(o.face_loops_);
      vertex_face_begin_ = std::move(o.vertex_face_begin_);
      vertex_faces_ = std::move(o.vertex_faces_);
      copy_scalars(o);
    }
    return *this;
  }
  ~ConvexHullShapeT() = default;

  /// Number of hull vertices.
  std::size_t size() const { return nodes_.size(); }
  Vec3T<S> point(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }
  /// The index of vertex i's point in the points the hull was built from.
  std::uint32_t input_index(std::size_t i) const { return input_indices_[i]; }
  HullStatus status() const { return status_; }
  /// The hull's flatness tolerance (input units): the bound on the climb's error, see above.
  S tolerance() const { return tolerance_; }
  /// True when support climbs (at least kHullClimbMinVertices vertices), false when it scans.
  bool climbs() const { return climbs_; }

  /// The point of support_index(d), read from the vertex's record (in cache where a climb ended)
  /// rather than from the scan's arrays (three more lines).
  Vec3T<S> support_core(const Vec3T<S>& d) const {
    const S* p = support_position(d);
    return {p[0], p[1], p[2]};
  }
  /// support_core(d) as the address of its three coordinates (in the vertex's record), for a
  /// caller that builds the point in its own registers (PolytopeT).
  const S* support_position(const Vec3T<S>& d) const { return vertex_position(support_index(d)); }
  /// Vertex i's coordinates as support_position() returns them: those of its record.
  const S* vertex_position(std::size_t i) const { return nodes_[i].p; }
  /// The mean of the vertices: inside the hull.
  const Vec3T<S>& core_centre() const { return centre_; }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return bounding_radius_; }
  const char* error() const {
    return nodes_.empty() ? "convex hull shape has no vertices" : nullptr;
  }

  /// Index of a vertex farthest along d (thread-safe). The climb starts from the higher of the
  /// previous answer (the hint) and the direction table's seed for d.
  std::size_t support_index(const Vec3T<S>& d) const {
    if (!climbs_) return scan_index(d);
    const std::uint32_t hint = hint_.load(std::memory_order_relaxed);
    const std::uint32_t seed = seed_index(d);
    const S hint_value = dot(nodes_[hint].p, d.x(), d.y(), d.z());
    const S seed_value = dot(nodes_[seed].p, d.x(), d.y(), d.z());
    const std::uint32_t v =
        seed_value > hint_value ? climb(d, seed, seed_value) : climb(d, hint, hint_value);
    if (v != hint) hint_.store(v, std::memory_order_relaxed);
    return v;
  }

  /// The climb from vertex `start` (< size()), without hint or seed: the same answer as
  /// support_index for every start. NaN directions return `start`.
  std::uint32_t climb_index(const Vec3T<S>& d, std::uint32_t start) const {
    return climb(d, start, dot(nodes_[start].p, d.x(), d.y(), d.z()));
  }

  /// Calls f(u) for each neighbour u of vertex v (< size()) on the hull's edge graph.
  template <class F>
  void for_each_neighbor(std::uint32_t v, F&& f) const {
    for (const std::uint32_t u : neighbors_of(nodes_[v])) f(u);
  }

  /// Faces (none for Segment and Point hulls; two opposite ones for Flat): unit outward normals and
  /// vertex loops, counter-clockwise seen from outside. For support features (manifolds).
  std::size_t face_count() const { return face_normals_.size(); }
  const Vec3T<S>& face_normal(std::size_t f) const { return face_normals_[f]; }
  std::span<const std::uint32_t> face_loop(std::size_t f) const {
    return {face_loops_.data() + face_begin_[f], face_loops_.data() + face_begin_[f + 1]};
  }
  /// The faces that have vertex v (< size()) as a corner.
  std::span<const std::uint32_t> faces_around(std::uint32_t v) const {
    return {vertex_faces_.data() + vertex_face_begin_[v],
            vertex_faces_.data() + vertex_face_begin_[v + 1]};
  }

  /// The brute-force answer: lowest index among the vertices farthest along d.
  std::size_t scan_index(const Vec3T<S>& d) const {
    return detail::support_index(x_.data(), y_.data(), z_.data(), x_.size(), d.x(), d.y(), d.z());
  }

  /// The start the direction table gives for d: the answer for the centre of d's cell (0 for a
  /// zero or non-finite direction, and for shapes that scan).
  std::uint32_t seed_index(const Vec3T<S>& d) const { return seed_index(d.x(), d.y(), d.z()); }
  /// The same for d = (dx, dy, dz). By coordinates, in registers: from an array of |d|, Clang read
  /// x and y with one packed load of the caller's direction, which it had stored a coordinate at
  /// a time, and the load waited for the stores (store forwarding fails from narrower stores).
  std::uint32_t seed_index(S dx, S dy, S dz) const {
    if (seeds_.empty()) return 0;
    const S d[3] = {dx, dy, dz};
    const S abs_d[3] = {std::abs(dx), std::abs(dy), std::abs(dz)};
    int axis = 0;
    if (abs_d[1] > abs_d[axis]) axis = 1;
    if (abs_d[2] > abs_d[axis]) axis = 2;
    // abs_d[axis] (NaN where that is), in registers: the division below need not wait for the
    // axis and a load.
    const S a = std::max(std::max(abs_d[0], abs_d[1]), abs_d[2]);
    if (!(a > S(0)) || !(a <= std::numeric_limits<S>::max())) return 0;
    // A coordinate u across the axis, in [-a, a], lies (u + a) k / (2 a) cells from the face's
    // edge: one division for both coordinates, and no conversion of k (2 ns of a support call).
    const S scale = seed_half_cells_ / a;
    const std::size_t face = std::size_t(2 * axis + (d[axis] < S(0) ? 1 : 0));
    const std::size_t cu = cell((d[detail::kNextAxis[axis]] + a) * scale);
    const std::size_t cv = cell((d[detail::kPrevAxis[axis]] + a) * scale);
    return seeds_[(face * seed_cells_ + cu) * seed_cells_ + cv];
  }

 private:
  /// Neighbours a vertex record holds inline: 8 indices fill a 64-byte record in double.
  static constexpr std::uint32_t kInlineNeighbors = 8;
  /// A vertex: its position, the range of its edges in edges_ and, when it has at most
  /// kInlineNeighbors of them, the neighbours' indices. One cache line: a climb step reads it and
  /// then its neighbours' records, all at once.
  struct alignas(64) Node {
    S p[3];
    std::uint32_t begin, end;
    std::uint32_t near[kInlineNeighbors];
  };
  /// Vertex `node`'s neighbours: inline, or in edges_ for a vertex of higher degree.
  std::span<const std::uint32_t> neighbors_of(const Node& node) const {
    const std::uint32_t degree = node.end - node.begin;
    return {degree <= kInlineNeighbors ? node.near : edges_.data() + node.begin, degree};
  }

  ConvexHullShapeT() = default;

  void copy_scalars(const ConvexHullShapeT& o) {
    status_ = o.status_;
    climbs_ = o.climbs_;
    seed_cells_ = o.seed_cells_;
    seed_half_cells_ = o.seed_half_cells_;
    tolerance_ = o.tolerance_;
    bounding_radius_ = o.bounding_radius_;
    centre_ = o.centre_;
    hint_.store(o.hint_.load(std::memory_order_relaxed), std::memory_order_relaxed);
  }

  /// Face loops and the faces around each vertex, from the hull's half-edges.
  bool copy_faces(const ConvexHull& hull) {
    const std::size_t n = nodes_.size();
    face_begin_.assign(1, 0);
    vertex_face_begin_.assign(n + 1, 0);
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
      const HullFace& face = hull.faces[f];
      if (std::size_t(face.first) + face.count > hull.half_edges.size()) return false;
      face_normals_.push_back(face.normal.template cast<S>());
      for (std::uint32_t k = 0; k < face.count; ++k) {
        const std::uint32_t v = hull.face_vertex(f, k);
        if (v >= n) return false;
        face_loops_.push_back(v);
        ++vertex_face_begin_[v + 1];
      }
      face_begin_.push_back(std::uint32_t(face_loops_.size()));
    }
    for (std::size_t v = 0; v < n; ++v) vertex_face_begin_[v + 1] += vertex_face_begin_[v];
    vertex_faces_.resize(face_loops_.size());
    std::vector<std::uint32_t> fill(vertex_face_begin_.begin(), vertex_face_begin_.end() - 1);
    for (std::size_t f = 0; f + 1 < face_begin_.size(); ++f)
      for (std::uint32_t k = face_begin_[f]; k < face_begin_[f + 1]; ++k)
        vertex_faces_[fill[face_loops_[k]]++] = std::uint32_t(f);
    return true;
  }

  /// The one formula for a support value, so that equal vertices give bit-identical values.
  static S dot(const S* p, S dx, S dy, S dz) { return p[0] * dx + p[1] * dy + p[2] * dz; }

  /// The cell f cells from a face's edge, f in [0, k] (NaN: cell 0).
  std::size_t cell(S f) const {
    if (!(f > S(0))) return 0;
    // Through int: f < k <= 64 here, and a conversion to an unsigned 64-bit integer takes a
    // second conversion and a select.
    return f >= S(2) * seed_half_cells_ ? seed_cells_ - 1 : std::size_t(int(f));
  }

  /// The direction table: the cube of directions, each face cut into k x k cells (k about
  /// sqrt(2 n / 3), so some four cells share a vertex's normal cone), each cell holding the
  /// support vertex of its centre direction. A random direction's seed is then its answer three
  /// times in four, and one move from it otherwise (points on an ellipsoid, 64 to 4,096
  /// vertices); a coarser table (k about sqrt(n / 24), one cell for several vertices) left cold
  /// queries two or three moves away. Built by climbing from the previous cell's answer, so it
  /// costs about one climb step per cell: a tenth of building the hull at 128 vertices.
  void build_seeds() {
    seed_cells_ = std::clamp<std::size_t>(
        std::size_t(std::ceil(std::sqrt(double(nodes_.size()) * (2.0 / 3.0)))), 1, 64);
    const std::size_t k = seed_cells_;
    seed_half_cells_ = S(0.5) * S(k);
    seeds_.assign(6 * k * k, 0);
    std::uint32_t v = 0;
    for (std::size_t face = 0; face < 6; ++face) {
      const int axis = int(face / 2);
      for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < k; ++j) {
          // Serpentine order: consecutive cells are neighbours, so each climb is short.
          const std::size_t jj = i % 2 ? k - 1 - j : j;
          Vec3T<S> d;
          d[axis] = face % 2 ? S(-1) : S(1);
          d[(axis + 1) % 3] = S((2 * double(i) + 1) / double(k) - 1);
          d[(axis + 2) % 3] = S((2 * double(jj) + 1) / double(k) - 1);
          v = climb(d, v, dot(nodes_[v].p, d.x(), d.y(), d.z()));
          seeds_[(face * k + i) * k + jj] = v;
        }
    }
  }

  /// Strict-improvement climb from `start`, whose support value is `best`.
  std::uint32_t climb(const Vec3T<S>& d, std::uint32_t start, S best) const {
    const S dx = d.x(), dy = d.y(), dz = d.z();
    std::uint32_t v = start;
    const Node* node = &nodes_[v];
    // Each move strictly increases the support value, so at most size() - 1 moves can happen.
    for (std::size_t moves = 0; moves < nodes_.size(); ++moves) {
      std::uint32_t next = v;  // none
      S next_value = best;
      bool tie = false;
      for (const std::uint32_t u : neighbors_of(*node)) {
        const S value = dot(nodes_[u].p, dx, dy, dz);
        if (value > next_value) {
          next_value = value;
          next = u;
        }
        tie |= value == best;
      }
      if (next == v) return tie ? plateau_index(d, v, best) : v;
      v = next;
      node = &nodes_[v];
      best = next_value;
    }
    return std::uint32_t(scan_index(d));  // unreachable in exact arithmetic: a safety net
  }

  /// v is a local maximum with value `best` and a neighbour of equal value: the lowest index of
  /// the connected set of vertices with that value (the face or edge facing d). A vertex of the
  /// set with a strictly larger neighbour (possible only through rounding) or a set larger than
  /// kHullPlateauLimit hands the query to the scan.
  std::uint32_t plateau_index(const Vec3T<S>& d, std::uint32_t v, S best) const {
    const S dx = d.x(), dy = d.y(), dz = d.z();
    std::uint32_t set[kHullPlateauLimit];
    std::size_t count = 0;
    set[count++] = v;
    std::uint32_t lowest = v;
    for (std::size_t i = 0; i < count; ++i) {
      for (const std::uint32_t to : neighbors_of(nodes_[set[i]])) {
        const S value = dot(nodes_[to].p, dx, dy, dz);
        if (value > best) return std::uint32_t(scan_index(d));
        if (value != best) continue;
        bool seen = false;
        for (std::size_t j = 0; j < count; ++j) seen |= set[j] == to;
        if (seen) continue;
        if (count == kHullPlateauLimit) return std::uint32_t(scan_index(d));
        set[count++] = to;
        lowest = std::min(lowest, to);
      }
    }
    return lowest;
  }

  std::vector<S> x_, y_, z_;                  // structure of arrays, for the scan
  std::vector<Node> nodes_;                   // array of structures, for the climb
  std::vector<std::uint32_t> input_indices_;  // vertex -> index of its input point
  // CSR adjacency: vertex v's neighbours are edges_[nodes_[v].begin .. nodes_[v].end).
  std::vector<std::uint32_t> edges_;
  std::vector<std::uint32_t> seeds_;    // direction table, 6 k k entries (empty when scanning)
  std::vector<Vec3T<S>> face_normals_;  // unit, outward
  // CSR lists: face f's vertex loop, and the faces around vertex v.
  std::vector<std::uint32_t> face_begin_, face_loops_, vertex_face_begin_, vertex_faces_;
  std::size_t seed_cells_ = 0;  // k
  S seed_half_cells_ = S(0);    // k / 2
  HullStatus status_ = HullStatus::Point;
  bool climbs_ = false;
  S tolerance_ = S(0);
  S bounding_radius_ = S(0);
  Vec3T<S> centre_ = Vec3T<S>::Zero();
  // On its own cache line: the climb writes it, while other threads read the members above.
  // The class is then 64-aligned and a multiple of 64 bytes long, so nothing follows on that line.
  alignas(64) mutable std::atomic<std::uint32_t> hint_{0};
};

using ConvexHullShape = ConvexHullShapeT<double>;

}  // namespace mink
