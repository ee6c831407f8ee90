#include "prism/render/light_estimator.h"

namespace prism {

std::string_view light_estimator_name(LightEstimator estimator) {
  switch (estimator) {
    case LightEstimator::mis: return "mis";
    case LightEstimator::nee_only: return "nee";
    case LightEstimator::bsdf_only: return "bsdf";
  }
  return "unknown";
}

std::optional<LightEstimator> parse_light_estimator(std::string_view name) {
  for (const LightEstimator e : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only})
    if (name == light_estimator_name(e)) return e;
  return std::nullopt;
}

}  // namespace prism
