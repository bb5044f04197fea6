// build_convex_hull: input checks, an exact local frame, the dimension of the input, and the
// assembly of the output. The solid case is in triangle_hull.cpp and hull_faces.cpp.
#include "mink/hull/convex_hull.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "hull_faces.hpp"
#include "interior_filter.hpp"
#include "mink/hull/predicates.hpp"
#include "triangle_hull.hpp"

namespace mink {
namespace {

constexpr double kU = exact::kUnitRoundoff;
constexpr std::size_t kMaxPoints = std::size_t{1} << 28;
constexpr double kMaxCoordinate = 1e100;

/// Input translated by `shift` and scaled by the power of two `scale`, exactly.
struct Frame {
  Vec3 shift = Vec3::Zero();
  double scale = 1;
  std::vector<Vec3> q;
  double tolerance = 0;  // world units
  double diagonal = 0;
};

/// Upper bound of the exact n . x for a computed n . x.
double dot_up(const Vec3& n, const Vec3& x) {
  return n.dot(x) +
         4 * kU * (std::fabs(n[0] * x[0]) + std::fabs(n[1] * x[1]) + std::fabs(n[2] * x[2]));
}

/// A plane offset in the local frame, in world units: the smallest double at least
/// local / scale + n . shift (exact evaluation, then rounded up).
double world_offset(const Frame& frame, const Vec3& n, double local) {
  using namespace exact;
  if (frame.shift == Vec3::Zero()) return local / frame.scale;  // exact: a power of two
  const auto sum =
      add(add(add(scale(expansion(frame.shift[0]), n[0]), scale(expansion(frame.shift[1]), n[1])),
              scale(expansion(frame.shift[2]), n[2])),
          expansion(local / frame.scale));  // division by a power of two: exact
  double up = estimate(sum);
  for (int i = 0; i < 4 && sign(sub(sum, expansion(up))) > 0; ++i)
    up = std::nextafter(up, HUGE_VAL);
  return up;
}

/// Output from face loops over point indices (local planes): vertices, half-edges with twins,
/// neighbours, volume and area.
bool assemble(std::span<const Vec3> points, const Frame& frame, const std::vector<int>& loop,
              const std::vector<int>& start, const std::vector<Vec3>& normal,
              const std::vector<double>& offset, ConvexHull& hull, std::string& error) {
  const std::size_t f_count = normal.size();
  std::vector<int> id(points.size(), -1);
  hull.vertices.clear();
  hull.faces.clear();
  hull.half_edges.clear();
  for (const int v : loop) {
    if (id[static_cast<std::size_t>(v)] < 0) {
      id[static_cast<std::size_t>(v)] = static_cast<int>(hull.vertices.size());
      hull.vertices.push_back({points[static_cast<std::size_t>(v)], static_cast<std::uint32_t>(v)});
    }
  }
  for (std::size_t f = 0; f < f_count; ++f) {
    HullFace face;
    face.normal = normal[f];
    face.offset = world_offset(frame, normal[f], offset[f]);
    face.first = static_cast<std::uint32_t>(start[f]);
    face.count = static_cast<std::uint32_t>(start[f + 1] - start[f]);
    if (face.count < 3) {
      error = "a face has fewer than three vertices";
      return false;
    }
    hull.faces.push_back(face);
    for (int i = start[f]; i < start[f + 1]; ++i) {
      hull.half_edges.push_back(
          {static_cast<std::uint32_t>(
               id[static_cast<std::size_t>(loop[static_cast<std::size_t>(i)])]),
           0, static_cast<std::uint32_t>(f)});
    }
  }
  // Twins: the half-edge b -> a for each a -> b, among the half-edges out of b.
  const std::size_t e_count = hull.half_edges.size();
  const std::size_t v_count = hull.vertices.size();
  // Per vertex, its outgoing half-edges with their far ends (so the search stays local).
  std::vector<std::uint32_t> dest(e_count);
  for (const auto& face : hull.faces) {
    for (std::uint32_t k = 0; k < face.count; ++k)
      dest[face.first + k] = hull.half_edges[face.first + (k + 1) % face.count].vertex;
  }
  std::vector<std::uint32_t> out_start(v_count + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out_list(e_count);  // (far end, edge)
  for (const auto& he : hull.half_edges) ++out_start[he.vertex + 1];
  for (std::size_t v = 0; v < v_count; ++v) out_start[v + 1] += out_start[v];
  {
    std::vector<std::uint32_t> fill(out_start.begin(), out_start.end() - 1);
    for (std::uint32_t h = 0; h < e_count; ++h)
      out_list[fill[hull.half_edges[h].vertex]++] = {dest[h], h};
  }
  for (std::uint32_t h = 0; h < e_count; ++h) {
    const std::uint32_t a = hull.half_edges[h].vertex, b = dest[h];
    int found = 0;
    for (std::uint32_t i = out_start[b]; i < out_start[b + 1]; ++i) {
      if (out_list[i].first == a) {
        hull.half_edges[h].twin = out_list[i].second;
        ++found;
      }
    }
    if (found != 1) {
      error = "an edge is not shared by exactly two faces";
      return false;
    }
  }
  // Neighbours, counter-clockwise seen from outside: rotate from one outgoing half-edge.
  hull.neighbor_offsets.assign(1, 0);
  hull.neighbors.clear();
  hull.neighbors.reserve(e_count);
  for (std::size_t v = 0; v < v_count; ++v) {
    const std::uint32_t h0 = out_list[out_start[v]].second;
    std::uint32_t h = h0;
    std::size_t steps = 0;
    do {
      hull.neighbors.push_back(dest[h]);
      const HullFace& f = hull.faces[hull.half_edges[h].face];
      const std::uint32_t prev = h == f.first ? f.first + f.count - 1 : h - 1;
      h = hull.half_edges[prev].twin;
      if (++steps > e_count) {
        error = "a vertex has an open fan";
        return false;
      }
    } while (h != h0);
    hull.neighbor_offsets.push_back(static_cast<std::uint32_t>(hull.neighbors.size()));
  }
  if (hull.neighbors.size() != e_count) {
    error = "a vertex is shared by two separate fans";
    return false;
  }
  // Volume and area in the local frame, then scaled back exactly. The volume is a sum of
  // tetrahedra from one vertex; when their rounding could be more than 1e-10 of the sum (on a
  // needle or a sliver of a hull it can exceed the volume itself), each is taken again to within
  // roundoff of its exact value.
  const Vec3& o = frame.q[static_cast<std::size_t>(loop.front())];
  auto for_each_tetrahedron = [&](auto&& visit) {
    for (std::size_t f = 0; f < f_count; ++f) {
      const Vec3& a = frame.q[static_cast<std::size_t>(loop[static_cast<std::size_t>(start[f])])];
      for (int i = start[f] + 1; i + 1 < start[f + 1]; ++i)
        visit(f, a, frame.q[static_cast<std::size_t>(loop[static_cast<std::size_t>(i)])],
              frame.q[static_cast<std::size_t>(loop[static_cast<std::size_t>(i) + 1])]);
    }
  };
  double volume = 0, volume_bound = 0;
  std::vector<Vec3> vector_area(f_count, Vec3::Zero());
  for_each_tetrahedron([&](std::size_t f, const Vec3& a, const Vec3& b, const Vec3& c) {
    vector_area[f] += (b - a).cross(c - a);
    double bound;
    volume += exact::orient3d_estimate(o.data(), b.data(), c.data(), a.data(), bound);
    volume_bound += bound;
  });
  if (!(volume_bound <= 1e-10 * volume)) {
    volume = 0;
    for_each_tetrahedron([&](std::size_t, const Vec3& a, const Vec3& b, const Vec3& c) {
      volume += exact::orient3d_value(o.data(), b.data(), c.data(), a.data());
    });
  }
  double area = 0;
  for (const Vec3& va : vector_area) area += 0.5 * va.norm();
  const double inv = 1 / frame.scale;
  hull.volume = volume / 6 * inv * inv * inv;
  hull.area = area * inv * inv;
  return true;
}

/// Whether merged faces fail to make a convex polyhedron the way merging within a tolerance can
/// fail: fewer than four faces, or two faces that meet along more than one edge (the two sides
/// of a folded needle; convex faces share one edge at most).
bool folded(const ConvexHull& hull) {
  const std::size_t f_count = hull.faces.size();
  if (f_count < 4) return true;
  std::vector<std::uint32_t> met(f_count, std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t f = 0; f < f_count; ++f) {
    const HullFace& face = hull.faces[f];
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const std::uint32_t g = hull.half_edges[hull.half_edges[face.first + k].twin].face;
      if (met[g] == f) return true;
      met[g] = f;
    }
  }
  return false;
}

/// The convex polygon of points (local frame) lying within the tolerance of a plane with normal
/// n: monotone chain in the plane's own frame, with exact turns seen along n. (A chain on two
/// coordinates, dropping n's largest, is convex in that projection only: points up to the
/// tolerance off the plane shift by up to sqrt(2) times that across it, and a needle 1e-9 wide
/// had a vertex 1.03 tolerances outside an edge.) The loop is counter-clockwise about n.
std::vector<int> flat_polygon(const std::vector<Vec3>& q, const Vec3& n) {
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  std::vector<std::pair<double, double>> key(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) key[i] = {e1.dot(q[i]), e2.dot(q[i])};
  std::vector<int> order(q.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
  });
  std::vector<int> chain(2 * q.size() + 1);
  std::size_t m = 0;
  auto turn = [&](int a, int b, int c) {
    return exact::orient_along(q[static_cast<std::size_t>(a)].data(),
                               q[static_cast<std::size_t>(b)].data(),
                               q[static_cast<std::size_t>(c)].data(), n.data());
  };
  for (const int v : order) {  // lower chain
    while (m >= 2 && turn(chain[m - 2], chain[m - 1], v) <= 0) --m;
    chain[m++] = v;
  }
  const std::size_t lower = m + 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) {  // upper chain
    while (m >= lower && turn(chain[m - 2], chain[m - 1], *it) <= 0) --m;
    chain[m++] = *it;
  }
  chain.resize(m > 1 ? m - 1 : m);
  return chain;
}

