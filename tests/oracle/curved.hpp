/// @file curved.hpp
/// Penetration depth of posed spheres, boxes, capsules, cylinders, cones and ellipsoids, written
/// independently of mink (no mink header is included; only Eigen types are shared) and evaluated
/// in long double:
///   - each shape's support function h(u) = max over the shape of u . x in closed form, derived
///     from its geometry (a sum of simple sets, or the hull of an apex and a disc);
///   - the depth min over unit u of h_{A-B}(u) = h_A(u) + h_B(-u) by brute force: a Fibonacci
///     grid of 40,000 directions, then pattern search from the grid's lowest local minima and a
///     few directions the shapes single out (their axes and the cross products of those), with
///     the step shrunk to 1e-15 rad.
/// The convention is that of penetration.hpp: the minimiser is the normal from A towards B along
/// which B moves by `depth` to separate the shapes; when they are apart the minimum is minus their
/// distance. Every direction u gives an upper bound h_{A-B}(u) on the depth, so the result is an
/// upper bound that is exact once the search finds the global minimum. Cost: 50,000 to 100,000
/// support evaluations, 5 to 10 ms per pair.
///
/// Why pattern search converges on these non-smooth functions: h_{A-B} has kinks only where h_A
/// or h_B has one, i.e. on the great circles orthogonal to a shape axis (where the support point
/// of a box, cylinder or capsule jumps from one end of that axis to the other), on small circles
/// about a cone's axis (where it jumps between the apex and the base rim) and at the axes
/// themselves (a disc's centre). A kink whose two sides slope up steeply makes a narrow valley that
/// no fixed set of probe directions follows, so the search also probes along u x axis for every
/// shape axis: that is the tangent of each such circle through u, and it walks along the valley.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "oracle/analytic.hpp"
#include "oracle/penetration.hpp"

namespace oracle {

enum class CurvedKind { Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid };

inline const char* kind_name(CurvedKind kind) {
  switch (kind) {
    case CurvedKind::Sphere:
      return "Sphere";
    case CurvedKind::Box:
      return "Box";
    case CurvedKind::Capsule:
      return "Capsule";
    case CurvedKind::Cylinder:
      return "Cylinder";
    case CurvedKind::Cone:
      return "Cone";
    case CurvedKind::Ellipsoid:
      return "Ellipsoid";
  }
  return "?";
}

/// One of the six shapes in its local frame, centred at the origin, axis along local z:
///   - Sphere: `radius`;
///   - Box: half extents `extents` along the local axes;
///   - Capsule: the segment z in [-half_height, half_height] swept by a ball of `radius`;
///   - Cylinder: radius `radius`, z in [-half_height, half_height];
///   - Cone: base disc of `radius` at z = -half_height, apex at z = +half_height;
///   - Ellipsoid: semi-axes `extents` along the local axes.
struct CurvedShape {
  CurvedKind kind = CurvedKind::Sphere;
  Real radius = 0;
  Real half_height = 0;
  V3 extents = V3::Zero();
};

/// world = rotation * local + translation. The rotation need not be exactly orthonormal: the
/// support function below is exact for the image of the shape under any linear map, so a matrix
/// rounded to double is taken as the shape the caller meant.
struct RigidPose {
  M3 rotation = M3::Identity();
  V3 translation = V3::Zero();

