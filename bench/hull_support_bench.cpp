// Support queries on convex hulls of n points on a sphere (every point a vertex), n = 8 .. 100,000:
//   Scan         the vectorised brute-force scan over the vertices (shapes/support_scan.hpp), the
//                support of a plain Polytope;
//   ClimbWarm    ConvexHullShape::climb_index from the previous answer (a caller-held hint)
//                along directions turning by 0.02 rad per query (a body turning slowly);
//   ClimbCold    the same on independent random directions (the start is then a random vertex);
//   SupportWarm  support_index, the public path (shared hint and direction table), turning;
//   SupportCold  support_index on random directions;
//   Bullet       btConvexHullShape::localGetSupportingVertexWithoutMargin (Bullet's double build,
//                a brute-force loop) on the same vertices and random directions;
//   HullBuild    build_convex_hull on the n points, for the cost the polytope -> hull path adds;
//   Gjk*         mink::distance between two 4,096-vertex hulls, hull shapes against plain
//                polytopes, and Bullet's btGjkPairDetector on btConvexHullShapes.
// The crossover (kHullClimbMinVertices in shapes/hull_shape.hpp) is where SupportCold drops below
// Scan. Run: hull_support_bench --benchmark_repetitions=5 --benchmark_min_time=0.2
// --benchmark_report_aggregates_only=true
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "mink/mink.hpp"
#include "mink/shapes/hull_shape.hpp"

namespace {

using mink::ConvexHullShape;
using mink::Vec3;

Vec3 unit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  for (;;) {
    const Vec3 v(n(g), n(g), n(g));
    if (v.norm() > 1e-3) return v.normalized();
  }
}

std::vector<Vec3> sphere(std::size_t n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < n; ++i) p.push_back(unit(g));
  return p;
}

constexpr std::size_t kDirections = 4096;  // a power of two: the loops cycle with a mask

std::vector<Vec3> random_directions(unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<Vec3> d;
  for (std::size_t i = 0; i < kDirections; ++i) d.push_back(unit(g));
  return d;
}

/// A direction turning by `angle` per query about an axis that itself drifts.
std::vector<Vec3> turning_directions(double angle, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<Vec3> d;
  Vec3 v = unit(g), axis = unit(g).cross(v).normalized();
  for (std::size_t i = 0; i < kDirections; ++i) {
    d.push_back(v);
    v = Eigen::AngleAxisd(angle, axis) * v;
    axis = (axis + 0.05 * unit(g)).cross(v).normalized();
  }
  return d;
}

const ConvexHullShape& hull_of(std::size_t n) {
  static std::vector<std::pair<std::size_t, ConvexHullShape>> cache;
  for (const auto& [size, shape] : cache)
    if (size == n) return shape;
  const auto points = sphere(n, unsigned(n));
  auto shape = ConvexHullShape::make(std::span<const Vec3>(points));
  if (!shape) throw std::runtime_error(shape.error());
  cache.emplace_back(n, std::move(shape).value());
  return cache.back().second;
}

void BM_Scan(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  const auto dirs = random_directions(1);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.scan_index(dirs[i++ & (kDirections - 1)]));
}

void BM_ClimbWarm(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  const auto dirs = turning_directions(0.02, 2);
  std::uint32_t v = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    v = s.climb_index(dirs[i++ & (kDirections - 1)], v);
    benchmark::DoNotOptimize(v);
  }
}

void BM_ClimbCold(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  const auto dirs = random_directions(3);
  std::uint32_t v = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    v = s.climb_index(dirs[i++ & (kDirections - 1)], v);
    benchmark::DoNotOptimize(v);
  }
}

/// support_index, the public path (hint and direction table), on turning directions.
void BM_SupportWarm(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  const auto dirs = turning_directions(0.02, 2);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.support_index(dirs[i++ & (kDirections - 1)]));
}

/// support_index on independent random directions: the hint is useless, the table decides.
void BM_SupportCold(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  const auto dirs = random_directions(3);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.support_index(dirs[i++ & (kDirections - 1)]));
}