/// Distance of x from the line through a and b.
double line_distance(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len = d.norm();
  return len > 0 ? (x - a).cross(d).norm() / len : (x - a).norm();
}

/// Keeps at most max_vertices vertices of a convex polygon, furthest first; returns the largest
/// distance of a dropped vertex from the chord that replaced it.
double reduce_polygon(const std::vector<Vec3>& q, std::vector<int>& poly,
                      std::size_t max_vertices) {
  const std::size_t m = poly.size();
  auto at = [&](std::size_t i) -> const Vec3& { return q[static_cast<std::size_t>(poly[i])]; };
  std::vector<char> keep(m, 0);
  std::size_t far = 0;
  for (std::size_t i = 1; i < m; ++i) {
    if ((at(i) - at(0)).squaredNorm() > (at(far) - at(0)).squaredNorm()) far = i;
  }
  keep[0] = keep[far] = 1;
  std::size_t kept = 2;
  // Per kept vertex: the farthest dropped vertex before the next kept one, and its distance.
  std::vector<std::size_t> best(m, 0);
  std::vector<double> best_dist(m, -1);
  auto next_kept = [&](std::size_t i) {
    std::size_t j = (i + 1) % m;
    while (!keep[j]) j = (j + 1) % m;
    return j;
  };
  auto rescan = [&](std::size_t i) {
    const std::size_t j = next_kept(i);
    best_dist[i] = -1;
    for (std::size_t k = (i + 1) % m; k != j; k = (k + 1) % m) {
      const double dist = line_distance(at(k), at(i), at(j));
      if (dist > best_dist[i]) {
        best_dist[i] = dist;
        best[i] = k;
      }
    }
  };
  rescan(0);
  rescan(far);
  while (kept < max_vertices) {
    std::size_t gap = m;
    for (std::size_t i = 0; i < m; ++i) {
      if (keep[i] && best_dist[i] >= 0 && (gap == m || best_dist[i] > best_dist[gap])) gap = i;
    }
    if (gap == m) break;
    keep[best[gap]] = 1;
    ++kept;
    rescan(gap);
    rescan(best[gap]);
  }
  double worst = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (keep[i]) worst = std::max(worst, best_dist[i]);
  }
  std::vector<int> reduced;
  for (std::size_t i = 0; i < m; ++i) {
    if (keep[i]) reduced.push_back(poly[i]);
  }
  poly = std::move(reduced);
  return worst;
}

