// Polygonal faces from the exact triangulated hull.
//
// 1. Exact facets: triangles joined across edges where the neighbour's far vertex is exactly
//    coplanar (exact orientation 0). A facet is a planar convex polygon of the true hull, so it
//    is always a valid face on its own; it is never split.
// 2. Regions: from the largest facet left, a region grows over neighbouring facets whose
//    vertices all lie within `tolerance` below the supporting plane of the seed's normal, that
//    face that normal (exact sign), and keep the region a disk without pinches. The region is
//    accepted when its boundary turns left at every vertex along the normal (exact signs);
//    otherwise the facets at its reflex vertices are excluded and it grows again, and after a
//    few attempts the seed facet alone is taken.
// 3. Planes: the normal is the region's area-weighted normal when that keeps the region flat,
//    front-facing and convex, else the seed's (rounded from its exact value). The offset is an
//    upper bound of the maximum of n . x over the hull: for the seed's normal, from the facet's
//    own vertices plus a proven margin (facet_support); for any other normal, the exact maximum
//    found by an exact hill climb on the convex triangulation, rounded up.
// 4. Loops: vertices where fewer than three regions meet are left out of the loops, unless a
//    region would keep fewer than three vertices.
#include "hull_faces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "mink/hull/predicates.hpp"

namespace mink::detail {
namespace {

constexpr double kU = exact::kUnitRoundoff;
constexpr int kMaxAttempts = 8;

class FaceBuilder {
 public:
  FaceBuilder(std::span<const Vec3> q, const TriangleHull& hull, double tol)
      : q_(q), hull_(hull), tris_(hull.triangles), tol_(tol) {}

  bool run(PolygonFaces& out, std::string& error);

 private:
  // ---- the triangle mesh ----
  static int next_he(int h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static int prev_he(int h) { return h - h % 3 + (h % 3 + 2) % 3; }
  int origin(int h) const { return tris_[static_cast<std::size_t>(h / 3)].v[h % 3]; }
  int dest(int h) const { return origin(next_he(h)); }
  int twin(int h) const { return tris_[static_cast<std::size_t>(h / 3)].twin[h % 3]; }
  /// The next half-edge out of origin(h), counter-clockwise seen from outside.
  int rotate(int h) const { return twin(prev_he(h)); }
  const double* p(int point) const { return q_[static_cast<std::size_t>(point)].data(); }
  int vid(int point) const { return vertex_id_[static_cast<std::size_t>(point)]; }

  bool build_facets(std::string& error);
  bool climb(const Vec3& n, int start, int& best, std::string& error) const;
  double support(const Vec3& n, int vertex_point) const {
    const double* x = p(vertex_point);
    const double dot = n[0] * x[0] + n[1] * x[1] + n[2] * x[2];
    return dot +
           4 * kU * (std::fabs(n[0] * x[0]) + std::fabs(n[1] * x[1]) + std::fabs(n[2] * x[2]));
  }
  Vec3 facet_normal(int facet) const;
  double facet_support(int facet, const Vec3& n) const;

  // ---- growing a region ----
  bool member(int triangle) const {
    return member_stamp_[static_cast<std::size_t>(facet_of_[static_cast<std::size_t>(triangle)])] ==
           stamp_;
  }
  bool fits(int facet, const Vec3& n, double d) const;
  bool disk_ok(int facet, int* run_start = nullptr, int* run_count = nullptr) const;
  bool junctions_convex(int facet, const Vec3& n) const;
  void accept(int facet);
  void grow(int seed, const Vec3& n, double d, int region, bool keep_convex);
  bool boundary(std::vector<int>& loop, std::string& error);
  bool convex_along(const std::vector<int>& loop, const Vec3& n, std::vector<int>* reflex) const;

  std::span<const Vec3> q_;
  const TriangleHull& hull_;
  const std::vector<HullTriangle>& tris_;
  double tol_;
  double support_pad_ = 0;  // see facet_support

  // Hull vertices: point -> dense id, and per id one outgoing half-edge and marks.
  std::vector<int> vertex_id_, vertex_point_, out_edge_;
  std::vector<std::uint64_t> vmark_, loop_mark_;

  // Facets.
  std::vector<int> facet_of_;
  std::vector<int> facet_tri_start_, facet_tris_;
  std::vector<int> facet_bnd_start_, facet_bnd_;
  std::vector<int> facet_seed_;  // its largest triangle
  std::vector<double> facet_area_;

  // Region growth state.
  std::vector<int> region_of_facet_, blocked_;
  std::vector<std::uint64_t> member_stamp_, reject_stamp_;
  std::uint64_t stamp_ = 0;
  std::vector<int> members_, queue_, deferred_, scratch_;
  long budget_ = 0;
  bool progress_ = false;
};

bool FaceBuilder::build_facets(std::string& error) {
  const int t_count = static_cast<int>(tris_.size());
  facet_of_.assign(tris_.size(), -1);
  facet_tri_start_.clear();
  facet_tris_.clear();
  std::vector<int> stack;
  for (int t0 = 0; t0 < t_count; ++t0) {
    if (facet_of_[static_cast<std::size_t>(t0)] >= 0) continue;
    const int f = static_cast<int>(facet_tri_start_.size());
    facet_tri_start_.push_back(static_cast<int>(facet_tris_.size()));
    const HullTriangle& ref = tris_[static_cast<std::size_t>(t0)];
    facet_of_[static_cast<std::size_t>(t0)] = f;
    stack.assign(1, t0);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      facet_tris_.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int h = twin(3 * t + k);
        const int nb = h / 3;
        if (facet_of_[static_cast<std::size_t>(nb)] >= 0) continue;
        const int far = origin(prev_he(h));
        if (exact::orient3d(p(ref.v[0]), p(ref.v[1]), p(ref.v[2]), p(far)) == 0) {
          facet_of_[static_cast<std::size_t>(nb)] = f;
          stack.push_back(nb);
        }
      }
    }
  }
  const int f_count = static_cast<int>(facet_tri_start_.size());
  facet_tri_start_.push_back(static_cast<int>(facet_tris_.size()));

