#include "prism/bsdf/normal_mapping_model.h"

namespace prism {

std::string_view normal_mapping_name(NormalMapping model) {
  return model == NormalMapping::microfacet ? "microfacet" : "classic";
}

std::optional<NormalMapping> parse_normal_mapping(std::string_view name) {
  for (const NormalMapping model : {NormalMapping::classic, NormalMapping::microfacet})
    if (name == normal_mapping_name(model)) return model;
  return std::nullopt;
}

}  // namespace prism
