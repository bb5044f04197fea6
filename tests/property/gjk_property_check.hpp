/// @file gjk_property_check.hpp
// Shared by the gjk_property_*_test.cpp files, which split the sweep so that the 144 type pairs
// compile in parallel.
//
// Properties of distance() and intersect() on random pairs of every shape kind (static types and
// the run-time Shape path), checked with this suite's own support functions and membership tests
// (tests/property/shape_zoo.hpp), never with mink's:
//   - the witnesses lie on the shapes and on their support planes along the normal, which
//     brackets the true distance between -(h_A(n) + h_B(-n)) and |point_b - point_a|;
//   - swapping A and B flips the normal and keeps the distance;
//   - a rigid motion of both moves the points and normal with it and keeps the distance;
//   - intersect() agrees with distance(); no output is ever NaN;
//   - for pairs reported intersecting, no tested axis separates them.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "oracle/check.hpp"
#include "property/shape_zoo.hpp"

namespace property {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::V3;
using oracle::widen;

/// Support value of a posed shape along a world direction n.
inline Real world_support(const zoo::Desc& d, const Pose& pose, const V3& n) {
  return zoo::support_value(d, widen(pose.rotation).transpose() * n) +
         n.dot(widen(pose.translation));
}

/// Largest separation -(h_A(n) + h_B(-n)) over unit n: positive proves the shapes apart.
inline Real separation(const zoo::Desc& da, const Pose& pa, const zoo::Desc& db, const Pose& pb,
                       const V3& n) {
  return -(world_support(da, pa, n) + world_support(db, pb, V3(-n)));
}

inline Pose compose(const Pose& m, const Pose& p) {
  Pose r;
  r.rotation = m.rotation * p.rotation;
  r.translation = m.rotation * p.translation + m.translation;
  return r;
}

struct Stats {
  // Per kind (max over partners): worst certified distance error relative to size, and the
  // largest iteration count.
  std::array<double, zoo::kKindCount> certified{};
  std::array<int, zoo::kKindCount> iterations{};
  int separated = 0, intersecting = 0;
  void print(const char* name) const {
    std::printf("[  worst   ] %s: %d separated, %d intersecting pairs\n", name, separated,
                intersecting);
    for (int k = 0; k < zoo::kKindCount; ++k)
      std::printf(
          "[  worst   ]   %-17s certified distance error %.3g (relative), max iterations %d\n",
          zoo::kind_name(k), certified[k], iterations[k]);
  }
};

// Tolerances, relative to the pair's size (sum of bounding radii).
constexpr double kSupportTol = 1e-9;  // witness on its support plane, witness inside its shape
constexpr double kNormalTol = 1e-8;   // unit normal, when the distance exceeds 1e-3 of the size
constexpr double kPointTol = 1e-6;    // witnesses under swap and motion (ill-conditioned near
                                      // parallel features, so looser than the distance)
// On a curved surface (cylinder rim, cone rim, ellipsoid) GJK converges the *distance* to
// 1e-12 of the size, and the distance is quadratic in the direction there, so the normal and the
// witnesses are only good to about sqrt(1e-12 * size / distance), at most 3e-5 for the compared
// distances (> 1e-3 of the size): 1e-4 allows for that.
constexpr double kCurvedTol = 1e-4;

inline bool curved(int kind) {
  return kind == zoo::kCylinder || kind == zoo::kCone || kind == zoo::kEllipsoid ||
         kind == zoo::kRoundedCone;
}

/// Twelve fixed directions (the icosahedron's vertices) for the local search of lower bounds.
inline Vec3 icosahedron_direction(int k) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  const double c[12][3] = {{0, 1, g}, {0, -1, g}, {0, 1, -g}, {0, -1, -g},
                           {1, g, 0}, {-1, g, 0}, {1, -g, 0}, {-1, -g, 0},
                           {g, 0, 1}, {-g, 0, 1}, {g, 0, -1}, {-g, 0, -1}};
  return Vec3(c[k][0], c[k][1], c[k][2]).normalized();
}

