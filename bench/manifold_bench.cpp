// Contact manifolds: mink::manifold() against Bullet's manifold path (the double build, as in
// peers/bullet_adapter.cpp) on the same poses.
//   box-box:            btBoxBoxDetector::getClosestPoints (the ODE box-box routine, up to 4
//                       points) against manifold(Box, Box) (separating axes, then clipping).
//   polytopeN (8, 32):  btPolyhedralContactClipping::findSeparatingAxis (the normal: face and
//                       edge-edge axes over btConvexPolyhedron) then clipHullAgainstHull, on
//                       btConvexHullShape with initializePolyhedralFeatures() done once at set-up,
//                       against manifold(Polytope, Polytope) (GJK + EPA, then clipping). The
//                       normal-finding time counts for both.
//   box-as-polytope:    the same on the 8 corners of boxes (Bullet merges the hull's coplanar
//                       triangles into the box's 6 faces).
// Poses: half resting (B turned about A's up axis, or tilted onto an edge, and pushed into A's top
// face by 1e-3 to 3e-2), half random overlapping. Bullet gives every clipped point (no reduction
// to four; its persistent manifold does that later), mink at most four.
//
// Before the timings the program prints the points each method gives on the exact cases of
// issue 6 (box resting face down on a larger box, box tilted on an edge) and the per-case
// agreement of the deepest depth on the benchmark poses.
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mink/manifold/manifold.hpp"
#include "mink/mink.hpp"
#include "peer_pose.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Vec3;

/// Collects Bullet's contact points (depth < 0 penetrating in Bullet's sign).
struct Collector final : btDiscreteCollisionDetectorInterface::Result {
  int count = 0;
  double deepest = 0;  // in mink's sign: > 0 penetrating
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar depth) override {
    deepest = count == 0 ? -depth : std::max(deepest, double(-depth));
    ++count;
  }
};

struct Pair {
  int a, b;  // shape indices
  Pose pa, pb;
  bool resting = false;  // B pushed flat into A's top face (shallow), else random and often deep
};

/// A box-box or polytope-polytope case set with both libraries' shapes.
struct CaseSet {
  std::string name;
  bool boxes = false;
  std::vector<mink::Box> mink_boxes;
  std::vector<mink::Polytope> mink_hulls;
  std::vector<std::unique_ptr<btBoxShape>> bt_boxes;
  std::vector<std::unique_ptr<btConvexHullShape>> bt_hulls;
  std::vector<Pair> pairs;
  std::vector<btTransform> ta, tb;
};

std::unique_ptr<btConvexHullShape> bullet_hull(const std::vector<Vec3>& points) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const Vec3& p : points) hull->addPoint(btVector3(p.x(), p.y(), p.z()), false);
  hull->recalcLocalAabb();
  hull->setMargin(0);
  hull->initializePolyhedralFeatures();
  return hull;
}

std::vector<Vec3> box_corners(const Vec3& h) {
  std::vector<Vec3> c;
  for (int i = 0; i < 8; ++i)
    c.push_back(Vec3((i & 1 ? 1 : -1) * h.x(), (i & 2 ? 1 : -1) * h.y(), (i & 4 ? 1 : -1) * h.z()));
  return c;
}

template <class A, class B>
Pair make_pose(std::mt19937_64& rng, const A& a, const B& b, int ia, int ib) {
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  auto rotation = [&] { return Quat(g(rng), g(rng), g(rng), g(rng)).normalized(); };
  Pair p{
      ia, ib, Pose::from(Vec3(u(rng), u(rng), u(rng)) * 4 - Vec3(2, 2, 2), rotation()), {}, false};
  const double size = a.bounding_radius() + b.bounding_radius();
  for (int attempt = 0; attempt < 1000; ++attempt) {
    p.resting = u(rng) < 0.5;
    if (p.resting) {
      // Resting: B turned about A's local z, maybe tilted onto an edge, pushed into A's top.
      Quat q = Quat(p.pa.rotation) * Quat(Eigen::AngleAxisd(u(rng) * 7, Vec3::UnitZ()));
      if (u(rng) < 0.3) q = q * Quat(Eigen::AngleAxisd(0.2 + u(rng), Vec3::UnitX()));
      p.pb = Pose::from(Vec3::Zero(), q);
      const Vec3 up = p.pa.rotation.col(2);
      const double top = up.dot(p.pa.rotate(mink::support(a, p.pa.inverse_rotate(up))));
      const double low = up.dot(p.pb.rotate(mink::support(b, p.pb.inverse_rotate(-up))));
      const Vec3 lateral = p.pa.rotation * Vec3(u(rng) - 0.5, u(rng) - 0.5, 0) * 0.5 * size;
      const double overlap = 1e-3 + 3e-2 * u(rng);
      p.pb.translation = p.pa.translation + lateral + up * (top - low - overlap);
    } else {
      p.pb = Pose::from(
          p.pa.translation + (Vec3(u(rng), u(rng), u(rng)) - Vec3::Constant(0.5)) * size * 0.9,
          rotation());
    }
    if (mink::contact(a, p.pa, b, p.pb).depth > 1e-4 * size) return p;
  }
  return p;
}

