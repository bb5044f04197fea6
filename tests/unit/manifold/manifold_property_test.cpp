// manifold() properties over random penetrating pairs of boxes, polytopes, spheres, capsules,
// cylinders and rounded boxes, checked against signed distances computed here (closed forms for
// the primitives, brute-force facets for the polytopes):
//  - every point is on both surfaces: |signed distance of point_a from A| and of point_b from B
//    within tolerance;
//  - depths are the signed distances along the shared normal: point_b - point_a = -depth * normal;
//  - the deepest point's depth is the contact query's (EPA's) depth;
//  - swapping A and B flips the normal and keeps the deepest depth and the point positions;
//  - a rigid motion of both shapes moves the points with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mink/manifold/manifold.hpp"
#include "mink/mink.hpp"
#include "oracle/random.hpp"

namespace {

using mink::ManifoldResult;
using mink::Pose;
using mink::Vec3;
using oracle::Rng;

enum Kind { kBox, kPolytope, kSphere, kCapsule, kCylinder, kRoundedBox, kKinds };

const char* kind_name(int kind) {
  static const char* names[] = {"box", "polytope", "sphere", "capsule", "cylinder", "rounded_box"};
  return names[kind];
}

/// A random shape of a kind with the data the signed-distance oracle needs.
struct Desc {
  int kind = kBox;
  Vec3 half = Vec3::Zero();  // box, rounded box
  double radius = 0;         // sphere, capsule, cylinder, rounded box
  double half_height = 0;    // capsule, cylinder
  std::vector<Vec3> points;  // polytope
  struct Facet {
    Vec3 n;
    double w;
  };
  std::vector<Facet> facets;  // polytope, by brute force over triples
};

Desc random_desc(Rng& rng, int kind) {
  Desc d;
  d.kind = kind;
  switch (kind) {
    case kBox:
    case kRoundedBox:
      d.half = Vec3(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1));
      d.radius = kind == kRoundedBox ? rng.uniform(0.01, 0.2) : 0;
      break;
    case kSphere:
      d.radius = rng.uniform(0.1, 1);
      break;
    case kCapsule:
    case kCylinder:
      d.radius = rng.uniform(0.1, 0.8);
      d.half_height = rng.uniform(0.1, 1);
      break;
    case kPolytope: {
      const int n = rng.integer(5, 12);
      for (int i = 0; i < n; ++i)
        d.points.push_back(
            Vec3(rng.uniform(-1, 1), rng.uniform(-0.7, 0.7), rng.uniform(-0.5, 0.5)));
      // Facets: planes through three points with every point on one side.
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          for (int k = j + 1; k < n; ++k) {
            Vec3 normal = (d.points[j] - d.points[i]).cross(d.points[k] - d.points[i]);
            if (normal.norm() < 1e-9) continue;
            normal.normalize();
            double lo = 1e300, hi = -1e300;
            for (const Vec3& p : d.points) {
              lo = std::min(lo, normal.dot(p));
              hi = std::max(hi, normal.dot(p));
            }
            const double w = normal.dot(d.points[i]);
            if (hi <= w + 1e-12) d.facets.push_back({normal, w});
            if (lo >= w - 1e-12) d.facets.push_back({-normal, -w});
          }
      break;
    }
  }
  return d;
}

double size_of(const Desc& d) {
  switch (d.kind) {
    case kBox:
      return d.half.norm();
    case kRoundedBox:
      return d.half.norm() + d.radius;
    case kSphere:
      return d.radius;
    case kCapsule:
      return d.radius + d.half_height;
    case kCylinder:
      return std::hypot(d.radius, d.half_height);
    default: {
      double r = 0;
      for (const Vec3& p : d.points) r = std::max(r, p.norm());
      return r;
    }
  }
}

/// Signed distance of world point x from the shape's surface (negative inside). For polytopes
/// and points outside a box near a face this is the largest facet excess, exact near the faces.
double signed_distance(const Desc& d, const Pose& pose, const Vec3& x) {
  const Vec3 p = pose.inverse_rotate(x - pose.translation);
  auto box_sd = [](const Vec3& h, const Vec3& q) {
    const Vec3 excess = q.cwiseAbs() - h;
    const Vec3 outside = excess.cwiseMax(0.0);
    return outside.norm() + std::min(0.0, excess.maxCoeff());
  };
  switch (d.kind) {
    case kBox:
      return box_sd(d.half, p);
    case kRoundedBox:
      return box_sd(d.half, p) - d.radius;
    case kSphere:
      return p.norm() - d.radius;
    case kCapsule: {
      const double z = std::clamp(p.z(), -d.half_height, d.half_height);
      return (p - Vec3(0, 0, z)).norm() - d.radius;
    }
    case kCylinder: {
      const double radial = std::hypot(p.x(), p.y()) - d.radius;
      const double axial = std::abs(p.z()) - d.half_height;
      return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) +
             std::min(0.0, std::max(radial, axial));
    }
    default: {
      double worst = -1e300;
      for (const auto& f : d.facets) worst = std::max(worst, f.n.dot(p) - f.w);
      return worst;
    }
  }
}

