// Properties of contact() on random penetrating pairs of many kinds (spheres, boxes, capsules,
// polytopes, rounded boxes, and the curved cores: cylinders, ellipsoids, cones), through the
// run-time Shape path for every pair of kinds and the static types for a few pairs:
//   - the normal attains the depth, h_{A-B}(normal) = depth, and no sampled direction (random, and
//     near the normal) has a smaller support value: h_{A-B}(u) >= depth (this file's own support
//     functions, not mink's);
//   - moving B by depth * normal leaves the shapes touching (distance() ~ 0), by 1.01 * depth
//     separates them (intersect() false), by 0.99 * depth does not (intersect() true);
//   - swapping A and B keeps the depth and flips the normal; a rigid motion of both keeps the
//     depth and rotates the normal (when a different normal comes back, it must be as good);
//   - every output is finite, the normal unit, point_b - point_a = -depth * normal.
// Tolerances relative to the size (sum of bounding radii): 1e-9, and 1e-7 when a core is curved,
// where IterationLimit is accepted with a finite error_bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt), where the
// names of this file's helpers (kinds, cases) would clash with other files' helpers.
namespace contact_property_test {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

enum Kind {
  kSphere,
  kBox,
  kCapsule,
  kPolytope,
  kRoundedBox,
  kCylinder,
  kEllipsoid,
  kCone,
  kKindCount
};

const char* kind_name(int kind) {
  static const char* const kNames[] = {"sphere",      "box",      "capsule",   "polytope",
                                       "rounded box", "cylinder", "ellipsoid", "cone"};
  return kNames[kind];
}

bool curved(int kind) {
  return kind == kCylinder || kind == kEllipsoid || kind == kCone;
}

/// A shape by its parameters: r, h radius and half height; v half extents or radii; margin of a
/// rounded box; points of a polytope.
struct Desc {
  int kind = kSphere;
  double r = 0, h = 0, margin = 0;
  Vec3 v = Vec3::Zero();
  std::vector<Vec3> points;

