// clip_box_pair() (two boxes: features read off their axes, clipped in the reference box's frame)
// against clip_features() (general support features, in A's frame) on random box pairs: the same
// clipped points. The general path is the one the exact and property tests check against
// independent answers; this keeps the box path from drifting away from it. Covers Box and
// Rounded<Box>, the reference face on A and on B (boxes resting face to face, turned about the
// normal, where the larger face is the reference), a zero half extent, and edges parallel to 1e-7.
#include <gtest/gtest.h>

#include <random>

#include "mink/manifold/clip_box_pair.hpp"
#include "mink/mink.hpp"

namespace mink {
namespace {

struct Counts {
  int compared = 0, ref_on_a = 0, ref_on_b = 0;
};

template <class A, class B>
void expect_same_points(const A& a, const Pose& pa, const B& b, const Pose& pb, int k,
                        Counts& counts) {
  const Pose rel = pa.relative(pb);
  const double size = a.bounding_radius() + b.bounding_radius();
  const auto axis =
      detail::box_box_axis(detail::BoxCore<A>::half_extents(a), detail::BoxCore<B>::half_extents(b),
                           rel.rotation, rel.translation, 1e-9 * size);
  if (!(axis.overlap > 1e-9 * size)) return;
  const double min_depth = -1e-9 * size, slack = detail::kSideSlack * size;
  detail::ClippedPoints<double> box_path, general;
  detail::clip_box_pair(a, b, rel, axis.normal, 1e-3, min_depth, a.bounding_radius(),
                        b.bounding_radius(), slack, box_path);
  detail::clip_features(a, b, rel, axis.normal, 1e-3, min_depth, size, slack, general);
  if (general.count == 0) return;  // crossing edges: clip_box_pair adds their closest points
  ASSERT_EQ(box_path.count, general.count) << "case " << k;
  const double tol = 1e-12 * size;
  for (int i = 0; i < general.count; ++i) {
    bool found = false;
    for (int j = 0; j < box_path.count && !found; ++j)
      found = (box_path.on_a[j] - general.on_a[i]).norm() <= tol &&
              (box_path.on_b[j] - general.on_b[i]).norm() <= tol &&
              std::abs(box_path.planar[j].depth - general.planar[i].depth) <= tol;
    EXPECT_TRUE(found) << "case " << k << ": point " << general.on_a[i].transpose()
                       << " of the general path is not among the box path's";
  }
  // The reference is the face whose points are on it, seen from on_a: A's when on_a lie on A's
  // surface plane of the normal.
  ++counts.compared;
  const Vec3 n = axis.normal;
  const bool a_is_flat = std::abs(n.dot(general.on_a[0] - general.on_a[general.count - 1])) <= tol;
  const bool b_is_flat = std::abs(n.dot(general.on_b[0] - general.on_b[general.count - 1])) <= tol;
  counts.ref_on_a += a_is_flat && !b_is_flat;
  counts.ref_on_b += b_is_flat && !a_is_flat;
}

TEST(ClipBoxPair, SamePointsAsTheGeneralPath) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  auto rotation = [&] { return Quat(g(rng), g(rng), g(rng), g(rng)).normalized(); };
  Counts counts;
  for (int k = 0; k < 6000; ++k) {
    Vec3 ha(0.1 + u(rng), 0.1 + u(rng), 0.1 + u(rng)), hb(0.1 + u(rng), 0.1 + u(rng), 0.1 + u(rng));
    const int kind = k % 5;
    if (kind == 1) (k % 2 ? ha : hb)[k % 3] = 0;  // flat
    const Pose pa = Pose::from(Vec3(g(rng), g(rng), g(rng)), rotation());
    Pose pb = Pose::from(pa.translation + 0.8 * Vec3(g(rng), g(rng), g(rng)), rotation());
    if (kind == 2 || kind == 3) {
      // Resting on A's top face, turned about its normal (kind 3: by 1e-7 about a random axis
      // instead, nearly parallel edges).
      const Quat turn =
          kind == 2 ? Quat(Eigen::AngleAxisd(6 * u(rng), Vec3::UnitZ()))
                    : Quat(Eigen::AngleAxisd(1e-7, Vec3(g(rng), g(rng), g(rng)).normalized()));
      pb.rotation = pa.rotation * turn.toRotationMatrix();
      const Vec3 lateral(u(rng) - 0.5, u(rng) - 0.5, 0);
      pb.translation = pa.apply(Vec3(0, 0, ha.z() + hb.z() - 0.01) + lateral);
    }
    if (kind == 4) {
      expect_same_points(Rounded<Box>{Box{ha}, 0.1 * u(rng)}, pa,
                         Rounded<Box>{Box{hb}, 0.1 * u(rng)}, pb, k, counts);
    } else {
      expect_same_points(Box{ha}, pa, Box{hb}, pb, k, counts);
    }
    if (HasFatalFailure()) return;
  }
  // Not vacuous: most cases clip, with the reference face on either box.
  EXPECT_GT(counts.compared, 2000);
  EXPECT_GT(counts.ref_on_a, 200);
  EXPECT_GT(counts.ref_on_b, 200);
}

// Where the separating axis is an edge pair's cross product and both features are edges, the one
// manifold point is the edges' crossing seen along the normal, which lies inside both edges (the
// Minkowski difference's facet that the normal belongs to holds the origin's projection). Checked
// against the boxes' corners, not the box path's own steps: each point is its box's extreme point
// along the normal, lies on one of its box's edges (two coordinates at their extents), and the
// two are depth apart along the normal, on rotated, flat and rounded boxes.
TEST(ClipBoxPair, CrossingEdgesTouchAtTheirCommonPerpendicular) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  auto rotation = [&] { return Quat(g(rng), g(rng), g(rng), g(rng)).normalized(); };
  int checked = 0, rounded = 0;
  for (int k = 0; k < 4000; ++k) {
    Vec3 ha(0.1 + u(rng), 0.1 + u(rng), 0.1 + u(rng)), hb(0.1 + u(rng), 0.1 + u(rng), 0.1 + u(rng));
    if (k % 4 == 1) ha[k % 3] = 0;  // a flat box: a rectangle
    const double ra = k % 4 == 2 ? 0.2 * u(rng) : 0.0, rb = k % 4 == 2 ? 0.2 * u(rng) : 0.0;
    const Pose pa = Pose::from(Vec3(g(rng), g(rng), g(rng)) * 10, rotation());
    const Pose pb = Pose::from(pa.translation + 0.9 * Vec3(g(rng), g(rng), g(rng)), rotation());
    const Rounded<Box> a{Box{ha}, ra}, b{Box{hb}, rb};
    const Pose rel = pa.relative(pb);
    const double size = a.bounding_radius() + b.bounding_radius();
    const auto axis = detail::box_box_axis(ha, hb, rel.rotation, rel.translation, 1e-9 * size);
    if (axis.index < 6 || !(axis.overlap > 1e-6 * size)) continue;
    const ManifoldResult m = manifold(a, pa, b, pb);
    ASSERT_EQ(m.status, Status::Intersecting) << "case " << k;
    if (m.count != 1) continue;  // an edge within the tolerance of a face: clipped
    const Vec3 n = m.normal;
    double top_a = -1e300, low_b = 1e300;
    for (int c = 0; c < 8; ++c) {
      const Vec3 s((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1);
      top_a = std::max(top_a, n.dot(pa.apply(s.cwiseProduct(ha))));
      low_b = std::min(low_b, n.dot(pb.apply(s.cwiseProduct(hb))));
    }
    const double tol = 1e-12 * (size + pa.translation.norm());
    const ManifoldPoint& p = m.points[0];
    EXPECT_NEAR(n.dot(p.point_a), top_a + ra, tol) << "case " << k;
    EXPECT_NEAR(n.dot(p.point_b), low_b - rb, tol) << "case " << k;
    EXPECT_NEAR(p.depth, top_a - low_b + ra + rb, tol) << "case " << k;
    EXPECT_LE((p.point_a - p.point_b - p.depth * n).norm(), tol) << "case " << k;
    // On an edge of the core: two of the three local coordinates at their extents.
    auto on_an_edge = [&](const Vec3& local, const Vec3& h) {
      int at_extent = 0;
      for (int i = 0; i < 3; ++i) {
        EXPECT_LE(std::abs(local[i]), h[i] + tol) << "case " << k;
        at_extent += std::abs(std::abs(local[i]) - h[i]) <= tol;
      }
      return at_extent >= 2;
    };
    EXPECT_TRUE(on_an_edge(pa.inverse_apply(p.point_a - ra * n), ha)) << "case " << k;
    EXPECT_TRUE(on_an_edge(pb.inverse_apply(p.point_b + rb * n), hb)) << "case " << k;
    ++checked;
    rounded += ra > 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(rounded, 50);
}

}  // namespace
}  // namespace mink
