#pragma once
// Loads each texture file once per scene, however many materials or lights use it.
// Shared by every loader (JSON, OBJ/MTL and the later glTF and pbrt-v4 loaders).
#include <filesystem>
#include <map>
#include <tuple>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_file.h"

namespace prism::loaders {

class TextureCache {
 public:
  TextureCache(Scene& scene, const LoadOptions& options) : scene_(scene), options_(options) {}

  // Index into scene.textures of `file` (an already resolved path, see path_safety.h)
  // decoded with `encoding` and addressed with the wrap modes. The key is the canonical
  // path, the encoding and the addressing (the addressing lives in TextureImage, so the
  // same file with other wrap modes is a second entry). Throws IoError.
  int load(const std::filesystem::path& file, TextureEncoding encoding, TextureWrap wrap_u = TextureWrap::repeat,
           TextureWrap wrap_v = TextureWrap::repeat);

  std::size_t files_read() const { return files_read_; }

 private:
  using Key = std::tuple<std::string, TextureEncoding, TextureWrap, TextureWrap>;
  Scene& scene_;
  LoadOptions options_;
  std::map<Key, int> indices_;
  std::size_t files_read_ = 0;
};

}  // namespace prism::loaders
