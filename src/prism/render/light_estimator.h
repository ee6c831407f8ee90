#pragma once
// How direct light is estimated. All three converge to the same image; mis (next-event
// estimation and BSDF sampling combined by the power heuristic, Veach 1997 §9.2) has the
// lowest variance. nee_only and bsdf_only exist to test that claim.
#include <optional>
#include <string_view>

namespace prism {

enum class LightEstimator { mis, nee_only, bsdf_only };

inline constexpr std::string_view kLightEstimatorNames = "mis, nee, bsdf";  // for messages

// "mis", "nee" or "bsdf" (the names of `prism render --estimator` and the EXR metadata);
// parse_light_estimator reads them back (nullopt otherwise).
std::string_view light_estimator_name(LightEstimator estimator);
std::optional<LightEstimator> parse_light_estimator(std::string_view name);

}  // namespace prism
