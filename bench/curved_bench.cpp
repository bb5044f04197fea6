// Curved shapes apart and penetrating, against Bullet's btGjkEpaSolver2 (double build) and FCL's
// two solvers, on the same poses.
//
// Apart: mink::distance() against Bullet's Distance and FCL's shapeDistance with points. The
// pairs are built so that the answer is known: a unit normal n, each shape's support point along
// n (A's) and -n (B's) in closed form (below, not mink's), and B placed so that B's point lies
// `gap` beyond A's along n. Each shape lies on its side of its support plane, so the distance is
// the gap and the two support points are the closest points.
//   cylinders:   cylinder against cylinder;
//   cone-cyl:    cone against cylinder;
//   ellipsoids:  ellipsoid against ellipsoid (Bullet has no ellipsoid: mink and FCL).
// Radii and half heights in [0.3, 1.5], gaps 1e-3 to 1 of the size, random poses.
//
// Penetrating: mink::contact() against Bullet's Penetration and FCL's shapeIntersect (its own
// solver, and libccd's MPR, which fcl::collide runs). B's point lies `depth` inside A's support
// plane instead, at a point where a ball of radius r fits inside B touching there (an ellipsoid's
// c^2 / a anywhere; a cylinder's min(radius, half height - |z|) at a point of its side at height
// z, the normal across its axis), and likewise r' in A (0 for a box's edge), with depth <= r + r'.
// Then A - B holds a ball of radius r + r' touching its boundary at the two points' difference,
// depth n, whose distance from the origin is at least r + r' - |depth - r - r'| = depth, while
// moving B by depth along n separates them: the depth is exact, n the normal, and the two points
// the deepest (epa/inner_ball.hpp makes the same argument). Depths 1e-4 to 0.9 of that radius.
//   box-cyl-pen:     a box's edge across a cylinder's side;
//   cyl-cyl-pen:     two cylinders' sides, axes crossing;
//   ellipsoids-pen:  two ellipsoids (mink and FCL).
//
// Before the timings the program prints each method's worst errors over the pairs (distance or
// depth, points, and for penetration the normal; relative to the sum of the bounding radii) and
// how many answers are off by more than 1e-9 of it.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/box.h>
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
#include <type_traits>
#include <vector>

#include "mink/mink.hpp"
#include "peer_pose.hpp"

namespace {

using mink::Pose;
using mink::Vec3;
using mink_bench::bullet_pose;
using mink_bench::fcl_pose;

constexpr int kPairs = 64;

enum class Kind { Cylinder, Cone, Ellipsoid, Box };
enum class Family {
  Cylinders,
  ConeCylinder,
  Ellipsoids,
  BoxCylinderPen,
  CylindersPen,
  EllipsoidsPen,
  ParallelCylindersPen
};

const char* family_name(Family f) {
  switch (f) {
    case Family::Cylinders:
      return "cylinders";
    case Family::ConeCylinder:
      return "cone-cyl";
    case Family::Ellipsoids:
      return "ellipsoids";
    case Family::BoxCylinderPen:
      return "box-cyl-pen";
    case Family::CylindersPen:
      return "cyl-cyl-pen";
    case Family::EllipsoidsPen:
      return "ellipsoids-pen";
    case Family::ParallelCylindersPen:
      return "parallel-cyl-pen";
  }
  return "";
}

bool penetrating(Family f) {
  return f >= Family::BoxCylinderPen;
}

struct Solid {
  Kind kind = Kind::Cylinder;
  // cylinder, cone: (radius, radius, half height); ellipsoid: radii; box: half extents
  Vec3 extents = Vec3::Ones();

  double size() const {
    return kind == Kind::Ellipsoid ? extents.maxCoeff()
           : kind == Kind::Box     ? extents.norm()
                                   : std::hypot(extents.x(), extents.z());
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
      case Kind::Box:
        return {d.x() >= 0 ? extents.x() : -extents.x(), d.y() >= 0 ? extents.y() : -extents.y(),
                d.z() >= 0 ? extents.z() : -extents.z()};
    }
    return Vec3::Zero();
  }
};

