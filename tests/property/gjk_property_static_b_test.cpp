// Properties on static shape types, pairs whose lower kind is 2 to 4 (see
// gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds2To4) {
  run_static_sweep<2, 4>();
}

}  // namespace
}  // namespace property
