// Convex hull builders on the same points: mink's build_convex_hull, Qhull (libqhull_r,
// qh_new_qhull with default options and with Qt), CGAL convex_hull_3 (EPICK, to a Surface_mesh)
// and Bullet's btConvexHullComputer (Debian's float build, double input).
//
// Inputs (mt19937_64, seed 12345 + size): uniform in the unit ball, uniform in the cube
// [-0.5, 0.5]^3 (Qhull's `rbox D3`), uniform on the unit sphere (normalised Gaussians: every point
// is a hull vertex). For each input every builder runs in turn, the round is repeated, and the
// median time of each builder is reported: the machine is shared, so only ratios measured in the
// same run mean much. A time covers the library's own work (building and freeing its result,
// not converting the input or reading the result); mink and Qhull run at least 3 times unless a
// run takes over 2 s; --budget bounds the rounds of the others.
//
// Accuracy, per builder, against the true extreme points (CGAL's vertices from its first run:
// exact predicates; with --truth=mink, mink's exact build, for sizes CGAL takes too long on):
//   - kept: the fraction of true extreme points that are vertices of the result (Bullet maps its
//     snapped vertices back to input points with original_vertex_index);
//   - outside: the largest distance of a true extreme point beyond a face plane of the result.
//     Every input point is in the hull of the extreme points and the distance outside a convex
//     set is convex, so the largest over the extreme points is the largest over the input. When
//     points x faces exceeds 2e8, an evenly spaced sample of the extreme points is tested
//     (marked "~").
//
// Output: a Markdown table on stdout and, with --json=FILE, one JSON object per case and builder
// (bench/hull_report.py turns that into the table of docs/benchmarks.md).
//
// Options: --sizes=1000,10000,... --dists=ball,cube,sphere --builders=mink,qhull,qhull_qt,cgal,
// bullet --budget=SECONDS (per input, to choose the repetitions; default 6) --max-reps=N
// (default 7) --truth=cgal|mink --json=FILE.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <LinearMath/btConvexHullComputer.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "mink/hull/convex_hull.hpp"

namespace {

using mink::Vec3;

struct Plane {
  double n[3];
  double d;  // hull where n . x <= d
};

/// What a builder returns: its vertices as input indices (-1 when unknown) and its face planes.
struct Result {
  std::vector<int> vertices;
  std::vector<Plane> planes;
  bool ok = true;
};

struct PointIndex {
  std::unordered_map<std::uint64_t, std::vector<int>> map;
  const std::vector<Vec3>* points = nullptr;