inline void check_witnesses(const zoo::Desc& da, const Pose& pa, const zoo::Desc& db,
                            const Pose& pb, const mink::DistanceResult& r, double size,
                            Stats& stats) {
  const double scale = size + pa.translation.norm();
  const V3 n = widen(r.normal);
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-12) << "normal not unit (tolerance 1e-12)";
  const Real ha = world_support(da, pa, n), hb = world_support(db, pb, V3(-n));
  EXPECT_NEAR(r.normal.dot(r.point_a), double(ha), kSupportTol * scale)
      << "point_a off A's support plane along the normal";
  EXPECT_NEAR(-r.normal.dot(r.point_b), double(hb), kSupportTol * scale)
      << "point_b off B's support plane along -normal";
  EXPECT_NEAR((r.point_b - r.point_a).norm(), r.distance, 1e-10 * scale)
      << "|point_b - point_a| != distance";
  const auto in_a = zoo::distance_to(
      da, widen(pa.rotation).transpose() * (widen(r.point_a) - widen(pa.translation)));
  const auto in_b = zoo::distance_to(
      db, widen(pb.rotation).transpose() * (widen(r.point_b) - widen(pb.translation)));
  if (in_a) {
    EXPECT_LE(double(*in_a), kSupportTol* scale) << "point_a is not in A";
  }
  if (in_b) {
    EXPECT_LE(double(*in_b), kSupportTol* scale) << "point_b is not in B";
  }
  // Certified error: the true distance lies in [lower, upper]. Any unit direction gives a valid
  // lower bound -(h_A(n) + h_B(-n)); the reported normal's is loose when the normal is only
  // approximately optimal (curved or non-smooth shapes converge the distance faster than the
  // direction), so when the bracket is too wide, tighten it by a local search over directions
  // around the normal, with this suite's own support functions.
  const double upper = (r.point_b - r.point_a).norm();
  Real lower_bound = -(ha + hb);
  if ((r.distance - double(lower_bound)) / size > oracle::kDistanceTolerance) {
    V3 best = n;
    for (double step = 1e-3; step >= 1e-11; step *= 0.5) {
      for (int k = 0; k < 12; ++k) {
        const V3 trial = (best + Real(step) * widen(icosahedron_direction(k))).normalized();
        const Real bound = separation(da, pa, db, pb, trial);
        if (bound > lower_bound) {
          lower_bound = bound;
          best = trial;
        }
      }
    }
  }
  const double lower = double(lower_bound);
  const double err = std::max({r.distance - lower, upper - r.distance, 0.0}) / size;
  EXPECT_LE(err, oracle::kDistanceTolerance)
      << "distance " << r.distance << " not within [" << lower << ", " << upper << "]";
  stats.certified[da.kind] = std::max(stats.certified[da.kind], err);
  stats.certified[db.kind] = std::max(stats.certified[db.kind], err);
}

