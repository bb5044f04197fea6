// Pairs on which EPA needs 500 to 1,600 support calls to close its bracket, and which ended at
// its old cap of 512 (stop 48's probe, tests/slow/probe_stop48/status_iteration_limit.jsonl lines
// 3, 5, 7, 8 and 12): near-coincident ellipsoids (A - B nearly symmetric, two nearly equal minima
// on a flat support function) and unit cones and cylinders at the corner of a polytope or box
// 1e3 across. Tolerances::max_epa_iterations (2048) lets them converge: status ok, the depth
// against the independent long-double search of tests/oracle/curved.hpp where it knows the shapes,
// and for the polytopes no greater than the least support value over a grid of directions (each
// one an upper bound on the depth), with the normal's own support value equal to the depth within
// EPA's tolerance (relative_depth: a converged EPA answers the lower end of its bracket, and its
// normal's support value is the upper end).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/curved.hpp"
#include "oracle/curved_to_mink.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Shape;
using mink::Vec3;
using oracle::CurvedKind;
using oracle::CurvedShape;
using oracle::Real;
using oracle::V3;

TEST(ContactEpaBudget, CurvedPairsThatNeedMoreThan512SupportCalls) {
  struct Case {
    const char* name;
    CurvedShape a;
    Pose pose_a;
    CurvedShape b;
    Pose pose_b;
  };
  auto ellipsoid = [](double x, double y, double z) {
    return CurvedShape{CurvedKind::Ellipsoid, 0, 0, V3(x, y, z)};
  };
  const Case cases[] = {
      {"near-coincident ellipsoids, turned 4e-7 rad (line 8)",
       ellipsoid(1.1999910043100297, 1.4023174437162373, 1.2168884717706483),
       Pose::from(Vec3::Zero(), Quat(-0.12802045527010456, -0.2279198118721221,
                                     -0.42234343113029355, 0.8679224323461762)),
       ellipsoid(1.1999910043100297, 1.4023174437162373, 1.2168884717706483),
       Pose::from(Vec3(9.504868499688035e-07, 0.00019032555901062797, -2.456642619993258e-10),
                  Quat(-0.12802080295284654, -0.22792003437860567, -0.4223431502725936,
                       0.86792245930036))},
      {"ellipsoid and its copy 9e-4 off (line 12)",
       ellipsoid(1.2471449111248671, 1.2003013181507687, 1.3054623970542714),
       Pose::from(Vec3::Zero(), Quat(0.22949894375618746, -0.8836921202350261, -0.38802167534210946,
                                     -0.1259271651154796)),
       ellipsoid(1.2471449111248671, 1.2003013181507687, 1.3054623970542714),
       Pose::from(Vec3(-0.0009258883639479491, -3.2123801664021516e-10, 0),
                  Quat(0.22949894375618746, -0.8836921202350261, -0.38802167534210946,
                       -0.1259271651154796))},
      {"unit cone at the corner of a box 2e3 across (line 5)",
       CurvedShape{CurvedKind::Box, 0, 0,
                   V3(987.4394701474098, 909.1232860256711, 340.437345736427)},
       Pose::from(Vec3::Zero(), Quat(0.06535248304494183, 0.798884172915021, 0.5933065113864843,
                                     -0.07416545538283449)),
       CurvedShape{CurvedKind::Cone, 0.9984784795770802, 0.48276070988573055, V3::Zero()},
       Pose::from(Vec3(603.1781172218405, -1122.2910299886796, 542.2899955759198),
                  Quat(0.25673149200444917, -0.9398003114658662, -0.2229582748327063,
                       -0.033969446057509546))},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto r =
        mink::contact(oracle::to_mink_shape(c.a), c.pose_a, oracle::to_mink_shape(c.b), c.pose_b);
    ASSERT_EQ(r.status, mink::Status::Intersecting) << "error bound " << r.error_bound;
    const auto expected = oracle::curved_depth(c.a, oracle::to_oracle_pose(c.pose_a), c.b,
                                               oracle::to_oracle_pose(c.pose_b));
    const double size =
        static_cast<double>(oracle::bounding_radius(c.a) + oracle::bounding_radius(c.b));
    EXPECT_NEAR(r.depth, static_cast<double>(expected.depth), 1e-9 * size);
    const V3 n = r.normal.cast<Real>();
    const Real h = oracle::world_support(c.a, oracle::to_oracle_pose(c.pose_a), n) +
                   oracle::world_support(c.b, oracle::to_oracle_pose(c.pose_b), -n);
    EXPECT_NEAR(static_cast<double>(h), r.depth, 1e-10 * size) << "the normal is not the depth's";
    EXPECT_LE((r.point_b - r.point_a + r.depth * r.normal).norm(), 1e-12 * size);
  }
}