  std::string describe() const {
    std::ostringstream out;
    out.precision(17);
    out << kind_name(kind) << " r=" << r << " h=" << h << " margin=" << margin << " v=("
        << v.transpose() << ")";
    if (kind == kPolytope) {
      out << " points:";
      for (const Vec3& p : points) out << " (" << p.transpose() << ")";
    }
    return out.str();
  }
};

Desc random_desc(Rng& rng, int kind, double scale) {
  Desc d;
  d.kind = kind;
  auto len = [&] { return scale * rng.log_uniform(0.1, 1.5); };
  d.r = len();
  d.h = len();
  d.margin = 0.3 * len();
  d.v = Vec3(len(), len(), len());
  if (kind == kPolytope) {
    const int count = rng.integer(4, 8);
    for (int i = 0; i < count; ++i) d.points.push_back(rng.in_ball(scale));
  }
  return d;
}

/// Support value of the shape in its local frame, from its definition (long double).
Real local_support(const Desc& d, const V3& u) {
  const V3 v = widen(d.v);
  const Real rho = std::sqrt(u.x() * u.x() + u.y() * u.y());
  auto box = [&] {
    return v.x() * std::abs(u.x()) + v.y() * std::abs(u.y()) + v.z() * std::abs(u.z());
  };
  switch (d.kind) {
    case kSphere:
      return d.r * u.norm();
    case kBox:
      return box();
    case kCapsule:
      return d.h * std::abs(u.z()) + d.r * u.norm();
    case kPolytope: {
      Real best = -std::numeric_limits<Real>::infinity();
      for (const Vec3& p : d.points) best = std::max(best, u.dot(widen(p)));
      return best;
    }
    case kRoundedBox:
      return box() + d.margin * u.norm();
    case kCylinder:
      return d.r * rho + d.h * std::abs(u.z());
    case kEllipsoid:
      return v.cwiseProduct(u).norm();
    case kCone:
      return std::max(d.h * u.z(), d.r * rho - d.h * u.z());
  }
  return 0;
}

oracle::SupportFn world_support(const Desc& d, const Pose& pose) {
  const oracle::M3 rt = widen(pose.rotation).transpose();
  const V3 t = widen(pose.translation);
  return [d, rt, t](const V3& u) { return local_support(d, rt * u) + t.dot(u); };
}

double size_of(const Desc& d) {
  switch (d.kind) {
    case kSphere:
      return d.r;
    case kBox:
      return d.v.norm();
    case kCapsule:
      return d.r + d.h;
    case kPolytope: {
      double m = 0;
      for (const Vec3& p : d.points) m = std::max(m, p.norm());
      return m;
    }
    case kRoundedBox:
      return d.v.norm() + d.margin;
    case kCylinder:
    case kCone:
      return std::hypot(d.r, d.h);
    case kEllipsoid:
      return d.v.maxCoeff();
  }
  return 0;
}

mink::Shape make_runtime(const Desc& d) {
  switch (d.kind) {
    case kSphere:
      return mink::Shape::sphere(d.r).value();
    case kBox:
      return mink::Shape::box(d.v).value();
    case kCapsule:
      return mink::Shape::capsule(d.r, d.h).value();
    case kPolytope:
      return mink::Shape::polytope(d.points).value();
    case kRoundedBox:
      return mink::Shape::rounded(mink::Shape::box(d.v).value(), d.margin).value();
    case kCylinder:
      return mink::Shape::cylinder(d.r, d.h).value();
    case kEllipsoid:
      return mink::Shape::ellipsoid(d.v).value();
    case kCone:
      return mink::Shape::cone(d.r, d.h).value();
  }
  return mink::Shape::sphere(1).value();
}

// Static types for the pairs checked through templates as well.
template <class T>
T make_static(const Desc& d);
template <>
mink::Sphere make_static(const Desc& d) {
  return {d.r};
}
template <>
mink::Box make_static(const Desc& d) {
  return {d.v};
}
template <>
mink::Capsule make_static(const Desc& d) {
  return {d.r, d.h};
}
template <>
mink::Polytope make_static(const Desc& d) {
  return mink::Polytope::make(d.points).value();
}
template <>
mink::Rounded<mink::Box> make_static(const Desc& d) {
  return {mink::Box{d.v}, d.margin};
}
template <>
mink::Cylinder make_static(const Desc& d) {
  return {d.r, d.h};
}
template <>
mink::Ellipsoid make_static(const Desc& d) {
  return {d.v};
}
template <>
mink::Cone make_static(const Desc& d) {
  return {d.r, d.h};
}

Pose compose(const Pose& m, const Pose& p) {
  Pose r;
  r.rotation = m.rotation * p.rotation;
  r.translation = m.rotation * p.translation + m.translation;
  return r;
}

Pose moved(const Pose& p, const Vec3& by) {
  Pose r = p;
  r.translation += by;
  return r;
}

struct Stats {
  std::string name;
  int pairs = 0, limit = 0, shallow = 0, swap_other_normal = 0, motion_other_normal = 0;
  double optimality = 0, undercut = 0, touching = 0, swap = 0, motion = 0, points = 0;
  /// Pairs whose points break point_b - point_a = -depth * normal: the first few fail one by one
  /// (with their trace), the rest are counted in one failure at the end.
  int point_failures = 0;
  static constexpr int kShown = 3;
  explicit Stats(std::string n) : name(std::move(n)) {}
  ~Stats() {
    if (point_failures > kShown) {
      ADD_FAILURE() << name << ": " << point_failures << " of " << pairs
                    << " pairs break point_b - point_a = -depth * normal (worst " << points
                    << " relative; the first " << kShown << " are reported above)";
    }
    std::printf(
        "[  worst   ] %s: %d penetrating pairs (%d iteration-limited, %d too shallow for the "
        "0.99/1.01 moves); relative to size: optimality %.3g, sampled direction below depth "
        "%.3g, distance after the move %.3g, depth change under swap %.3g and motion %.3g, "
        "points %.3g; another equally good normal under swap %d, under motion %d\n",
        name.c_str(), pairs, limit, shallow, optimality, undercut, touching, swap, motion, points,
        swap_other_normal, motion_other_normal);
  }
};

/// All the properties for one penetrating pair; `r` is contact(a, pa, b, pb).
template <class A, class B>
void check_pair(const A& a, const Desc& da, const Pose& pa, const B& b, const Desc& db,
                const Pose& pb, const mink::ContactResult& r, Rng& rng, Stats& stats) {
  const double size = size_of(da) + size_of(db);
  const bool is_curved = curved(da.kind) || curved(db.kind);
  const double tol = (is_curved ? oracle::kCurvedDepthTolerance : oracle::kDepthTolerance) * size;
  const double position = pa.translation.norm() + pb.translation.norm();
  ++stats.pairs;
  ASSERT_TRUE(oracle::all_finite(r)) << oracle::describe(r);
  EXPECT_EQ(r.error, nullptr);
  if (r.status == mink::Status::IterationLimit) {
    ++stats.limit;
    EXPECT_TRUE(is_curved) << "iteration limit on flat cores: " << oracle::describe(r);
  } else {
    EXPECT_EQ(r.status, mink::Status::Intersecting) << oracle::describe(r);
  }
  // The bound a capped run promises, on top of the tolerance.
  const double slack = tol + (r.status == mink::Status::IterationLimit ? r.error_bound : 0.0);
  EXPECT_TRUE(r.intersect);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-12);
  const double consistency =
      (r.point_b - r.point_a + r.depth * r.normal).norm() / (size + position);
  stats.points = std::max(stats.points, consistency);
  if (!(consistency <= 1e-9) && stats.point_failures++ < Stats::kShown) {
    ADD_FAILURE() << "point_b - point_a != -depth * normal: off by " << consistency
                  << " of the size + position (tolerance 1e-9); " << oracle::describe(r);
  }