template <class A, class B>
void check_pair(const A& a, const zoo::Desc& da, const Pose& pa, const B& b, const zoo::Desc& db,
                const Pose& pb, const Pose& motion, oracle::Rng& rng, Stats& stats) {
  const double size = zoo::size_of(da) + zoo::size_of(db);
  const double band = oracle::kTouchingBand * size;
  const auto rab = mink::distance(a, pa, b, pb);
  const auto rba = mink::distance(b, pb, a, pa);
  const auto iab = mink::intersect(a, pa, b, pb);
  const auto iba = mink::intersect(b, pb, a, pa);
  ASSERT_FALSE(oracle::has_nan(rab)) << "NaN in distance(A, B)";
  ASSERT_FALSE(oracle::has_nan(rba)) << "NaN in distance(B, A)";
  ASSERT_NE(rab.status, mink::Status::InvalidInput) << rab.error;
  EXPECT_NE(rab.status, mink::Status::IterationLimit);
  EXPECT_NE(rba.status, mink::Status::IterationLimit);
  EXPECT_NE(iab.status, mink::Status::IterationLimit);
  stats.iterations[da.kind] = std::max(stats.iterations[da.kind], rab.iterations);
  stats.iterations[db.kind] = std::max(stats.iterations[db.kind], rab.iterations);

  // Swap symmetry.
  EXPECT_NEAR(rab.distance, rba.distance, 1e-10 * size) << "swap changed the distance";
  if (rab.distance > band) {
    EXPECT_FALSE(iab.intersect) << "intersect() says yes at distance " << rab.distance;
    EXPECT_FALSE(iba.intersect) << "intersect(B, A) says yes at distance " << rab.distance;
  }
  if (rab.intersect) {
    EXPECT_TRUE(iab.intersect) << "distance() says intersecting, intersect() does not";
    EXPECT_TRUE(iba.intersect) << "distance() says intersecting, intersect(B, A) does not";
    EXPECT_TRUE(rba.intersect || rba.distance <= band) << "swap changed the intersect flag";
  }

  if (rab.intersect) {
    ++stats.intersecting;
    EXPECT_EQ(rab.distance, 0.0);
    // No axis may separate intersecting shapes: the line of centres and random directions.
    std::vector<V3> axes{widen(Vec3(pb.translation - pa.translation))};
    for (int k = 0; k < 16; ++k) axes.push_back(widen(rng.unit()));
    for (const V3& axis : axes) {
      if (!(axis.norm() > 0)) continue;
      const Real s = separation(da, pa, db, pb, axis.normalized());
      EXPECT_LE(double(s), band) << "reported intersecting, but axis "
                                 << axis.normalized().cast<double>().transpose()
                                 << " separates them by " << double(s);
    }
    return;
  }
  ++stats.separated;
  EXPECT_EQ(rab.status, mink::Status::Separated);
  check_witnesses(da, pa, db, pb, rab, size, stats);
  check_witnesses(db, pb, da, pa, rba, size, stats);
  const double scale = size + pa.translation.norm();
  const bool any_curved = curved(da.kind) || curved(db.kind);
  const double normal_tol = any_curved ? kCurvedTol : kNormalTol;
  const double point_tol = any_curved ? kCurvedTol : kPointTol;
  if (rab.distance > 1e-3 * size) {
    EXPECT_LE((rab.normal + rba.normal).norm(), normal_tol) << "swap did not flip the normal";
    EXPECT_LE((rab.point_a - rba.point_b).norm(), point_tol * scale) << "swap moved point_a";
    EXPECT_LE((rab.point_b - rba.point_a).norm(), point_tol * scale) << "swap moved point_b";
  }

  // Rigid motion of both shapes.
  const Pose ma = compose(motion, pa), mb = compose(motion, pb);
  const auto rm = mink::distance(a, ma, b, mb);
  ASSERT_FALSE(oracle::has_nan(rm));
  EXPECT_NEAR(rm.distance, rab.distance, 1e-10 * scale) << "rigid motion changed the distance";
  if (rab.distance > 1e-3 * size && rm.status == mink::Status::Separated) {
    EXPECT_LE((rm.normal - motion.rotation * rab.normal).norm(), normal_tol)
        << "normal did not move with the shapes";
    const double mscale = scale + motion.translation.norm();
    EXPECT_LE((rm.point_a - motion.apply(rab.point_a)).norm(), point_tol * mscale)
        << "point_a did not move with the shapes";
    EXPECT_LE((rm.point_b - motion.apply(rab.point_b)).norm(), point_tol * mscale)
        << "point_b did not move with the shapes";
  }
}

/// Position of T among the alternatives of a variant, at compile time.
template <class T, class... Ts>
constexpr int index_in(std::variant<Ts...>*) {
  int i = 0, found = -1;
  ((std::is_same_v<T, Ts> ? (found = i, ++i) : ++i), ...);
  return found;
}

