// Penetration depth of solids of revolution on a common axis, where every normal around the axis
// ties: mink::contact() (query/axial_pair.hpp) against Bullet's btGjkEpaSolver2 (double build)
// and FCL's two solvers (GJKSolver_indep's contacts; GJKSolver_libccd's signed distance with
// --with-fcl-ccd, as it takes seconds a call here), on the same poses.
//   cylinders:         coaxial cylinders, B shifted along the axis by up to 0.2 and turned end
//                      for end in half the pairs; depth min(r_a + r_b, h_a + h_b - |shift|).
//   cones-coincident:  two copies of one cone at one pose; depth the least width of its
//                      section, min(2 h, 4 r h / sqrt(r^2 + 4 h^2)).
// Radii and half heights in [0.3, 1.5], under a random common rotation and translation.
// Before the timings the program prints each method's worst depth error over the pairs (relative
// to the sum of the bounding radii) and how many answers are off by more than 1e-9 of it.
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
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

constexpr int kPairs = 32;

struct Solid {
  bool cone = false;
  double radius = 1, half_height = 1;
  double size() const { return std::hypot(radius, half_height); }
};

std::shared_ptr<btConvexShape> bullet_shape(const Solid& s) {
  std::shared_ptr<btConvexShape> shape;
  if (s.cone)
    shape = std::make_shared<btConeShapeZ>(s.radius, 2 * s.half_height);
  else
    shape = std::make_shared<btCylinderShapeZ>(btVector3(s.radius, s.radius, s.half_height));
  shape->setMargin(0);  // the cylinder keeps its outer extents; the cone has no margin then
  return shape;
}

/// A pair, with each library's shapes built once, as a simulation keeps them.
struct Pair {
  Solid a, b;
  Pose pa, pb;
  double depth = 0;  // exact
  std::shared_ptr<btConvexShape> bullet_a, bullet_b;
  fcl::Cylinder<double> fcl_cylinder_a{1, 1}, fcl_cylinder_b{1, 1};
  fcl::Cone<double> fcl_cone_a{1, 1}, fcl_cone_b{1, 1};

  void build_peers() {
    bullet_a = bullet_shape(a);
    bullet_b = bullet_shape(b);
    fcl_cylinder_a = fcl::Cylinder<double>(a.radius, 2 * a.half_height);
    fcl_cylinder_b = fcl::Cylinder<double>(b.radius, 2 * b.half_height);
    fcl_cone_a = fcl::Cone<double>(a.radius, 2 * a.half_height);
    fcl_cone_b = fcl::Cone<double>(b.radius, 2 * b.half_height);
  }
};

std::vector<Pair> make_pairs(bool cones) {
  std::mt19937_64 rng(cones ? 7 : 3);
  std::uniform_real_distribution<double> length(0.3, 1.5), unit(-1, 1), shift(-0.2, 0.2);
  std::vector<Pair> pairs;
  for (int k = 0; k < kPairs; ++k) {
    Pair p;
    const mink::Quat q = mink::Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    p.pa = Pose::from(Vec3(unit(rng), unit(rng), unit(rng)), q);
    p.pb = p.pa;
    if (cones) {
      p.a = p.b = {true, length(rng), length(rng)};
      const double r = p.a.radius, h = p.a.half_height;
      p.depth = std::min(2 * h, 4 * r * h / std::sqrt(r * r + 4 * h * h));
    } else {
      p.a = {false, length(rng), length(rng)};
      p.b = {false, length(rng), length(rng)};
      const double z = shift(rng);
      p.pb.translation += p.pa.rotation.col(2) * z;
      if (k % 2)
        p.pb.rotation = p.pa.rotation * Eigen::AngleAxisd(M_PI, Vec3::UnitX()).toRotationMatrix();
      p.depth = std::min(p.a.radius + p.b.radius, p.a.half_height + p.b.half_height - std::abs(z));
    }
    p.build_peers();
    pairs.push_back(p);
  }
  return pairs;
}

/// One method's depth for pair i, and whether it answered at all.
using DepthFn = std::function<bool(const Pair&, double&)>;

bool mink_depth(const Pair& p, double& depth) {
  auto run = [&](const auto& a, const auto& b) { return mink::contact(a, p.pa, b, p.pb); };
  const auto r = p.a.cone ? run(mink::Cone{p.a.radius, p.a.half_height},
                                mink::Cone{p.b.radius, p.b.half_height})
                          : run(mink::Cylinder{p.a.radius, p.a.half_height},
                                mink::Cylinder{p.b.radius, p.b.half_height});
  depth = r.depth;
  return r.intersect;
}

