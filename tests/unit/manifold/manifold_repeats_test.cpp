// Manifold points that are one point: two lines of probe 51's generators (tests/slow/probe_stop51,
// stop 52's rerun) that kept a point twice.
//   - Far from the origin the contact's pair went to the world and back before it joined the
//     clipped points, and came back moved by the world's rounding (1e-8 at 8e7), more than the
//     reduction's 1e-9 of the size: a box against a needle plus an ellipsoid gave 1 point in one
//     argument order and 2 in the other, once stop 52's witness points made the contact's pair
//     deeper than the clipped one by 9e-12 (stop 51's code, whose pair was no deeper, passes).
//     contact() now runs in A's frame for the manifold.
//   - A rounded triangle tilted 8e-5 rad on a prism: the clipped corner (the face moved by the
//     radius along its own normal) and the corner's deepest point (moved along the contact's)
//     are 1.2e-5 apart and 5e-10 apart in depth, and both were kept: 4 points for 3.
#include <gtest/gtest.h>

#include <vector>

#include "mink/mink.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Shape;
using mink::Vec3;

Pose pose(const Vec3& t, double w, double x, double y, double z) {
  return Pose::from(t, Quat(w, x, y, z));
}

// The smallest distance between two of the manifold's points on A.
double closest_pair(const mink::ManifoldResult& m) {
  double closest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.count; ++i)
    for (int j = i + 1; j < m.count; ++j)
      closest = std::min(closest, (m.points[i].point_a - m.points[j].point_a).norm());
  return closest;
}

TEST(ManifoldRepeats, FarFromTheOriginBothOrdersKeepOnePoint) {
  const Shape box =
      Shape::box(Vec3(0.8858882658167293, 0.2139571590274185, 0.7389419349316879)).value();
  const std::vector<Vec3> needle = {
      {-0.09501039067405048, 0.1677815500418529, -0.24145809149566858},
      {-0.09500943601631082, 0.1677814851549434, -0.24145791577733353},
      {-0.09500884827345646, 0.1677823744902125, -0.24145690057807803},
      {-0.0950086873979979, 0.16778041770785235, -0.24145647074362853},
      {-0.09500874103949285, 0.1677809884580614, -0.24145774074810197},
      {-0.09500893341160661, 0.16778352852146886, -0.2414569529469503},
      {0.03889074386330192, -0.06867529719566455, 0.09883505740695038},
      {0.03888877397910593, -0.06867518583657718, 0.09883373245236356},
      {0.03888952586059746, -0.06867591738866287, 0.09883400395909678},
      {0.03889116646238613, -0.068676870859149, 0.09883255468829383},
      {0.038889034621123225, -0.06867570695517992, 0.0988333416479782},
      {0.038890485080727025, -0.06867809253498748, 0.0988346296998903}};
  const Shape sum =
      Shape::sum(
          Shape::polytope(needle).value(),
          Shape::ellipsoid(Vec3(0.11535432317203927, 0.18368335401770935, 0.1650637167020049))
              .value())
          .value();
  const Pose pose_box =
      pose(Vec3(14032235.162380895, 15164559.574384304, 81420070.56168242), 0.5280986482964702,
           -0.17257522273287562, 0.1076508380623833, 0.8244640120894338);
  const Pose pose_sum =
      pose(Vec3(14032235.1589791, 15164559.939751908, 81420071.49340956), -0.13384802518596242,
           -0.5441889587478344, -0.18064414048189306, -0.8082764241522352);
  mink::ManifoldOptions options;
  options.margin = 0.07327031374337867;
  const auto ab = mink::manifold(box, pose_box, sum, pose_sum, options);
  const auto ba = mink::manifold(sum, pose_sum, box, pose_box, options);
  ASSERT_EQ(ab.status, mink::Status::Intersecting);
  ASSERT_EQ(ba.status, mink::Status::Intersecting);
  EXPECT_EQ(ab.count, ba.count);
  EXPECT_EQ(ab.count, 1);
  // The deepest points agree, to the world's rounding at 8e7.
  const double rounding = 16 * std::numeric_limits<double>::epsilon() * 8.2e7;
  EXPECT_LE((ab.points[0].point_a - ba.points[0].point_b).norm(), rounding);
  EXPECT_NEAR(ab.depth, ba.depth, 1e-12);
}

TEST(ManifoldRepeats, ATiltedRoundedTriangleKeepsItsThreeCorners) {
  const Shape triangle =
      Shape::rounded(Shape::triangle(Vec3(0.2707342305166749, -0.3613010746817331, 0.0),
                                     Vec3(0.6603383457866048, 0.5517515752396478, 0.0),
                                     Vec3(0.5210012857988764, 0.10291692439985933, 0.0))
                         .value(),
                     0.15310786164460205)
          .value();
  std::vector<Vec3> prism;
  const double corners[7][2] = {
      {3.0037949957684895, -0.2184123032059492},  {1.3973613854448295, 2.6546044067626635},
      {-1.189190842135511, 2.516650514517723},    {-3.0329262991058146, 1.0897086055481586},
      {-2.8854916724439104, -0.9149980496150917}, {-0.6863780364826463, -3.0170713473827915},
      {1.6403565516477456, -2.0194263399917274}};
  for (const double z : {-0.21415598070921762, 0.21415598070921762})
    for (const auto& c : corners) prism.emplace_back(c[0], c[1], z);
  const Shape slab = Shape::polytope(prism).value();
  const Pose pose_triangle =
      pose(Vec3(1.896331305902906, -0.9019776983827411, 1.4785328729309972), -0.4945356512442313,
           -0.5436451886351905, -0.34107739155788963, -0.586131906221047);
  const Pose pose_slab =
      pose(Vec3(1.5406483680722907, -1.0461534083505202, 1.264726273277072), -0.49450980715018567,
           -0.5436470565810922, -0.34110831594583335, -0.5861339823757008);
  mink::ManifoldOptions options;
  options.margin = 0.0002452729435376066;
  for (const bool swapped : {false, true}) {
    const auto m = swapped ? mink::manifold(slab, pose_slab, triangle, pose_triangle, options)
                           : mink::manifold(triangle, pose_triangle, slab, pose_slab, options);
    ASSERT_EQ(m.status, mink::Status::Intersecting) << swapped;
    EXPECT_EQ(m.count, 3) << swapped;
    // The corners are 0.4 to 1 apart; a repeat would be 1.2e-5 from its twin.
    EXPECT_GT(closest_pair(m), 0.1) << swapped;
    // The first point is the deepest: the contact's.
    EXPECT_NEAR(m.points[0].depth, m.depth, 1e-12) << swapped;
  }
}

}  // namespace