  // Support values of A - B, this file's own.
  const auto ha = world_support(da, pa), hb = world_support(db, pb);
  auto h = [&](const V3& u) { return ha(u) + hb(V3(-u)); };
  const V3 n = widen(r.normal);
  const double gap = double(h(n)) - r.depth;
  stats.optimality = std::max(stats.optimality, std::abs(gap) / size);
  EXPECT_LE(std::abs(gap), slack) << "h_{A-B}(normal) - depth = " << gap << "; "
                                  << oracle::describe(r);
  // No direction separates with less: random ones, and ones near the normal.
  const V3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  for (int k = 0; k < 48; ++k) {
    V3 u;
    if (k < 24) {
      u = widen(rng.unit());
    } else {
      const Real angle = std::pow(Real(10), -Real(k % 6));  // 1 down to 1e-5 radians
      const Real phi = Real(rng.uniform(0, 2 * M_PI));
      u = (std::cos(angle) * n + std::sin(angle) * (std::cos(phi) * t1 + std::sin(phi) * t2))
              .normalized();
    }
    const double below = r.depth - double(h(u));
    stats.undercut = std::max(stats.undercut, below / size);
    EXPECT_LE(below, slack) << "direction " << u.transpose() << " separates with " << double(h(u))
                            << " < depth " << r.depth;
  }

  // Moving B by the depth along the normal: touching; a little less or more: in or out.
  const auto touching = mink::distance(a, pa, b, moved(pb, r.depth * r.normal));
  EXPECT_NE(touching.status, mink::Status::InvalidInput);
  // distance() may stop with a bracket [distance - error_bound, distance] near contact on
  // curved shapes: its lower end must be within the tolerance.
  const double touching_gap = touching.distance - touching.error_bound;
  stats.touching = std::max(stats.touching, touching_gap / size);
  EXPECT_LE(touching_gap, slack) << "moved by depth * normal: distance " << touching.distance
                                 << " (error_bound " << touching.error_bound << ")";
  const auto still = mink::contact(a, pa, b, moved(pb, r.depth * r.normal));
  EXPECT_LE(still.depth, slack) << "moved by depth * normal: still penetrating";
  if (r.depth >= 1e-6 * size) {
    EXPECT_FALSE(mink::intersect(a, pa, b, moved(pb, 1.01 * r.depth * r.normal)).intersect)
        << "moved by 1.01 depth: still intersecting";
    EXPECT_TRUE(mink::intersect(a, pa, b, moved(pb, 0.99 * r.depth * r.normal)).intersect)
        << "moved by 0.99 depth: separated";
  } else {
    ++stats.shallow;
  }

  // Swap: the same depth, the opposite normal (or another one as good).
  const auto s = mink::contact(b, pb, a, pa);
  ASSERT_TRUE(oracle::all_finite(s)) << oracle::describe(s);
  const double swap_slack =
      slack + (s.status == mink::Status::IterationLimit ? s.error_bound : 0.0);
  stats.swap = std::max(stats.swap, std::abs(s.depth - r.depth) / size);
  EXPECT_NEAR(s.depth, r.depth, swap_slack) << "swapped: " << oracle::describe(s);
  if ((s.normal + r.normal).norm() > 1e-6) {
    ++stats.swap_other_normal;
    EXPECT_LE(std::abs(double(h(widen(Vec3(-s.normal)))) - r.depth), swap_slack)
        << "swapped normal " << s.normal.transpose() << " is not as good as "
        << r.normal.transpose();
  }

  // A rigid motion of both: the same depth, the normal rotated (or another one as good).
  const Pose m = rng.pose(10);
  const auto q = mink::contact(a, compose(m, pa), b, compose(m, pb));
  ASSERT_TRUE(oracle::all_finite(q)) << oracle::describe(q);
  const double motion_slack =
      slack + (q.status == mink::Status::IterationLimit ? q.error_bound : 0.0) + 1e-15 * 20;
  stats.motion = std::max(stats.motion, std::abs(q.depth - r.depth) / size);
  EXPECT_NEAR(q.depth, r.depth, motion_slack) << "moved: " << oracle::describe(q);
  const Vec3 back = m.rotation.transpose() * q.normal;
  if ((back - r.normal).norm() > 1e-6) {
    ++stats.motion_other_normal;
    EXPECT_LE(std::abs(double(h(widen(back))) - r.depth), motion_slack)
        << "moved normal (rotated back) " << back.transpose() << " is not as good as "
        << r.normal.transpose();
  }
}

