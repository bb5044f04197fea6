// contact() on penetrating pairs of spheres, boxes, capsules, cylinders, cones and ellipsoids (all
// 36 ordered pairs) against an independent depth: the least support value of A - B over unit
// directions, searched by brute force in long double (tests/oracle/curved.hpp). The poses are the
// ones that are hard for EPA: coaxial, one shape inside the other (a circle of equally good
// normals); coaxial stacks of caps on caps, slightly overlapping, with very thin discs and flat
// boxes; exact 90 and 180 degree turns; parallel axes offset sideways; perpendicular axes; random
// poses; and pairs 1e3 from the origin. A case passes when the depth is within 1e-9 of the size
// (the sum of bounding radii) and the normal is as good, h_{A-B}(normal) - depth <= 1e-9 of the
// size, evaluated with the oracle's support functions; or when mink says iteration_limit and its
// error_bound covers the error ("flagged"). Anything else is a failure, and one that mink reports
// as converged is "silent". Every failure prints its shapes and poses to 17 digits. A draw whose
// oracle depth is below 1e-7 of the size (touching or apart: any normal is then about as good) is
// replaced by the next draw of the same generator, up to 5 times, and then skipped and counted.
//
// Slow: the oracle takes about 8 ms per case. The default runs 2 cases per ordered pair and
// configuration (504, 4 s on a 2-core VM); MINK_SWEEP_SCALE=n multiplies that (30: 15,120 cases,
// about 2.5 minutes with the oracle's own tests). Before the sweep, the oracle is checked against
// closed forms (tests/oracle/penetration.hpp and a few derived here), sampled surfaces, and for
// symmetry and invariance, so that a disagreement is mink's.
//
// A second sweep (DistanceMatchesOracle) runs distance() and contact() on the same pairs and
// configurations pulled apart: each penetrating case of the generator has B moved along the line
// of centres, the oracle's normal, an axis of A or a random direction until the oracle's gap is
// 1e-9 to 1 of the size (log-uniform) or 0 (touching, within 2.5e-13 of the size: a sixth of the
// cases), by Newton's method on the oracle's depth as a function of the shift. A result passes
// when its distance (contact(): distance minus depth) is within 1e-9 of the size of the oracle's,
// its normal is unit and optimal (h_{A-B}(normal) + oracle distance <= 1e-9 of the size), point_a
// and point_b lie on their shapes and on the support planes along +-normal, and
// point_b - point_a = distance * normal, all within 1e-9 of the size; the status must be
// separated, or intersecting when the oracle's gap is within mink's touching tolerance (1e-12 of
// the size). Flagged and silent as above. It takes about 3 full oracle searches per case: the
// default, 1 case per ordered pair and configuration (252), about 5 s; MINK_SWEEP_SCALE
// multiplies it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/curved.hpp"
#include "oracle/curved_to_mink.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Mat3;
using mink::Pose;
using mink::Vec3;
using oracle::CurvedKind;
using oracle::CurvedShape;
using oracle::Real;
using oracle::RigidPose;
using oracle::Rng;
using oracle::V3;
using oracle::widen;
using oracle::with_mink_shape;

constexpr double kPi = std::numbers::pi;
constexpr std::array<CurvedKind, 6> kKinds = {CurvedKind::Sphere,  CurvedKind::Box,
                                              CurvedKind::Capsule, CurvedKind::Cylinder,
                                              CurvedKind::Cone,    CurvedKind::Ellipsoid};

/// Cases per ordered pair and configuration: `default_count` times the integer in
/// MINK_SWEEP_SCALE (1 when unset).
int sweep_count(int default_count) {
  const char* env = std::getenv("MINK_SWEEP_SCALE");
  return default_count * (env ? std::max(1, std::atoi(env)) : 1);
}

/// The pose as the oracle takes it: mink's double matrix and translation, widened exactly, so
/// that both see the same shape.
RigidPose rigid(const Pose& p) {
  return {widen(p.rotation), widen(p.translation)};
}

/// A shape from double parameters (so that mink's copy is exact).
CurvedShape make_shape(CurvedKind kind, double radius, double half_height, const Vec3& extents) {
  return {kind, radius, half_height, widen(extents)};
}

mink::ContactResult run_contact(const CurvedShape& a, const Pose& pa, const CurvedShape& b,
                                const Pose& pb) {
  return with_mink_shape(a, [&](const auto& ma) {
    return with_mink_shape(b, [&](const auto& mb) { return mink::contact(ma, pa, mb, pb); });
  });
}

Real size_of(const CurvedShape& a, const CurvedShape& b) {
  return oracle::bounding_radius(a) + oracle::bounding_radius(b);
}

Real difference_support(const CurvedShape& a, const Pose& pa, const CurvedShape& b, const Pose& pb,
                        const V3& u) {
  return oracle::DifferenceSupport(a, rigid(pa), b, rigid(pb))(u);
}

std::string describe_shape(const CurvedShape& s) {
  char buffer[160];
  const double r = static_cast<double>(s.radius), h = static_cast<double>(s.half_height);
  const Vec3 e = s.extents.cast<double>();
  switch (s.kind) {
    case CurvedKind::Sphere:
      std::snprintf(buffer, sizeof buffer, "Sphere{radius %.17g}", r);
      break;
    case CurvedKind::Box:
    case CurvedKind::Ellipsoid:
      std::snprintf(buffer, sizeof buffer, "%s{%s (%.17g, %.17g, %.17g)}",
                    oracle::kind_name(s.kind), s.kind == CurvedKind::Box ? "half_extents" : "radii",
                    e.x(), e.y(), e.z());
      break;
    default:
      std::snprintf(buffer, sizeof buffer, "%s{radius %.17g, half_height %.17g}",
                    oracle::kind_name(s.kind), r, h);
  }
  return buffer;
}

std::string describe_pose(const Pose& p) {
  char buffer[512];
  const Mat3& m = p.rotation;
  std::snprintf(buffer, sizeof buffer,
                "rotation [%.17g, %.17g, %.17g; %.17g, %.17g, %.17g; %.17g, %.17g, %.17g], "
                "translation (%.17g, %.17g, %.17g)",
                m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2),
                p.translation.x(), p.translation.y(), p.translation.z());
  return buffer;
}