  // Boundary loop, largest triangle and area of each facet.
  facet_bnd_start_.assign(1, 0);
  facet_bnd_.clear();
  facet_seed_.assign(static_cast<std::size_t>(f_count), -1);
  facet_area_.assign(static_cast<std::size_t>(f_count), 0);
  const long cap = 3L * t_count + 3;
  for (int f = 0; f < f_count; ++f) {
    int start = -1;
    double best = -1;
    for (int i = facet_tri_start_[static_cast<std::size_t>(f)];
         i < facet_tri_start_[static_cast<std::size_t>(f) + 1]; ++i) {
      const int t = facet_tris_[static_cast<std::size_t>(i)];
      const HullTriangle& tri = tris_[static_cast<std::size_t>(t)];
      const Vec3 a = q_[static_cast<std::size_t>(tri.v[0])];
      const double area2 = (q_[static_cast<std::size_t>(tri.v[1])] - a)
                               .cross(q_[static_cast<std::size_t>(tri.v[2])] - a)
                               .squaredNorm();
      facet_area_[static_cast<std::size_t>(f)] += std::sqrt(area2);
      if (area2 > best) {
        best = area2;
        facet_seed_[static_cast<std::size_t>(f)] = t;
      }
      for (int k = 0; k < 3; ++k) {
        if (start < 0 && facet_of_[static_cast<std::size_t>(twin(3 * t + k) / 3)] != f)
          start = 3 * t + k;
      }
    }
    if (start < 0) {
      error = "a facet covers the whole hull";
      return false;
    }
    int h = start;
    long steps = 0;
    do {
      facet_bnd_.push_back(h);
      int g = next_he(h);
      while (facet_of_[static_cast<std::size_t>(twin(g) / 3)] == f) {
        g = next_he(twin(g));
        if (++steps > cap) {
          error = "facet boundary walk cap reached";
          return false;
        }
      }
      h = g;
      if (++steps > cap) {
        error = "facet boundary walk cap reached";
        return false;
      }
    } while (h != start);
    facet_bnd_start_.push_back(static_cast<int>(facet_bnd_.size()));
  }
  return true;
}

Vec3 FaceBuilder::facet_normal(int facet) const {
  const HullTriangle& t =
      tris_[static_cast<std::size_t>(facet_seed_[static_cast<std::size_t>(facet)])];
  double n[3];
  exact::cross_rounded(p(t.v[0]), p(t.v[1]), p(t.v[2]), n);
  return Vec3(n[0], n[1], n[2]).normalized();
}

// An upper bound of max n . x over the hull, for n the normal of the facet rounded from its
// exact value (|n - exact unit normal| <= 8 u): every hull point x has exact_normal . (x - v) <= 0
// for a facet vertex v, so n . x <= n . v + 8 u |x - v| <= n . v + 8 u 2 sqrt(3) M, with M the
// largest coordinate magnitude; plus 4 u sqrt(3) M for rounding n . v: 48 u M in all. The
// tolerance of convex_hull.hpp is at least 64 u M, so the facet stays flat within it.
// An axis-aligned normal (two components exactly 0) is exact, and so are its dot products: no
// margin then, so boxes get offsets equal to their coordinates.
double FaceBuilder::facet_support(int facet, const Vec3& n) const {
  double best = -HUGE_VAL;
  for (int i = facet_bnd_start_[static_cast<std::size_t>(facet)];
       i < facet_bnd_start_[static_cast<std::size_t>(facet) + 1]; ++i)
    best = std::max(
        best, n.dot(q_[static_cast<std::size_t>(origin(facet_bnd_[static_cast<std::size_t>(i)]))]));
  const int zeros = (n[0] == 0) + (n[1] == 0) + (n[2] == 0);
  return zeros == 2 ? best : best + support_pad_;
}

// Hill climb to a vertex maximising n . x, with exact comparisons: on the convex triangulated
// hull a vertex no neighbour of which is strictly higher is a global maximum.
bool FaceBuilder::climb(const Vec3& n, int start, int& best, std::string& error) const {
  int cur = start;
  const std::size_t cap = vertex_point_.size() + 1;
  const long ring_cap = 3L * static_cast<long>(tris_.size()) + 3;
  for (std::size_t moves = 0; moves <= cap; ++moves) {
    const int h0 = out_edge_[static_cast<std::size_t>(vid(cur))];
    int h = h0;
    bool moved = false;
    for (long s = 0; s <= ring_cap; ++s) {
      const int w = dest(h);
      if (exact::dot_sign(n.data(), p(cur), p(w)) > 0) {
        cur = w;
        moved = true;
        break;
      }
      h = rotate(h);
      if (h == h0) break;
    }
    if (!moved) {
      best = cur;
      return true;
    }
  }
  error = "hill climb cap reached";
  return false;
}

bool FaceBuilder::fits(int facet, const Vec3& n, double d) const {
  const double floor = d - tol_;
  for (int i = facet_tri_start_[static_cast<std::size_t>(facet)];
       i < facet_tri_start_[static_cast<std::size_t>(facet) + 1]; ++i) {
    const HullTriangle& t =
        tris_[static_cast<std::size_t>(facet_tris_[static_cast<std::size_t>(i)])];
    for (int k = 0; k < 3; ++k) {
      if (n.dot(q_[static_cast<std::size_t>(t.v[k])]) < floor) return false;
    }
  }
  const HullTriangle& s =
      tris_[static_cast<std::size_t>(facet_seed_[static_cast<std::size_t>(facet)])];
  return exact::orient_along(p(s.v[0]), p(s.v[1]), p(s.v[2]), n.data()) > 0;
}

// Adding the facet keeps the region a disk without pinches: the facet's boundary meets the
// region along one contiguous run of edges, and nowhere else.
bool FaceBuilder::disk_ok(int facet, int* run_start_out, int* run_count_out) const {
  const int b0 = facet_bnd_start_[static_cast<std::size_t>(facet)];
  const int m = facet_bnd_start_[static_cast<std::size_t>(facet) + 1] - b0;
  auto shared = [&](int i) {
    return member(twin(facet_bnd_[static_cast<std::size_t>(b0 + (i % m + m) % m)]) / 3);
  };
  int runs = 0, run_start = -1, count = 0;
  for (int i = 0; i < m; ++i) {
    if (shared(i)) {
      ++count;
      if (!shared(i - 1)) {
        ++runs;
        run_start = i;
      }
    }
  }
  if (runs != 1 || count == m) return false;
  if (run_start_out != nullptr) *run_start_out = run_start;
  if (run_count_out != nullptr) *run_count_out = count;
  // Vertices strictly off the run: origins of edges run_start + count + 1 .. run_start + m - 1.
  for (int i = run_start + count + 1; i < run_start + m; ++i) {
    const int v = origin(facet_bnd_[static_cast<std::size_t>(b0 + i % m)]);
    if (vmark_[static_cast<std::size_t>(vid(v))] == stamp_) return false;
  }
  return true;
}

// With the facet added, the region's boundary keeps turning left at the two ends of the shared
// run (its other corners are unchanged, or corners of the convex facet itself).
bool FaceBuilder::junctions_convex(int facet, const Vec3& n) const {
  int s = 0, count = 0;
  if (!disk_ok(facet, &s, &count)) return false;
  const int b0 = facet_bnd_start_[static_cast<std::size_t>(facet)];
  const int m = facet_bnd_start_[static_cast<std::size_t>(facet) + 1] - b0;
  auto edge = [&](int i) { return facet_bnd_[static_cast<std::size_t>(b0 + (i % m + m) % m)]; };
  const long cap = 3L * static_cast<long>(tris_.size()) + 3;
  // End of the run, q: the region's boundary arrives at q from x, the facet's leaves q.
  const int last = edge(s + count - 1);
  const int q = dest(last);
  int g = prev_he(twin(last));
  for (long k = 0; member(twin(g) / 3); ++k) {
    g = prev_he(twin(g));
    if (k > cap) return false;
  }
  const int x = origin(g), after_q = dest(edge(s + count));
  // Start of the run, p: the facet's boundary arrives at p, the region's leaves p towards y.
  const int first = edge(s);
  const int pv = origin(first);
  g = next_he(twin(first));
  for (long k = 0; member(twin(g) / 3); ++k) {
    g = next_he(twin(g));
    if (k > cap) return false;
  }
  const int y = dest(g), before_p = origin(edge(s - 1));
  return exact::orient_along(p(x), p(q), p(after_q), n.data()) >= 0 &&
         exact::orient_along(p(before_p), p(pv), p(y), n.data()) >= 0;
}

void FaceBuilder::accept(int facet) {
  member_stamp_[static_cast<std::size_t>(facet)] = stamp_;
  members_.push_back(facet);
  for (int i = facet_tri_start_[static_cast<std::size_t>(facet)];
       i < facet_tri_start_[static_cast<std::size_t>(facet) + 1]; ++i) {
    const HullTriangle& t =
        tris_[static_cast<std::size_t>(facet_tris_[static_cast<std::size_t>(i)])];
    for (int k = 0; k < 3; ++k) vmark_[static_cast<std::size_t>(vid(t.v[k]))] = stamp_;
  }
  queue_.push_back(facet);
  budget_ += 8L * (facet_bnd_start_[static_cast<std::size_t>(facet) + 1] -
                   facet_bnd_start_[static_cast<std::size_t>(facet)]);
  progress_ = true;
}

void FaceBuilder::grow(int seed, const Vec3& n, double d, int region, bool keep_convex) {
  ++stamp_;
  members_.clear();
  queue_.clear();
  deferred_.clear();
  budget_ = 64;
  accept(seed);
  auto consider = [&](int g) {
    const auto gi = static_cast<std::size_t>(g);
    if (region_of_facet_[gi] >= 0 || member_stamp_[gi] == stamp_ || reject_stamp_[gi] == stamp_ ||
        (!keep_convex && blocked_[gi] == region))
      return;
    if (--budget_ < 0) return;
    if (!fits(g, n, d)) {
      reject_stamp_[gi] = stamp_;
      return;
    }
    if (keep_convex ? !junctions_convex(g, n) : !disk_ok(g)) {
      deferred_.push_back(g);
      return;
    }
    accept(g);
  };
  for (;;) {
    while (!queue_.empty()) {
      const int f = queue_.back();
      queue_.pop_back();
      for (int i = facet_bnd_start_[static_cast<std::size_t>(f)];
           i < facet_bnd_start_[static_cast<std::size_t>(f) + 1]; ++i)
        consider(
            facet_of_[static_cast<std::size_t>(twin(facet_bnd_[static_cast<std::size_t>(i)]) / 3)]);
    }
    if (deferred_.empty() || !progress_ || budget_ < 0) break;
    progress_ = false;
    scratch_.swap(deferred_);
    deferred_.clear();
    for (const int g : scratch_) consider(g);
    scratch_.clear();
  }
}

// The boundary loop of the current region (members), as points; false if it is not one simple
// loop covering every boundary edge.
bool FaceBuilder::boundary(std::vector<int>& loop, std::string& error) {
  loop.clear();
  long edges = 0;
  int start = -1;
  for (const int f : members_) {
    for (int i = facet_bnd_start_[static_cast<std::size_t>(f)];
         i < facet_bnd_start_[static_cast<std::size_t>(f) + 1]; ++i) {
      const int h = facet_bnd_[static_cast<std::size_t>(i)];
      if (!member(twin(h) / 3)) {
        ++edges;
        if (start < 0) start = h;
      }
    }
  }
  if (start < 0) {
    error = "a face covers the whole hull";
    return false;
  }
  const long cap = 3L * static_cast<long>(tris_.size()) + 3;
  long steps = 0;
  int h = start;
  do {
    const int v = origin(h);
    auto& mark = loop_mark_[static_cast<std::size_t>(vid(v))];
    if (mark == stamp_) return false;  // pinch
    mark = stamp_;
    loop.push_back(v);
    int g = next_he(h);
    while (member(twin(g) / 3)) {
      g = next_he(twin(g));
      if (++steps > cap) return false;
    }
    h = g;
    if (++steps > cap || static_cast<long>(loop.size()) > edges) return false;
  } while (h != start);
  return static_cast<long>(loop.size()) == edges;
}

bool FaceBuilder::convex_along(const std::vector<int>& loop, const Vec3& n,
                               std::vector<int>* reflex) const {
  const std::size_t m = loop.size();
  bool ok = true;
  for (std::size_t i = 0; i < m; ++i) {
    const int u = loop[(i + m - 1) % m], v = loop[i], w = loop[(i + 1) % m];
    if (exact::orient_along(p(u), p(v), p(w), n.data()) < 0) {
      ok = false;
      if (reflex == nullptr) return false;
      reflex->push_back(v);
    }
  }
  return ok;
}

bool FaceBuilder::run(PolygonFaces& out, std::string& error) {
  const std::size_t t_count = tris_.size();
  // Hull vertices.
  vertex_id_.assign(q_.size(), -1);
  vertex_point_.clear();
  out_edge_.clear();
  for (std::size_t t = 0; t < t_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = tris_[t].v[k];
      if (vertex_id_[static_cast<std::size_t>(v)] < 0) {
        vertex_id_[static_cast<std::size_t>(v)] = static_cast<int>(vertex_point_.size());
        vertex_point_.push_back(v);
        out_edge_.push_back(static_cast<int>(3 * t) + k);
      }
    }
  }
  const std::size_t v_count = vertex_point_.size();
  vmark_.assign(v_count, 0);
  loop_mark_.assign(v_count, 0);
  double magnitude = 0;
  for (const Vec3& x : q_) magnitude = std::max(magnitude, x.cwiseAbs().maxCoeff());
  support_pad_ = 48 * kU * magnitude;

