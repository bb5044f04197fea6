// Temporally coherent queries: a GjkCache carried from one frame to the next starts GJK from the
// previous simplex, which usually saves most of the iterations.
#include <mink/mink.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  using namespace mink;
  std::vector<Vec3> points;
  for (int i = 0; i < 64; ++i) {  // points on a sphere of radius 1 (a golden-angle spiral)
    const double z = 1.0 - (i + 0.5) / 32.0, r = std::sqrt(1.0 - z * z), phi = 2.39996323 * i;
    points.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  const auto made = Polytope::make(points);
  if (!made) {
    std::printf("%s\n", made.error().c_str());
    return 1;
  }
  const Polytope& hull = *made;

  GjkCache cache;  // zero-initialised: a cold start
  int cold_total = 0, warm_total = 0;
  for (int frame = 0; frame < 100; ++frame) {
    const double angle = 0.01 * frame;
    const Pose pa = Pose::identity();
    const Pose pb = Pose::from(Vec3(2.5 + 0.1 * std::sin(angle), 0.3, 0.0),
                               Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ())));
    cold_total += distance(hull, pa, hull, pb).iterations;
    warm_total += distance(hull, pa, hull, pb, Tolerances{}, &cache).iterations;
  }
  std::printf("support calls over 100 frames: cold %d, warm %d\n", cold_total, warm_total);
  return warm_total <= cold_total ? 0 : 1;
}