template <class Fn>
auto with_static(const Desc& d, Fn&& fn) {
  switch (d.kind) {
    case kBox:
      return fn(mink::Box{d.half});
    case kRoundedBox:
      return fn(mink::Rounded<mink::Box>{mink::Box{d.half}, d.radius});
    case kSphere:
      return fn(mink::Sphere{d.radius});
    case kCapsule:
      return fn(mink::Capsule{d.radius, d.half_height});
    case kCylinder:
      return fn(mink::Cylinder{d.radius, d.half_height});
    default:
      return fn(mink::Polytope::make(d.points).value());
  }
}

struct Worst {
  double surface = 0, pair = 0, deepest = 0, swap = 0, motion = 0;
  int cases = 0, points = 0, multi = 0;
};

/// Twice the area of the convex hull of a manifold's points seen along its normal.
double manifold_area(const ManifoldResult& r) {
  auto p = [&](int i) { return r.points[i].position(); };
  if (r.count < 3) return 0;
  if (r.count == 3) return std::abs((p(1) - p(0)).cross(p(2) - p(0)).dot(r.normal));
  double area = 0;  // a convex quadrilateral's area is half the cross product of its diagonals
  for (int d = 1; d < 4; ++d) {
    const int o1 = d == 1 ? 2 : 1, o2 = 6 - d - o1;
    area = std::max(area, std::abs((p(d) - p(0)).cross(p(o2) - p(o1)).dot(r.normal)));
  }
  return area;
}

/// Points of r and s (positions) match one to one within tol. When more than four points tie
/// (a square patch clipped to eight corners), A's and B's orders may keep different fours: then
/// the kept area must match instead.
bool same_positions(const ManifoldResult& r, const ManifoldResult& s, double tol, double& worst) {
  if (r.count != s.count) return false;
  bool all = true;
  double worst_here = 0;
  for (int i = 0; i < r.count; ++i) {
    double best = 1e300;
    for (int j = 0; j < s.count; ++j)
      best = std::min(best, (r.points[i].position() - s.points[j].position()).norm());
    worst_here = std::max(worst_here, best);
    all = all && best <= tol;
  }
  if (all) {
    worst = std::max(worst, worst_here);
    return true;
  }
  return r.count == 4 && std::abs(manifold_area(r) - manifold_area(s)) <= tol * 10;
}

/// Random poses: half of them generic, half "resting": B turned about A's z axis (and maybe
/// upside down or on its side) and placed on A's top along z with a small overlap, so that faces,
/// caps and sides meet flat and the manifolds have several points.
template <class A, class B>
void random_poses(Rng& rng, const A& a, const B& b, double size, Pose& pa, Pose& pb) {
  pa = rng.pose(10);
  if (rng.chance(0.5)) {
    pb = Pose::from(pa.translation + rng.in_ball(0.8 * size), rng.rotation());
    return;
  }
  mink::Quat q =
      mink::Quat(pa.rotation) * mink::Quat(Eigen::AngleAxisd(rng.uniform(0, 7), Vec3::UnitZ()));
  if (rng.chance(0.5)) q = q * mink::Quat(Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()));
  if (rng.chance(0.3)) q = q * mink::Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()));
  pb = Pose::from(Vec3::Zero(), q);
  const Vec3 up = pa.rotation.col(2);
  const double top_a =
      up.dot(pa.translation) + up.dot(pa.rotate(mink::support(a, pa.inverse_rotate(up))));
  const double low_b = up.dot(pb.rotate(mink::support(b, pb.inverse_rotate(-up))));
  const Vec3 lateral = pa.rotation * Vec3(rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4), 0) * size;
  const double overlap = size * rng.log_uniform(1e-5, 0.05);
  pb.translation =
      pa.translation + lateral + up * (top_a - up.dot(pa.translation + lateral) - low_b - overlap);
}

