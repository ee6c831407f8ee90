// The light estimators' names: what `prism render --estimator`, the viewer and the EXR
// metadata (prism:estimator) use, read back to the same estimator.
#include "prism/render/light_estimator.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(LightEstimatorNames, RoundTripAndRefuseOthers) {
  for (const LightEstimator e : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only})
    EXPECT_EQ(parse_light_estimator(light_estimator_name(e)), e);
  EXPECT_EQ(light_estimator_name(LightEstimator::nee_only), "nee");
  EXPECT_EQ(light_estimator_name(LightEstimator::bsdf_only), "bsdf");
  EXPECT_FALSE(parse_light_estimator("nee_only").has_value());
  EXPECT_FALSE(parse_light_estimator("MIS").has_value());
  EXPECT_FALSE(parse_light_estimator("").has_value());
}

}  // namespace
}  // namespace prism