  /// From a translation and a quaternion (normalised here), in long double.
  static RigidPose from(const V3& translation, const Eigen::Quaternion<Real>& q) {
    return {q.normalized().toRotationMatrix(), translation};
  }
};

/// Support function of the shape in its own frame; u need not be unit (h is positively
/// homogeneous).
inline Real local_support(const CurvedShape& s, const V3& u) {
  const Real rho = std::sqrt(u.x() * u.x() + u.y() * u.y());
  switch (s.kind) {
    case CurvedKind::Sphere:
      return s.radius * u.norm();
    case CurvedKind::Box:  // a sum of three segments
      return s.extents.x() * std::abs(u.x()) + s.extents.y() * std::abs(u.y()) +
             s.extents.z() * std::abs(u.z());
    case CurvedKind::Capsule:  // a segment plus a ball
      return s.half_height * std::abs(u.z()) + s.radius * u.norm();
    case CurvedKind::Cylinder:  // a segment plus a disc
      return s.half_height * std::abs(u.z()) + s.radius * rho;
    case CurvedKind::Cone:  // the hull of the apex and the base disc: the larger support
      return std::max(s.half_height * u.z(), s.radius * rho - s.half_height * u.z());
    case CurvedKind::Ellipsoid:  // the unit ball under D = diag(extents): h(u) = |D u|
      return s.extents.cwiseProduct(u).norm();
  }
  return 0;
}

/// A support point of the shape in its own frame along u (nonzero): the gradient of
/// local_support() where it has one; on a flat face or edge, the end or corner the signs of u pick.
/// Tests that build a pair with a known answer place the shapes by it.
inline V3 local_support_point(const CurvedShape& s, const V3& u) {
  const Real rho = std::sqrt(u.x() * u.x() + u.y() * u.y());
  const auto sign = [](Real x) { return x < 0 ? Real(-1) : Real(1); };
  const auto rim = [&](Real z) {
    return rho > 0 ? V3(s.radius * u.x() / rho, s.radius * u.y() / rho, z) : V3(0, 0, z);
  };
  switch (s.kind) {
    case CurvedKind::Sphere:
      return s.radius * u.normalized();
    case CurvedKind::Box:
      return V3(sign(u.x()) * s.extents.x(), sign(u.y()) * s.extents.y(),
                sign(u.z()) * s.extents.z());
    case CurvedKind::Capsule:
      return V3(0, 0, sign(u.z()) * s.half_height) + s.radius * u.normalized();
    case CurvedKind::Cylinder:
      return rim(sign(u.z()) * s.half_height);
    case CurvedKind::Cone:
      if (s.half_height * u.z() >= s.radius * rho - s.half_height * u.z())
        return V3(0, 0, s.half_height);
      return rim(-s.half_height);
    case CurvedKind::Ellipsoid: {
      const V3 scaled = s.extents.cwiseProduct(u);
      return s.extents.cwiseProduct(scaled) / scaled.norm();
    }
  }
  return V3::Zero();
}

/// Support function of the posed shape: h(u) = t . u + h_local(R^T u).
inline Real world_support(const CurvedShape& s, const RigidPose& p, const V3& u) {
  return p.translation.dot(u) + local_support(s, p.rotation.transpose() * u);
}

/// Radius of the smallest ball about the local origin that holds the shape.
inline Real bounding_radius(const CurvedShape& s) {
  switch (s.kind) {
    case CurvedKind::Sphere:
      return s.radius;
    case CurvedKind::Box:
      return s.extents.norm();
    case CurvedKind::Capsule:
      return s.radius + s.half_height;
    case CurvedKind::Cylinder:
    case CurvedKind::Cone:
      return std::sqrt(s.radius * s.radius + s.half_height * s.half_height);
    case CurvedKind::Ellipsoid:
      return s.extents.maxCoeff();
  }
  return 0;
}

/// h_{A-B}(u) = h_A(u) + h_B(-u), with the translations subtracted first so that pairs far from
/// the origin lose nothing to cancellation.
class DifferenceSupport {
 public:
  DifferenceSupport(const CurvedShape& a, const RigidPose& pa, const CurvedShape& b,
                    const RigidPose& pb)
      : a_(a),
        b_(b),
        offset_(pa.translation - pb.translation),
        inverse_a_(pa.rotation.transpose()),
        inverse_b_(pb.rotation.transpose()) {
    for (int i = 0; i < 3; ++i) axes_[i] = pa.rotation.col(i), axes_[3 + i] = pb.rotation.col(i);
  }

  Real operator()(const V3& u) const {
    return offset_.dot(u) + local_support(a_, inverse_a_ * u) +
           local_support(b_, -(inverse_b_ * u));
  }
  /// World axes of A then B: every kink of h_{A-B} lies on a circle about one of them.
  const std::array<V3, 6>& axes() const { return axes_; }

