// The normal-mapping models' names: what `--normal-mapping`, a JSON scene's
// render.normal_mapping, the viewer and the EXR metadata use, read back to the same model.
#include "prism/bsdf/normal_mapping_model.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(NormalMappingNames, RoundTripAndRefuseOthers) {
  for (const NormalMapping m : {NormalMapping::classic, NormalMapping::microfacet})
    EXPECT_EQ(parse_normal_mapping(normal_mapping_name(m)), m);
  EXPECT_EQ(normal_mapping_name(NormalMapping::microfacet), "microfacet");
  EXPECT_FALSE(parse_normal_mapping("Microfacet").has_value());
  EXPECT_FALSE(parse_normal_mapping("bent").has_value());
}

}  // namespace
}  // namespace prism
