#pragma once
// Mapping of Wavefront MTL parameters onto Prism's materials (documented in
// docs/scene-formats.md, "OBJ and MTL").
#include <string>
#include <vector>

#include "prism/scene/material.h"

namespace tinyobj {
struct material_t;
}

namespace prism::loaders {

// Perceptual roughness r (α = r²) equivalent to a Phong/Blinn-Phong exponent Ns, through the
// Beckmann correspondence α = sqrt(2 / (Ns + 2)) (Walter et al. 2007, §5.2).
float roughness_from_phong_exponent(float ns);

// The material without its textures (texture indices are left at -1; the OBJ loader fills
// them). Parameters Prism cannot represent are named in `ignored`.
Material material_from_mtl(const tinyobj::material_t& mtl, std::vector<std::string>& ignored);

}  // namespace prism::loaders
