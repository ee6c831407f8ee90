#include "prism/scene/surface_alpha.h"

#include "prism/scene/texture_sampling.h"

namespace prism {

bool has_alpha_coverage(const Material& m) {
  switch (m.alpha_mode) {
    case AlphaMode::opaque: return false;
    case AlphaMode::mask: return true;
    case AlphaMode::blend: return m.opacity < 1.0f || m.base_color_texture >= 0;
  }
  return false;
}

float surface_alpha(const Scene& scene, const TriangleMesh& mesh, std::uint32_t triangle, float b1, float b2) {
  const Material& m = scene.materials[mesh.material];
  float alpha = m.opacity;
  const int t = m.base_color_texture;
  if (t >= 0 && static_cast<std::size_t>(t) < scene.textures.size() && !mesh.uvs.empty()) {
    const TextureImage& image = scene.textures[static_cast<std::size_t>(t)];
    // Only grey+alpha and RGBA textures carry alpha; the others are opaque.
    if (image.channels == 2 || image.channels == 4) {
      const std::uint32_t* v = &mesh.indices[3 * static_cast<std::size_t>(triangle)];
      const float b0 = 1.0f - b1 - b2;
      const Vec2f uv(b0 * mesh.uvs[v[0]].x + b1 * mesh.uvs[v[1]].x + b2 * mesh.uvs[v[2]].x,
                     b0 * mesh.uvs[v[0]].y + b1 * mesh.uvs[v[1]].y + b2 * mesh.uvs[v[2]].y);
      alpha *= sample_bilinear(image, apply_uv_transform(image, uv))[3];
    }
  }
  return alpha;
}

bool surface_alpha_accepts(const Material& m, float alpha, float u) {
  switch (m.alpha_mode) {
    case AlphaMode::opaque: return true;
    case AlphaMode::mask: return alpha >= m.alpha_cutoff;
    case AlphaMode::blend: return u < alpha;
  }
  return true;
}

}  // namespace prism
