// pbrt-v4 Shape "alpha" → Prism alpha coverage. pbrt-v4 keeps a hit whose alpha is a with
// probability a (a hash of the ray decides; 0 always passes, 1 always hits: pbrt-v4's
// GeometricPrimitive::Intersect), which is Prism's BLEND (stochastic coverage, Enderton et
// al. 2010). Prism reads coverage from the base-colour texture's alpha, so a float alpha
// image becomes the alpha channel of an RGBA copy of the material's reflectance image.
#include <algorithm>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/pbrt_builder.h"

namespace prism::loaders {

int PbrtBuilder::texture_with_alpha(int base, int alpha) {
  textures_->finish();  // both images' texels are read here
  const TextureImage a = scene_.textures[static_cast<std::size_t>(alpha)];
  TextureImage out;
  if (base >= 0) {
    const TextureImage& b = scene_.textures[static_cast<std::size_t>(base)];
    out = b;  // addressing and uv transform of the reflectance image
    out.name = fmt::format("{}+alpha {}", b.name, a.name);
  } else {
    out = a;
    out.name = fmt::format("alpha {}", a.name);
  }
  const int w = out.width, h = out.height;
  const TextureImage* colour = base >= 0 ? &scene_.textures[static_cast<std::size_t>(base)] : nullptr;
  std::vector<float> texels(static_cast<std::size_t>(w) * h * 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* t = &texels[(static_cast<std::size_t>(y) * w + x) * 4];
      if (colour) {
        const std::size_t c = (static_cast<std::size_t>(y) * w + x) * colour->channels;
        const bool grey = colour->channels <= 2;
        for (int k = 0; k < 3; ++k) t[k] = colour->value(c + (grey ? 0 : k));
      }
      // Nearest alpha texel (the same texel when both images have the same size).
      const int ax = static_cast<int>(static_cast<long>(x) * a.width / w), ay = static_cast<int>(static_cast<long>(y) * a.height / h);
      t[3] = std::clamp(a.value((static_cast<std::size_t>(ay) * a.width + ax) * a.channels), 0.0f, 1.0f);
    }
  out.channels = 4;
  out.texels = std::move(texels);
  out.codes.clear();  // the copy's 8-bit texels, if the image it copied had them
  scene_.textures.push_back(std::move(out));
  return static_cast<int>(scene_.textures.size() - 1);
}

std::uint32_t PbrtBuilder::alpha_material(std::uint32_t material, const PbrtParams& p) {
  const PbrtParam* param = p.find("alpha");
  if (!param) return material;
  int image = -1;
  float constant = 1.0f;
  std::string key;
  if (param->type == "texture") {
    const std::string name = p.get_string("alpha", "");
    const auto it = float_textures_.find(name);
    if (it == float_textures_.end()) p.fail(*param, fmt::format("unknown float texture '{}'", name));
    image = it->second.image;
    constant = it->second.value.x;  // a constant texture's value, an image's "scale"
    key = "texture " + name;
  } else {
    constant = static_cast<float>(p.get_float("alpha", 1.0));
    key = fmt::format("float {}", constant);
  }
  if (!(constant >= 0.0f)) p.fail(*param, "alpha must be ≥ 0");
  if (image < 0 && constant >= 1.0f) return material;
  const auto cached = alpha_materials_.find({material, key});
  if (cached != alpha_materials_.end()) return cached->second;
  Material m = scene_.materials[material];
  m.name += "+alpha";
  m.alpha_mode = AlphaMode::blend;
  m.opacity = std::min(constant, 1.0f) * m.opacity;
  if (image >= 0) m.base_color_texture = texture_with_alpha(m.base_color_texture, image);
  scene_.materials.push_back(std::move(m));
  const auto index = static_cast<std::uint32_t>(scene_.materials.size() - 1);
  alpha_materials_[{material, key}] = index;
  return index;
}

}  // namespace prism::loaders