/// The least of h_A(u) + h_B(-u) over a Fibonacci grid of directions: an upper bound on the depth.
template <class Support>
double least_on_grid(const Support& h, int count) {
  double least = INFINITY;
  for (int i = 0; i < count; ++i) {
    const double z = 1 - (2 * i + 1.0) / count, rho = std::sqrt(1 - z * z);
    const double phi = i * std::numbers::pi * (3 - std::sqrt(5.0));
    least = std::min(least, h(Vec3(rho * std::cos(phi), rho * std::sin(phi), z)));
  }
  return least;
}

TEST(ContactEpaBudget, UnitCurvedShapesAtTheVertexOfALargePolytope) {
  struct Case {
    const char* name;
    std::vector<Vec3> points;
    Pose pose_a;
    CurvedShape b;
    Pose pose_b;
  };
  const Case cases[] = {
      {"unit cone at a vertex of a 5-point polytope 1e3 across (line 3)",
       {Vec3(414.0079557082162, 11.055425375760592, 142.86777504007992),
        Vec3(-430.07969123163605, -884.5700020395705, 159.1362741799339),
        Vec3(342.49670849933034, -503.06219401732733, 85.9574073562624),
        Vec3(50.64164814191213, -532.7227957761728, -129.2007951122493),
        Vec3(-230.65028087812072, 490.6021233487819, 56.98050749787299)},
       Pose::from(Vec3::Zero(), Quat(0.8578049253639431, 0.03967480011205853, 0.5025584445643159,
                                     0.10015802541246391)),
       CurvedShape{CurvedKind::Cone, 1.3249105809656272, 0.4707464122691772, V3::Zero()},
       Pose::from(Vec3(50.989166478276346, -949.9015052697645, 296.3852582726501),
                  Quat(-0.013271264906981746, -0.8470085919673173, -0.11549134313494303,
                       -0.5187119319258023))},
      {"unit cylinder at a vertex of a 5-point polytope 1e3 across (line 7)",
       {Vec3(-347.36711380384304, 77.01572369068958, 63.74981470501541),
        Vec3(-321.5786410445773, 96.1065877843871, -185.17620370470797),
        Vec3(-336.93191896032215, 21.436688011745105, 494.04715772919815),
        Vec3(-9.773684057680327, -232.844872581127, -105.9643090078373),
        Vec3(-299.2301567586105, 526.5475440136374, 64.58584815774623)},
       Pose::from(Vec3::Zero(), Quat(0.16769357090096182, 0.36076230171468543, 0.03853611120008345,
                                     -0.9166484582835348)),
       CurvedShape{CurvedKind::Cylinder, 0.42111874483028544, 0.8573973290110541, V3::Zero()},
       Pose::from(Vec3(-82.90429773114111, -20.632755597187924, 592.2553641934707),
                  Quat(0.38674044119896905, 0.9115698137245754, 0.08164338037234858,
                       0.11316653343080721))},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Shape a = Shape::polytope(c.points).value();
    const auto r = mink::contact(a, c.pose_a, oracle::to_mink_shape(c.b), c.pose_b);
    ASSERT_EQ(r.status, mink::Status::Intersecting) << "error bound " << r.error_bound;
    // h_A(u) + h_B(-u), each from its definition: the polytope's points posed, the curved
    // shape's closed form (tests/oracle/curved.hpp).
    auto h = [&](const Vec3& u) {
      double h_a = -INFINITY;
      for (const Vec3& p : c.points) h_a = std::max(h_a, u.dot(c.pose_a.apply(p)));
      return h_a + static_cast<double>(oracle::world_support(c.b, oracle::to_oracle_pose(c.pose_b),
                                                             V3(-u.cast<Real>())));
    };
    double size = oracle::bounding_radius(c.b);
    for (const Vec3& p : c.points)
      size = std::max(size, p.norm() + double(oracle::bounding_radius(c.b)));
    EXPECT_LE(r.depth, least_on_grid(h, 50000) + 1e-12 * size);
    EXPECT_NEAR(h(r.normal), r.depth, 1e-10 * size) << "the normal is not the depth's";
    EXPECT_LE((r.point_b - r.point_a + r.depth * r.normal).norm(), 1e-12 * size);
  }
}

}  // namespace