Mat3 about(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// One of the 24 rotations that map the axes onto the axes, with exact entries 0 and +-1.
Mat3 exact_turn(int index) {
  static const std::array<std::array<int, 3>, 6> perms = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  const auto& p = perms[index % 6];
  const bool odd = index % 6 >= 3;
  const int signs = index / 6;  // 0..3: two free signs, the third fixes the determinant at +1
  Mat3 m = Mat3::Zero();
  const double s0 = (signs & 1) ? -1 : 1, s1 = (signs & 2) ? -1 : 1;
  m(p[0], 0) = s0;
  m(p[1], 1) = s1;
  m(p[2], 2) = (odd ? -1 : 1) * s0 * s1;
  return m;
}

/// 180 degrees about x: z to -z, exactly.
Mat3 flip() {
  return Eigen::Vector3d(1, -1, -1).asDiagonal();
}

/// k quarter turns about z, exactly.
Mat3 quarter_turns_z(int k) {
  const std::array<double, 4> c = {1, 0, -1, 0}, s = {0, 1, 0, -1};
  Mat3 m = Mat3::Identity();
  m(0, 0) = m(1, 1) = c[k % 4];
  m(1, 0) = s[k % 4];
  m(0, 1) = -s[k % 4];
  return m;
}

/// A quarter turn about x (z to -y), exactly.
Mat3 quarter_turn_x() {
  Mat3 m;
  m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return m;
}

/// A turn about z by a random angle, a quarter of the time an exact multiple of 90 degrees.
Mat3 spin(Rng& rng) {
  if (rng.chance(0.25)) return quarter_turns_z(rng.integer(0, 3));
  return about(rng.uniform(0, 2 * kPi), Vec3::UnitZ());
}

/// Base orientation: the identity (axes exactly along the world's), an exact turn, or random.
Mat3 base_rotation(Rng& rng) {
  const int pick = rng.integer(0, 3);
  if (pick == 0) return Mat3::Identity();
  if (pick == 1) return exact_turn(rng.integer(0, 23));
  return rng.rotation().toRotationMatrix();
}

/// A shape of the kind with sizes in [0.2, 2] (log-uniform). `thin`: flat along local z (a
/// disc, a pancake, a flat box with a zero or tiny half extent, a needle capsule or cone).
CurvedShape random_shape(CurvedKind kind, Rng& rng, bool thin) {
  auto len = [&] { return rng.log_uniform(0.2, 2); };
  auto sliver = [&](double of) {
    return rng.chance(0.25) ? 0.0 : of * rng.log_uniform(1e-6, 1e-2);
  };
  switch (kind) {
    case CurvedKind::Sphere:
      return make_shape(kind, len(), 0, Vec3::Zero());
    case CurvedKind::Box: {
      Vec3 e(len(), len(), len());
      // Flat mostly across the stacking axis z; sometimes a blade standing on x or y.
      if (thin) e[rng.chance(0.7) ? 2 : rng.integer(0, 1)] = sliver(e.maxCoeff());
      return make_shape(kind, 0, 0, e);
    }
    case CurvedKind::Capsule: {
      double r = rng.log_uniform(0.1, 1), h = len();
      if (thin)
        (rng.chance(0.5) ? h : r) = rng.chance(0.5) ? 0.0 : 0.3 * rng.log_uniform(1e-6, 1e-2);
      if (r == 0 && h == 0) r = 0.5;
      return make_shape(kind, r, h, Vec3::Zero());
    }
    case CurvedKind::Cylinder:
    case CurvedKind::Cone: {
      double r = len(), h = len();
      if (thin) {
        if (kind == CurvedKind::Cone && rng.chance(0.3))
          r = r * rng.log_uniform(1e-6, 1e-2);  // a needle
        else
          h = sliver(r);
      }
      return make_shape(kind, r, h, Vec3::Zero());
    }
    case CurvedKind::Ellipsoid: {
      Vec3 e(len(), len(), len());
      if (thin) e.z() = e.maxCoeff() * rng.log_uniform(1e-6, 1e-2);
      return make_shape(kind, 0, 0, e);
    }
  }
  return {};
}

/// Scales every length of a shape.
CurvedShape scaled(CurvedShape s, double k) {
  s.radius = static_cast<double>(s.radius) * k;
  s.half_height = static_cast<double>(s.half_height) * k;
  s.extents = widen(Vec3(s.extents.cast<double>() * k));
  return s;
}

/// Support value of the shape at rotation r (no translation) along world direction d.
double reach(const CurvedShape& s, const Mat3& r, const Vec3& d) {
  return static_cast<double>(oracle::local_support(s, widen(Mat3(r.transpose())) * widen(d)));
}

/// Extent of the shape along its own axis, either way (z for all six kinds).
double axial_reach(const CurvedShape& s) {
  return static_cast<double>(oracle::local_support(s, V3::UnitZ()));
}

enum class Config {
  CoaxialInside,
  CoaxialStack,
  ExactTurns,
  ParallelOffset,
  Perpendicular,
  Random,
  Far
};
constexpr int kConfigs = 7;
constexpr std::array<const char*, kConfigs> kConfigNames = {"coaxial, one inside the other",
                                                            "coaxial stacks",
                                                            "exact 90/180 degree turns",
                                                            "parallel axes, offset",
                                                            "perpendicular axes",
                                                            "random poses",
                                                            "1e3 from the origin"};

struct Case {
  CurvedShape a, b;
  Pose pose_a, pose_b;
};

/// B placed from A along unit d: at `fraction` of the distance at which their supports along d
/// would just touch (0 = centres together, 1 = touching planes), so that fractions below 1
/// overlap along d.
Vec3 along(const Case& c, const Vec3& d, double fraction) {
  const double span = reach(c.a, c.pose_a.rotation, d) + reach(c.b, c.pose_b.rotation, -d);
  return c.pose_a.translation + fraction * span * d;
}

Case make_case(Config config, CurvedKind ka, CurvedKind kb, Rng& rng) {
  Case c;
  if (config == Config::Far) {
    // One of the others, then both moved 1e3 away (translations rounded to double once more).
    c = make_case(static_cast<Config>(rng.integer(0, kConfigs - 2)), ka, kb, rng);
    const Vec3 far = 1e3 * rng.unit();
    c.pose_a.translation += far;
    c.pose_b.translation += far;
    return c;
  }
  const bool thin = config == Config::CoaxialStack;
  c.a = random_shape(ka, rng, thin && rng.chance(0.5));
  c.b = random_shape(kb, rng, thin && rng.chance(0.5));
  const Mat3 q = base_rotation(rng);
  const Vec3 axis = q.col(2);
  c.pose_a.rotation = q;
  c.pose_a.translation = rng.in_ball(1);
  switch (config) {
    case Config::CoaxialInside: {
      // The smaller one (B, or A a third of the time) shrunk to 0.05..0.6 of the other's size,
      // its centre on the common axis near the other's centre.
      const bool a_inside = rng.chance(1.0 / 3);
      CurvedShape& inner = a_inside ? c.a : c.b;
      const CurvedShape& outer = a_inside ? c.b : c.a;
      inner = scaled(inner,
                     rng.uniform(0.05, 0.6) * static_cast<double>(oracle::bounding_radius(outer) /
                                                                  oracle::bounding_radius(inner)));
      c.pose_b.rotation = q * spin(rng) * (rng.chance(0.5) ? flip() : Mat3::Identity());
      const double slack = std::min(axial_reach(c.a), axial_reach(c.b));
      c.pose_b.translation = c.pose_a.translation + rng.uniform(-0.3, 0.3) * slack * axis;
      break;
    }
    case Config::CoaxialStack: {
      // B on top of A (or below), overlapping along the axis by 1e-6..0.1 of the size, a third
      // of the time shifted sideways by up to half the smaller cross-section.
      c.pose_b.rotation = q * spin(rng) * (rng.chance(0.5) ? flip() : Mat3::Identity());
      const Vec3 d = rng.chance(0.5) ? axis : Vec3(-axis);
      const double span = reach(c.a, c.pose_a.rotation, d) + reach(c.b, c.pose_b.rotation, -d);
      const double size = static_cast<double>(size_of(c.a, c.b));
      const double overlap = std::min(0.9 * span, size * rng.log_uniform(1e-6, 0.1));
      c.pose_b.translation = c.pose_a.translation + (span - overlap) * d;
      if (rng.chance(1.0 / 3)) {
        const Vec3 side = q * about(rng.uniform(0, 2 * kPi), Vec3::UnitZ()) * Vec3::UnitX();
        const double room =
            std::min(reach(c.a, c.pose_a.rotation, side), reach(c.b, c.pose_b.rotation, side));
        c.pose_b.translation += rng.uniform(0, 0.5) * room * side;
      }
      break;
    }
    case Config::ExactTurns: {
      // Both exact (entries 0, +-1), or B turned by 90 or 180 degrees through a quaternion (what
      // a caller writes; exact to rounding). B along a world axis half of the time.
      c.pose_a.rotation = exact_turn(rng.integer(0, 23));
      if (rng.chance(2.0 / 3)) {
        c.pose_b.rotation = exact_turn(rng.integer(0, 23));
      } else {
        const Vec3 turn_axis = Vec3::Unit(rng.integer(0, 2));
        c.pose_b.rotation =
            Pose::from(Vec3::Zero(),
                       mink::Quat(Eigen::AngleAxisd(rng.chance(0.5) ? kPi / 2 : kPi, turn_axis)))
                .rotation;
      }
      const Vec3 d = rng.chance(0.5)
                         ? Vec3((rng.chance(0.5) ? 1 : -1) * Vec3::Unit(rng.integer(0, 2)))
                         : rng.unit();
      c.pose_b.translation = along(c, d, rng.uniform(0.2, 0.85));
      break;
    }
    case Config::ParallelOffset: {
      c.pose_b.rotation = q * spin(rng) * (rng.chance(0.5) ? flip() : Mat3::Identity());
      const Vec3 side = q * about(rng.uniform(0, 2 * kPi), Vec3::UnitZ()) * Vec3::UnitX();
      const double slack = std::min(axial_reach(c.a), axial_reach(c.b));
      c.pose_b.translation =
          along(c, side, rng.uniform(0.4, 0.9)) + rng.uniform(-0.2, 0.2) * slack * axis;
      break;
    }
    case Config::Perpendicular: {
      c.pose_b.rotation =
          q * about(rng.uniform(0, 2 * kPi), Vec3::UnitZ()) * quarter_turn_x() * spin(rng);
      c.pose_b.translation = along(c, rng.unit(), rng.uniform(0.2, 0.85));
      break;
    }
    case Config::Random:
      c.pose_a.rotation = rng.rotation().toRotationMatrix();
      c.pose_b.rotation = rng.rotation().toRotationMatrix();
      c.pose_b.translation = along(c, rng.unit(), rng.uniform(0, 0.85));
      break;
    case Config::Far:
      break;
  }
  return c;
}

std::string reproduction(const Case& c) {
  return "A = " + describe_shape(c.a) + " at " + describe_pose(c.pose_a) +
         "\n    B = " + describe_shape(c.b) + " at " + describe_pose(c.pose_b);
}

// ---- The oracle's own checks ----

TEST(CurvedOracle, SupportsMatchSampledSurfaces) {
  // h(u) is the maximum of u . x over the shape: no sampled point lies beyond it, and the best
  // sample comes within the sampling's reach (rims sampled 1e-3 rad apart, balls by 50,000
  // Fibonacci points about 0.016 rad apart: within 1e-4 of the size). Boxes against their corners,
  // exactly.
  const std::uint64_t base = 410000;
  for (int i = 0; i < 60; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const CurvedKind kind = kKinds[i % 6];
    const CurvedShape s = random_shape(kind, rng, i % 12 >= 6);
    std::vector<V3> points;
    auto circle = [&](Real radius, Real z, int n) {
      for (int k = 0; k < n; ++k) {
        const Real t = 2 * std::numbers::pi_v<Real> * k / n;
        points.push_back(V3(radius * std::cos(t), radius * std::sin(t), z));
      }
    };
    auto ball = [&](const V3& centre, const V3& radii) {
      for (int k = 0; k < 50000; ++k)
        points.push_back(centre +
                         radii.cwiseProduct(oracle::curved_detail::fibonacci_direction(k, 50000)));
    };
    const Real r = s.radius, h = s.half_height;
    switch (kind) {
      case CurvedKind::Sphere:
        ball(V3::Zero(), V3::Constant(r));
        break;
      case CurvedKind::Box:
        for (const V3& p : oracle::box_corners({s.extents, oracle::M3::Identity(), V3::Zero()}))
          points.push_back(p);
        break;
      case CurvedKind::Capsule:
        ball(V3(0, 0, -h), V3::Constant(r));
        ball(V3(0, 0, h), V3::Constant(r));
        break;
      case CurvedKind::Cylinder:
        circle(r, -h, 6283);
        circle(r, h, 6283);
        break;
      case CurvedKind::Cone:
        circle(r, -h, 6283);
        points.push_back(V3(0, 0, h));
        break;
      case CurvedKind::Ellipsoid:
        ball(V3::Zero(), s.extents);
        break;
    }
    const Real size = oracle::bounding_radius(s);
    const Real reach_tol = kind == CurvedKind::Box ? Real(1e-18) * size : Real(1e-4) * size;
    for (int k = 0; k < 20; ++k) {
      const V3 u = widen(rng.unit());
      const Real h_u = oracle::local_support(s, u);
      const Real best = oracle::support_of(points, u);
      EXPECT_GE(double(h_u - best), -1e-18 * double(size)) << oracle::kind_name(kind);
      EXPECT_LE(double(h_u - best), double(reach_tol)) << oracle::kind_name(kind);
    }
  }
}

TEST(CurvedOracle, SupportsMatchContactCheck) {
  // The world supports of contact_check.hpp (written separately) for the four shapes it has, to
  // 1e-15: the rotation matrix, rounded to double, is orthonormal only to about 1e-16, and the two
  // read it differently (a ball's image under it against a ball about the centre).
  Rng rng(420000);
  for (int i = 0; i < 200; ++i) {
    const RigidPose p = rigid(rng.pose(3));
    const V3 u = widen(rng.unit());
    const CurvedShape sphere = random_shape(CurvedKind::Sphere, rng, false);
    const CurvedShape box = random_shape(CurvedKind::Box, rng, false);
    const CurvedShape cyl = random_shape(CurvedKind::Cylinder, rng, false);
    const CurvedShape cap = random_shape(CurvedKind::Capsule, rng, false);
    EXPECT_NEAR(double(oracle::world_support(sphere, p, u)),
                double(oracle::sphere_support(p.translation, sphere.radius)(u)), 1e-15);
    EXPECT_NEAR(double(oracle::world_support(box, p, u)),
                double(oracle::box_support(oracle::world_box(box, p))(u)), 1e-15);
    EXPECT_NEAR(double(oracle::world_support(cyl, p, u)),
                double(oracle::cylinder_support(oracle::world_cylinder(cyl, p))(u)), 1e-15);
    EXPECT_NEAR(double(oracle::world_support(cap, p, u)),
                double(oracle::capsule_support(oracle::world_capsule(cap, p))(u)), 1e-15);
  }
}

/// Depth from the closed forms of penetration.hpp for the pairs that have one.
struct ClosedForm {
  bool known = false;
  Real depth = 0;
};

ClosedForm closed_form(const Case& c) {
  const RigidPose pa = rigid(c.pose_a), pb = rigid(c.pose_b);
  const CurvedKind ka = c.a.kind, kb = c.b.kind;
  using K = CurvedKind;
  if (ka == K::Sphere && kb == K::Sphere)
    return {true, oracle::sphere_sphere_penetration(pa.translation, c.a.radius, pb.translation,
                                                    c.b.radius)
                      .depth};
  if (ka == K::Box && kb == K::Box)
    return {
        true,
        oracle::box_box_penetration(oracle::world_box(c.a, pa), oracle::world_box(c.b, pb)).depth};
  if (ka == K::Sphere && kb == K::Box)
    return {true,
            oracle::sphere_box_penetration(pa.translation, c.a.radius, oracle::world_box(c.b, pb))
                .depth};
  if (ka == K::Sphere && kb == K::Cylinder)
    return {true, oracle::sphere_cylinder_penetration(pa.translation, c.a.radius,
                                                      oracle::world_cylinder(c.b, pb))
                      .depth};
  if ((ka == K::Capsule || ka == K::Sphere) && (kb == K::Capsule || kb == K::Sphere)) {
    auto capsule = [](const CurvedShape& s, const RigidPose& p) {
      return oracle::make_capsule(s.radius, s.kind == K::Sphere ? Real(0) : s.half_height,
                                  p.rotation, p.translation);
    };
    return {true, oracle::capsule_capsule_penetration(capsule(c.a, pa), capsule(c.b, pb)).depth};
  }
  return {};
}

TEST(CurvedOracle, MatchesClosedForms) {
  // Sphere-sphere, box-box (15 axes), sphere-box, sphere-cylinder, capsule-capsule and
  // sphere-capsule, in random and aligned poses, penetrating or apart (minus the distance).
  // 1e-13 of the size: the closed forms' own rounding (box axes normalised from cross products
  // in long double) is far below it.
  using K = CurvedKind;
  const std::array<std::pair<K, K>, 7> pairs = {{{K::Sphere, K::Sphere},
                                                 {K::Box, K::Box},
                                                 {K::Sphere, K::Box},
                                                 {K::Sphere, K::Cylinder},
                                                 {K::Capsule, K::Capsule},
                                                 {K::Sphere, K::Capsule},
                                                 {K::Capsule, K::Sphere}}};
  const std::uint64_t base = 430000;
  const int per_pair = sweep_count(12);
  for (int i = 0; i < per_pair * 7; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const auto [ka, kb] = pairs[i % 7];
    const Config config =
        std::array<Config, 4>{Config::Random, Config::ExactTurns, Config::CoaxialStack,
                              Config::Perpendicular}[(i / 7) % 4];
    Case c = make_case(config, ka, kb, rng);
    if (i % 5 == 0) c.pose_b.translation += 0.3 * rng.unit();  // often apart
    const ClosedForm expected = closed_form(c);
    ASSERT_TRUE(expected.known);
    const auto got = oracle::curved_depth(c.a, rigid(c.pose_a), c.b, rigid(c.pose_b));
    const Real size = size_of(c.a, c.b);
    if (ka == CurvedKind::Box && kb == CurvedKind::Box && expected.depth < 0) {
      // Apart, the 15 axes give the largest separation of projections, a lower bound on the
      // distance only.
      EXPECT_LE(double(got.depth), double(expected.depth) + 1e-13 * double(size))
          << reproduction(c);
    } else {
      EXPECT_NEAR(double(got.depth), double(expected.depth), 1e-13 * double(size))
          << reproduction(c);
    }
    EXPECT_NEAR(double(got.normal.norm()), 1, 1e-18);
    EXPECT_EQ(difference_support(c.a, c.pose_a, c.b, c.pose_b, got.normal), got.depth);
  }
}

TEST(CurvedOracle, MatchesConeAndEllipsoidClosedForms) {
  // A sphere centred on a cone's axis: inside, the nearest boundary is the base (z + h below the
  // centre) or the slanted side, (h - z) r / sqrt(r^2 + 4 h^2) away, and the depth is the
  // sphere's radius plus the nearer; above the apex or below the base, the radius minus the gap.
  // A sphere centred on an ellipsoid's centre: the radius plus the least semi-axis; on its x axis
  // beyond the vertex: the radius minus the gap to the vertex.
  Rng rng(440000);
  for (int i = 0; i < 40; ++i) {
    SCOPED_TRACE(testing::Message() << "case " << i);
    const Pose pose = rng.pose(2);
    const CurvedShape cone = random_shape(CurvedKind::Cone, rng, false);
    const CurvedShape ball = random_shape(CurvedKind::Sphere, rng, false);
    const double r = double(cone.radius), h = double(cone.half_height), rs = double(ball.radius);
    const double z = rng.uniform(-1.5 * h, 1.5 * h);
    Pose at = Pose::from_translation(pose.apply(Vec3(0, 0, z)));
    double expected;
    if (z > h)
      expected = rs - (z - h);
    else if (z < -h)
      expected = rs - (-h - z);
    else
      expected = rs + std::min(z + h, (h - z) * r / std::sqrt(r * r + 4 * h * h));
    const double size = double(size_of(cone, ball));
    const double tol = 1e-13 * size;
    auto depth = [](const CurvedShape& a, const Pose& pa, const CurvedShape& b, const Pose& pb) {
      return double(oracle::curved_depth(a, rigid(pa), b, rigid(pb)).depth);
    };
    EXPECT_NEAR(depth(cone, pose, ball, at), expected, tol) << "cone first";
    EXPECT_NEAR(depth(ball, at, cone, pose), expected, tol) << "sphere first";
    const CurvedShape ell = random_shape(CurvedKind::Ellipsoid, rng, i % 2 == 1);
    const double ax = double(ell.extents.x());
    EXPECT_NEAR(depth(ell, pose, ball, Pose::from_translation(pose.translation)),
                rs + double(ell.extents.minCoeff()), tol);
    const double beyond = rng.uniform(0, 0.5);
    EXPECT_NEAR(depth(ball, Pose::from_translation(pose.apply(Vec3(ax + beyond, 0, 0))), ell, pose),
                rs - beyond, tol);
  }
}

TEST(CurvedOracle, SymmetricAndInvariant) {
  // Swapping A and B negates the normal and keeps the depth; turning and moving both shapes by
  // one rigid motion (built in long double) turns the normal and keeps the depth. Every kind,
  // with no closed form to lean on: the search must find the same minimum from different grids.
  const std::uint64_t base = 450000;
  for (int i = 0; i < 36; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const Case c = make_case(static_cast<Config>(i % 6), kKinds[i % 6], kKinds[i / 6], rng);
    const RigidPose pa = rigid(c.pose_a), pb = rigid(c.pose_b);
    const auto ab = oracle::curved_depth(c.a, pa, c.b, pb);
    const auto ba = oracle::curved_depth(c.b, pb, c.a, pa);
    const double size = double(size_of(c.a, c.b));
    EXPECT_NEAR(double(ab.depth), double(ba.depth), 1e-13 * size) << reproduction(c);
    const mink::Quat q = rng.rotation();
    const RigidPose motion =
        RigidPose::from(widen(rng.in_ball(5)), Eigen::Quaternion<Real>(q.w(), q.x(), q.y(), q.z()));
    auto moved = [&](const RigidPose& p) {
      return RigidPose{motion.rotation * p.rotation,
                       motion.rotation * p.translation + motion.translation};
    };
    const auto m = oracle::curved_depth(c.a, moved(pa), c.b, moved(pb));
    EXPECT_NEAR(double(m.depth), double(ab.depth), 1e-13 * size) << reproduction(c);
  }
}

// ---- The sweep ----

struct Tally {
  int cases = 0, pass = 0, flagged = 0, silent = 0, bound_short = 0, oracle_miss = 0, skipped = 0;
  int redrawn = 0;      ///< draws replaced because they did not penetrate
  int flagged_off = 0;  ///< flagged cases whose error exceeds the tolerance (covered by the bound)
  double worst_flagged = 0;           ///< largest error / size among flagged cases
  std::string worst_flagged_account;  ///< and its reproduction
  double worst_pass = 0;              ///< largest error / size among passing cases
};

/// Full-precision account of one case for a failure or a flagged line.
std::string account(const Case& c, const oracle::CurvedDepth& expected,
                    const mink::ContactResult& r, double error, double optimality, double size) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "\n    oracle depth %.17g normal (%.17g, %.17g, %.17g); size %.17g"
                "\n    |depth - oracle| = %.3g (%.3g of the size), h_{A-B}(normal) - depth = %.3g"
                "\n    mink: ",
                double(expected.depth), double(expected.normal.x()), double(expected.normal.y()),
                double(expected.normal.z()), size, error, error / size, optimality);
  return "\n    " + reproduction(c) + buffer + oracle::describe(r);
}