 private:
  CurvedShape a_, b_;
  V3 offset_;
  M3 inverse_a_, inverse_b_;
  std::array<V3, 6> axes_;
};

/// Least support value of A - B and the direction that attains it.
struct CurvedDepth {
  Real depth = 0;           ///< > 0 penetrating, < 0 apart (minus the distance)
  V3 normal = V3::UnitZ();  ///< unit, from A towards B: B moves by depth along it to separate
  long evaluations = 0;     ///< support evaluations of A - B spent (for the oracle's own tests)
};

namespace curved_detail {

/// A direction and its support value.
struct Probe {
  V3 u;
  Real value;
};

inline constexpr int kGridSize = 40000;
/// The lowest kSeeds local minima of the grid (one per basin; these pairs have a few) are refined
/// down to steps of kCoarseStep, and the kFinalists lowest of those on to kFineStep: by then the
/// order of the basins is settled, since a basin's coarse value is within about its slope times
/// 1e-6 rad of its minimum.
inline constexpr int kSeeds = 16;
inline constexpr int kFinalists = 4;
inline constexpr Real kCoarseStep = 1e-6L;
inline constexpr Real kFineStep = 1e-15L;
/// Generic probe directions per step, on top of the 12 along the kink circles.
inline constexpr int kProbeDirections = 16;

/// Fibonacci sphere: point i at height 1 - (2i + 1) / n, turned by the golden angle from the last.
inline V3 fibonacci_direction(int i, int n) {
  const Real golden_angle = std::numbers::pi_v<Real> * (3 - std::sqrt(Real(5)));
  const Real z = 1 - (2 * Real(i) + 1) / Real(n);
  const Real r = std::sqrt(std::max(Real(0), 1 - z * z));
  const Real phi = golden_angle * Real(i);
  return V3(r * std::cos(phi), r * std::sin(phi), z);
}

/// The direction grid with, for each direction, the others within 2.5 mean spacings (about 20):
/// built once, by a voxel hash of that cell size (only the 27 cells about a point can hold its
/// neighbours).
struct Grid {
  std::vector<V3> dirs;
  std::vector<int> first, neighbours;  ///< neighbours of i: [first[i], first[i + 1])
  Real spacing;                        ///< side of a square of area 4 pi / n

  static const Grid& get() {
    static const Grid grid(kGridSize);
    return grid;
  }

  explicit Grid(int n)
      : dirs(n), first(n + 1, 0), spacing(std::sqrt(4 * std::numbers::pi_v<Real> / n)) {
    for (int i = 0; i < n; ++i) dirs[i] = fibonacci_direction(i, n);
    const Real radius = Real(2.5) * spacing;
    const int cells = static_cast<int>(std::ceil(2 / radius)) + 1;
    auto cell = [&](Real x) {
      return std::clamp(static_cast<int>((x + 1) / radius), 0, cells - 1);
    };
    std::vector<int> head(static_cast<std::size_t>(cells) * cells * cells, -1), next(n, -1);
    for (int i = 0; i < n; ++i) {
      const int c = (cell(dirs[i].x()) * cells + cell(dirs[i].y())) * cells + cell(dirs[i].z());
      next[i] = head[c];
      head[c] = i;
    }
    for (int i = 0; i < n; ++i) {
      const int cx = cell(dirs[i].x()), cy = cell(dirs[i].y()), cz = cell(dirs[i].z());
      for (int x = std::max(0, cx - 1); x <= std::min(cells - 1, cx + 1); ++x)
        for (int y = std::max(0, cy - 1); y <= std::min(cells - 1, cy + 1); ++y)
          for (int z = std::max(0, cz - 1); z <= std::min(cells - 1, cz + 1); ++z)
            for (int j = head[(x * cells + y) * cells + z]; j >= 0; j = next[j])
              if (j != i && (dirs[j] - dirs[i]).squaredNorm() <= radius * radius)
                neighbours.push_back(j);
      first[i + 1] = static_cast<int>(neighbours.size());
    }
  }

