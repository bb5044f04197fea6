// Distance and closest points of curved shapes apart: mink::distance() against Bullet's
// btGjkEpaSolver2::Distance (double build) and FCL's two solvers (shapeDistance with points), on
// the same poses. The pairs are built so that the answer is known: a unit normal n, each shape's
// support point along n (A's) and -n (B's) in closed form (below, not mink's), and B placed so
// that B's point lies `gap` beyond A's along n. Each shape lies on its side of its support plane,
// so the distance is the gap and the two support points are the closest points.
//   cylinders:   cylinder against cylinder;
//   cone-cyl:    cone against cylinder;
//   ellipsoids:  ellipsoid against ellipsoid (Bullet has no ellipsoid: mink and FCL).
// Radii and half heights in [0.3, 1.5], gaps 1e-3 to 1 of the size, random poses.
// Before the timings the program prints each method's worst distance and point errors over the
// pairs (relative to the sum of the bounding radii) and how many answers are off by more than
// 1e-9 of it.
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "peer_pose.hpp"

namespace {

using mink::Pose;
using mink::Vec3;
using mink_bench::bullet_pose;
using mink_bench::fcl_pose;

constexpr int kPairs = 64;

enum class Kind { Cylinder, Cone, Ellipsoid };
enum class Family { Cylinders, ConeCylinder, Ellipsoids };

const char* family_name(Family f) {
  return f == Family::Cylinders      ? "cylinders"
         : f == Family::ConeCylinder ? "cone-cyl"
                                     : "ellipsoids";
}

struct Solid {
  Kind kind = Kind::Cylinder;
  Vec3 extents = Vec3::Ones();  // cylinder, cone: (radius, radius, half height); ellipsoid: radii