bool bullet_depth(const Pair& p, double& depth) {
  const btTransform ta = bullet_pose(p.pa), tb = bullet_pose(p.pb);
  btGjkEpaSolver2::sResults r;
  if (!btGjkEpaSolver2::Penetration(p.bullet_a.get(), ta, p.bullet_b.get(), tb,
                                    ta.getOrigin() - tb.getOrigin(), r))
    return false;
  depth = -r.distance;
  return true;
}

template <class Solver>
bool fcl_depth(const Pair& p, double& depth) {
  const Solver solver;
  const fcl::Transform3d ta = fcl_pose(p.pa), tb = fcl_pose(p.pb);
  auto run = [&](const auto& a, const auto& b) {
    if constexpr (std::is_same_v<Solver, fcl::detail::GJKSolver_libccd<double>>) {
      double d = 0;
      fcl::Vector3d p1, p2;
      solver.shapeSignedDistance(a, ta, b, tb, &d, &p1, &p2);
      depth = -d;
      return d <= 0;
    } else {
      std::vector<fcl::ContactPoint<double>> contacts;
      if (!solver.shapeIntersect(a, ta, b, tb, &contacts) || contacts.empty()) return false;
      double deepest = 0;
      for (const auto& c : contacts) deepest = std::max(deepest, std::abs(c.penetration_depth));
      depth = deepest;
      return true;
    }
  };
  return p.a.cone ? run(p.fcl_cone_a, p.fcl_cone_b) : run(p.fcl_cylinder_a, p.fcl_cylinder_b);
}

struct Method {
  const char* name;
  DepthFn depth;
};

/// FCL's libccd solver takes seconds on some of these pairs (4.2-4.7 s a call on average at stop
/// 45), so it runs only with --with-fcl-ccd.
std::vector<Method> methods(bool with_fcl_ccd) {
  std::vector<Method> m = {{"mink", mink_depth},
                           {"bullet64_epa2", bullet_depth},
                           {"fcl_indep", fcl_depth<fcl::detail::GJKSolver_indep<double>>}};
  if (with_fcl_ccd) m.push_back({"fcl_ccd", fcl_depth<fcl::detail::GJKSolver_libccd<double>>});
  return m;
}

const std::vector<Pair>& pairs_of(bool cones) {
  static const std::vector<Pair> cylinders = make_pairs(false), coincident = make_pairs(true);
  return cones ? coincident : cylinders;
}

void print_accuracy(const std::vector<Method>& all) {
  std::printf("%-18s %-14s %12s %10s %10s\n", "family", "method", "worst error", "> 1e-9",
              "no answer");
  for (const bool cones : {false, true}) {
    for (const Method& m : all) {
      double worst = 0;
      int off = 0, missing = 0;
      for (const Pair& p : pairs_of(cones)) {
        double depth = 0;
        if (!m.depth(p, depth)) {
          ++missing;
          continue;
        }
        const double error = std::abs(depth - p.depth) / (p.a.size() + p.b.size());
        worst = std::max(worst, error);
        off += error > 1e-9;
      }
      std::printf("%-18s %-14s %12.2e %7d/%d %7d/%d\n", cones ? "cones-coincident" : "cylinders",
                  m.name, worst, off, kPairs, missing, kPairs);
    }
  }
}

void run(benchmark::State& state, const Method& m, bool cones) {
  const auto& pairs = pairs_of(cones);
  std::size_t i = 0;
  for (auto _ : state) {
    double depth = 0;
    benchmark::DoNotOptimize(m.depth(pairs[i], depth));
    benchmark::DoNotOptimize(depth);
    i = (i + 1) % pairs.size();
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool with_fcl_ccd = false;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--with-fcl-ccd") {
      with_fcl_ccd = true;
      for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      break;
    }
  static const std::vector<Method> all = methods(with_fcl_ccd);
  print_accuracy(all);
  for (const bool cones : {false, true})
    for (const Method& m : all)
      benchmark::RegisterBenchmark(
          (std::string("contact/") + (cones ? "cones-coincident/" : "cylinders/") + m.name).c_str(),
          [&m, cones](benchmark::State& state) { run(state, m, cones); });
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