/// A random penetrating pose for B near A (up to eight tries, each closer); false if none.
template <class A, class B>
bool penetrating_pose(const A& a, const Desc& da, const Pose& pa, const B& b, const Desc& db,
                      Rng& rng, Pose& pb, mink::ContactResult& r) {
  double reach = 0.6 * (size_of(da) + size_of(db));
  for (int attempt = 0; attempt < 8; ++attempt, reach *= 0.6) {
    pb = Pose::from(pa.translation + rng.in_ball(reach), rng.rotation());
    r = mink::contact(a, pa, b, pb);
    if (r.depth > 0 && r.status != mink::Status::InvalidInput) return true;
  }
  return false;
}

TEST(ContactProperty, EveryPairOfKindsRuntime) {
  const std::uint64_t base = 500000;
  const int n = oracle::sweep_count(64 * 40);
  Stats stats("contact properties (run-time shapes)");
  Stats curved_stats("contact properties (run-time shapes, curved cores)");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const int ka = i % kKindCount, kb = (i / kKindCount) % kKindCount;
    const Desc da = random_desc(rng, ka, rng.log_uniform(0.1, 3));
    const Desc db = random_desc(rng, kb, rng.log_uniform(0.1, 3));
    SCOPED_TRACE("A: " + da.describe() + "\nB: " + db.describe());
    const mink::Shape a = make_runtime(da), b = make_runtime(db);
    const Pose pa = rng.pose(5);
    Pose pb;
    mink::ContactResult r;
    if (!penetrating_pose(a, da, pa, b, db, rng, pb, r)) continue;
    check_pair(a, da, pa, b, db, pb, r, rng, curved(ka) || curved(kb) ? curved_stats : stats);
  }
  EXPECT_GT(stats.pairs + curved_stats.pairs, n * 8 / 10);
}

template <class A, class B>
void static_pairs(const char* name, int ka, int kb, std::uint64_t base, int default_count) {
  const int n = oracle::sweep_count(default_count);
  Stats stats(name);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const Desc da = random_desc(rng, ka, rng.log_uniform(0.1, 3));
    const Desc db = random_desc(rng, kb, rng.log_uniform(0.1, 3));
    SCOPED_TRACE("A: " + da.describe() + "\nB: " + db.describe());
    const A a = make_static<A>(da);
    const B b = make_static<B>(db);
    const Pose pa = rng.pose(5);
    Pose pb;
    mink::ContactResult r;
    if (!penetrating_pose(a, da, pa, b, db, rng, pb, r)) continue;
    check_pair(a, da, pa, b, db, pb, r, rng, stats);
    // The run-time path gives the same answer, within the two answers' error bounds: it may run
    // the pair as (B, A) (src/shape_dispatch.hpp), and EPA on a curved core stops within a bracket.
    const auto rt = mink::contact(make_runtime(da), pa, make_runtime(db), pb);
    EXPECT_NEAR(rt.depth, r.depth,
                rt.error_bound + r.error_bound + 1e-12 * (size_of(da) + size_of(db)));
  }
  EXPECT_GT(stats.pairs, n * 8 / 10);
}

TEST(ContactProperty, StaticRoundedBoxCylinder) {
  static_pairs<mink::Rounded<mink::Box>, mink::Cylinder>("contact static rounded box-cylinder",
                                                         kRoundedBox, kCylinder, 510000, 150);
}

TEST(ContactProperty, StaticPolytopeEllipsoid) {
  static_pairs<mink::Polytope, mink::Ellipsoid>("contact static polytope-ellipsoid", kPolytope,
                                                kEllipsoid, 520000, 150);
}

TEST(ContactProperty, StaticBoxCone) {
  static_pairs<mink::Box, mink::Cone>("contact static box-cone", kBox, kCone, 530000, 150);
}

TEST(ContactProperty, StaticCapsulePolytope) {
  static_pairs<mink::Capsule, mink::Polytope>("contact static capsule-polytope", kCapsule,
                                              kPolytope, 540000, 150);
}

TEST(ContactProperty, StaticSphereRoundedBox) {
  static_pairs<mink::Sphere, mink::Rounded<mink::Box>>("contact static sphere-rounded box", kSphere,
                                                       kRoundedBox, 550000, 150);
}

TEST(ContactProperty, StaticEllipsoidEllipsoid) {
  static_pairs<mink::Ellipsoid, mink::Ellipsoid>("contact static ellipsoid-ellipsoid", kEllipsoid,
                                                 kEllipsoid, 560000, 150);
}

TEST(ContactProperty, StaticBoxBox) {
  static_pairs<mink::Box, mink::Box>("contact static box-box", kBox, kBox, 570000, 150);
}

}  // namespace contact_property_test
