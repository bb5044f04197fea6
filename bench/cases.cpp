#include "cases.hpp"

#include <cmath>
#include <random>

#include "hull.hpp"
#include "reference.hpp"

namespace mink_bench {

double ShapeDesc::bounding_radius() const {
  switch (kind) {
    case ShapeKind::Box:
      return half_extents.norm();
    case ShapeKind::Capsule:
      return radius + half_height;
    case ShapeKind::Sphere:
      return radius;
    case ShapeKind::Polytope: {
      double r = 0;
      for (const auto& p : points) r = std::max(r, p.norm());
      return r;
    }
  }
  return 0;
}

Eigen::Vector3d ShapeDesc::support(const Eigen::Vector3d& d) const {
  const Eigen::Vector3d unit = d.normalized();
  switch (kind) {
    case ShapeKind::Box:
      return {d.x() >= 0 ? half_extents.x() : -half_extents.x(),
              d.y() >= 0 ? half_extents.y() : -half_extents.y(),
              d.z() >= 0 ? half_extents.z() : -half_extents.z()};
    case ShapeKind::Capsule:
      return Eigen::Vector3d(0, 0, d.z() >= 0 ? half_height : -half_height) + radius * unit;
    case ShapeKind::Sphere:
      return radius * unit;
    case ShapeKind::Polytope: {
      std::size_t best = 0;
      for (std::size_t i = 1; i < points.size(); ++i)
        if (points[i].dot(d) > points[best].dot(d)) best = i;
      return points[best];
    }
  }
  return Eigen::Vector3d::Zero();
}

namespace {

class Rng {
 public:
  explicit Rng(unsigned long long seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * std::uniform_real_distribution<double>(0.0, 1.0)(engine_);
  }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  Eigen::Vector3d unit_vector() {
    std::normal_distribution<double> normal;
    Eigen::Vector3d v;
    do v = Eigen::Vector3d(normal(engine_), normal(engine_), normal(engine_));
    while (v.norm() < 1e-6);
    return v.normalized();
  }
  /// Uniformly distributed rotation (Shoemake's subgroup algorithm).
  Eigen::Matrix3d rotation() {
    const double u1 = uniform(0, 1), u2 = uniform(0, 2 * M_PI), u3 = uniform(0, 2 * M_PI);
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const Eigen::Quaterniond q(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2),
                               b * std::sin(u3));
    return q.normalized().toRotationMatrix();
  }

 private:
  std::mt19937_64 engine_;
};

ShapeDesc make_box(Rng& rng) {
  ShapeDesc s;
  s.kind = ShapeKind::Box;
  s.half_extents = {rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0)};
  for (int i = 0; i < 8; ++i)
    s.points.emplace_back(i & 1 ? s.half_extents.x() : -s.half_extents.x(),
                          i & 2 ? s.half_extents.y() : -s.half_extents.y(),
                          i & 4 ? s.half_extents.z() : -s.half_extents.z());
  // Corner i has bit 0 = +x, bit 1 = +y, bit 2 = +z; two outward triangles per face.
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  s.edges = collect_edges(s.triangles);
  return s;
}

ShapeDesc make_capsule(Rng& rng) {
  ShapeDesc s;
  s.kind = ShapeKind::Capsule;
  s.radius = rng.uniform(0.1, 0.5);
  s.half_height = rng.uniform(0.2, 1.0);
  return s;
}

ShapeDesc make_sphere(Rng& rng) {
  ShapeDesc s;
  s.kind = ShapeKind::Sphere;
  s.radius = rng.uniform(0.2, 1.0);
  return s;
}

/// n points on an ellipsoid with semi-axes in [0.5, 1]: all of them are vertices of the hull, so
/// every library sees the same n support candidates.
ShapeDesc make_polytope(Rng& rng, int n) {
  ShapeDesc s;
  s.kind = ShapeKind::Polytope;
  const Eigen::Vector3d axes(rng.uniform(0.5, 1.0), rng.uniform(0.5, 1.0), rng.uniform(0.5, 1.0));
  for (int i = 0; i < n; ++i) s.points.push_back(axes.cwiseProduct(rng.unit_vector()));
  // Centre on the mean of the points, which lies inside the hull: the local origin must be an
  // interior point (the overlapping pairs are built around it). Shifting keeps every point a
  // vertex of the hull.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : s.points) mean += p;
  mean /= n;
  for (auto& p : s.points) p -= mean;
  s.triangles = compute_hull(s.points);
  s.edges = collect_edges(s.triangles);
  return s;
}

