// Properties on static shape types, pairs whose lower kind is 5 to 11 (see
// gjk_property_check.hpp).
#include "property/gjk_property_check.hpp"

namespace property {
namespace {

TEST(GjkProperties, AllShapePairsStaticKinds5To11) {
  run_static_sweep<5, 11>();
}

}  // namespace
}  // namespace property
