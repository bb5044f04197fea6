// The oracle's search (curved.hpp), compiled once for every test executable.
#include "oracle/curved.hpp"

#include <algorithm>
#include <vector>

namespace oracle {

CurvedDepth curved_depth(const CurvedShape& a, const RigidPose& pose_a, const CurvedShape& b,
                         const RigidPose& pose_b) {
  using namespace curved_detail;
  const DifferenceSupport f(a, pose_a, b, pose_b);
  CurvedDepth out;
  const Real scale =
      (pose_a.translation - pose_b.translation).norm() + bounding_radius(a) + bounding_radius(b);
  const Grid& grid = Grid::get();
  std::vector<Real> values(kGridSize);
  for (int i = 0; i < kGridSize; ++i) values[i] = f(grid.dirs[i]);
  out.evaluations += kGridSize;
  // Seeds: the grid's local minima, each refined from steps of 2 spacings.
  const Real spacing = grid.spacing;
  std::vector<Probe> seeds;
  for (const int i : grid.minima(values, kSeeds)) seeds.push_back({grid.dirs[i], values[i]});
  // Directions the shapes single out, where aligned poses put exact minima (a face or a cap
  // normal, an edge-edge normal, the line of centres): the best four become seeds too.
  std::vector<Probe> special;
  auto add_special = [&](const V3& u) {
    const Real len = u.norm();
    if (!(len > Real(1e-9))) return;
    for (const Real sign : {Real(1), Real(-1)}) {
      const V3 unit = sign * u / len;
      special.push_back({unit, f(unit)});
      ++out.evaluations;
    }
  };
  const auto& axes = f.axes();
  for (int i = 0; i < 6; ++i) add_special(axes[i]);
  for (int i = 0; i < 3; ++i)
    for (int j = 3; j < 6; ++j) add_special(axes[i].cross(axes[j]));
  add_special(pose_b.translation - pose_a.translation);
  std::sort(special.begin(), special.end(),
            [](const Probe& x, const Probe& y) { return x.value < y.value; });
  for (std::size_t i = 0; i < std::min<std::size_t>(4, special.size()); ++i)
    seeds.push_back(special[i]);
  // Coarse refinement of every seed, then the few best to the end.
  for (Probe& s : seeds)
    s = refine(f, axes, s, 2 * spacing, 2 * spacing, kCoarseStep, scale, out.evaluations);
  std::sort(seeds.begin(), seeds.end(),
            [](const Probe& x, const Probe& y) { return x.value < y.value; });
  Probe best = seeds.front();
  for (std::size_t i = 0; i < std::min<std::size_t>(kFinalists, seeds.size()); ++i) {
    const Probe p =
        refine(f, axes, seeds[i], 2 * kCoarseStep, 2 * spacing, kFineStep, scale, out.evaluations);
    if (p.value < best.value) best = p;
  }
  out.depth = best.value;
  out.normal = best.u;
  return out;
}

}  // namespace oracle
