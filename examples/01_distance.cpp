// Distance and closest points between two posed shapes, and the boolean test.
#include <mink/mink.hpp>

#include <cstdio>

int main() {
  using namespace mink;
  const Box box{Vec3(1.0, 0.5, 0.25)};  // half extents
  const Capsule capsule{0.3, 0.8};      // radius, half height of the core segment along z

  // world = R * local + t; quaternions are (w, x, y, z).
  const Pose box_pose = Pose::identity();
  const Pose capsule_pose =
      Pose::from(Vec3(2.5, 0.0, 0.0), Quat(Eigen::AngleAxisd(0.5, Vec3::UnitY())));

  const DistanceResult d = distance(box, box_pose, capsule, capsule_pose);
  if (d.status == Status::InvalidInput) {
    std::printf("invalid input: %s\n", d.error);
    return 1;
  }
  std::printf("status %s, distance %.12f after %d iterations\n", to_string(d.status), d.distance,
              d.iterations);
  std::printf("point on box     (%.6f, %.6f, %.6f)\n", d.point_a.x(), d.point_a.y(), d.point_a.z());
  std::printf("point on capsule (%.6f, %.6f, %.6f)\n", d.point_b.x(), d.point_b.y(), d.point_b.z());
  std::printf("normal box->capsule (%.6f, %.6f, %.6f)\n", d.normal.x(), d.normal.y(), d.normal.z());

  const IntersectResult hit =
      intersect(box, box_pose, capsule, Pose::from_translation(Vec3(1.2, 0.0, 0.0)));
  std::printf("moved closer: intersect = %s\n", hit.intersect ? "true" : "false");
  return d.status == Status::Separated && hit.intersect ? 0 : 1;
}
