// Properties on static shape types, A kinds 0 to 3 (see gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds0To3) {
  run_static_sweep<0, 3>();
}

}  // namespace
}  // namespace property