  /// Directions whose value is below those of all their neighbours (ties broken by index, so
  /// that a plateau gives one), lowest first, at most `count`. One per basin of the values.
  std::vector<int> minima(const std::vector<Real>& values, int count) const {
    std::vector<int> out;
    const int n = static_cast<int>(dirs.size());
    for (int i = 0; i < n; ++i) {
      bool lowest = true;
      for (int k = first[i]; k < first[i + 1] && lowest; ++k) {
        const int j = neighbours[k];
        lowest = values[i] < values[j] || (values[i] == values[j] && i < j);
      }
      if (lowest) out.push_back(i);
    }
    std::sort(out.begin(), out.end(), [&](int x, int y) { return values[x] < values[y]; });
    if (static_cast<int>(out.size()) > count) out.resize(count);
    return out;
  }
};

/// Pattern search on the sphere from `p`, in the tangent plane of the current direction (two
/// angles about it, re-centred after every move, so no pole of a fixed chart gets in the way).
/// Each round probes u + step d for kProbeDirections directions d evenly spread (turned by the
/// golden angle each time the step shrinks, so that successive rounds do not repeat the same
/// bearings) and for +-(u x axis) for the six axes. It moves to the best probe when that is lower
/// by a sufficient decrease, 1e-4 scale step^2 (and at least 1e-17 scale, above rounding), and
/// doubles the step (up to `max_step`); else it halves the step. Stops below `min_step`. `scale`
/// is the magnitude of the values (lengths and offsets in them). Without the sufficient decrease
/// the search crawls: next to a kink circle, a full step along it gains a little every time (its
/// chord moves inwards) while the step that would cross to the circle is never tried; and where
/// a circle of directions ties (coaxial shapes), rounding alone makes some probe "lower".
template <class F>
Probe refine(const F& f, const std::array<V3, 6>& axes, Probe p, Real step, Real max_step,
             Real min_step, Real scale, long& evaluations) {
  // The ring of probe bearings, turned by rotating (cos, sin) pairs: the trigonometry of long
  // double costs more than a support evaluation.
  static const std::array<std::array<Real, 2>, kProbeDirections> ring = [] {
    std::array<std::array<Real, 2>, kProbeDirections> r;
    for (int i = 0; i < kProbeDirections; ++i) {
      const Real angle = 2 * std::numbers::pi_v<Real> * i / kProbeDirections;
      r[i] = {std::cos(angle), std::sin(angle)};
    }
    return r;
  }();
  const Real turn = std::numbers::pi_v<Real> * (3 - std::sqrt(Real(5)));
  const Real cos_turn = std::cos(turn), sin_turn = std::sin(turn);
  Real cos_bearing = 1, sin_bearing = 0;
  // A cap on rounds, far above the few hundred a search takes, in case the threshold misjudges.
  for (int round = 0; round < 20000 && step >= min_step; ++round) {
    // Tangent basis at u: the axis least aligned with u, made orthogonal to it.
    const V3 a = p.u;
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(a[i]) < std::abs(a[k])) k = i;
    const V3 e1 = a.cross(V3::Unit(k)).normalized();
    const V3 e2 = a.cross(e1);
    std::array<V3, kProbeDirections + 12> dirs;
    int count = 0;
    for (const auto& [c, s] : ring)
      dirs[count++] =
          (c * cos_bearing - s * sin_bearing) * e1 + (s * cos_bearing + c * sin_bearing) * e2;
    for (const V3& axis : axes) {
      const V3 t = a.cross(axis);
      const Real len = t.norm();
      if (!(len > Real(1e-12))) continue;  // u on the axis: the generic probes cover it
      dirs[count++] = t / len;
      dirs[count++] = -t / len;
    }
    Probe best = p;
    for (int i = 0; i < count; ++i) {
      const V3 u = (a + step * dirs[i]).normalized();
      const Real v = f(u);
      ++evaluations;
      if (v < best.value) best = {u, v};
    }
    if (best.value < p.value - std::max(Real(1e-17), Real(1e-4) * step * step) * scale) {
      p = best;
      step = std::min(2 * step, max_step);
    } else {
      step /= 2;
      const Real c = cos_bearing * cos_turn - sin_bearing * sin_turn;
      sin_bearing = sin_bearing * cos_turn + cos_bearing * sin_turn;
      cos_bearing = c;
    }
  }
  return p;
}

}  // namespace curved_detail

/// Penetration depth of A at pose_a and B at pose_b: min over unit u of h_A(u) + h_B(-u), with
/// the direction that attains it (see the file comment for the method and the conventions).
/// Defined in curved.cpp, one optimized copy for every test: as an inline function, the linker
/// kept the copy of the first test file that used it, which was compiled at -O0 (tests/
/// CMakeLists.txt, mink_quick_tests_at_O0), and every search ran 30 times slower (50 s for the
/// five of ContactEpaBudget).
CurvedDepth curved_depth(const CurvedShape& a, const RigidPose& pose_a, const CurvedShape& b,
                         const RigidPose& pose_b);

/// The posed shapes as the closed-form oracles of analytic.hpp and penetration.hpp take them
/// (for the oracle's own tests).
inline WorldBox world_box(const CurvedShape& s, const RigidPose& p) {
  return {s.extents, p.rotation, p.translation};
}
inline WorldCylinder world_cylinder(const CurvedShape& s, const RigidPose& p) {
  return {s.radius, s.half_height, p.rotation, p.translation};
}
inline WorldCapsule world_capsule(const CurvedShape& s, const RigidPose& p) {
  return make_capsule(s.radius, s.half_height, p.rotation, p.translation);
}

}  // namespace oracle
