// Quickhull in 3D with conflict lists ("outside sets") and exact visibility.
//
// Every decision is an exact orientation sign (mink/hull/predicates.hpp), so the triangulation
// built is exactly the convex hull of the points: the faces a new point sees form a disk bounded
// by one simple loop (the horizon), the new faces joining the point to that loop are never
// degenerate, and a point of a removed face's conflict list that is above none of the new faces
// is inside the new hull. Floating-point distances only choose which point comes next (the
// farthest beyond the newest face with conflicts, or beyond any face when max_vertices may stop
// the build early), which affects speed, never correctness. The code
// still checks the horizon loop and stops with an error rather than build on a broken mesh.
#include "triangle_hull.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "mink/hull/predicates.hpp"

namespace mink::detail {
namespace {

constexpr double kU = exact::kUnitRoundoff;

/// A point in a conflict list, with its coordinates: the lists are scanned far more often than
/// they change, and reading coordinates through the index would miss the cache.
struct Conflict {
  double x[3];
  int index;
};

struct Face {
  int v[3];
  int twin[3];
  double n[3];   // (b - a) x (c - a), rounded
  double pm[3];  // per component: |products| whose difference gave n, for the filter
  double bound;  // the filter's bound for the farthest any point can be (see side())
  double inv_len;
  int furthest;
  double furthest_dist;
  unsigned stamp;  // bumped when the slot is reused, to invalidate heap entries
  int mark;        // +iteration: visible in that iteration; -iteration: seen, not visible
  bool alive;
  std::vector<Conflict> outside;
};

struct QueueEntry {
  double dist;
  int face;
  unsigned stamp;
  bool operator<(const QueueEntry& o) const { return dist < o.dist; }
};

class Builder {
 public:
  Builder(std::span<const Vec3> points, std::size_t max_vertices)
      : q_(points), max_vertices_(max_vertices) {}

  bool run(const int simplex[4], TriangleHull& out, std::string& error);

 private:
  const double* p(int i) const { return q_[static_cast<std::size_t>(i)].data(); }

  int new_face(int a, int b, int c) {
    int f;
    if (!free_.empty()) {
      f = free_.back();
      free_.pop_back();
    } else {
      f = static_cast<int>(faces_.size());
      faces_.emplace_back();
      faces_.back().stamp = 0;
    }
    Face& face = faces_[static_cast<std::size_t>(f)];
    face.v[0] = a;
    face.v[1] = b;
    face.v[2] = c;
    face.furthest = -1;
    face.furthest_dist = 0;
    face.mark = 0;
    face.alive = true;
    face.outside.clear();
    const double *pa = p(a), *pb = p(b), *pc = p(c);
    const double ux = pb[0] - pa[0], uy = pb[1] - pa[1], uz = pb[2] - pa[2];
    const double vx = pc[0] - pa[0], vy = pc[1] - pa[1], vz = pc[2] - pa[2];
    const double p1 = uy * vz, p2 = uz * vy, p3 = uz * vx, p4 = ux * vz, p5 = ux * vy, p6 = uy * vx;
    face.n[0] = p1 - p2;
    face.n[1] = p3 - p4;
    face.n[2] = p5 - p6;
    face.pm[0] = std::fabs(p1) + std::fabs(p2);
    face.pm[1] = std::fabs(p3) + std::fabs(p4);
    face.pm[2] = std::fabs(p5) + std::fabs(p6);
    const double len =
        std::sqrt(face.n[0] * face.n[0] + face.n[1] * face.n[1] + face.n[2] * face.n[2]);
    face.inv_len = len > 0 ? 1 / len : 0;
    face.bound =
        9 * kU * (reach_[0] * face.pm[0] + reach_[1] * face.pm[1] + reach_[2] * face.pm[2]);
    return f;
  }

  void free_face(int f) {
    Face& face = faces_[static_cast<std::size_t>(f)];
    face.alive = false;
    face.outside.clear();
    ++face.stamp;
    free_.push_back(f);
  }