void BM_Bullet(benchmark::State& state) {
  const ConvexHullShape& s = hull_of(std::size_t(state.range(0)));
  btConvexHullShape bt;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3 p = s.point(k);
    bt.addPoint(btVector3(p.x(), p.y(), p.z()), false);
  }
  bt.recalcLocalAabb();
  bt.setMargin(0);
  std::vector<btVector3> dirs;
  for (const Vec3& d : random_directions(1)) dirs.emplace_back(d.x(), d.y(), d.z());
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        bt.localGetSupportingVertexWithoutMargin(dirs[i++ & (kDirections - 1)]));
}

void BM_HullBuild(benchmark::State& state) {
  const auto points = sphere(std::size_t(state.range(0)), 5);
  for (auto _ : state) benchmark::DoNotOptimize(mink::build_convex_hull(points));
}

/// Random poses of B about A at distances from touching to 1 apart: 64 pairs cycled.
std::vector<mink::Pose> poses() {
  std::mt19937_64 g(6);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<mink::Pose> p;
  for (int k = 0; k < 64; ++k) {
    std::normal_distribution<double> n;
    mink::Quat q(n(g), n(g), n(g), n(g));
    p.push_back(mink::Pose::from(unit(g) * (2.05 + 0.5 * (u(g) + 1)), q.normalized()));
  }
  return p;
}

template <class Shape>
void gjk_loop(benchmark::State& state, const Shape& a, const Shape& b) {
  const auto ps = poses();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(mink::distance(a, mink::Pose::identity(), b, ps[i++ & 63]).distance);
}

void BM_GjkHull(benchmark::State& state) {
  gjk_loop(state, hull_of(4096), hull_of(4097));
}

void BM_GjkPolytope(benchmark::State& state) {
  static const auto a = mink::Polytope::make(sphere(4096, 4096)).value();
  static const auto b = mink::Polytope::make(sphere(4097, 4097)).value();
  gjk_loop(state, a, b);
}

void BM_GjkBullet(benchmark::State& state) {
  btConvexHullShape ba, bb;
  for (const Vec3& p : sphere(4096, 4096)) ba.addPoint(btVector3(p.x(), p.y(), p.z()), false);
  for (const Vec3& p : sphere(4097, 4097)) bb.addPoint(btVector3(p.x(), p.y(), p.z()), false);
  for (btConvexHullShape* s : {&ba, &bb}) {
    s->recalcLocalAabb();
    s->setMargin(0);
  }
  std::vector<btTransform> tr;
  for (const mink::Pose& p : poses()) {
    const mink::Quat q(p.rotation);
    tr.emplace_back(btQuaternion(q.x(), q.y(), q.z(), q.w()),
                    btVector3(p.translation.x(), p.translation.y(), p.translation.z()));
  }
  btVoronoiSimplexSolver simplex;
  std::size_t i = 0;
  for (auto _ : state) {
    btGjkPairDetector gjk(&ba, &bb, &simplex, nullptr);
    btGjkPairDetector::ClosestPointInput in;
    in.m_transformA.setIdentity();
    in.m_transformB = tr[i++ & 63];
    btPointCollector out;
    gjk.getClosestPoints(in, out, nullptr);
    benchmark::DoNotOptimize(out.m_distance);
  }
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n : {8, 12, 16, 24, 32, 48, 64, 96, 128, 256, 512, 1024, 4096, 16384, 100000}) b->Arg(n);
}

BENCHMARK(BM_Scan)->Apply(Sizes);
BENCHMARK(BM_ClimbWarm)->Apply(Sizes);
BENCHMARK(BM_ClimbCold)->Apply(Sizes);
BENCHMARK(BM_SupportWarm)->Apply(Sizes);
BENCHMARK(BM_SupportCold)->Apply(Sizes);
BENCHMARK(BM_Bullet)->Apply(Sizes);
BENCHMARK(BM_HullBuild)->Arg(64)->Arg(256)->Arg(1024)->Arg(4096)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GjkHull);
BENCHMARK(BM_GjkPolytope);
BENCHMARK(BM_GjkBullet);

}  // namespace

BENCHMARK_MAIN();