std::shared_ptr<btConvexShape> bullet_shape(const Solid& s) {
  std::shared_ptr<btConvexShape> shape;
  if (s.kind == Kind::Box)
    shape = std::make_shared<btBoxShape>(btVector3(s.extents.x(), s.extents.y(), s.extents.z()));
  else if (s.kind == Kind::Cone)
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
  bool penetrating = false;
  double gap = 0;   // apart: the distance; penetrating: the depth
  Vec3 normal;      // penetrating: the normal, from A to B
  Vec3 on_a, on_b;  // the closest (deepest) points, world
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
    case Kind::Box:
      return std::make_shared<fcl::Boxd>(2 * s.extents);
  }
  return nullptr;
}

/// The pair with each library's shapes (Bullet has no ellipsoid).
Pair& with_peer_shapes(Pair& p) {
  if (p.a.kind != Kind::Ellipsoid && p.b.kind != Kind::Ellipsoid) {
    p.bullet_a = bullet_shape(p.a);
    p.bullet_b = bullet_shape(p.b);
  }
  p.fcl_a = fcl_shape(p.a);
  p.fcl_b = fcl_shape(p.b);
  return p;
}

/// A random unit vector, uniform over the sphere, and a random turn.
Vec3 random_unit(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  Vec3 v;
  do v = Vec3(unit(rng), unit(rng), unit(rng));
  while (v.squaredNorm() > 1 || v.squaredNorm() < 1e-4);
  return v.normalized();
}
mink::Quat random_turn(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  return mink::Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
}

std::vector<Pair> make_pairs(Family family) {
  std::mt19937_64 rng(11 + static_cast<int>(family));
  std::uniform_real_distribution<double> length(0.3, 1.5), unit(-1, 1), exponent(-3, 0);
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
    const mink::Quat qa = random_turn(rng);
    const mink::Quat qb = random_turn(rng);
    p.pa = Pose::from(Vec3(unit(rng), unit(rng), unit(rng)), qa);
    const Vec3 n = random_unit(rng);
    p.gap = (p.a.size() + p.b.size()) * std::pow(10.0, exponent(rng));
    p.on_a = p.pa.apply(p.a.support(p.pa.rotation.transpose() * n));
    p.on_b = p.on_a + p.gap * n;
    const Vec3 local_b = p.b.support(qb.toRotationMatrix().transpose() * -n);
    p.pb = Pose::from(Vec3(p.on_b - qb.toRotationMatrix() * local_b), qb);
    pairs.push_back(with_peer_shapes(p));
  }
  return pairs;
}