/// One random case of the sweeps: two shapes of the given kinds, their poses (B within reach of
/// A) and a rigid motion. The draws are sequenced one statement at a time so that a seed gives
/// the same case whatever order a compiler evaluates function arguments in.
struct Case {
  zoo::Desc da, db;
  Pose pa, pb, motion;
};

inline Case draw_case(oracle::Rng& rng, int ka, int kb) {
  Case c;
  c.da = zoo::random_desc(rng, ka, 1.0);
  c.db = zoo::random_desc(rng, kb, 1.0);
  c.pa = rng.pose(5);
  const double reach = zoo::size_of(c.da) + zoo::size_of(c.db);
  const Vec3 offset = rng.in_ball(1.2 * reach);
  c.pb = Pose::from(c.pa.translation + offset, rng.rotation());
  c.motion = rng.pose(20);
  return c;
}

/// The unordered pairs of kinds (ka <= kb), in a fixed order: check_pair() runs every query both
/// ways, so an unordered pair covers both ordered ones.
struct KindPair {
  int a, b;
};
inline constexpr int kUnorderedPairs = zoo::kKindCount * (zoo::kKindCount + 1) / 2;
inline constexpr KindPair unordered_pair(int index) {
  for (int a = 0; a < zoo::kKindCount; ++a) {
    const int row = zoo::kKindCount - a;  // pairs (a, a..kKindCount-1)
    if (index < row) return {a, a + index};
    index -= row;
  }
  return {0, 0};
}

/// The static-type sweep restricted to pairs whose A kind (the lower one) lies in [kFirst,
/// kLast]: every case keeps its seed, so the union of the ranges is the whole sweep. Unordered
/// pairs only: each file instantiates the queries once per ordered pair it needs, and with all
/// ordered pairs per file the three files instantiated 240 pairs of templates between them for
/// 144 distinct ones (most of CI's compile time).
template <int kFirst, int kLast>
void run_static_sweep() {
  const std::uint64_t base = 30000;
  const int n = oracle::sweep_count(3000);
  Stats stats;
  int share = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    oracle::Rng rng(seed);
    const KindPair kinds = unordered_pair(i % kUnorderedPairs);
    const int ka = kinds.a, kb = kinds.b;
    if (ka < kFirst || ka > kLast) continue;
    ++share;
    // Named references, not a structured binding: clang 14 cannot capture bindings in lambdas.
    const Case c = draw_case(rng, ka, kb);
    const zoo::Desc &da = c.da, &db = c.db;
    const Pose &pa = c.pa, &pb = c.pb, &motion = c.motion;
    SCOPED_TRACE(testing::Message() << oracle::seed_note(seed) << "\nA: " << da.describe()
                                    << "\nB: " << db.describe());
    const zoo::Static sa = zoo::make_static(da), sb = zoo::make_static(db);
    std::visit(
        [&](const auto& a) {
          // Instantiate check_pair only for this file's A kinds, against B kinds from A's on.
          constexpr int kKind =
              index_in<std::decay_t<decltype(a)>>(static_cast<zoo::Static*>(nullptr));
          if constexpr (kKind >= kFirst && kKind <= kLast)
            std::visit(
                [&](const auto& b) {
                  constexpr int kOther =
                      index_in<std::decay_t<decltype(b)>>(static_cast<zoo::Static*>(nullptr));
                  if constexpr (kOther >= kKind)
                    check_pair(a, da, pa, b, db, pb, motion, rng, stats);
                },
                sb);
        },
        sa);
  }
  stats.print("static shapes");
  // Both answers must be exercised; points, segments and triangles rarely meet at random poses,
  // so the files that pair them among themselves see 1 intersecting pair in 20 or fewer.
  EXPECT_GT(stats.separated, share / 4);
  EXPECT_GT(stats.intersecting, share / 40);
}

}  // namespace property