  static std::uint64_t hash(double x, double y, double z) {
    std::uint64_t a, b, c;
    std::memcpy(&a, &x, 8);
    std::memcpy(&b, &y, 8);
    std::memcpy(&c, &z, 8);
    return a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xBF58476D1CE4E5B9ull ^ c;
  }
  void build(const std::vector<Vec3>& p) {
    points = &p;
    map.clear();
    map.reserve(p.size() * 2);
    for (std::size_t i = 0; i < p.size(); ++i)
      map[hash(p[i].x(), p[i].y(), p[i].z())].push_back(static_cast<int>(i));
  }
  int find(double x, double y, double z) const {
    const auto it = map.find(hash(x, y, z));
    if (it == map.end()) return -1;
    for (const int i : it->second) {
      const Vec3& q = (*points)[static_cast<std::size_t>(i)];
      if (q.x() == x && q.y() == y && q.z() == z) return i;
    }
    return -1;
  }
};

std::vector<Vec3> make_points(const std::string& dist, std::size_t n) {
  std::mt19937_64 rng(12345 + n);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> p;
  p.reserve(n);
  while (p.size() < n) {
    if (dist == "ball") {
      const Vec3 x(u(rng), u(rng), u(rng));
      if (x.squaredNorm() <= 1) p.push_back(x);
    } else if (dist == "cube") {
      p.emplace_back(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
    } else {
      const Vec3 x(g(rng), g(rng), g(rng));
      const double len = x.norm();
      if (len > 1e-3) p.push_back(x / len);
    }
  }
  return p;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// ---- builders -------------------------------------------------------------------------------
// Each builder adds the time of the library's own work (building and freeing its result) to
// `seconds`; reading its result for the accuracy columns is not timed.

bool run_mink(const std::vector<Vec3>& pts, Result* out, double& seconds) {
  const double t0 = now();
  auto hull = mink::build_convex_hull(pts);
  seconds += now() - t0;
  if (!hull) return false;
  if (out) {
    for (const auto& v : hull->vertices) out->vertices.push_back(static_cast<int>(v.input_index));
    for (const auto& f : hull->faces)
      out->planes.push_back({{f.normal.x(), f.normal.y(), f.normal.z()}, f.offset});
  }
  const double t1 = now();
  { const auto drop = std::move(*hull); }
  seconds += now() - t1;
  return true;
}

bool run_qhull(const std::vector<double>& coords, bool triangulate, Result* out, double& seconds) {
  const double t0 = now();
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, stderr);
  char flags[16];
  std::snprintf(flags, sizeof flags, "%s", triangulate ? "qhull Qt" : "qhull");
  const int n = static_cast<int>(coords.size() / 3);
  const int code =
      qh_new_qhull(qh, 3, n, const_cast<double*>(coords.data()), False, flags, nullptr, stderr);
  seconds += now() - t0;
  if (code == 0 && out) {
    vertexT* vertex;
    FORALLvertices out->vertices.push_back(qh_pointid(qh, vertex->point));
    facetT* facet;
    FORALLfacets {
      out->planes.push_back(
          {{facet->normal[0], facet->normal[1], facet->normal[2]}, -facet->offset});
    }
  }
  const double t1 = now();
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  seconds += now() - t1;
  return code == 0;
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

bool run_cgal(const std::vector<K::Point_3>& pts, const PointIndex& index, Result* out,
              double& seconds) {
  const double t0 = now();
  Mesh mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  seconds += now() - t0;
  if (out) {
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      out->vertices.push_back(index.find(p.x(), p.y(), p.z()));
    }
    for (const auto f : mesh.faces()) {
      std::vector<Vec3> loop;
      for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        const auto& p = mesh.point(v);
        loop.emplace_back(p.x(), p.y(), p.z());
      }
      const Vec3 n = (loop[1] - loop[0]).cross(loop[2] - loop[0]).normalized();
      double d = -HUGE_VAL;
      for (const Vec3& x : loop) d = std::max(d, n.dot(x));
      out->planes.push_back({{n.x(), n.y(), n.z()}, d});
    }
  }
  const bool ok = !mesh.is_empty();
  const double t1 = now();
  mesh.clear();
  seconds += now() - t1;
  return ok;
}

bool run_bullet(const std::vector<double>& coords, Result* out, double& seconds) {
  const double t0 = now();
  btConvexHullComputer hull;
  const int n = static_cast<int>(coords.size() / 3);
  hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)), n, 0, 0);
  seconds += now() - t0;
  if (out) {
    for (int i = 0; i < hull.vertices.size(); ++i)
      out->vertices.push_back(hull.original_vertex_index[i]);
    for (int f = 0; f < hull.faces.size(); ++f) {
      // Newell normal of the face loop, offset from its own (snapped) vertices.
      std::vector<Vec3> loop;
      const btConvexHullComputer::Edge* e0 = &hull.edges[hull.faces[f]];
      const btConvexHullComputer::Edge* e = e0;
      do {
        const btVector3& v = hull.vertices[e->getSourceVertex()];
        loop.emplace_back(v.x(), v.y(), v.z());
        e = e->getNextEdgeOfFace();
      } while (e != e0 && loop.size() < static_cast<std::size_t>(hull.vertices.size()) + 1);
      Vec3 nrm = Vec3::Zero();
      for (std::size_t i = 0; i < loop.size(); ++i)
        nrm += loop[i].cross(loop[(i + 1) % loop.size()]);
      nrm.normalize();
      double d = -HUGE_VAL;
      for (const Vec3& x : loop) d = std::max(d, nrm.dot(x));
      out->planes.push_back({{nrm.x(), nrm.y(), nrm.z()}, d});
    }
  }
  return hull.vertices.size() > 0;
}

// ---- accuracy -------------------------------------------------------------------------------