/// Touching or apart: the depth and the normal are ambiguous (any normal is as good at depth 0).
bool penetrating(const Case& c, const oracle::CurvedDepth& expected) {
  return expected.depth >= Real(1e-7) * size_of(c.a, c.b);
}

void judge(const Case& c, const oracle::CurvedDepth& expected, const std::string& label,
           Tally& tally) {
  const Real size_l = size_of(c.a, c.b);
  const double size = double(size_l);
  if (!penetrating(c, expected)) {
    ++tally.skipped;
    return;
  }
  ++tally.cases;
  const mink::ContactResult r = run_contact(c.a, c.pose_a, c.b, c.pose_b);
  const double tol = 1e-9 * size;
  const bool finite = oracle::all_finite(r);
  const Real h_normal =
      finite ? difference_support(c.a, c.pose_a, c.b, c.pose_b, widen(r.normal)) : Real(0);
  const double depth_error = finite ? std::abs(r.depth - double(expected.depth)) : INFINITY;
  const double optimality = finite ? double(h_normal - Real(r.depth)) : INFINITY;
  const double error = std::max(depth_error, optimality);
  // A normal below the oracle's minimum means the oracle's search missed: a bug of the test.
  if (finite && h_normal < expected.depth - Real(1e-13) * size_l) {
    ++tally.oracle_miss;
    ADD_FAILURE() << label << ": the oracle missed its minimum (mink's normal gives "
                  << double(h_normal) << ")"
                  << account(c, expected, r, depth_error, optimality, size);
    return;
  }
  if (r.status == mink::Status::IterationLimit) {
    if (error <= r.error_bound + tol) {
      ++tally.flagged;
      if (error > tol) {
        ++tally.flagged_off;
        std::printf("[ off      ] %s: %.3g of the size%s\n", label.c_str(), error / size,
                    account(c, expected, r, depth_error, optimality, size).c_str());
      }
      if (error / size >= tally.worst_flagged) {
        tally.worst_flagged = error / size;
        tally.worst_flagged_account =
            label + account(c, expected, r, depth_error, optimality, size);
      }
      return;
    }
    ++tally.bound_short;
    ADD_FAILURE() << label << ": iteration_limit, but error_bound does not cover the error"
                  << account(c, expected, r, depth_error, optimality, size);
    return;
  }
  if (r.status == mink::Status::Intersecting && r.intersect && finite && error <= tol) {
    ++tally.pass;
    tally.worst_pass = std::max(tally.worst_pass, error / size);
    return;
  }
  ++tally.silent;
  ADD_FAILURE() << label << ": silent failure (status " << mink::to_string(r.status) << ")"
                << account(c, expected, r, depth_error, optimality, size);
}

