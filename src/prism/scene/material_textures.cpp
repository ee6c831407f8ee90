#include "prism/scene/material_textures.h"

namespace prism {

std::vector<bool> textures_used_by_materials(const Scene& scene) {
  std::vector<bool> used(scene.textures.size(), false);
  const auto mark = [&](int texture) {
    if (texture >= 0 && static_cast<std::size_t>(texture) < used.size()) used[static_cast<std::size_t>(texture)] = true;
  };
  for (const Material& m : scene.materials) {
    mark(m.base_color_texture);
    mark(m.metallic_roughness_texture);
    mark(m.normal_texture);
    mark(m.bump_texture);
    mark(m.emission.texture);
    mark(m.clearcoat_texture);
    mark(m.clearcoat_roughness_texture);
    mark(m.clearcoat_normal_texture);
    mark(m.sheen_color_texture);
    mark(m.sheen_roughness_texture);
    mark(m.specular_texture);
    mark(m.specular_color_texture);
    mark(m.iridescence_texture);
    mark(m.iridescence_thickness_texture);
    mark(m.anisotropy_texture);
  }
  return used;
}

}  // namespace prism
