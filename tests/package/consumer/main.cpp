// A user's program built against an installed mink: one static-shape query and one run-time one.
#include <mink/mink.hpp>

#include <cmath>
#include <cstdio>

int main() {
  const mink::Sphere a{1.0};
  const mink::Box b{mink::Vec3(1, 1, 1)};
  const auto r = mink::distance(a, mink::Pose::identity(), b,
                                mink::Pose::from_translation(mink::Vec3(4, 0, 0)));
  // Sphere of radius 1 at the origin, box face at x = 3: the gap is 2.
  if (r.status != mink::Status::Separated || std::abs(r.distance - 2.0) > 1e-12) {
    std::printf("unexpected distance %.17g\n", r.distance);
    return 1;
  }
  const auto capsule = mink::Shape::capsule(0.5, 1.0);
  if (!capsule) return 1;
  const auto hit = mink::intersect(*capsule, mink::Pose::identity(), *capsule,
                                   mink::Pose::from_translation(mink::Vec3(0.9, 0, 0)));
  if (!hit.intersect) return 1;
  std::printf("mink %s consumer ok: distance %.17g\n", mink::kVersion, r.distance);
  return 0;
}