TEST(CurvedOracleSweep, ContactMatchesOracle) {
  const std::uint64_t base = 5000000;
  const int per_pair = sweep_count(2);
  std::printf(
      "[ sweep    ] base seed %llu; case seed = base + 100000 config + 1000 pair + index; "
      "%d cases per ordered pair and configuration\n",
      static_cast<unsigned long long>(base), per_pair);
  std::array<Tally, kConfigs> tallies;
  for (int config = 0; config < kConfigs; ++config) {
    for (int pair = 0; pair < 36; ++pair)
      for (int i = 0; i < per_pair; ++i) {
        const std::uint64_t seed = base + 100000 * config + 1000 * pair + i;
        Rng rng(seed);
        // The placements aim at overlap but do not ensure it (two cones pointing opposite ways,
        // offset sideways, can miss): a draw that does not penetrate is replaced by the next
        // one of the same generator, so the case seed still reproduces the case.
        Case c;
        oracle::CurvedDepth expected;
        for (int draw = 0; draw < 5; ++draw) {
          c = make_case(static_cast<Config>(config), kKinds[pair / 6], kKinds[pair % 6], rng);
          expected = oracle::curved_depth(c.a, rigid(c.pose_a), c.b, rigid(c.pose_b));
          if (penetrating(c, expected)) break;
          ++tallies[config].redrawn;
        }
        const std::string label = std::string(kConfigNames[config]) + ", " +
                                  oracle::kind_name(c.a.kind) + " - " +
                                  oracle::kind_name(c.b.kind) + ", " + oracle::seed_note(seed);
        judge(c, expected, label, tallies[config]);
      }
    if (tallies[config].flagged > 0)
      std::printf("[ flagged  ] the worst of %d (%.3g of the size): %s\n", tallies[config].flagged,
                  tallies[config].worst_flagged, tallies[config].worst_flagged_account.c_str());
  }
  std::printf(
      "\n| configuration | cases | pass | flagged | flagged, off | silent | bound short | "
      "oracle miss | skipped | redrawn | worst pass |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto row = [](const char* name, const Tally& t) {
    std::printf("| %s | %d | %d | %d | %d | %d | %d | %d | %d | %d | %.2g |\n", name, t.cases,
                t.pass, t.flagged, t.flagged_off, t.silent, t.bound_short, t.oracle_miss, t.skipped,
                t.redrawn, t.worst_pass);
  };
  Tally total;
  for (int config = 0; config < kConfigs; ++config) {
    const Tally& t = tallies[config];
    row(kConfigNames[config], t);
    total.cases += t.cases, total.pass += t.pass, total.flagged += t.flagged;
    total.flagged_off += t.flagged_off;
    total.silent += t.silent, total.bound_short += t.bound_short;
    total.oracle_miss += t.oracle_miss, total.skipped += t.skipped, total.redrawn += t.redrawn;
    total.worst_pass = std::max(total.worst_pass, t.worst_pass);
  }
  row("all", total);
  std::printf("\n");
}

