#pragma once
// What a normal or bump map does to a reflecting surface. classic: the BSDF is evaluated
// around the mapped normal (what glTF viewers and most renderers do; not energy
// conserving). microfacet: the mapped normal is a facet of a two-facet microsurface whose
// mean normal is the unperturbed one (Schüßler et al. 2017, bsdf/microfacet_normal_mapping.h):
// no light is lost to directions below the surface. Transmitting materials stay classic.
// Chosen by `prism render|view --normal-mapping`, or by a JSON scene's `render` object.
#include <optional>
#include <string_view>

namespace prism {

enum class NormalMapping { classic, microfacet };

inline constexpr std::string_view kNormalMappingNames = "classic, microfacet";  // for messages

// "classic" or "microfacet"; parse_normal_mapping reads those names back (nullopt otherwise).
std::string_view normal_mapping_name(NormalMapping model);
std::optional<NormalMapping> parse_normal_mapping(std::string_view name);

}  // namespace prism