/// A penetrating pair (see the top of the file): A's point on its support plane along n, B's
/// `depth` below it, each where an inner ball touches.
std::vector<Pair> make_penetrating_pairs(Family family) {
  std::mt19937_64 rng(23 + static_cast<int>(family));
  std::uniform_real_distribution<double> length(0.3, 1.5), unit(-1, 1), exponent(-4, 0);
  // A turn that takes local z onto unit `axis`.
  auto frame_about = [&](const Vec3& axis) {
    const Vec3 x = random_unit(rng).cross(axis).normalized();
    mink::Mat3 r;
    r.col(0) = x;
    r.col(1) = axis.cross(x);
    r.col(2) = axis;
    return r;
  };
  // One that takes local z across unit n (a cylinder's axis across the normal).
  auto axis_across = [&](const Vec3& n) {
    return frame_about(Vec3(random_unit(rng).cross(n).normalized()));
  };
  // A cylinder's point of its side along local d (d across its axis) at height z, and the radius
  // of the ball inside it that touches there.
  auto side_point = [](const Solid& c, const Vec3& d, double z, double& ball) {
    const double r = c.extents.x(), h = c.extents.z(), across = std::hypot(d.x(), d.y());
    ball = std::min(r, h - std::abs(z));
    return Vec3(r * d.x() / across, r * d.y() / across, z);
  };
  std::vector<Pair> pairs;
  for (int k = 0; k < kPairs; ++k) {
    Pair p;
    const Vec3 n = random_unit(rng);
    double ball_a = 0, ball_b = 0;
    mink::Mat3 ra, rb;
    Vec3 local_a, local_b;
    if (family == Family::EllipsoidsPen) {
      for (Solid* e : {&p.a, &p.b})
        *e = {Kind::Ellipsoid, Vec3(length(rng), length(rng), length(rng))};
      ra = random_turn(rng).toRotationMatrix();
      rb = random_turn(rng).toRotationMatrix();
      local_a = p.a.support(ra.transpose() * n);
      local_b = p.b.support(rb.transpose() * -n);
      for (const Solid* e : {&p.a, &p.b}) {
        const double least = e->extents.minCoeff(), most = e->extents.maxCoeff();
        (e == &p.a ? ball_a : ball_b) = least * least / most;
      }
    } else {
      p.b = {Kind::Cylinder, Vec3::Zero()};
      const double rb_radius = length(rng);
      p.b.extents = Vec3(rb_radius, rb_radius, length(rng));
      rb = axis_across(n);
      local_b = side_point(p.b, rb.transpose() * -n, 0.8 * p.b.extents.z() * unit(rng), ball_b);
      if (family == Family::BoxCylinderPen) {
        // A's edge along local x at (y, z) = (+, +), n within its normal cone at angle phi from
        // local y, and the cylinder's axis across n at angle psi from the edge: the side line
        // crosses the edge (along a box's face it would lie in it, a line of deepest points).
        p.a = {Kind::Box, Vec3(length(rng), length(rng), length(rng))};
        std::uniform_real_distribution<double> phi_of(0.1, 1.47), psi_of(0.2, 1.37);
        const double phi = phi_of(rng), psi = psi_of(rng) * (unit(rng) < 0 ? -1 : 1);
        const Vec3 edge = random_unit(rng).cross(n).normalized(), w = edge.cross(n);
        ra.col(0) = edge;
        ra.col(1) = std::cos(phi) * n - std::sin(phi) * w;
        ra.col(2) = std::sin(phi) * n + std::cos(phi) * w;
        local_a = Vec3(0.8 * p.a.extents.x() * unit(rng), p.a.extents.y(), p.a.extents.z());
        rb = frame_about(Vec3(std::cos(psi) * edge - std::sin(psi) * w));
        local_b = side_point(p.b, rb.transpose() * -n, 0.8 * p.b.extents.z() * unit(rng), ball_b);
      } else {
        p.a = {Kind::Cylinder, Vec3::Zero()};
        const double ra_radius = length(rng);
        p.a.extents = Vec3(ra_radius, ra_radius, length(rng));
        ra = axis_across(n);
        local_a = side_point(p.a, ra.transpose() * n, 0.8 * p.a.extents.z() * unit(rng), ball_a);
        if (family == Family::ParallelCylindersPen) {
          // Side by side: B's axis A's turned about n by 1e-3 to 1e-2 rad, so the side lines
          // cross (seen along n) at the deepest points, at a small angle. Not less: B's axis is
          // rounded to 1e-16, which turns the true normal by 1e-16 / tilt and moves the crossing
          // along the lines by that over the tilt again, so the construction's points would be
          // off the rounded pair's by more than 1e-9 of the size.
          std::uniform_real_distribution<double> tilt_exponent(-3, -2);
          const double tilt = std::pow(10.0, tilt_exponent(rng)) * (unit(rng) < 0 ? -1 : 1);
          rb = frame_about(Eigen::AngleAxisd(tilt, n) * ra.col(2));
          local_b = side_point(p.b, rb.transpose() * -n, 0.8 * p.b.extents.z() * unit(rng), ball_b);
        }
      }
    }
    p.penetrating = true;
    p.gap = 0.9 * (ball_a + ball_b) * std::pow(10.0, exponent(rng));
    p.normal = n;
    p.pa.rotation = ra;
    p.pa.translation = Vec3(unit(rng), unit(rng), unit(rng));
    p.on_a = p.pa.apply(local_a);
    p.on_b = p.on_a - p.gap * n;
    p.pb.rotation = rb;
    p.pb.translation = p.on_b - rb * local_b;
    pairs.push_back(with_peer_shapes(p));
  }
  return pairs;
}