// ---- The distance sweep ----

mink::DistanceResult run_distance(const CurvedShape& a, const Pose& pa, const CurvedShape& b,
                                  const Pose& pb) {
  return with_mink_shape(a, [&](const auto& ma) {
    return with_mink_shape(b, [&](const auto& mb) { return mink::distance(ma, pa, mb, pb); });
  });
}

/// Distance from a world point to the posed shape (0 inside), in long double, from the shape's
/// definition: spheres, boxes and capsules by clamping; cylinders and cones as a rectangle and a
/// triangle in the (radial, axial) half-plane, which their symmetry about the axis makes exact;
/// ellipsoids by bisection on the multiplier t of the nearest point, x_i e_i^2 / (e_i^2 + t).
Real distance_to_shape(const CurvedShape& s, const Pose& pose, const V3& world) {
  const V3 x = widen(pose.rotation).transpose() * (world - widen(pose.translation));
  const Real r = s.radius, h = s.half_height, zero = 0;
  const Real rho = std::hypot(x.x(), x.y()), z = x.z();
  // Distance from (rho, z) to the segment from (r0, z0) to (r1, z1) of the half-plane.
  auto segment = [&](Real r0, Real z0, Real r1, Real z1) {
    const Real dr = r1 - r0, dz = z1 - z0, len2 = dr * dr + dz * dz;
    const Real t =
        len2 > 0 ? std::clamp(((rho - r0) * dr + (z - z0) * dz) / len2, zero, Real(1)) : zero;
    return std::hypot(rho - r0 - t * dr, z - z0 - t * dz);
  };
  switch (s.kind) {
    case CurvedKind::Sphere:
      return std::max(zero, x.norm() - r);
    case CurvedKind::Box:
      return (x.cwiseAbs() - s.extents).cwiseMax(zero).norm();
    case CurvedKind::Capsule:
      return std::max(zero, (x - V3(0, 0, std::clamp(z, -h, h))).norm() - r);
    case CurvedKind::Cylinder:
      return std::hypot(std::max(zero, rho - r), std::max(zero, std::abs(z) - h));
    case CurvedKind::Cone:  // the triangle (0, -h), (r, -h), (0, h)
      if (h > 0 && z >= -h && 2 * h * rho <= r * (h - z)) return 0;
      return std::min({segment(0, -h, r, -h), segment(r, -h, 0, h), segment(0, -h, 0, h)});
    case CurvedKind::Ellipsoid: {
      const V3& e = s.extents;
      if (x.cwiseQuotient(e).squaredNorm() <= 1) return 0;
      // sum (e_i x_i / (e_i^2 + t))^2 falls from above 1 at t = 0 to at most 1 at t = max e |x|.
      auto level = [&](Real t) {
        Real sum = 0;
        for (int i = 0; i < 3; ++i) sum += std::pow(e[i] * x[i] / (e[i] * e[i] + t), 2);
        return sum;
      };
      Real lo = 0, hi = e.maxCoeff() * x.norm();
      for (int i = 0; i < 400; ++i) {
        const Real mid = (lo + hi) / 2;
        if (!(mid > lo && mid < hi)) break;
        (level(mid) > 1 ? lo : hi) = mid;
      }
      V3 nearest;
      for (int i = 0; i < 3; ++i) nearest[i] = e[i] * e[i] * x[i] / (e[i] * e[i] + hi);
      return (x - nearest).norm();
    }
  }
  return 0;
}

