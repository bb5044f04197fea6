// core_centre(): the point of its core that each shape names for GJK's first phase
// (shapes/shape_common.hpp). It must lie in the shape, checked by the zoo's own membership tests
// (tests/property/shape_zoo.hpp, written from the shapes' definitions), for the static types and
// the run-time Shape alike.
#include <gtest/gtest.h>

#include <variant>

#include "mink/mink.hpp"
#include "property/shape_zoo.hpp"

namespace {

TEST(CoreCentre, LiesInEveryKindOfShape) {
  oracle::Rng rng(20261127);
  for (int kind = 0; kind < zoo::kKindCount; ++kind) {
    for (int i = 0; i < 60; ++i) {
      const double scale = i % 3 == 0 ? 1e-6 : (i % 3 == 1 ? 1.0 : 1e6);
      const zoo::Desc desc = zoo::random_desc(rng, kind, scale);
      SCOPED_TRACE(desc.describe());
      const double size = zoo::size_of(desc);
      const mink::Vec3 from_static = std::visit(
          [](const auto& shape) -> mink::Vec3 {
            static_assert(mink::HasCoreCentre<std::decay_t<decltype(shape)>>);
            return shape.core_centre();
          },
          zoo::make_static(desc));
      const mink::Vec3 from_runtime = zoo::make_runtime(desc).core_centre();
      for (const mink::Vec3& centre : {from_static, from_runtime}) {
        const auto outside = zoo::distance_to(desc, oracle::widen(centre));
        ASSERT_TRUE(outside.has_value());
        EXPECT_LE(double(*outside), 1e-12 * size) << centre.transpose();
      }
      EXPECT_LE((from_static - from_runtime).norm(), 1e-15 * size);
    }
  }
}

// A polytope's centre is the mean of its points, which lies inside the hull even where no
// point does (every point a vertex) and stays finite for points near the largest doubles.
TEST(CoreCentre, PolytopeMeanAtTheEdgesOfTheRange) {
  const double big = 1.5e308;
  const std::vector<mink::Vec3> points = {{big, 0, 0}, {big, big, 0}, {big, 0, big}, {0, 0, 0}};
  const auto polytope = mink::Polytope::make(points);
  ASSERT_TRUE(polytope);
  const mink::Vec3 centre = polytope->core_centre();
  EXPECT_TRUE(centre.allFinite());
  EXPECT_DOUBLE_EQ(centre.x(), 0.75 * big);
  EXPECT_DOUBLE_EQ(centre.y(), 0.25 * big);
  EXPECT_DOUBLE_EQ(centre.z(), 0.25 * big);
  const mink::Segment segment{{big, -big, big}, {big, big, big}};
  EXPECT_EQ(segment.core_centre(), mink::Vec3(big, 0, big));
  const mink::Triangle triangle{{big, big, big}, {big, big, big}, {big, big, big}};
  EXPECT_TRUE(triangle.core_centre().allFinite());
}

}  // namespace
