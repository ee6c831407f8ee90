#pragma once
// The one table of names for each scene enum: what prism-scene/1 files say, what `prism
// info` prints and what the scene writers write. A new material type, light type, texture
// wrap or alpha mode gets its name here and every loader, summary and writer knows it.
#include <array>

#include "prism/core/enum_names.h"
#include "prism/scene/light.h"
#include "prism/scene/material.h"
#include "prism/scene/texture.h"

namespace prism {

inline constexpr std::array<EnumName<MaterialType>, 5> kMaterialTypeNames{{
    {MaterialType::diffuse, "diffuse"},
    {MaterialType::mirror, "mirror"},
    {MaterialType::conductor, "conductor"},
    {MaterialType::dielectric, "dielectric"},
    {MaterialType::metallic_roughness, "metallic_roughness"},
}};

inline constexpr std::array<EnumName<LightType>, 4> kLightTypeNames{{
    {LightType::point, "point"},
    {LightType::spot, "spot"},
    {LightType::directional, "directional"},
    {LightType::environment, "environment"},
}};

inline constexpr std::array<EnumName<TextureWrap>, 3> kTextureWrapNames{{
    {TextureWrap::repeat, "repeat"},
    {TextureWrap::clamp, "clamp"},
    {TextureWrap::mirror, "mirror"},
}};

inline constexpr std::array<EnumName<AlphaMode>, 3> kAlphaModeNames{{
    {AlphaMode::opaque, "opaque"},
    {AlphaMode::mask, "mask"},
    {AlphaMode::blend, "blend"},
}};

}  // namespace prism