/// One method's answer for a pair: distance (apart) or depth (penetrating), the normal from A to B
/// (penetrating), and the closest or deepest points (world); false when it gave none.
struct Answer {
  double distance = 0;
  Vec3 normal = Vec3::Zero();
  Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();
  bool points = true;  // FCL's shapeIntersect gives one contact position, not the two points
};
using QueryFn = std::function<bool(const Pair&, Answer&)>;

template <class F>
auto with_mink(const Solid& s, F&& f) {
  switch (s.kind) {
    case Kind::Cylinder:
      return f(mink::Cylinder{s.extents.x(), s.extents.z()});
    case Kind::Cone:
      return f(mink::Cone{s.extents.x(), s.extents.z()});
    case Kind::Ellipsoid:
      return f(mink::Ellipsoid{s.extents});
    case Kind::Box:
      break;
  }
  return f(mink::Box{s.extents});
}

bool mink_query(const Pair& p, Answer& out) {
  return with_mink(p.a, [&](const auto& a) {
    return with_mink(p.b, [&](const auto& b) {
      if (p.penetrating) {
        const auto r = mink::contact(a, p.pa, b, p.pb);
        out = {r.depth, r.normal, r.point_a, r.point_b};
        return r.status == mink::Status::Intersecting;
      }
      const auto r = mink::distance(a, p.pa, b, p.pb);
      out = {r.distance, r.normal, r.point_a, r.point_b};
      return r.status == mink::Status::Separated;
    });
  });
}

bool bullet_query(const Pair& p, Answer& out) {
  if (!p.bullet_a) return false;
  const btTransform ta = bullet_pose(p.pa), tb = bullet_pose(p.pb);
  btGjkEpaSolver2::sResults r;
  if (p.penetrating) {
    if (!btGjkEpaSolver2::Penetration(p.bullet_a.get(), ta, p.bullet_b.get(), tb,
                                      ta.getOrigin() - tb.getOrigin(), r))
      return false;
    // Its normal is in A's frame and points from B to A.
    const btVector3 normal = -(ta.getBasis() * r.normal);
    out.distance = -r.distance;
    out.normal = Vec3(normal.x(), normal.y(), normal.z());
  } else {
    if (!btGjkEpaSolver2::Distance(p.bullet_a.get(), ta, p.bullet_b.get(), tb,
                                   ta.getOrigin() - tb.getOrigin(), r))
      return false;
    out.distance = r.distance;
  }
  out.on_a = Vec3(r.witnesses[0].x(), r.witnesses[0].y(), r.witnesses[0].z());
  out.on_b = Vec3(r.witnesses[1].x(), r.witnesses[1].y(), r.witnesses[1].z());
  return true;
}

template <class F>
auto with_fcl(const Solid& s, const fcl::ShapeBased& shape, F&& f) {
  switch (s.kind) {
    case Kind::Cylinder:
      return f(static_cast<const fcl::Cylinderd&>(shape));
    case Kind::Cone:
      return f(static_cast<const fcl::Coned&>(shape));
    case Kind::Ellipsoid:
      return f(static_cast<const fcl::Ellipsoidd&>(shape));
    case Kind::Box:
      break;
  }
  return f(static_cast<const fcl::Boxd&>(shape));
}

template <class Solver>
bool fcl_query(const Pair& p, Answer& out) {
  const Solver solver;
  const fcl::Transform3d ta = fcl_pose(p.pa), tb = fcl_pose(p.pb);
  return with_fcl(p.a, *p.fcl_a, [&](const auto& a) {
    return with_fcl(p.b, *p.fcl_b, [&](const auto& b) {
      if (!p.penetrating)
        return solver.shapeDistance(a, ta, b, tb, &out.distance, &out.on_a, &out.on_b);
      std::vector<fcl::ContactPoint<double>> contacts;
      if (!solver.shapeIntersect(a, ta, b, tb, &contacts) || contacts.empty()) return false;
      out.distance = std::abs(contacts[0].penetration_depth);
      // FCL's own solver gives the normal in A's frame, libccd's in the world's.
      out.normal = std::is_same_v<Solver, fcl::detail::GJKSolver_indep<double>>
                       ? Vec3(p.pa.rotation * contacts[0].normal)
                       : Vec3(contacts[0].normal);
      out.points = false;
      return true;
    });
  });
}