  if (!build_facets(error)) return false;
  const std::size_t f_count = facet_seed_.size();
  region_of_facet_.assign(f_count, -1);
  blocked_.assign(f_count, -1);
  member_stamp_.assign(f_count, 0);
  reject_stamp_.assign(f_count, 0);

  std::vector<int> region_loop_start{0}, region_loop;
  std::vector<Vec3> region_normal;
  std::vector<double> region_offset;

  // Facets that no region can join to a neighbour become faces at once, in memory order: the
  // tetrahedron of an edge and the two far vertices across it is wider than twice the
  // tolerance for every edge of the facet, so no slab of the tolerance holds the facet and any
  // neighbour.
  std::vector<char> mergeable(f_count, 0);
  for (std::size_t t = 0; t < t_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int h = static_cast<int>(3 * t) + k, g = twin(h);
      const int ft = facet_of_[t], fg = facet_of_[static_cast<std::size_t>(g / 3)];
      if (ft == fg ||
          (mergeable[static_cast<std::size_t>(ft)] && mergeable[static_cast<std::size_t>(fg)]))
        continue;
      const Vec3 &a = q_[static_cast<std::size_t>(origin(h))],
                 &b = q_[static_cast<std::size_t>(dest(h))];
      const Vec3& f = q_[static_cast<std::size_t>(origin(prev_he(h)))];
      const Vec3& w = q_[static_cast<std::size_t>(origin(prev_he(g)))];
      const Vec3 ab = b - a, af = f - a, aw = w - a, bf = f - b, bw = w - b;
      const double volume6 = std::fabs(ab.dot(af.cross(aw)));
      // Every cross product below is at most the squared longest edge: most edges are decided
      // by that bound (with room for rounding) without the seven products.
      const double longest2 = std::max({ab.squaredNorm(), af.squaredNorm(), aw.squaredNorm(),
                                        bf.squaredNorm(), bw.squaredNorm(), (w - f).squaredNorm()});
      if (volume6 > 2 * tol_ * longest2 * (1 + 1e-12)) continue;
      const double widest = std::max({ab.cross(af).norm(), ab.cross(aw).norm(), af.cross(aw).norm(),
                                      bf.cross(bw).norm(), ab.cross(w - f).norm(),
                                      af.cross(bw).norm(), aw.cross(bf).norm()});
      if (!(volume6 > 2 * tol_ * widest)) {
        mergeable[static_cast<std::size_t>(ft)] = 1;
        mergeable[static_cast<std::size_t>(fg)] = 1;
      }
    }
  }
  for (std::size_t f = 0; f < f_count; ++f) {
    if (mergeable[f]) continue;
    const int facet = static_cast<int>(f);
    const Vec3 n = facet_normal(facet);
    region_of_facet_[f] = static_cast<int>(region_normal.size());
    region_normal.push_back(n);
    region_offset.push_back(facet_support(facet, n));
    for (int i = facet_bnd_start_[f]; i < facet_bnd_start_[f + 1]; ++i)
      region_loop.push_back(origin(facet_bnd_[static_cast<std::size_t>(i)]));
    region_loop_start.push_back(static_cast<int>(region_loop.size()));
  }

  // The others grow into regions, largest facet first.
  std::vector<int> order;
  for (std::size_t f = 0; f < f_count; ++f) {
    if (mergeable[f]) order.push_back(static_cast<int>(f));
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double fa = facet_area_[static_cast<std::size_t>(a)],
                 fb = facet_area_[static_cast<std::size_t>(b)];
    return fa > fb || (fa == fb && a < b);
  });
  std::vector<int> loop, reflex;
  for (const int seed : order) {
    if (region_of_facet_[static_cast<std::size_t>(seed)] >= 0) continue;
    const int region = static_cast<int>(region_normal.size());
    const Vec3 n0 = facet_normal(seed);
    const int seed_point =
        tris_[static_cast<std::size_t>(facet_seed_[static_cast<std::size_t>(seed)])].v[0];
    int top = seed_point;
    const double d0 = facet_support(seed, n0);

    bool accepted = false, alone = false;
    for (int attempt = 0; attempt < kMaxAttempts && !accepted; ++attempt) {
      grow(seed, n0, d0, region, false);
      alone = members_.size() == 1;
      if (alone) break;  // nothing joined: the facet alone, below
      reflex.clear();
      if (!boundary(loop, error)) {
        if (!error.empty()) return false;
        break;
      }
      if (convex_along(loop, n0, &reflex)) {
        accepted = true;
        break;
      }
      // Exclude the facets at the reflex corners (never the seed) and grow again.
      int newly_blocked = 0;
      for (const int v : reflex) {
        const int h0 = out_edge_[static_cast<std::size_t>(vid(v))];
        int h = h0;
        for (std::size_t s = 0; s <= 3 * t_count; ++s) {
          const int f = facet_of_[static_cast<std::size_t>(h / 3)];
          if (member(h / 3) && f != seed && blocked_[static_cast<std::size_t>(f)] != region) {
            blocked_[static_cast<std::size_t>(f)] = region;
            ++newly_blocked;
          }
          h = rotate(h);
          if (h == h0) break;
        }
      }
      if (newly_blocked == 0) break;
    }
    if (!accepted && !alone) {
      // Grow again keeping the region convex at every step: a smaller region, but a valid one.
      grow(seed, n0, d0, region, true);
      if (members_.size() > 1 && boundary(loop, error) && convex_along(loop, n0, nullptr))
        accepted = true;
      if (!error.empty()) return false;
    }
    if (!accepted) {
      ++stamp_;
      members_.assign(1, seed);
      member_stamp_[static_cast<std::size_t>(seed)] = stamp_;
      if (!boundary(loop, error)) {
        if (error.empty()) error = "facet boundary is not a simple loop";
        return false;
      }
      if (!convex_along(loop, n0, nullptr)) {
        error = "facet is not convex along its normal";
        return false;
      }
    }

    Vec3 n = n0;
    double d = d0;
    if (members_.size() > 1) {
      // Area-weighted normal of the whole region, kept only if the region stays flat within
      // the tolerance, front-facing and convex along it.
      Vec3 sum = Vec3::Zero();
      for (const int f : members_) {
        for (int i = facet_tri_start_[static_cast<std::size_t>(f)];
             i < facet_tri_start_[static_cast<std::size_t>(f) + 1]; ++i) {
          const HullTriangle& t =
              tris_[static_cast<std::size_t>(facet_tris_[static_cast<std::size_t>(i)])];
          const Vec3 a = q_[static_cast<std::size_t>(t.v[0])];
          sum += (q_[static_cast<std::size_t>(t.v[1])] - a)
                     .cross(q_[static_cast<std::size_t>(t.v[2])] - a);
        }
      }
      const double len = sum.norm();
      if (len > 0) {
        const Vec3 n1 = sum / len;
        if (!climb(n1, top, top, error)) return false;
        const double d1 = support(n1, top);
        bool ok = convex_along(loop, n1, nullptr);
        for (std::size_t i = 0; ok && i < members_.size(); ++i) ok = fits(members_[i], n1, d1);
        if (ok) {
          n = n1;
          d = d1;
        }
      }
    }
    for (const int f : members_) region_of_facet_[static_cast<std::size_t>(f)] = region;
    region_normal.push_back(n);
    region_offset.push_back(d);
    region_loop.insert(region_loop.end(), loop.begin(), loop.end());
    region_loop_start.push_back(static_cast<int>(region_loop.size()));
  }
  const std::size_t r_count = region_normal.size();

  // Vertices where at least three regions meet are kept.
  std::vector<char> kept(v_count, 0);
  auto region_of_tri = [&](int t) {
    return region_of_facet_[static_cast<std::size_t>(facet_of_[static_cast<std::size_t>(t)])];
  };
  // Around a vertex, the region changes once per outgoing half-edge between two regions.
  std::vector<int> changes(v_count, 0);
  for (std::size_t t = 0; t < t_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int h = static_cast<int>(3 * t) + k;
      if (region_of_tri(static_cast<int>(t)) != region_of_tri(twin(h) / 3))
        ++changes[static_cast<std::size_t>(vid(origin(h)))];
    }
  }
  for (std::size_t v = 0; v < v_count; ++v) kept[v] = changes[v] >= 3;
  // ... and every corner of a boundary between two regions: regions are flat only within the
  // tolerance, so two of them can share a chain that bends (the rim of a disk 1e-9 thick, whose
  // top and bottom are one region each). Each run of left-out vertices along a loop must lie
  // within the tolerance of the chord between the kept vertices at its ends; the farthest one
  // that does not is kept (Douglas-Peucker), until every run fits. A vertex is on the loops of
  // both regions, so a corner kept for one loop splits a run of the other: repeat until no loop
  // changes (each pass keeps one more vertex or ends).
  for (std::size_t pass = 0; pass <= v_count; ++pass) {
    bool changed = false;
    for (std::size_t r = 0; r < r_count; ++r) {
      const int begin = region_loop_start[r], end = region_loop_start[r + 1];
      const int n = end - begin;
      auto vertex_at = [&](int i) { return region_loop[std::size_t(begin + (i % n))]; };
      auto is_kept = [&](int i) { return kept[std::size_t(vid(vertex_at(i)))] != 0; };
      int first = 0;
      while (first < n && !is_kept(first)) ++first;
      if (first == n) continue;  // no corner yet: the rule below keeps them all
      for (int a = first; a < first + n;) {
        int b = a + 1;
        while (!is_kept(b)) ++b;
        // The run a+1 .. b-1 against the chord from a's vertex to b's.
        const Vec3 pa = q_[std::size_t(vertex_at(a))], chord = q_[std::size_t(vertex_at(b))] - pa;
        const double chord_sq = chord.squaredNorm();
        double worst = tol_ * tol_;
        int worst_i = -1;
        for (int i = a + 1; i < b; ++i) {
          const Vec3 off = q_[std::size_t(vertex_at(i))] - pa;
          const double t = chord_sq > 0 ? std::clamp(off.dot(chord) / chord_sq, 0.0, 1.0) : 0.0;
          const double dist_sq = (off - t * chord).squaredNorm();
          if (dist_sq > worst) {
            worst = dist_sq;
            worst_i = i;
          }
        }
        if (worst_i >= 0) {
          kept[std::size_t(vid(vertex_at(worst_i)))] = 1;
          changed = true;
          continue;  // the run from a to the new corner is checked next
        }
        a = b;
      }
    }
    if (!changed) break;
  }
  // ... and every vertex of a region that would otherwise keep fewer than three.
  for (std::size_t r = 0; r < r_count; ++r) {
    int count = 0;
    for (int i = region_loop_start[r]; i < region_loop_start[r + 1]; ++i)
      count += kept[static_cast<std::size_t>(vid(region_loop[static_cast<std::size_t>(i)]))];
    if (count < 3) {
      for (int i = region_loop_start[r]; i < region_loop_start[r + 1]; ++i)
        kept[static_cast<std::size_t>(vid(region_loop[static_cast<std::size_t>(i)]))] = 1;
    }
  }

  out.loop.clear();
  out.start.assign(1, 0);
  out.normal = std::move(region_normal);
  out.offset = std::move(region_offset);
  for (std::size_t r = 0; r < r_count; ++r) {
    for (int i = region_loop_start[r]; i < region_loop_start[r + 1]; ++i) {
      const int v = region_loop[static_cast<std::size_t>(i)];
      if (kept[static_cast<std::size_t>(vid(v))]) out.loop.push_back(v);
    }
    out.start.push_back(static_cast<int>(out.loop.size()));
  }

  out.max_outside = 0;
  if (!hull_.complete) {
    for (std::size_t t = 0; t < t_count; ++t) {
      const auto r = static_cast<std::size_t>(region_of_tri(static_cast<int>(t)));
      for (const int i : hull_.outside[t]) {
        const double dist = out.normal[r].dot(q_[static_cast<std::size_t>(i)]) - out.offset[r];
        out.max_outside = std::max(out.max_outside, dist);
      }
    }
  }
  return true;
}

}  // namespace

bool build_polygon_faces(std::span<const Vec3> points, const TriangleHull& hull, double tolerance,
                         PolygonFaces& faces, std::string& error) {
  FaceBuilder builder(points, hull, tolerance);
  return builder.run(faces, error);
}

}  // namespace mink::detail
