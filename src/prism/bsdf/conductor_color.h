#pragma once
// The colour of a measured metal's normal-incidence reflectance F0(λ), for formats that can
// only describe a metal by an RGB F0 (glTF metallic-roughness's base colour of a metal).
#include <string_view>

#include "prism/core/vec.h"

namespace prism::bsdf {

// Linear Rec.709 colour of F0(λ) = fresnel_conductor(1, η(λ), k(λ)) of the named metal
// (conductor_ior's data): XYZ of the reflectance under CIE D65 (the space's white, so a
// perfect reflector is (1, 1, 1)), normalised as CIE 15:2004 §7.1, then to Rec.709 and
// clamped to [0, 1] (a glTF base colour's range). Throws UsageError for unknown names.
Vec3f conductor_f0_rec709(std::string_view name);

}  // namespace prism::bsdf
