// Properties on the run-time Shape path (see gjk_property_check.hpp).
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
    // Named references, not a structured binding: clang 14 cannot capture bindings in lambdas.
    const Case c = draw_case(rng, ka, kb);
    const zoo::Desc &da = c.da, &db = c.db;
    const Pose &pa = c.pa, &pb = c.pb, &motion = c.motion;
    const double reach = zoo::size_of(da) + zoo::size_of(db);
    SCOPED_TRACE(testing::Message() << oracle::seed_note(seed) << "\nA: " << da.describe()
                                    << "\nB: " << db.describe());
    const mink::Shape a = zoo::make_runtime(da), b = zoo::make_runtime(db);
    check_pair(a, da, pa, b, db, pb, motion, rng, stats);
    // The run-time path answers like the static one. Both stop anywhere inside GJK's convergence
    // band on curved shapes (1e-12 of the size), and may round differently (different
    // translation units), so they agree to the accuracy bar, 1e-10 of the size, not bit for bit.
    const zoo::Static sa = zoo::make_static(da), sb = zoo::make_static(db);
    const auto rs = std::visit(
        [&](const auto& x, const auto& y) { return mink::distance(x, pa, y, pb); }, sa, sb);
    const auto rr = mink::distance(a, pa, b, pb);
    if (rs.distance > oracle::kTouchingBand * reach) {
      EXPECT_EQ(rs.intersect, rr.intersect);
    }
    EXPECT_NEAR(rs.distance, rr.distance, oracle::kDistanceTolerance * reach);
  }
  stats.print("run-time Shape");
}

}  // namespace
}  // namespace property
