// Properties on static shape types, pairs whose lower kind is 0 to 1 (see
// gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds0To1) {
  run_static_sweep<0, 1>();
}

}  // namespace
}  // namespace property