struct Accuracy {
  double kept = 0;
  double outside = 0;
  bool sampled = false;
  std::size_t vertices = 0;
};

Accuracy measure(const std::vector<Vec3>& pts, const std::vector<int>& truth, const Result& r) {
  Accuracy a;
  a.vertices = r.vertices.size();
  std::vector<char> has(pts.size(), 0);
  for (const int v : r.vertices) {
    if (v >= 0) has[static_cast<std::size_t>(v)] = 1;
  }
  std::size_t kept = 0;
  for (const int t : truth) kept += has[static_cast<std::size_t>(t)];
  a.kept = truth.empty() ? 0 : static_cast<double>(kept) / static_cast<double>(truth.size());
  const double work = static_cast<double>(truth.size()) * static_cast<double>(r.planes.size());
  std::size_t step = 1;
  if (work > 2e8) {
    step = static_cast<std::size_t>(std::ceil(work / 2e8));
    a.sampled = true;
  }
  for (std::size_t i = 0; i < truth.size(); i += step) {
    const Vec3& x = pts[static_cast<std::size_t>(truth[i])];
    double worst = -HUGE_VAL;
    for (const Plane& p : r.planes)
      worst = std::max(worst, p.n[0] * x.x() + p.n[1] * x.y() + p.n[2] * x.z() - p.d);
    a.outside = std::max(a.outside, worst);
  }
  return a;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t end = s.find(',', start);
    out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> dists = {"ball", "cube", "sphere"};
  std::vector<std::size_t> sizes = {1000, 10000, 100000, 1000000};
  std::vector<std::string> builders = {"mink", "qhull", "qhull_qt", "cgal", "bullet"};
  double budget = 6;
  int max_reps = 7;
  std::string truth_from = "cgal", json_path;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&](const char* name) -> const char* {
      const std::size_t len = std::strlen(name);
      return arg.compare(0, len, name) == 0 ? arg.c_str() + len : nullptr;
    };
    if (const char* v = value("--sizes=")) {
      sizes.clear();
      for (const auto& s : split(v)) sizes.push_back(static_cast<std::size_t>(std::stod(s)));
    } else if (const char* v2 = value("--dists=")) {
      dists = split(v2);
    } else if (const char* v3 = value("--builders=")) {
      builders = split(v3);
    } else if (const char* v4 = value("--budget=")) {
      budget = std::stod(v4);
    } else if (const char* v5 = value("--max-reps=")) {
      max_reps = std::stoi(v5);
    } else if (const char* v6 = value("--truth=")) {
      truth_from = v6;
    } else if (const char* v7 = value("--json=")) {
      json_path = v7;
    } else {
      std::fprintf(stderr, "hull_bench: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  std::FILE* json = json_path.empty() ? nullptr : std::fopen(json_path.c_str(), "w");

  std::printf(
      "| input | n | builder | time (s) | Mpts/s | vs Qhull | reps | vertices | kept | max outside "
      "|\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& dist : dists) {
    for (const std::size_t n : sizes) {
      const std::vector<Vec3> pts = make_points(dist, n);
      std::vector<double> coords;
      coords.reserve(3 * n);
      std::vector<K::Point_3> cgal_pts;
      cgal_pts.reserve(n);
      for (const Vec3& p : pts) {
        coords.insert(coords.end(), {p.x(), p.y(), p.z()});
        cgal_pts.emplace_back(p.x(), p.y(), p.z());
      }
      PointIndex index;
      index.build(pts);

      std::vector<std::function<bool(Result*, double&)>> run;
      for (const auto& b : builders) {
        if (b == "mink") {
          run.push_back([&](Result* r, double& t) { return run_mink(pts, r, t); });
        } else if (b == "qhull") {
          run.push_back([&](Result* r, double& t) { return run_qhull(coords, false, r, t); });
        } else if (b == "qhull_qt") {
          run.push_back([&](Result* r, double& t) { return run_qhull(coords, true, r, t); });
        } else if (b == "cgal") {
          run.push_back([&](Result* r, double& t) { return run_cgal(cgal_pts, index, r, t); });
        } else if (b == "bullet") {
          run.push_back([&](Result* r, double& t) { return run_bullet(coords, r, t); });
        } else {
          std::fprintf(stderr, "hull_bench: unknown builder %s\n", b.c_str());
          return 2;
        }
      }
      // Timed rounds, builders interleaved; the first round also keeps the results.
      std::vector<std::vector<double>> times(builders.size());
      std::vector<Result> results(builders.size());
      std::vector<bool> ok(builders.size(), true);
      int reps = max_reps;
      for (int rep = 0; rep < reps; ++rep) {
        double round = 0;
        for (std::size_t b = 0; b < builders.size(); ++b) {
          double t = 0;
          ok[b] = run[b](rep == 0 ? &results[b] : nullptr, t) && ok[b];
          times[b].push_back(t);
          round += t;
        }
        if (rep == 0)
          reps = std::clamp(static_cast<int>(budget / std::max(round, 1e-9)), 1, max_reps);
      }
      // The pair every ratio is about gets at least 3 runs (unless a run takes over 2 s).
      for (std::size_t b = 0; b < builders.size(); ++b) {
        if (builders[b] != "mink" && builders[b] != "qhull") continue;
        while (times[b].size() < 3 && times[b].front() < 2) {
          double t = 0;
          ok[b] = run[b](nullptr, t) && ok[b];
          times[b].push_back(t);
        }
      }
      // Truth: CGAL's vertices (exact predicates), from its timed run when it ran.
      Result truth_result;
      const auto cgal_at = std::find(builders.begin(), builders.end(), std::string("cgal"));
      double unused = 0;
      if (truth_from == "mink") {
        run_mink(pts, &truth_result, unused);
      } else if (cgal_at != builders.end()) {
        truth_result = results[static_cast<std::size_t>(cgal_at - builders.begin())];
      } else {
        run_cgal(cgal_pts, index, &truth_result, unused);
      }
      std::vector<int> truth = truth_result.vertices;
      std::sort(truth.begin(), truth.end());
      truth.erase(std::unique(truth.begin(), truth.end()), truth.end());
      if (!truth.empty() && truth.front() < 0) {
        std::fprintf(stderr, "hull_bench: truth vertex not found among the input\n");
        return 1;
      }
      double qhull_time = 0;
      std::vector<double> median(builders.size());
      for (std::size_t b = 0; b < builders.size(); ++b) {
        auto t = times[b];
        std::sort(t.begin(), t.end());
        median[b] = t[t.size() / 2];
        if (builders[b] == "qhull") qhull_time = median[b];
      }
      for (std::size_t b = 0; b < builders.size(); ++b) {
        const Result& r = results[b];
        const Accuracy acc = measure(pts, truth, r);
        const double mpts = static_cast<double>(n) / median[b] / 1e6;
        char ratio[32] = "";
        if (qhull_time > 0) std::snprintf(ratio, sizeof ratio, "%.2f", qhull_time / median[b]);
        std::printf("| %s | %zu | %s | %.4g | %.3g | %s | %zu | %zu | %.4f%% | %s%.2g |%s\n",
                    dist.c_str(), n, builders[b].c_str(), median[b], mpts, ratio, times[b].size(),
                    acc.vertices, 100 * acc.kept, acc.sampled ? "~" : "", acc.outside,
                    ok[b] ? "" : " FAILED");
        std::fflush(stdout);
        if (json) {
          std::fprintf(json,
                       "{\"dist\": \"%s\", \"n\": %zu, \"builder\": \"%s\", \"median_s\": %.6g, "
                       "\"min_s\": %.6g, \"reps\": %zu, \"vertices\": %zu, \"true_vertices\": %zu, "
                       "\"truth\": \"%s\", \"kept\": %.8f, \"max_outside\": %.6g, "
                       "\"sampled\": %s, \"ok\": %s}\n",
                       dist.c_str(), n, builders[b].c_str(), median[b],
                       *std::min_element(times[b].begin(), times[b].end()), times[b].size(),
                       acc.vertices, truth.size(), truth_from.c_str(), acc.kept, acc.outside,
                       acc.sampled ? "true" : "false", ok[b] ? "true" : "false");
          std::fflush(json);
        }
      }
    }
  }
  if (json) std::fclose(json);
  return 0;
}
