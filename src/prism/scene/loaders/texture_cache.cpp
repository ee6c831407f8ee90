#include "prism/scene/loaders/texture_cache.h"

namespace prism::loaders {

int TextureCache::load(const std::filesystem::path& file, TextureEncoding encoding, TextureWrap wrap_u,
                       TextureWrap wrap_v) {
  std::error_code ec;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(file, ec);
  if (ec) canonical = file;
  const Key key{canonical.string(), encoding, wrap_u, wrap_v};
  if (const auto it = indices_.find(key); it != indices_.end()) return it->second;
  TextureImage image = read_texture_file(canonical, encoding, {options_.max_texture_dimension, options_.memory_budget});
  ++files_read_;
  image.name = file.filename().string();
  image.wrap_u = wrap_u;
  image.wrap_v = wrap_v;
  const int index = static_cast<int>(scene_.textures.size());
  scene_.textures.push_back(std::move(image));
  indices_.emplace(key, index);
  return index;
}

}  // namespace prism::loaders
