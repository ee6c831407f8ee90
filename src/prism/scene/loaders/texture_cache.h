#pragma once
// Loads each texture file once per scene, however many materials or lights use it, and
// decodes the files together: load() only reserves the texture's index, and the images
// asked for since the last sync are decoded at the next one (image(), finish()), on all
// threads where the memory budget holds them at once. JPEG and PNG decoding is most of a
// textured scene's load, and a loader asks for its images one material after another.
// Shared by the JSON, OBJ/MTL and pbrt-v4 loaders (glTF decodes its embedded images ahead
// in its own builder).
//
// What a user sees is the same as decoding each file when it is asked for: the same
// indices, images and warnings, and a failing load reports what one-at-a-time decoding
// would have reported first: decode errors and the per-image checks in request order, and
// before any error the loader found after asking for a failing image (rethrow_first_error).
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_file.h"

namespace prism::loaders {

class TextureCache {
 public:
  // Checks a decoded image (e.g. that a normal map has three channels); throws to refuse it.
  using ImageCheck = std::function<void(const TextureImage&)>;

  TextureCache(Scene& scene, const LoadOptions& options) : scene_(scene), options_(options) {}

  // Index into scene.textures of `file` (an already resolved path, see path_safety.h)
  // decoded with `encoding` and addressed with the wrap modes. The key is the canonical
  // path, the encoding and the addressing (the addressing lives in TextureImage, so the
  // same file with other wrap modes is a second entry). Until the next sync the entry holds
  // only its name and addressing. `context` is put before an IoError of this file's decode
  // ("<context>: <error>"); `check` runs on the decoded image, the first time the file is
  // asked for with this key.
  // `content` (read_texture_file): by default colour when asked sRGB-encoded, data when
  // linear; a loader that knows better says (an OpenEXR is linear whatever is asked). A
  // colour in a wide space is kept in the key only for a file named .exr, .hdr or .pic,
  // whose header can name its primaries, and for a PNG or JPEG with colour tags
  // (image_file_has_color_tags): any other image is sRGB whatever is asked
  // (texture_file.h), and is decoded once.
  int load(const std::filesystem::path& file, TextureEncoding encoding, TextureWrap wrap_u = TextureWrap::repeat,
           TextureWrap wrap_v = TextureWrap::repeat, std::string context = {}, ImageCheck check = {},
           std::optional<TextureContent> content = std::nullopt);

  // Decodes every image asked for and not decoded yet, and throws the first failure in
  // request order (IoError and the budget's Error from decoding, whatever a check throws).
  void finish();
  // The decoded image of `index` (a sync: finish() first).
  const TextureImage& image(int index);
  // A new texture: the image of `index` (a sync) looked up at s·uv + d, uv with v UP the
  // image (pbrt-v4's uscale/vscale/udelta/vdelta, MTL's -s/-o). Prism's v runs down it
  // (v' = 1 − v, as the loaders flip uvs): scale (s_u, s_v), offset (d_u, 1 − s_v − d_v).
  // Returns the new texture's index.
  int add_with_uv_transform(int index, double scale_u, double scale_v, double offset_u, double offset_v_upward);
  // For a loader that failed with `error`: what decoding one image at a time would have
  // reported instead, i.e. the first failure among the images asked for before it, if any.
  [[noreturn]] void rethrow_first_error(std::exception_ptr error);

  std::size_t files_read() const { return files_read_; }
  // Syncs that decoded their images together, split across the threads (for tests).
  std::size_t parallel_batches() const { return parallel_batches_; }

 private:
  struct Request {
    int index = -1;
    std::filesystem::path path;
    TextureEncoding encoding = TextureEncoding::srgb;
    TextureContent content = TextureContent::color;
    std::string context;
    ImageCheck check;
    std::optional<TextureImage> image;
    std::exception_ptr error;
  };
  void decode(Request& request) const;
  // Whether every image of `batch` fits in the memory budget together with its decoder's
  // buffer (all are decoded at once); read from their headers.
  bool fits_together(const std::vector<Request>& batch) const;
  [[noreturn]] static void rethrow(const Request& request);

  using Key = std::tuple<std::string, TextureEncoding, TextureWrap, TextureWrap, TextureContent>;
  Scene& scene_;
  LoadOptions options_;
  std::map<Key, int> indices_;
  std::vector<Request> pending_;  // in request order
  std::size_t files_read_ = 0, parallel_batches_ = 0;
};

}  // namespace prism::loaders
