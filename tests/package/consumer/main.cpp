// A user's program built against an installed mink: static-shape queries (distance, contact,
// manifold) and a run-time one.
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
  // EPA and the manifold on static types: a cylinder of radius 1 standing on a box's top face
  // (z = 1), sunk 0.25 into it.
  const mink::Cylinder cylinder{1.0, 0.5};
  const mink::Pose standing = mink::Pose::from_translation(mink::Vec3(0, 0, 1.25));
  const auto deep = mink::contact(b, mink::Pose::identity(), cylinder, standing);
  if (deep.status != mink::Status::Intersecting || std::abs(deep.depth - 0.25) > 1e-12 ||
      std::abs(deep.normal.z() - 1.0) > 1e-12) {
    std::printf("unexpected contact: depth %.17g\n", deep.depth);
    return 1;
  }
  const auto patch = mink::manifold(b, mink::Pose::identity(), cylinder, standing);
  if (patch.count < 3) {
    std::printf("unexpected manifold of %d points\n", patch.count);
    return 1;
  }
  std::printf("mink %s consumer ok: distance %.17g, depth %.17g, %d manifold points\n",
              mink::kVersion, r.distance, deep.depth, patch.count);
  return 0;
}