TEST(CurvedOracle, PointDistancesMatchSearch) {
  // distance_to_shape against the oracle's search with B a point (a sphere of radius 0): minus its
  // depth is the distance of the point when apart, and 0 inside. Points around every kind, thin
  // ones included, up to twice its bounding radius from its centre, to 1e-13 of that radius.
  const std::uint64_t base = 460000;
  for (int i = 0; i < 60; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const CurvedShape s = random_shape(kKinds[i % 6], rng, i % 12 >= 6);
    const Pose pose = rng.pose(2);
    const double radius = double(oracle::bounding_radius(s));
    const Vec3 at = pose.translation + rng.in_ball(2 * radius);
    const CurvedShape point = make_shape(CurvedKind::Sphere, 0, 0, Vec3::Zero());
    const Real depth =
        oracle::curved_depth(s, rigid(pose), point, rigid(Pose::from_translation(at))).depth;
    EXPECT_NEAR(double(distance_to_shape(s, pose, widen(at))), double(std::max(Real(0), -depth)),
                1e-13 * radius)
        << describe_shape(s) << " at " << describe_pose(pose);
  }
}

/// A case of the contact sweep's generator with B moved along `direction` by `shift` until the
/// oracle's gap (minus its depth) is `target`.
struct Placement {
  Case c;                        ///< the final poses (B's translation rounded to double)
  oracle::CurvedDepth expected;  ///< the oracle at exactly those poses
  Vec3 direction = Vec3::UnitZ();
  const char* direction_name = "";
  Real shift = 0;         ///< B's translation minus the generator's, along direction
  double target = 0;      ///< the gap aimed at (0: touching)
  int band = 0;           ///< index into kBandNames, from the target
  bool on_target = true;  ///< the gap reached is within 1e-3 of the target, relative
                          ///< (touching: 2.5e-13 of the size)
  int oracle_calls = 0;   ///< full oracle searches spent (local refinements not counted)
};

constexpr int kBands = 6;
constexpr std::array<const char*, kBands> kBandNames = {
    "touching (0)", "1e-9 .. 1e-7", "1e-7 .. 1e-5", "1e-5 .. 1e-3", "1e-3 .. 1e-1", "1e-1 .. 1"};

/// B's pose moved by t along d (rounded to double once).
Pose shifted(const Pose& p, const Vec3& d, Real t) {
  Pose q = p;
  q.translation = (widen(p.translation) + t * widen(d)).cast<double>();
  return q;
}

/// Moves B along the unit direction until the oracle's depth is -target. The depth as a function
/// of the shift t, g(t) = min over u of h_{A-B}(u) - t d.u, is concave (a minimum of affine
/// functions) and falls without bound; beyond its largest root it falls strictly, so Newton's
/// steps t += (g + target) / d.u, started right of that root (at h_{A-B}(d) + target, where u = d
/// alone proves g <= -target), approach it from the right. With g(0) > 0 (the case penetrates)
/// there is no other root. The steps take the oracle's pattern search from the last minimiser; a
/// full search then checks the result and, if it finds a lower minimum, Newton goes on from it (at
/// most 4 full searches).
void place(Placement& p, const Vec3& d, double target) {
  using oracle::curved_detail::Probe;
  const Pose start = p.c.pose_b;
  const RigidPose pose_a = rigid(p.c.pose_a);
  const Real size = size_of(p.c.a, p.c.b);
  const Real want = target;
  const Real close = target > 0 ? Real(1e-3) * want : Real(2.5e-13) * size;
  const V3 dl = widen(d);
  const Real spacing = oracle::curved_detail::Grid::get().spacing;
  p.direction = d;
  p.target = target;
  Real t = oracle::DifferenceSupport(p.c.a, pose_a, p.c.b, rigid(start))(dl) + want;
  for (int search = 0;; ++search) {
    p.c.pose_b = shifted(start, d, t);
    p.expected = oracle::curved_depth(p.c.a, pose_a, p.c.b, rigid(p.c.pose_b));
    ++p.oracle_calls;
    p.shift = t;
    p.on_target = std::abs(p.expected.depth + want) <= close;
    if (p.on_target || search == 3) return;
    Probe probe{p.expected.normal, p.expected.depth};
    for (int step = 0; step < 40 && std::abs(probe.value + want) > close; ++step) {
      const Real slope = dl.dot(probe.u);
      if (!(slope > Real(1e-6))) break;  // not right of the root: let the full search decide
      t += (probe.value + want) / slope;
      const RigidPose pose_b = rigid(shifted(start, d, t));
      const oracle::DifferenceSupport f(p.c.a, pose_a, p.c.b, pose_b);
      const Real scale = (pose_a.translation - pose_b.translation).norm() + size;
      long evaluations = 0;
      probe = oracle::curved_detail::refine(f, f.axes(), {probe.u, f(probe.u)}, 2 * spacing,
                                            2 * spacing, oracle::curved_detail::kFineStep, scale,
                                            evaluations);
    }
  }
}