  /// Exact side of point i against face f: > 0 strictly outside (then `dist` is its distance
  /// beyond the plane, >= 0), 0 on the plane, < 0 inside.
  /// The face's own bound (f.bound) is the point's bound below with |x - a| replaced by its
  /// largest possible value per axis (reach_): computed with the same operations on larger
  /// non-negative terms, it is never smaller, so it decides most points with one comparison.
  int side(const Face& f, const double* x, double& dist) const {
    const double* a = p(f.v[0]);
    const double wx = x[0] - a[0], wy = x[1] - a[1], wz = x[2] - a[2];
    const double det = wx * f.n[0] + wy * f.n[1] + wz * f.n[2];
    if (det > f.bound) {
      dist = det * f.inv_len;
      return 1;
    }
    if (det < -f.bound) return -1;
    const double bound =
        9 * kU * (std::fabs(wx) * f.pm[0] + std::fabs(wy) * f.pm[1] + std::fabs(wz) * f.pm[2]);
    if (det > bound) {
      dist = det * f.inv_len;
      return 1;
    }
    if (det < -bound) return -1;
    const int s = exact::orient3d_exact(a, p(f.v[1]), p(f.v[2]), x);
    dist = std::max(det * f.inv_len, 0.0);
    return s;
  }

  void add_outside(int f, const Conflict& c, double dist) {
    Face& face = faces_[static_cast<std::size_t>(f)];
    face.outside.push_back(c);
    if (face.furthest < 0 || dist > face.furthest_dist) {
      face.furthest = c.index;
      face.furthest_dist = dist;
    }
  }

  /// Puts point c in the conflict list of a candidate face it is strictly beyond, if any: the
  /// first one found for a complete build (as Qhull does: any face that sees the point is a
  /// valid owner, and stopping at the first halves the tests), the farthest one when
  /// max_vertices may stop the build (furthest-first then picks the points that matter most).
  void assign(const Conflict& c, const int* candidates, std::size_t count) {
    int best = -1;
    double best_dist = 0;
    for (std::size_t k = 0; k < count; ++k) {
      double d;
      if (side(faces_[static_cast<std::size_t>(candidates[k])], c.x, d) > 0 &&
          (best < 0 || d > best_dist)) {
        best = candidates[k];
        best_dist = d;
        if (max_vertices_ == 0) break;
      }
    }
    if (best >= 0) add_outside(best, c, best_dist);
  }

  /// Furthest first over all faces only when the build may stop early (max_vertices): then
  /// the order decides which vertices the hull keeps. A complete build takes the newest face
  /// first instead, whose conflict points and neighbours are still in cache; the order only
  /// changes the speed, since the result is the exact hull either way.
  void enqueue(int f) {
    const Face& face = faces_[static_cast<std::size_t>(f)];
    if (face.outside.empty()) return;
    if (max_vertices_ != 0) {
      heap_.push({face.furthest_dist, f, face.stamp});
    } else {
      stack_faces_.push_back({face.furthest_dist, f, face.stamp});
    }
  }
  bool pending_empty() const { return max_vertices_ != 0 ? heap_.empty() : stack_faces_.empty(); }
  QueueEntry pending_top() const { return max_vertices_ != 0 ? heap_.top() : stack_faces_.back(); }
  void pending_pop() {
    if (max_vertices_ != 0) {
      heap_.pop();
    } else {
      stack_faces_.pop_back();
    }
  }

  bool add_point(int apex, int start_face, int iteration, std::string& error);

  std::span<const Vec3> q_;
  std::size_t max_vertices_;
  std::vector<Face> faces_;
  std::vector<int> free_;
  std::priority_queue<QueueEntry> heap_;
  std::vector<QueueEntry> stack_faces_;
  std::size_t vertex_count_ = 0;

