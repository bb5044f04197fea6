// Properties on static shape types, A kinds 8 to 11 (see gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds8To11) {
  run_static_sweep<8, 11>();
}

}  // namespace
}  // namespace property