/// A separated or touching case: the contact sweep's case, redrawn like there until it
/// penetrates (so that B's path below crosses every gap exactly once), then B moved away along the
/// line of centres (40%), the oracle's normal there (20%), one of A's axes (20%; towards B) or a
/// random direction (20%), to a gap of 0 (a sixth of the cases) or 1e-9 to 1 of the size,
/// log-uniform. False when 5 draws do not penetrate.
bool make_separated_case(Config config, CurvedKind ka, CurvedKind kb, Rng& rng, Placement& p,
                         int& redrawn) {
  oracle::CurvedDepth start;
  for (int draw = 0;; ++draw) {
    if (draw == 5) return false;
    p.c = make_case(config, ka, kb, rng);
    start = oracle::curved_depth(p.c.a, rigid(p.c.pose_a), p.c.b, rigid(p.c.pose_b));
    ++p.oracle_calls;
    if (penetrating(p.c, start)) break;
    ++redrawn;
  }
  const Vec3 centres = p.c.pose_b.translation - p.c.pose_a.translation;
  const double size = double(size_of(p.c.a, p.c.b));
  const double pick = rng.uniform(0, 1);
  Vec3 d;
  if (pick < 0.4 && centres.norm() > 1e-6 * size) {
    d = centres.normalized();
    p.direction_name = "line of centres";
  } else if (pick < 0.6) {
    d = start.normal.cast<double>().normalized();
    p.direction_name = "the oracle's normal at the start";
  } else if (pick < 0.8) {
    d = p.c.pose_a.rotation.col(rng.integer(0, 2));
    if (d.dot(centres) < 0 || (d.dot(centres) == 0 && rng.chance(0.5))) d = -d;
    p.direction_name = "an axis of A";
  } else {
    d = rng.unit();
    p.direction_name = "a random direction";
  }
  const bool touching = rng.chance(1.0 / 6);
  const double target = touching ? 0.0 : size * rng.log_uniform(1e-9, 1);
  p.band = touching
               ? 0
               : std::clamp(1 + static_cast<int>(std::floor((std::log10(target / size) + 9) / 2)),
                            1, kBands - 1);
  place(p, d, target);
  return true;
}

double signed_distance(const mink::DistanceResult& r) {
  return r.distance;
}
double signed_distance(const mink::ContactResult& r) {
  return r.distance - r.depth;
}

bool all_finite(const mink::DistanceResult& r) {
  return std::isfinite(r.distance) && r.normal.allFinite() && r.point_a.allFinite() &&
         r.point_b.allFinite() && std::isfinite(r.error_bound);
}
bool all_finite(const mink::ContactResult& r) {
  return oracle::all_finite(r);
}

/// distance() leaves the normal and the points zero when it says Intersecting (touching here).
bool has_normal(const mink::DistanceResult& r) {
  return r.status != mink::Status::Intersecting;
}
bool has_normal(const mink::ContactResult&) {
  return true;
}

std::string describe(const mink::DistanceResult& r) {
  char buffer[640];
  std::snprintf(buffer, sizeof buffer,
                "status %s, intersect %d, distance %.17g, normal (%.17g, %.17g, %.17g), point_a "
                "(%.17g, %.17g, %.17g), point_b (%.17g, %.17g, %.17g), error_bound %.3g, "
                "iterations %d",
                mink::to_string(r.status), int(r.intersect), r.distance, r.normal.x(), r.normal.y(),
                r.normal.z(), r.point_a.x(), r.point_a.y(), r.point_a.z(), r.point_b.x(),
                r.point_b.y(), r.point_b.z(), r.error_bound, r.iterations);
  return buffer;
}
std::string describe(const mink::ContactResult& r) {
  return "intersect " + std::to_string(int(r.intersect)) + ", " + oracle::describe(r);
}

/// Errors of one result, absolute (unit: length) except `unit`. Those of the normal and the points
/// are 0 when the result has none.
struct DistanceErrors {
  double distance = 0;    ///< |distance (minus depth) - oracle distance|
  double optimality = 0;  ///< h_{A-B}(normal) + oracle distance: 0 for an optimal normal
  double support = 0;     ///< the points off A's support plane along the normal, B's along -normal
  double inside = 0;      ///< the points' distances to their shapes
  double points = 0;      ///< |point_b - point_a - distance normal|
  double unit = 0;        ///< ||normal| - 1|
  double max() const { return std::max({distance, optimality, support, inside, points}); }
};

struct QueryTally {
  int pass = 0, flagged = 0, flagged_off = 0, silent = 0, bound_short = 0, oracle_miss = 0;
  int touching_intersecting = 0;  ///< touching cases reported as intersecting (allowed)
  double worst_pass = 0;          ///< largest error / size among passing cases
  double worst_flagged = 0;
  std::string worst_flagged_account;
  int failures() const { return silent + bound_short + oracle_miss; }
};

struct DistanceTally {
  int cases = 0, touching = 0, off_target = 0, oracle_calls = 0;
  int skipped = 0, redrawn = 0;  ///< as in the contact sweep
  QueryTally distance, contact;
};

/// Full-precision account of one case and one result.
std::string distance_account(const Placement& p, const std::string& result, const DistanceErrors& e,
                             double size) {
  char buffer[1024];
  std::snprintf(
      buffer, sizeof buffer,
      "\n    B moved along %s (%.17g, %.17g, %.17g) by %.17g from the generator's pose; gap "
      "wanted %.17g"
      "\n    oracle distance %.17g normal (%.17g, %.17g, %.17g); size %.17g"
      "\n    errors / size: distance %.3g, h_{A-B}(normal) + oracle distance %.3g, support "
      "planes %.3g, points off their shapes %.3g, |point_b - point_a - distance normal| %.3g; "
      "||normal| - 1| %.3g"
      "\n    mink: ",
      p.direction_name, p.direction.x(), p.direction.y(), p.direction.z(), double(p.shift),
      p.target, double(-p.expected.depth), double(p.expected.normal.x()),
      double(p.expected.normal.y()), double(p.expected.normal.z()), size, e.distance / size,
      e.optimality / size, e.support / size, e.inside / size, e.points / size, e.unit);
  return "\n    " + reproduction(p.c) + buffer + result;
}

/// Judges a distance() or contact() result on a separated or touching case: the distance (for
/// contact(), distance minus depth) within 1e-9 of the size of the oracle's; the normal optimal,
/// h_{A-B}(normal) <= -oracle distance + 1e-9 size, and unit to 1e-12; point_a and point_b on
/// their shapes (within 1e-9 size of them, and of the support planes along +-normal) and
/// point_b - point_a = distance * normal. Status Separated, or Intersecting when the oracle's gap
/// is within mink's touching tolerance, 1e-12 of the size (plus the rounding of the positions).
/// Returns whether it failed.
template <class R>
bool judge_query(const Placement& p, const R& r, const std::string& label, QueryTally& tally) {
  const Case& c = p.c;
  const Real size_l = size_of(c.a, c.b);
  const double size = double(size_l), tol = 1e-9 * size;
  const Real oracle_distance = -p.expected.depth;
  const double position = std::max(c.pose_a.translation.cwiseAbs().maxCoeff(),
                                   c.pose_b.translation.cwiseAbs().maxCoeff());
  const bool may_touch = oracle_distance <= Real(1e-12) * size_l + Real(1e-15) * position;
  const bool finite = all_finite(r);
  DistanceErrors e;
  const double s = signed_distance(r);
  e.distance = finite ? std::abs(double(Real(s) - oracle_distance)) : INFINITY;
  Real h_normal = 0;
  const bool normal = finite && has_normal(r);
  if (normal) {
    const V3 n = widen(r.normal), pa = widen(r.point_a), pb = widen(r.point_b);
    const RigidPose rigid_a = rigid(c.pose_a), rigid_b = rigid(c.pose_b);
    h_normal = difference_support(c.a, c.pose_a, c.b, c.pose_b, n);
    e.optimality = double(h_normal - p.expected.depth);
    e.support = double(std::max(std::abs(n.dot(pa) - oracle::world_support(c.a, rigid_a, n)),
                                std::abs(n.dot(pb) + oracle::world_support(c.b, rigid_b, -n))));
    e.inside = double(
        std::max(distance_to_shape(c.a, c.pose_a, pa), distance_to_shape(c.b, c.pose_b, pb)));
    e.points = double((pb - pa - Real(s) * n).norm());
    e.unit = double(std::abs(n.norm() - 1));
  }
  const bool unit = e.unit <= 1e-12;
  const double error = finite ? e.max() : INFINITY;
  // A normal below the oracle's minimum means the oracle's search missed: a bug of the test.
  if (normal && h_normal < p.expected.depth - Real(1e-13) * size_l) {
    ++tally.oracle_miss;
    ADD_FAILURE() << label << ": the oracle missed its minimum (mink's normal gives "
                  << double(h_normal) << ")" << distance_account(p, describe(r), e, size);
    return true;
  }
  if (r.status == mink::Status::IterationLimit) {
    if (finite && unit && error <= r.error_bound + tol) {
      ++tally.flagged;
      if (error > tol) {
        ++tally.flagged_off;
        std::printf("[ off      ] %s: %.3g of the size\n", label.c_str(), error / size);
      }
      if (error / size >= tally.worst_flagged) {
        tally.worst_flagged = error / size;
        tally.worst_flagged_account = label + distance_account(p, describe(r), e, size);
      }
      return false;
    }
    ++tally.bound_short;
    ADD_FAILURE() << label << ": iteration_limit, but error_bound does not cover the error"
                  << distance_account(p, describe(r), e, size);
    return true;
  }
  const bool status = (r.status == mink::Status::Separated && !r.intersect) ||
                      (r.status == mink::Status::Intersecting && r.intersect && may_touch);
  if (status && finite && unit && error <= tol) {
    ++tally.pass;
    if (r.status == mink::Status::Intersecting) ++tally.touching_intersecting;
    tally.worst_pass = std::max(tally.worst_pass, error / size);
    return false;
  }
  ++tally.silent;
  ADD_FAILURE() << label << ": silent failure (status " << mink::to_string(r.status) << ")"
                << distance_account(p, describe(r), e, size);
  return true;
}