CaseSet box_cases(int count) {
  CaseSet set;
  set.name = "box-box";
  set.boxes = true;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.2, 1);
  for (int i = 0; i < 16; ++i) {
    const Vec3 h(u(rng), u(rng), u(rng));
    set.mink_boxes.push_back(mink::Box{h});
    auto box = std::make_unique<btBoxShape>(btVector3(h.x(), h.y(), h.z()));
    box->setMargin(0);
    set.bt_boxes.push_back(std::move(box));
  }
  for (int k = 0; k < count; ++k) {
    const int ia = k % 16, ib = (k * 7 + 3) % 16;
    set.pairs.push_back(make_pose(rng, set.mink_boxes[ia], set.mink_boxes[ib], ia, ib));
  }
  return set;
}

CaseSet hull_cases(const std::string& name, int vertices, bool as_boxes, int count) {
  CaseSet set;
  set.name = name;
  std::mt19937_64 rng(7 + vertices + (as_boxes ? 1000 : 0));
  std::uniform_real_distribution<double> u(0.2, 1);
  std::normal_distribution<double> g;
  for (int i = 0; i < 16; ++i) {
    std::vector<Vec3> points;
    if (as_boxes) {
      points = box_corners(Vec3(u(rng), u(rng), u(rng)));
    } else {
      // On an ellipsoid: every point is a vertex of the hull.
      const Vec3 radii(u(rng), u(rng), u(rng));
      for (int v = 0; v < vertices; ++v)
        points.push_back(Vec3(g(rng), g(rng), g(rng)).normalized().cwiseProduct(radii));
    }
    set.mink_hulls.push_back(mink::Polytope::make(points).value());
    set.bt_hulls.push_back(bullet_hull(points));
  }
  for (int k = 0; k < count; ++k) {
    const int ia = k % 16, ib = (k * 7 + 3) % 16;
    set.pairs.push_back(make_pose(rng, set.mink_hulls[ia], set.mink_hulls[ib], ia, ib));
  }
  return set;
}

void finish(CaseSet& set) {
  for (const Pair& p : set.pairs) {
    set.ta.push_back(mink_bench::bullet_pose(p.pa));
    set.tb.push_back(mink_bench::bullet_pose(p.pb));
  }
}

mink::ManifoldResult mink_manifold(const CaseSet& set, std::size_t i) {
  const Pair& p = set.pairs[i];
  if (set.boxes) return mink::manifold(set.mink_boxes[p.a], p.pa, set.mink_boxes[p.b], p.pb);
  return mink::manifold(set.mink_hulls[p.a], p.pa, set.mink_hulls[p.b], p.pb);
}

Collector bullet_manifold(const CaseSet& set, std::size_t i) {
  const Pair& p = set.pairs[i];
  Collector out;
  if (set.boxes) {
    btBoxBoxDetector detector(set.bt_boxes[p.a].get(), set.bt_boxes[p.b].get());
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = set.ta[i];
    input.m_transformB = set.tb[i];
    detector.getClosestPoints(input, out, nullptr);
    return out;
  }
  const btConvexPolyhedron& ha = *set.bt_hulls[p.a]->getConvexPolyhedron();
  const btConvexPolyhedron& hb = *set.bt_hulls[p.b]->getConvexPolyhedron();
  btVector3 normal;
  // As btConvexConvexAlgorithm does with m_enableSatConvex: the axis, then the clipping.
  if (btPolyhedralContactClipping::findSeparatingAxis(ha, hb, set.ta[i], set.tb[i], normal, out)) {
    btVertexArray scratch1, scratch2;
    const btScalar threshold = 0;
    btPolyhedralContactClipping::clipHullAgainstHull(normal, ha, hb, set.ta[i], set.tb[i],
                                                     btScalar(-1e30) - threshold, threshold,
                                                     scratch1, scratch2, out);
  }
  return out;
}