ShapeDesc make_shape(Rng& rng, ShapeKind kind, int n) {
  switch (kind) {
    case ShapeKind::Box:
      return make_box(rng);
    case ShapeKind::Capsule:
      return make_capsule(rng);
    case ShapeKind::Sphere:
      return make_sphere(rng);
    case ShapeKind::Polytope:
      return make_polytope(rng, n);
  }
  return {};
}

/// World support point of shape s with rotation r and translation t.
Eigen::Vector3d world_support(const ShapeDesc& s, const Eigen::Matrix3d& r,
                              const Eigen::Vector3d& t, const Eigen::Vector3d& d) {
  return r * s.support(r.transpose() * d) + t;
}

Case make_case(const std::string& family, ShapeKind ka, ShapeKind kb, int n, bool intersecting,
               unsigned long long seed) {
  Rng rng(seed);
  Case c;
  c.family = family;
  c.intersecting = intersecting;
  // Primitives: one shape per pair. Polytopes: a pool of 16 per side (as a scene would reuse
  // meshes), cycled through by the pairs.
  const std::size_t pool_a = ka == ShapeKind::Polytope ? 16 : kPairsPerCase;
  const std::size_t pool_b = kb == ShapeKind::Polytope ? 16 : kPairsPerCase;
  for (std::size_t i = 0; i < pool_a; ++i) c.shapes_a.push_back(make_shape(rng, ka, n));
  for (std::size_t i = 0; i < pool_b; ++i) c.shapes_b.push_back(make_shape(rng, kb, n));
  for (std::size_t i = 0; i < kPairsPerCase; ++i) {
    PairPose p;
    p.a = static_cast<int>(i % pool_a);
    p.b = static_cast<int>((i * 5 + 3) % pool_b);
    p.rotation_a = rng.rotation();
    p.rotation_b = rng.rotation();
    p.translation_a = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
    p.axis = rng.unit_vector();
    const ShapeDesc& sa = c.shapes_a[p.a];
    const ShapeDesc& sb = c.shapes_b[p.b];
    const double size = sa.bounding_radius() + sb.bounding_radius();
    const Eigen::Vector3d on_a = world_support(sa, p.rotation_a, p.translation_a, p.axis);
    const Eigen::Vector3d on_b = world_support(sb, p.rotation_b, Eigen::Vector3d::Zero(), -p.axis);
    if (!intersecting) {
      // A plane normal to the axis separates the shapes by `gap`; the distance is at least that.
      const double gap = size * rng.log_uniform(1e-3, 0.3);
      p.translation_b =
          p.translation_a + (p.axis.dot(on_a - p.translation_a - on_b) + gap) * p.axis;
    } else {
      // Both shapes contain the same point, taken a fraction `inset` of the way from a boundary
      // point towards the centre (an interior point of every shape here): shallow to deep overlaps.
      const double inset = rng.log_uniform(1e-3, 0.5);
      const Eigen::Vector3d shared = on_a + inset * (p.translation_a - on_a);
      p.translation_b = shared - (1 - inset) * on_b;
    }
    c.pairs.push_back(p);
  }
  c.reference.assign(c.pairs.size(), 0.0L);
  for (std::size_t i = 0; i < c.pairs.size(); ++i)
    c.reference[i] = intersecting ? reference_depth(c, i) : reference_distance(c, i);
  return c;
}

std::vector<Case> generate() {
  struct Family {
    std::string name;
    ShapeKind a, b;
    int n;
  };
  std::vector<Family> families = {{"box-box", ShapeKind::Box, ShapeKind::Box, 0},
                                  {"capsule-capsule", ShapeKind::Capsule, ShapeKind::Capsule, 0}};
  for (int n : {8, 32, 128, 512})
    families.push_back(
        {"sphere-polytope" + std::to_string(n), ShapeKind::Sphere, ShapeKind::Polytope, n});
  for (int n : {8, 32, 128, 512})
    families.push_back({"polytope" + std::to_string(n) + "-polytope" + std::to_string(n),
                        ShapeKind::Polytope, ShapeKind::Polytope, n});
  // Last, so that the families above keep their seeds.
  families.push_back({"sphere-box", ShapeKind::Sphere, ShapeKind::Box, 0});
  std::vector<Case> cases;
  unsigned long long seed = 20240601;
  for (const auto& f : families)
    for (bool intersecting : {false, true})
      cases.push_back(make_case(f.name, f.a, f.b, f.n, intersecting, seed++));
  return cases;
}

}  // namespace

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases = generate();
  return cases;
}

}  // namespace mink_bench
