// Minkowski sums ("sweeps") and margins ("collision skins") compose at compile time, and run on
// their cores: a segment swept by a sphere is exactly a capsule.
#include <mink/mink.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace mink;
  const Segment rod{Vec3(0, 0, -1), Vec3(0, 0, 1)};
  const MinkowskiSum swept{rod, Sphere{0.25}};           // == Capsule{0.25, 1}
  const Rounded skinned{Box{Vec3(0.5, 0.5, 0.5)}, 0.1};  // box with 0.1 rounded skin

  const Pose at_origin = Pose::identity();
  const Pose beside = Pose::from_translation(Vec3(2.0, 0.0, 0.0));
  const DistanceResult d = distance(swept, at_origin, skinned, beside);
  // The capsule reaches x = 0.25, the skinned box starts at x = 2 - 0.5 - 0.1 = 1.4.
  std::printf("sum vs rounded box: distance %.15f (expected 1.15)\n", d.distance);

  // The same through the run-time Shape used by the command line.
  const auto a = Shape::sum(*Shape::segment(rod.a, rod.b), *Shape::sphere(0.25));
  const auto b = Shape::rounded(*Shape::box(Vec3(0.5, 0.5, 0.5)), 0.1);
  if (!a || !b) return 1;
  const DistanceResult e = distance(*a, at_origin, *b, beside);
  std::printf("run-time shapes:    distance %.15f\n", e.distance);
  return std::abs(d.distance - 1.15) < 1e-12 && std::abs(e.distance - 1.15) < 1e-12 ? 0 : 1;
}