void bm_mink(benchmark::State& state, const CaseSet* set) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mink_manifold(*set, i));
    if (++i == set->pairs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void bm_bullet(benchmark::State& state, const CaseSet* set) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bullet_manifold(*set, i));
    if (++i == set->pairs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

/// Points and deepest depth of both on every case, and how often the deepest depths agree.
void report_agreement(const CaseSet& set) {
  int agree = 0, mink_points = 0, bullet_points = 0, bullet_empty = 0, resting = 0;
  double worst = 0;
  for (std::size_t i = 0; i < set.pairs.size(); ++i) {
    const auto m = mink_manifold(set, i);
    const auto b = bullet_manifold(set, i);
    double deepest = -1e300;
    for (int k = 0; k < m.count; ++k) deepest = std::max(deepest, m.points[k].depth);
    mink_points += m.count;
    bullet_points += b.count;
    bullet_empty += b.count == 0;
    const double diff = b.count > 0 ? std::abs(deepest - b.deepest) : 1e300;
    // Only resting (shallow) cases: in deep random overlaps Bullet's deepest clipped point is not
    // the penetration depth (its incident face reaches far below the reference face).
    if (!set.pairs[i].resting) continue;
    ++resting;
    if (diff <= 1e-6) ++agree;
    if (b.count > 0) worst = std::max(worst, diff);
  }
  std::printf(
      "%-16s %zu cases: mink %.2f points/case, Bullet %.2f points/case (%d cases with none); "
      "resting cases: deepest depth agrees within 1e-6 on %d of %d, worst difference %.1e\n",
      set.name.c_str(), set.pairs.size(), double(mink_points) / set.pairs.size(),
      double(bullet_points) / set.pairs.size(), bullet_empty, agree, resting, worst);
}

/// The exact cases of issue 6 through both libraries' box paths.
void report_exact_cases() {
  CaseSet set;
  set.boxes = true;
  const Vec3 table(2, 2, 0.5), small(0.5, 0.3, 0.2);
  for (const Vec3& h : {table, small}) {
    set.mink_boxes.push_back(mink::Box{h});
    auto box = std::make_unique<btBoxShape>(btVector3(h.x(), h.y(), h.z()));
    box->setMargin(0);
    set.bt_boxes.push_back(std::move(box));
  }
  const double overlap = 0.01, tilt = 0.4;
  const double low = small.y() * std::sin(tilt) + small.z() * std::cos(tilt);
  set.pairs.push_back({0, 1, Pose::identity(),
                       Pose::from(Vec3(0.2, 0.1, 0.5 + small.z() - overlap),
                                  Quat(Eigen::AngleAxisd(0.7, Vec3::UnitZ())))});
  set.pairs.push_back({0, 1, Pose::identity(),
                       Pose::from(Vec3(0.2, 0.1, 0.5 + low - overlap),
                                  Quat(Eigen::AngleAxisd(0.7, Vec3::UnitZ()) *
                                       Eigen::AngleAxisd(tilt, Vec3::UnitX())))});
  finish(set);
  const char* names[] = {"box resting face down (expect 4 points, depth 0.01)",
                         "box tilted on an edge (expect 2 points, depth 0.01)"};
  for (std::size_t i = 0; i < set.pairs.size(); ++i) {
    const auto m = mink_manifold(set, i);
    std::printf("%s\n  mink:   %d points, depths", names[i], m.count);
    for (int k = 0; k < m.count; ++k) std::printf(" %.17g", m.points[k].depth);
    struct Printer final : btDiscreteCollisionDetectorInterface::Result {
      int count = 0;
      void setShapeIdentifiersA(int, int) override {}
      void setShapeIdentifiersB(int, int) override {}
      void addContactPoint(const btVector3&, const btVector3&, btScalar depth) override {
        std::printf(" %.17g", double(-depth));
        ++count;
      }
    } printer;
    std::printf("\n  Bullet btBoxBoxDetector: depths");
    btBoxBoxDetector detector(set.bt_boxes[0].get(), set.bt_boxes[1].get());
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = set.ta[i];
    input.m_transformB = set.tb[i];
    detector.getClosestPoints(input, printer, nullptr);
    std::printf(" (%d points)\n", printer.count);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  constexpr int kCases = 512;
  static std::vector<CaseSet> sets;
  sets.push_back(box_cases(kCases));
  sets.push_back(hull_cases("box-as-polytope", 8, true, kCases));
  sets.push_back(hull_cases("polytope8", 8, false, kCases));
  sets.push_back(hull_cases("polytope32", 32, false, kCases));
  for (CaseSet& s : sets) finish(s);
  report_exact_cases();
  for (const CaseSet& s : sets) report_agreement(s);
  for (const CaseSet& s : sets) {
    benchmark::RegisterBenchmark(("manifold/" + s.name + "/mink").c_str(), bm_mink, &s);
    benchmark::RegisterBenchmark(
        ("manifold/" + s.name + (s.boxes ? "/bullet64_boxbox" : "/bullet64_sat_clip")).c_str(),
        bm_bullet, &s);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