TEST(CurvedOracleSweep, DistanceMatchesOracle) {
  const std::uint64_t base = 6000000;
  const int per_pair = sweep_count(1);
  std::printf(
      "[ sweep    ] base seed %llu; case seed = base + 100000 config + 1000 pair + index; "
      "%d cases per ordered pair and configuration\n",
      static_cast<unsigned long long>(base), per_pair);
  std::array<DistanceTally, kConfigs> tallies;
  struct BandTally {
    int cases = 0, distance_pass = 0, distance_flagged = 0, distance_failed = 0;
    int contact_pass = 0, contact_flagged = 0, contact_failed = 0;
  };
  std::array<BandTally, kBands> bands;
  for (int config = 0; config < kConfigs; ++config) {
    DistanceTally& tally = tallies[config];
    for (int pair = 0; pair < 36; ++pair)
      for (int i = 0; i < per_pair; ++i) {
        const std::uint64_t seed = base + 100000 * config + 1000 * pair + i;
        Rng rng(seed);
        Placement p;
        const bool made = make_separated_case(static_cast<Config>(config), kKinds[pair / 6],
                                              kKinds[pair % 6], rng, p, tally.redrawn);
        tally.oracle_calls += p.oracle_calls;
        if (!made) {
          ++tally.skipped;
          continue;
        }
        const Real size = size_of(p.c.a, p.c.b);
        ++tally.cases;
        if (std::abs(p.expected.depth) <= Real(1e-12) * size) ++tally.touching;
        if (!p.on_target) {
          ++tally.off_target;
          std::printf("[ off      ] %s, %s - %s, %s: gap wanted %.3g, reached %.3g (of the size)\n",
                      kConfigNames[config], oracle::kind_name(p.c.a.kind),
                      oracle::kind_name(p.c.b.kind), oracle::seed_note(seed).c_str(),
                      p.target / double(size), double(-p.expected.depth / size));
        }
        const std::string label = std::string(kConfigNames[config]) + ", " +
                                  oracle::kind_name(p.c.a.kind) + " - " +
                                  oracle::kind_name(p.c.b.kind) + ", " + oracle::seed_note(seed);
        BandTally& band = bands[p.band];
        ++band.cases;
        const int distance_flagged = tally.distance.flagged,
                  contact_flagged = tally.contact.flagged;
        if (judge_query(p, run_distance(p.c.a, p.c.pose_a, p.c.b, p.c.pose_b),
                        label + ", distance()", tally.distance))
          ++band.distance_failed;
        else if (tally.distance.flagged > distance_flagged)
          ++band.distance_flagged;
        else
          ++band.distance_pass;
        if (judge_query(p, run_contact(p.c.a, p.c.pose_a, p.c.b, p.c.pose_b), label + ", contact()",
                        tally.contact))
          ++band.contact_failed;
        else if (tally.contact.flagged > contact_flagged)
          ++band.contact_flagged;
        else
          ++band.contact_pass;
      }
    for (const auto& [name, q] :
         {std::pair<const char*, const QueryTally&>{"distance()", tally.distance},
          {"contact()", tally.contact}})
      if (q.flagged > 0)
        std::printf("[ flagged  ] %s, the worst of %d (%.3g of the size): %s\n", name, q.flagged,
                    q.worst_flagged, q.worst_flagged_account.c_str());
  }
  auto table = [&](const char* query, QueryTally DistanceTally::*member) {
    std::printf(
        "\n%s\n| configuration | cases | touching | off target | pass | touching, intersecting | "
        "flagged | flagged, off | silent | bound short | oracle miss | skipped | redrawn | worst "
        "pass |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        query);
    auto row = [](const char* name, const DistanceTally& t, const QueryTally& q) {
      std::printf("| %s | %d | %d | %d | %d | %d | %d | %d | %d | %d | %d | %d | %d | %.2g |\n",
                  name, t.cases, t.touching, t.off_target, q.pass, q.touching_intersecting,
                  q.flagged, q.flagged_off, q.silent, q.bound_short, q.oracle_miss, t.skipped,
                  t.redrawn, q.worst_pass);
    };
    DistanceTally total;
    QueryTally& all = total.*member;
    for (int config = 0; config < kConfigs; ++config) {
      const DistanceTally& t = tallies[config];
      const QueryTally& q = t.*member;
      row(kConfigNames[config], t, q);
      total.cases += t.cases, total.touching += t.touching, total.off_target += t.off_target;
      total.skipped += t.skipped, total.redrawn += t.redrawn;
      all.pass += q.pass, all.touching_intersecting += q.touching_intersecting;
      all.flagged += q.flagged, all.flagged_off += q.flagged_off, all.silent += q.silent;
      all.bound_short += q.bound_short, all.oracle_miss += q.oracle_miss;
      all.worst_pass = std::max(all.worst_pass, q.worst_pass);
    }
    row("all", total, all);
  };
  table("distance()", &DistanceTally::distance);
  table("contact()", &DistanceTally::contact);
  std::printf(
      "\nby the gap wanted, relative to the size\n| gap / size | cases | distance(): pass | "
      "flagged | failed | contact(): pass | flagged | failed |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int b = 0; b < kBands; ++b)
    std::printf("| %s | %d | %d | %d | %d | %d | %d | %d |\n", kBandNames[b], bands[b].cases,
                bands[b].distance_pass, bands[b].distance_flagged, bands[b].distance_failed,
                bands[b].contact_pass, bands[b].contact_flagged, bands[b].contact_failed);
  int calls = 0, cases = 0;
  for (const DistanceTally& t : tallies) calls += t.oracle_calls, cases += t.cases;
  std::printf("\n%d full oracle searches for %d cases\n\n", calls, cases);
}

}  // namespace
