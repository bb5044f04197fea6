#include <gtest/gtest.h>

#include "mink/mink.hpp"

namespace mink {

TEST(GjkSmoke, SpheresApart) {
  const Sphere a{1.0}, b{0.5};
  const auto r = distance(a, Pose::identity(), b, Pose::from_translation(Vec3(3, 0, 0)));
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_DOUBLE_EQ(r.distance, 1.5);
  const auto i = intersect(a, Pose::identity(), b, Pose::from_translation(Vec3(3, 0, 0)));
  EXPECT_FALSE(i.intersect);
}

TEST(GjkSmoke, BoxesApart) {
  const Box a{Vec3(1, 1, 1)}, b{Vec3(1, 1, 1)};
  const auto r = distance(a, Pose::identity(), b, Pose::from_translation(Vec3(3, 0.5, 0.2)));
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_NEAR(r.normal.x(), 1.0, 1e-15);
}

TEST(GjkSmoke, RuntimeShapes) {
  const auto a = Shape::capsule(0.5, 1.0);
  const auto b = Shape::box(Vec3(1, 1, 1));
  ASSERT_TRUE(a && b);
  const auto r = distance(*a, Pose::identity(), *b, Pose::from_translation(Vec3(0, 0, 4)));
  EXPECT_NEAR(r.distance, 1.5, 1e-15);
  const auto i = intersect(*a, Pose::identity(), *b, Pose::from_translation(Vec3(0, 0, 2)));
  EXPECT_TRUE(i.intersect);
}

}  // namespace mink
