// Properties on the run-time Shape path (see gjk_property_check.hpp): the same independent checks
// as the static sweeps, on the library's compiled dispatch, and its exact symmetry under swap. (It
// does not also compare with the static templates: that instantiated all 144 pairs a fourth time
// and cost minutes of CI per build.)
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsRuntimeShape) {
  const std::uint64_t base = 40000;
  const int n = oracle::sweep_count(1500);
  Stats stats;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    oracle::Rng rng(seed);
    const int ka = i % zoo::kKindCount, kb = (i / zoo::kKindCount) % zoo::kKindCount;
    const Case c = draw_case(rng, ka, kb);
    const zoo::Desc &da = c.da, &db = c.db;
    const Pose &pa = c.pa, &pb = c.pb, &motion = c.motion;
    SCOPED_TRACE(testing::Message() << oracle::seed_note(seed) << "\nA: " << da.describe()
                                    << "\nB: " << db.describe());
    const mink::Shape a = zoo::make_runtime(da), b = zoo::make_runtime(db);
    check_pair(a, da, pa, b, db, pb, motion, rng, stats);
  }
  stats.print("run-time Shape");
}

// The run-time Shape answers each pair of different core types in one order and swaps the answer
// for the other (src/shape_dispatch.hpp), so swapping A and B must flip every answer exactly: the
// normal's sign, the points' sides, the same distance, depth and status, for every query.
TEST(GjkProperties, RuntimeShapeSwapIsExact) {
  const std::uint64_t base = 47000;
  const int n = oracle::sweep_count(600);
  int apart = 0, overlapping = 0, checked = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    oracle::Rng rng(seed);
    const int ka = i % zoo::kKindCount, kb = (i / zoo::kKindCount) % zoo::kKindCount;
    const Case c = draw_case(rng, ka, kb);
    SCOPED_TRACE(testing::Message() << oracle::seed_note(seed) << "\nA: " << c.da.describe()
                                    << "\nB: " << c.db.describe());
    const mink::Shape a = zoo::make_runtime(c.da), b = zoo::make_runtime(c.db);
    // Cores of one type, and sums of several cores, run in the order given.
    if (a.cores().size() != 1 || b.cores().size() != 1 ||
        a.cores()[0].index() == b.cores()[0].index())
      continue;
    ++checked;

    const auto iab = mink::intersect(a, c.pa, b, c.pb), iba = mink::intersect(b, c.pb, a, c.pa);
    EXPECT_EQ(iab.status, iba.status);
    EXPECT_EQ(iab.intersect, iba.intersect);

    const auto dab = mink::distance(a, c.pa, b, c.pb), dba = mink::distance(b, c.pb, a, c.pa);
    EXPECT_EQ(dab.status, dba.status);
    EXPECT_EQ(dab.distance, dba.distance);
    EXPECT_EQ(dab.normal, -dba.normal);
    EXPECT_EQ(dab.point_a, dba.point_b);
    EXPECT_EQ(dab.point_b, dba.point_a);

    const auto cab = mink::contact(a, c.pa, b, c.pb), cba = mink::contact(b, c.pb, a, c.pa);
    EXPECT_EQ(cab.status, cba.status);
    EXPECT_EQ(cab.distance, cba.distance);
    EXPECT_EQ(cab.depth, cba.depth);
    EXPECT_EQ(cab.normal, -cba.normal);
    EXPECT_EQ(cab.point_a, cba.point_b);
    EXPECT_EQ(cab.point_b, cba.point_a);
    (cab.intersect ? overlapping : apart) += 1;

    const auto mab = mink::manifold(a, c.pa, b, c.pb), mba = mink::manifold(b, c.pb, a, c.pa);
    EXPECT_EQ(mab.status, mba.status);
    EXPECT_EQ(mab.normal, -mba.normal);
    ASSERT_EQ(mab.count, mba.count);
    for (int k = 0; k < mab.count; ++k) {
      EXPECT_EQ(mab.points[k].depth, mba.points[k].depth);
      EXPECT_EQ(mab.points[k].point_a, mba.points[k].point_b);
      EXPECT_EQ(mab.points[k].point_b, mba.points[k].point_a);
    }
  }
  // Most pairs of kinds have different core types, and both kinds of answer are swapped.
  EXPECT_GT(checked, n / 2);
  EXPECT_GT(apart, checked / 10);
  EXPECT_GT(overlapping, checked / 10);
}

}  // namespace
}  // namespace property