  double size() const {
    return kind == Kind::Ellipsoid ? extents.maxCoeff() : std::hypot(extents.x(), extents.z());
  }
  // The support point along local d, in closed form.
  Vec3 support(const Vec3& d) const {
    const double r = extents.x(), h = extents.z(), across = std::hypot(d.x(), d.y());
    switch (kind) {
      case Kind::Cylinder:
        return {r * d.x() / across, r * d.y() / across, d.z() >= 0 ? h : -h};
      case Kind::Cone:
        if (h * d.z() >= r * across - h * d.z()) return {0, 0, h};
        return {r * d.x() / across, r * d.y() / across, -h};
      case Kind::Ellipsoid: {
        const Vec3 scaled = extents.cwiseProduct(extents).cwiseProduct(d);
        return scaled / std::sqrt(d.dot(scaled));
      }
    }
    return Vec3::Zero();
  }
};

std::shared_ptr<btConvexShape> bullet_shape(const Solid& s) {
  std::shared_ptr<btConvexShape> shape;
  if (s.kind == Kind::Cone)
    shape = std::make_shared<btConeShapeZ>(s.extents.x(), 2 * s.extents.z());
  else
    shape =
        std::make_shared<btCylinderShapeZ>(btVector3(s.extents.x(), s.extents.x(), s.extents.z()));
  shape->setMargin(0);
  return shape;
}

/// A pair, with each library's shapes built once, as a simulation keeps them.
struct Pair {
  Solid a, b;
  Pose pa, pb;
  double gap = 0;
  Vec3 on_a, on_b;  // the closest points, world
  std::shared_ptr<btConvexShape> bullet_a, bullet_b;
  std::shared_ptr<fcl::ShapeBased> fcl_a, fcl_b;  // fcl::ShapeBased is ShapeBase<double>
};

std::shared_ptr<fcl::ShapeBased> fcl_shape(const Solid& s) {
  switch (s.kind) {
    case Kind::Cylinder:
      return std::make_shared<fcl::Cylinderd>(s.extents.x(), 2 * s.extents.z());
    case Kind::Cone:
      return std::make_shared<fcl::Coned>(s.extents.x(), 2 * s.extents.z());
    case Kind::Ellipsoid:
      return std::make_shared<fcl::Ellipsoidd>(s.extents);
  }
  return nullptr;
}

std::vector<Pair> make_pairs(Family family) {
  std::mt19937_64 rng(11 + static_cast<int>(family));
  std::uniform_real_distribution<double> length(0.3, 1.5), unit(-1, 1), exponent(-3, 0);
  auto random_unit = [&] {
    Vec3 v;
    do v = Vec3(unit(rng), unit(rng), unit(rng));
    while (v.squaredNorm() > 1 || v.squaredNorm() < 1e-4);
    return Vec3(v.normalized());
  };
  auto solid = [&](Kind kind) {
    Solid s{kind, Vec3::Zero()};
    const double r = length(rng);
    s.extents =
        kind == Kind::Ellipsoid ? Vec3(r, length(rng), length(rng)) : Vec3(r, r, length(rng));
    return s;
  };
  std::vector<Pair> pairs;
  for (int k = 0; k < kPairs; ++k) {
    Pair p;
    p.a = solid(family == Family::Cylinders      ? Kind::Cylinder
                : family == Family::ConeCylinder ? Kind::Cone
                                                 : Kind::Ellipsoid);
    p.b = solid(family == Family::Ellipsoids ? Kind::Ellipsoid : Kind::Cylinder);
    const mink::Quat qa = mink::Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    const mink::Quat qb = mink::Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    p.pa = Pose::from(Vec3(unit(rng), unit(rng), unit(rng)), qa);
    const Vec3 n = random_unit();
    p.gap = (p.a.size() + p.b.size()) * std::pow(10.0, exponent(rng));
    p.on_a = p.pa.apply(p.a.support(p.pa.rotation.transpose() * n));
    p.on_b = p.on_a + p.gap * n;
    const Vec3 local_b = p.b.support(qb.toRotationMatrix().transpose() * -n);
    p.pb = Pose::from(Vec3(p.on_b - qb.toRotationMatrix() * local_b), qb);
    if (family != Family::Ellipsoids) {
      p.bullet_a = bullet_shape(p.a);
      p.bullet_b = bullet_shape(p.b);
    }
    p.fcl_a = fcl_shape(p.a);
    p.fcl_b = fcl_shape(p.b);
    pairs.push_back(p);
  }
  return pairs;
}

/// One method's answer for a pair: distance and the closest points (world); false when it gave
/// none.
struct Answer {
  double distance = 0;
  Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();
};
using DistanceFn = std::function<bool(const Pair&, Answer&)>;

bool mink_distance(const Pair& p, Answer& out) {
  auto run = [&](const auto& a, const auto& b) { return mink::distance(a, p.pa, b, p.pb); };
  auto shape_b = [&](const auto& a) {
    return p.b.kind == Kind::Ellipsoid ? run(a, mink::Ellipsoid{p.b.extents})
                                       : run(a, mink::Cylinder{p.b.extents.x(), p.b.extents.z()});
  };
  const auto r = p.a.kind == Kind::Cylinder
                     ? shape_b(mink::Cylinder{p.a.extents.x(), p.a.extents.z()})
                 : p.a.kind == Kind::Cone ? shape_b(mink::Cone{p.a.extents.x(), p.a.extents.z()})
                                          : shape_b(mink::Ellipsoid{p.a.extents});
  out = {r.distance, r.point_a, r.point_b};
  return r.status == mink::Status::Separated;
}

bool bullet_distance(const Pair& p, Answer& out) {
  if (!p.bullet_a) return false;
  const btTransform ta = bullet_pose(p.pa), tb = bullet_pose(p.pb);
  btGjkEpaSolver2::sResults r;
  if (!btGjkEpaSolver2::Distance(p.bullet_a.get(), ta, p.bullet_b.get(), tb,
                                 ta.getOrigin() - tb.getOrigin(), r))
    return false;
  out.distance = r.distance;
  out.on_a = Vec3(r.witnesses[0].x(), r.witnesses[0].y(), r.witnesses[0].z());
  out.on_b = Vec3(r.witnesses[1].x(), r.witnesses[1].y(), r.witnesses[1].z());
  return true;
}

template <class Solver>
bool fcl_distance(const Pair& p, Answer& out) {
  const Solver solver;
  const fcl::Transform3d ta = fcl_pose(p.pa), tb = fcl_pose(p.pb);
  auto run = [&](const auto& a, const auto& b) {
    return solver.shapeDistance(a, ta, b, tb, &out.distance, &out.on_a, &out.on_b);
  };
  auto with_b = [&](const auto& a) -> bool {
    if (p.b.kind == Kind::Ellipsoid) return run(a, static_cast<const fcl::Ellipsoidd&>(*p.fcl_b));
    return run(a, static_cast<const fcl::Cylinderd&>(*p.fcl_b));
  };
  switch (p.a.kind) {
    case Kind::Cylinder:
      return with_b(static_cast<const fcl::Cylinderd&>(*p.fcl_a));
    case Kind::Cone:
      return with_b(static_cast<const fcl::Coned&>(*p.fcl_a));
    case Kind::Ellipsoid:
      return with_b(static_cast<const fcl::Ellipsoidd&>(*p.fcl_a));
  }
  return false;
}

struct Method {
  const char* name;
  DistanceFn distance;
};

const std::vector<Method>& methods() {
  static const std::vector<Method> all = {
      {"mink", mink_distance},
      {"bullet64_epa2", bullet_distance},
      {"fcl_indep", fcl_distance<fcl::detail::GJKSolver_indep<double>>},
      {"fcl_ccd", fcl_distance<fcl::detail::GJKSolver_libccd<double>>}};
  return all;
}

constexpr Family kFamilies[] = {Family::Cylinders, Family::ConeCylinder, Family::Ellipsoids};

const std::vector<Pair>& pairs_of(Family family) {
  static const std::vector<Pair> all[] = {make_pairs(Family::Cylinders),
                                          make_pairs(Family::ConeCylinder),
                                          make_pairs(Family::Ellipsoids)};
  return all[static_cast<int>(family)];
}

void print_accuracy() {
  std::printf("%-12s %-14s %14s %14s %10s %10s\n", "family", "method", "distance error",
              "point error", "> 1e-9", "no answer");
  for (const Family family : kFamilies) {
    for (const Method& m : methods()) {
      double worst = 0, worst_point = 0;
      int off = 0, missing = 0;
      for (const Pair& p : pairs_of(family)) {
        Answer answer;
        if (!m.distance(p, answer)) {
          ++missing;
          continue;
        }
        const double size = p.a.size() + p.b.size();
        const double error = std::abs(answer.distance - p.gap) / size;
        const double point_error =
            std::max((answer.on_a - p.on_a).norm(), (answer.on_b - p.on_b).norm()) / size;
        worst = std::max(worst, error);
        worst_point = std::max(worst_point, point_error);
        off += std::max(error, point_error) > 1e-9;
      }
      if (missing == kPairs) continue;  // no such shapes in the library
      std::printf("%-12s %-14s %14.2e %14.2e %7d/%d %7d/%d\n", family_name(family), m.name, worst,
                  worst_point, off, kPairs, missing, kPairs);
    }
  }
}

void run(benchmark::State& state, const Method& m, Family family) {
  const auto& pairs = pairs_of(family);
  std::size_t i = 0;
  for (auto _ : state) {
    Answer answer;
    benchmark::DoNotOptimize(m.distance(pairs[i], answer));
    benchmark::DoNotOptimize(answer);
    i = (i + 1) % pairs.size();
  }
}

}  // namespace

int main(int argc, char** argv) {
  print_accuracy();
  for (const Family family : kFamilies)
    for (const Method& m : methods()) {
      if (family == Family::Ellipsoids && std::string(m.name) == "bullet64_epa2") continue;
      benchmark::RegisterBenchmark(
          (std::string("distance/") + family_name(family) + "/" + m.name).c_str(),
          [&m, family](benchmark::State& state) { run(state, m, family); });
    }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