Expected<ConvexHull> fail(const std::string& reason) {
  return Expected<ConvexHull>::failure("convex hull: " + reason);
}

}  // namespace

Expected<ConvexHull> build_convex_hull(std::span<const Vec3> points, const HullOptions& options) {
  const std::size_t n = points.size();
  if (n == 0) return fail("no points");
  if (n > kMaxPoints) return fail("more than 2^28 points");
  if (!(options.relative_tolerance >= 0 && options.relative_tolerance <= 1e-2))
    return fail("relative_tolerance must be in [0, 1e-2]");
  if (options.max_vertices != 0 && options.max_vertices < 4)
    return fail("max_vertices must be 0 (no limit) or at least 4");

  // ---- Frame ----
  Vec3 lo = points[0], hi = points[0];
  double max_abs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = points[i];
    if (!is_finite(x)) return fail("point " + std::to_string(i) + " is not finite");
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
    max_abs = std::max(max_abs, x.cwiseAbs().maxCoeff());
  }
  if (max_abs > kMaxCoordinate) return fail("coordinates too large (above 1e100)");
  Frame frame;
  double extent = 0;
  for (int i = 0; i < 3; ++i) {
    // Shift only where x - shift is exact for the whole box (Sterbenz: shift <= x <= 2 shift).
    if (lo[i] > 0 && hi[i] <= 2 * lo[i]) frame.shift[i] = lo[i];
    if (hi[i] < 0 && lo[i] >= 2 * hi[i]) frame.shift[i] = hi[i];
    extent =
        std::max({extent, std::fabs(lo[i] - frame.shift[i]), std::fabs(hi[i] - frame.shift[i])});
  }
  frame.diagonal = (hi - lo).stableNorm();  // no underflow of the squares for tiny boxes
  frame.tolerance = options.relative_tolerance * frame.diagonal + 32 * DBL_EPSILON * max_abs;

  ConvexHull hull;
  hull.tolerance = frame.tolerance;
  if (frame.diagonal <= frame.tolerance) {  // all points equal, or within the tolerance
    hull.status = HullStatus::Point;
    hull.vertices.push_back({points[0], 0});
    hull.neighbor_offsets.assign(2, 0);
    return hull;
  }
  frame.scale = std::ldexp(1.0, -std::ilogb(extent));
  frame.q.resize(n);
  for (std::size_t i = 0; i < n; ++i) frame.q[i] = (points[i] - frame.shift) * frame.scale;
  const double tol = frame.tolerance * frame.scale;
  const std::vector<Vec3>& q = frame.q;

  // ---- Dimension ----
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
  }
  int a = 0, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (q[i][axis] < q[static_cast<std::size_t>(a)][axis]) a = static_cast<int>(i);
    if (q[i][axis] > q[static_cast<std::size_t>(b)][axis]) b = static_cast<int>(i);
  }
  const Vec3 qa = q[static_cast<std::size_t>(a)], ab = q[static_cast<std::size_t>(b)] - qa;
  int c = a;
  double c_dist2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d2 = (q[i] - qa).cross(ab).squaredNorm();
    if (d2 > c_dist2) {
      c_dist2 = d2;
      c = static_cast<int>(i);
    }
  }
  if (std::sqrt(c_dist2) / ab.norm() <= tol) {
    // A segment: the extreme points along the line.
    int i0 = a, i1 = b;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = ab.dot(q[i]);
      if (t < ab.dot(q[static_cast<std::size_t>(i0)])) i0 = static_cast<int>(i);
      if (t > ab.dot(q[static_cast<std::size_t>(i1)])) i1 = static_cast<int>(i);
    }
    hull.status = HullStatus::Segment;
    hull.vertices.push_back({points[static_cast<std::size_t>(i0)], static_cast<std::uint32_t>(i0)});
    hull.vertices.push_back({points[static_cast<std::size_t>(i1)], static_cast<std::uint32_t>(i1)});
    hull.neighbor_offsets = {0, 1, 2};
    hull.neighbors = {1, 0};
    return hull;
  }
  double nc[3];
  exact::cross_rounded(qa.data(), q[static_cast<std::size_t>(b)].data(),
                       q[static_cast<std::size_t>(c)].data(), nc);
  const Vec3 nrm = Vec3(nc[0], nc[1], nc[2]).normalized();
  int d_lo = a, d_hi = a;
  double s_lo = 0, s_hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = nrm.dot(q[i] - qa);
    if (s < s_lo) {
      s_lo = s;
      d_lo = static_cast<int>(i);
    }
    if (s > s_hi) {
      s_hi = s;
      d_hi = static_cast<int>(i);
    }
  }

  std::vector<int> loop, start;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  std::string error;
  if (s_hi - s_lo <= tol) {
    // ---- Flat: one polygon, front and back ----
    std::vector<int> poly = flat_polygon(q, nrm);
    if (poly.size() < 3) return fail("internal error: flat polygon has fewer than 3 vertices");
    if (options.max_vertices != 0 && poly.size() > options.max_vertices) {
      hull.max_outside = reduce_polygon(q, poly, options.max_vertices) / frame.scale;
      hull.complete = false;
    }
    double front = -HUGE_VAL, back = -HUGE_VAL;
    for (std::size_t i = 0; i < n; ++i) {
      front = std::max(front, dot_up(nrm, q[i]));
      back = std::max(back, dot_up(-nrm, q[i]));
    }
    loop = poly;
    loop.insert(loop.end(), poly.rbegin(), poly.rend());
    start = {0, static_cast<int>(poly.size()), static_cast<int>(2 * poly.size())};
    normals = {nrm, -nrm};
    offsets = {front, back};
    hull.status = HullStatus::Flat;
    if (!assemble(points, frame, loop, start, normals, offsets, hull, error))
      return fail("internal error: " + error);
    hull.volume = 0;
    return hull;
  }

  // ---- Full ----
  const int d = -s_lo > s_hi ? d_lo : d_hi;
  int simplex[4] = {a, b, c, d};
  // Points that cannot be vertices are dropped first (a complete build only: a stopped one
  // reports how far remaining points are outside). The simplex points are extreme, so kept.
  // The points left are copied in a spatial order (only speed depends on it).
  std::vector<int> kept;
  if (options.max_vertices == 0) {
    kept = detail::hull_candidates(q);
  } else {
    kept.resize(n);
    std::iota(kept.begin(), kept.end(), 0);
  }
  for (const int v : simplex) {
    if (!std::binary_search(kept.begin(), kept.end(), v))
      return fail("internal error: a simplex point was dropped");
  }
  detail::sort_spatially(q, kept);
  std::vector<Vec3> hull_q(kept.size());
  {
    std::vector<int> position(n, -1);
    for (std::size_t i = 0; i < kept.size(); ++i) {
      hull_q[i] = q[static_cast<std::size_t>(kept[i])];
      position[static_cast<std::size_t>(kept[i])] = static_cast<int>(i);
    }
    for (int& v : simplex) v = position[static_cast<std::size_t>(v)];
  }
  detail::TriangleHull triangles;
  if (!detail::build_triangle_hull(hull_q, simplex, options.max_vertices, triangles, error))
    return fail("internal error: " + error);
  hull.status = HullStatus::Full;
  hull.complete = triangles.complete;
  // Faces merged within the tolerance, or (tolerance 0) the exact facets alone.
  auto assemble_faces = [&](double merge_tolerance) {
    detail::PolygonFaces faces;
    if (!detail::build_polygon_faces(hull_q, triangles, merge_tolerance, faces, error))
      return false;
    for (int& v : faces.loop) v = kept[static_cast<std::size_t>(v)];
    hull.max_outside = faces.max_outside / frame.scale;
    return assemble(points, frame, faces.loop, faces.start, faces.normal, faces.offset, hull,
                    error);
  };
  if (!assemble_faces(tol)) return fail("internal error: " + error);
  if (folded(hull)) {
    // Merging within the tolerance folded a needle about as thin as the tolerance across its
    // length (but not flat along the first triangle's plane, step 2) onto two faces that meet
    // along both its sides. Its exact facets are a true solid: keep them unmerged.
    if (!assemble_faces(0.0)) return fail("internal error: " + error);
  }
  if (hull.vertices.size() + hull.faces.size() != hull.half_edges.size() / 2 + 2)
    return fail("internal error: Euler's formula does not hold");
  return hull;
}

}  // namespace mink