void check_case(const Desc& da, const Desc& db, std::uint64_t seed, Worst& worst) {
  Rng rng(seed);
  const double size = size_of(da) + size_of(db);
  // EPA's witness points on a curved core (the cylinder's rim) converge only to about the square
  // root of its depth tolerance, and one-point manifolds are those points.
  const bool curved = da.kind == kCylinder || db.kind == kCylinder;
  const double point_tol = (curved ? 1e-4 : 1e-7) * size;
  // A rounded face or edge tilted from the normal by an angle t within the feature tolerance is
  // moved out by the radius along the wrong direction by t: its points are off the surface by
  // about radius * t^2 / 2 (manifold.hpp), ~1e-7 of the size here.
  auto rounded = [](int kind) { return kind == kRoundedBox || kind == kCapsule; };
  const double surface_tol = (rounded(da.kind) || rounded(db.kind) ? 1e-6 : 1e-9) * size;
  const double deep_tol = (curved                                 ? 1e-5
                           : rounded(da.kind) || rounded(db.kind) ? 1e-6
                                                                  : 1e-9) *
                          size;
  with_static(da, [&](const auto& a) {
    with_static(db, [&](const auto& b) {
      Pose pa, pb;
      random_poses(rng, a, b, size, pa, pb);
      const mink::ContactResult c = mink::contact(a, pa, b, pb);
      if (!(c.intersect && c.depth > 1e-6 * size)) return 0;
      const ManifoldResult r = mink::manifold(a, pa, b, pb);
      const std::string note = std::string(kind_name(da.kind)) + "-" + kind_name(db.kind) + ", " +
                               oracle::seed_note(seed);
      EXPECT_EQ(r.status, mink::Status::Intersecting) << note;
      EXPECT_GE(r.count, 1) << note;
      EXPECT_LE(r.count, 4) << note;
      EXPECT_LE((r.normal - c.normal).norm(), 1e-12) << note;
      ++worst.cases;
      worst.multi += r.count > 1;
      double deepest = -1e300;
      for (int i = 0; i < r.count; ++i) {
        const auto& p = r.points[i];
        ++worst.points;
        deepest = std::max(deepest, p.depth);
        const double pair = (p.point_b - p.point_a + p.depth * r.normal).norm();
        const double surface = std::max(std::abs(signed_distance(da, pa, p.point_a)),
                                        std::abs(signed_distance(db, pb, p.point_b)));
        worst.pair = std::max(worst.pair, pair / size);
        worst.surface = std::max(worst.surface, surface / size);
        EXPECT_LE(pair, 1e-9 * size) << note;
        EXPECT_LE(surface, surface_tol) << note << " point " << i;
        EXPECT_GE(p.depth, -1e-9 * size) << note;
      }
      const double deep_err = std::abs(deepest - c.depth);
      worst.deepest = std::max(worst.deepest, deep_err / size);
      // Curved: the cap of a cylinder is a 16-gon when it is the reference face.
      EXPECT_LE(deep_err, deep_tol) << note << " deepest " << deepest << " EPA " << c.depth;

      const ManifoldResult s = mink::manifold(b, pb, a, pa);
      if (!s.normal_chosen && !r.normal_chosen) {
        EXPECT_LE((s.normal + r.normal).norm(), curved ? 1e-4 : 1e-9) << note;
        double swap = 0;
        EXPECT_TRUE(same_positions(r, s, point_tol, swap))
            << note << " swapped: " << r.count << " vs " << s.count << " points";
        if (!curved) worst.swap = std::max(worst.swap, swap / size);
      }

      const Pose motion = rng.pose(50);
      auto moved = [&](const Pose& p) {
        Pose q;
        q.rotation = motion.rotation * p.rotation;
        q.translation = motion.apply(p.translation);
        return q;
      };
      const ManifoldResult m = mink::manifold(a, moved(pa), b, moved(pb));
      EXPECT_EQ(m.count, r.count) << note;
      if (m.count == r.count) {
        for (int i = 0; i < r.count; ++i) {
          double best = 1e300;
          for (int j = 0; j < m.count; ++j)
            best = std::min(best,
                            (m.points[j].position() - motion.apply(r.points[i].position())).norm());
          if (!curved) worst.motion = std::max(worst.motion, best / size);
          EXPECT_LE(best, point_tol) << note;
        }
      }
      return 0;
    });
    return 0;
  });
}

TEST(ManifoldProperty, EveryPairOfKinds) {
  Worst worst;
  const int per_pair = oracle::sweep_count(60);
  std::uint64_t seed = 610000;
  for (int ka = 0; ka < kKinds; ++ka)
    for (int kb = 0; kb < kKinds; ++kb)
      for (int k = 0; k < per_pair; ++k, ++seed) {
        Rng rng(seed * 7919);
        const Desc da = random_desc(rng, ka), db = random_desc(rng, kb);
        check_case(da, db, seed, worst);
      }
  EXPECT_GT(worst.cases, kKinds * kKinds * per_pair / 3);
  std::printf(
      "[manifold property] %d penetrating cases (%d with several points), %d points; worst / size: "
      "surface %.1e, "
      "pair %.1e, deepest vs EPA %.1e, swap %.1e, rigid motion %.1e (swap and motion without "
      "cylinders)\n",
      worst.cases, worst.multi, worst.points, worst.surface, worst.pair, worst.deepest, worst.swap,
      worst.motion);
}

}  // namespace