  // Scratch, reused across iterations.
  std::vector<int> visible_, stack_, horizon_, created_;
  struct HorizonEdge {
    int from, to, kept;  // kept: the half-edge of the face that stays
  };
  std::vector<HorizonEdge> loop_;
  std::vector<int> vertex_stamp_, vertex_next_, vertex_seen_;
  double reach_[3] = {0, 0, 0};  // per axis: twice the largest |coordinate|, >= any |x - a|
};

bool Builder::run(const int simplex[4], TriangleHull& out, std::string& error) {
  const std::size_t n = q_.size();
  vertex_stamp_.assign(n, 0);
  vertex_next_.assign(n, -1);
  vertex_seen_.assign(n, 0);
  faces_.reserve(2 * n + 4);  // live faces never exceed 2 n - 4: few moves of conflict lists
  for (const Vec3& x : q_) {
    for (int k = 0; k < 3; ++k) reach_[k] = std::max(reach_[k], 2 * std::fabs(x[k]));
  }

  int a = simplex[0], b = simplex[1], c = simplex[2], d = simplex[3];
  const int o = exact::orient3d(p(a), p(b), p(c), p(d));
  if (o == 0) {
    error = "initial simplex is flat";
    return false;
  }
  if (o > 0) std::swap(b, c);  // d below the face (a, b, c)
  const int tri[4][3] = {{a, b, c}, {a, d, b}, {b, d, c}, {c, d, a}};
  for (const auto& t : tri) new_face(t[0], t[1], t[2]);
  // Twins of the tetrahedron by brute force over its 12 half-edges.
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int from = faces_[f].v[k], to = faces_[f].v[(k + 1) % 3];
      faces_[f].twin[k] = -1;
      for (int g = 0; g < 4; ++g) {
        for (int m = 0; m < 3; ++m) {
          if (faces_[g].v[m] == to && faces_[g].v[(m + 1) % 3] == from)
            faces_[f].twin[k] = 3 * g + m;
        }
      }
      if (faces_[f].twin[k] < 0) {
        error = "initial simplex has an unmatched edge";
        return false;
      }
    }
  }
  vertex_count_ = 4;
  const int initial[4] = {0, 1, 2, 3};
  for (std::size_t i = 0; i < n; ++i) {
    const int ii = static_cast<int>(i);
    if (ii == a || ii == b || ii == c || ii == d) continue;
    const Conflict cf{{q_[i][0], q_[i][1], q_[i][2]}, ii};
    assign(cf, initial, 4);
  }
  for (int f = 0; f < 4; ++f) enqueue(f);

  // Each iteration makes one point a vertex; a point leaves the conflict lists when it becomes
  // a vertex or is found inside, and never returns, so n iterations always suffice.
  bool complete = true;
  int iteration = 0;
  while (!pending_empty()) {
    const QueueEntry top = pending_top();
    const Face& face = faces_[static_cast<std::size_t>(top.face)];
    if (!face.alive || face.stamp != top.stamp || face.outside.empty()) {
      pending_pop();
      continue;
    }
    if (max_vertices_ != 0 && vertex_count_ >= max_vertices_) {
      complete = false;
      break;
    }
    pending_pop();
    if (++iteration > static_cast<int>(n)) {
      error = "iteration cap reached";
      return false;
    }
    if (!add_point(face.furthest, top.face, iteration, error)) return false;
  }

  // Compact the live faces.
  std::vector<int> index(faces_.size(), -1);
  int live = 0;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (faces_[f].alive) index[f] = live++;
  }
  out.triangles.resize(static_cast<std::size_t>(live));
  out.outside.assign(complete ? 0 : static_cast<std::size_t>(live), {});
  out.complete = complete;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (index[f] < 0) continue;
    HullTriangle& t = out.triangles[static_cast<std::size_t>(index[f])];
    for (int k = 0; k < 3; ++k) {
      t.v[k] = faces_[f].v[k];
      const int h = faces_[f].twin[k];
      t.twin[k] = 3 * index[static_cast<std::size_t>(h / 3)] + h % 3;
    }
    if (!complete) {
      for (const Conflict& cf : faces_[f].outside)
        out.outside[static_cast<std::size_t>(index[f])].push_back(cf.index);
    }
  }
  return true;
}

