// Properties on static shape types, A kinds 4 to 7 (see gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds4To7) {
  run_static_sweep<4, 7>();
}

}  // namespace
}  // namespace property
