// Properties on the run-time Shape path (see gjk_property_check.hpp): the same independent checks
// as the static sweeps, on the library's compiled dispatch. (It does not also compare with the
// static templates: that instantiated all 144 pairs a fourth time and cost minutes of CI per
// build.)
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

}  // namespace
}  // namespace property