bool Builder::add_point(int apex, int start_face, int iteration, std::string& error) {
  // 1. The faces the apex sees, by a search over face adjacency from one that it sees.
  visible_.clear();
  horizon_.clear();
  stack_.clear();
  faces_[static_cast<std::size_t>(start_face)].mark = iteration;
  stack_.push_back(start_face);
  const std::size_t cap = faces_.size();
  while (!stack_.empty()) {
    const int f = stack_.back();
    stack_.pop_back();
    visible_.push_back(f);
    if (visible_.size() > cap) {
      error = "visible set larger than the hull";
      return false;
    }
    for (int k = 0; k < 3; ++k) {
      const int g = faces_[static_cast<std::size_t>(f)].twin[k] / 3;
      Face& nb = faces_[static_cast<std::size_t>(g)];
      if (nb.mark == iteration) continue;
      if (nb.mark != -iteration) {
        double dist;
        if (side(nb, p(apex), dist) > 0) {
          nb.mark = iteration;
          stack_.push_back(g);
          continue;
        }
        nb.mark = -iteration;
      }
      horizon_.push_back(3 * f + k);
    }
  }

  // 2. The horizon as one loop: each horizon vertex must start exactly one horizon edge.
  for (const int h : horizon_) {
    const Face& f = faces_[static_cast<std::size_t>(h / 3)];
    const int from = f.v[h % 3];
    if (vertex_stamp_[static_cast<std::size_t>(from)] == iteration) {
      error = "horizon is not a simple loop";
      return false;
    }
    vertex_stamp_[static_cast<std::size_t>(from)] = iteration;
    vertex_next_[static_cast<std::size_t>(from)] = h;
  }
  loop_.clear();
  int h = horizon_.front();
  for (std::size_t step = 0; step <= horizon_.size(); ++step) {
    const Face& f = faces_[static_cast<std::size_t>(h / 3)];
    const int from = f.v[h % 3], to = f.v[(h % 3 + 1) % 3];
    loop_.push_back({from, to, f.twin[h % 3]});
    if (vertex_stamp_[static_cast<std::size_t>(to)] != iteration) {
      error = "horizon is open";
      return false;
    }
    h = vertex_next_[static_cast<std::size_t>(to)];
    if (h == horizon_.front()) break;
  }
  if (loop_.size() != horizon_.size()) {
    error = "horizon splits into several loops";
    return false;
  }

  // 3. Vertices strictly inside the visible region leave the hull.
  int removed = 0;
  for (const int f : visible_) {
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(faces_[static_cast<std::size_t>(f)].v[k]);
      if (vertex_stamp_[v] != iteration && vertex_seen_[v] != iteration) {
        vertex_seen_[v] = iteration;
        ++removed;
      }
    }
  }
  vertex_count_ = vertex_count_ + 1 - static_cast<std::size_t>(removed);

  // 4. The cone from the apex to the horizon, stitched to the kept faces and to itself. The
  // visible faces are still intact (their slots are freed in step 5).
  created_.clear();
  for (const HorizonEdge& e : loop_) created_.push_back(new_face(e.from, e.to, apex));
  const std::size_t m = created_.size();
  for (std::size_t i = 0; i < m; ++i) {
    const int f = created_[i];
    Face& face = faces_[static_cast<std::size_t>(f)];
    const int kept = loop_[i].kept;
    face.twin[0] = kept;
    faces_[static_cast<std::size_t>(kept / 3)].twin[kept % 3] = 3 * f;
    face.twin[1] = 3 * created_[(i + 1) % m] + 2;
    face.twin[2] = 3 * created_[(i + m - 1) % m] + 1;
  }

  // 5. Hand the conflict points of the visible faces to the new faces (those above none are
  // inside for good), straight from their lists, then free the visible faces.
  for (const int f : visible_) {
    for (const Conflict& c : faces_[static_cast<std::size_t>(f)].outside) {
      if (c.index != apex) assign(c, created_.data(), m);
    }
    free_face(f);
  }
  for (const int f : created_) enqueue(f);
  return true;
}

}  // namespace

bool build_triangle_hull(std::span<const Vec3> points, const int simplex[4],
                         std::size_t max_vertices, TriangleHull& hull, std::string& error) {
  Builder builder(points, max_vertices);
  return builder.run(simplex, hull, error);
}

}  // namespace mink::detail