struct Method {
  const char* name;
  QueryFn query;
};

const std::vector<Method>& methods() {
  static const std::vector<Method> all = {
      {"mink", mink_query},
      {"bullet64_epa2", bullet_query},
      {"fcl_indep", fcl_query<fcl::detail::GJKSolver_indep<double>>},
      {"fcl_ccd", fcl_query<fcl::detail::GJKSolver_libccd<double>>}};
  return all;
}

constexpr Family kFamilies[] = {Family::Cylinders,           Family::ConeCylinder,
                                Family::Ellipsoids,          Family::BoxCylinderPen,
                                Family::CylindersPen,        Family::EllipsoidsPen,
                                Family::ParallelCylindersPen};

const std::vector<Pair>& pairs_of(Family family) {
  static const std::vector<Pair> all[] = {make_pairs(Family::Cylinders),
                                          make_pairs(Family::ConeCylinder),
                                          make_pairs(Family::Ellipsoids),
                                          make_penetrating_pairs(Family::BoxCylinderPen),
                                          make_penetrating_pairs(Family::CylindersPen),
                                          make_penetrating_pairs(Family::EllipsoidsPen),
                                          make_penetrating_pairs(Family::ParallelCylindersPen)};
  return all[static_cast<int>(family)];
}

void print_accuracy() {
  std::printf("%-15s %-14s %14s %14s %14s %10s %10s\n", "family", "method", "dist/depth err",
              "normal error", "point error", "> 1e-9", "no answer");
  for (const Family family : kFamilies) {
    for (const Method& m : methods()) {
      double worst = 0, worst_normal = 0, worst_point = 0;
      int off = 0, missing = 0;
      bool points = true;
      for (const Pair& p : pairs_of(family)) {
        Answer answer;
        if (!m.query(p, answer)) {
          ++missing;
          continue;
        }
        const double size = p.a.size() + p.b.size();
        const double error = std::abs(answer.distance - p.gap) / size;
        const double normal_error = p.penetrating ? (answer.normal - p.normal).norm() : 0.0;
        points = answer.points;
        const double point_error =
            answer.points
                ? std::max((answer.on_a - p.on_a).norm(), (answer.on_b - p.on_b).norm()) / size
                : 0.0;
        worst = std::max(worst, error);
        worst_normal = std::max(worst_normal, normal_error);
        worst_point = std::max(worst_point, point_error);
        off += std::max({error, normal_error, point_error}) > 1e-9;
      }
      if (missing == kPairs) continue;  // no such shapes in the library
      char normal_text[32] = "-", point_text[32] = "-";
      if (penetrating(family)) std::snprintf(normal_text, sizeof normal_text, "%.2e", worst_normal);
      if (points) std::snprintf(point_text, sizeof point_text, "%.2e", worst_point);
      std::printf("%-15s %-14s %14.2e %14s %14s %7d/%d %7d/%d\n", family_name(family), m.name,
                  worst, normal_text, point_text, off, kPairs, missing, kPairs);
    }
  }
}

void run(benchmark::State& state, const Method& m, Family family) {
  const auto& pairs = pairs_of(family);
  std::size_t i = 0;
  for (auto _ : state) {
    Answer answer;
    benchmark::DoNotOptimize(m.query(pairs[i], answer));
    benchmark::DoNotOptimize(answer);
    i = (i + 1) % pairs.size();
  }
}

}  // namespace

int main(int argc, char** argv) {
  print_accuracy();
  for (const Family family : kFamilies)
    for (const Method& m : methods()) {
      const bool ellipsoids = family == Family::Ellipsoids || family == Family::EllipsoidsPen;
      if (ellipsoids && std::string(m.name) == "bullet64_epa2") continue;
      benchmark::RegisterBenchmark(
          (std::string(penetrating(family) ? "contact/" : "distance/") + family_name(family) + "/" +
           m.name)
              .c_str(),
          [&m, family](benchmark::State& state) { run(state, m, family); });
    }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
