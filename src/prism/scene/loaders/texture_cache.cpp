#include "prism/scene/loaders/texture_cache.h"

#include <fmt/format.h>

#include <cctype>
#include <string>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/scene/image_color_tags.h"

namespace prism::loaders {
namespace {

// OpenEXR and Radiance pictures can name their primaries (an OpenEXR's chromaticities, a
// .hdr's PRIMARIES line or XYZE format), and PNG and JPEG images theirs in colour tags
// (cICP, an ICC profile, cHRM and gAMA: image_color_tags.h), so their colour texels depend
// on the use.
bool may_name_primaries(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".exr" || extension == ".hdr" || extension == ".pic" || image_file_has_color_tags(file);
}

}  // namespace

int TextureCache::load(const std::filesystem::path& file, TextureEncoding encoding, TextureWrap wrap_u,
                       TextureWrap wrap_v, std::string context, ImageCheck check,
                       std::optional<TextureContent> content) {
  std::error_code ec;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(file, ec);
  if (ec) canonical = file;
  TextureContent what =
      content.value_or(encoding == TextureEncoding::srgb ? TextureContent::color : TextureContent::data);
  // Only an OpenEXR's, a Radiance picture's or a tagged PNG's or JPEG's texels go into a
  // wide space (texture_file.h): any other image is decoded once for every colour use.
  if (is_color_content(what) && !may_name_primaries(canonical)) what = TextureContent::color;
  const Key key{canonical.string(), encoding, wrap_u, wrap_v, what};
  if (const auto it = indices_.find(key); it != indices_.end()) return it->second;
  // The entry's place and addressing now, its texels at the next sync.
  TextureImage placeholder;
  placeholder.name = file.filename().string();
  placeholder.wrap_u = wrap_u;
  placeholder.wrap_v = wrap_v;
  const int index = static_cast<int>(scene_.textures.size());
  scene_.textures.push_back(std::move(placeholder));
  indices_.emplace(key, index);
  Request request;
  request.index = index;
  request.path = std::move(canonical);
  request.encoding = encoding;
  request.content = what;
  request.context = std::move(context);
  request.check = std::move(check);
  pending_.push_back(std::move(request));
  return index;
}

void TextureCache::decode(Request& request) const {
  try {
    request.image = read_texture_file(request.path, request.encoding,
                                      {options_.max_texture_dimension, options_.memory_budget}, request.content);
  } catch (...) {
    request.error = std::current_exception();
  }
}

bool TextureCache::fits_together(const std::vector<Request>& batch) const {
  const MemoryBudget* budget = options_.memory_budget;
  if (!budget || budget->limit_bytes() == 0) return true;
  // One at a time, each image's decoder buffer sits only beside the texels decoded before
  // it; all at once, every buffer is held together. So only when the whole batch fits does
  // every reservation succeed in any order, as it would have one at a time.
  std::uint64_t together = 0;
  for (const Request& r : batch) {
    const auto need = texture_file_memory_need(r.path);
    if (!need) return false;  // a header that does not read: one at a time
    together += need->texel_bytes + need->transient_bytes;
  }
  return budget->used_bytes() + together <= budget->limit_bytes();
}

void TextureCache::rethrow(const Request& request) {
  try {
    std::rethrow_exception(request.error);
  } catch (const IoError& e) {
    if (request.context.empty()) throw;
    throw IoError(fmt::format("{}: {}", request.context, e.what()));  // which material or light asked for it
  }
}

void TextureCache::finish() {
  if (pending_.empty()) return;
  std::vector<Request> batch = std::move(pending_);
  pending_.clear();
  if (batch.size() > 1 && fits_together(batch)) {
    parallel_for(batch.size(), 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) decode(batch[i]);
    });
    ++parallel_batches_;
  } else {
    // In request order, stopping at the first failure as one-at-a-time loading would.
    for (Request& r : batch) {
      decode(r);
      if (r.error) break;
    }
  }
  for (Request& r : batch) {
    if (r.error) rethrow(r);
    if (!r.image) continue;  // not reached: every request before a failure was decoded
    ++files_read_;
    TextureImage& entry = scene_.textures[static_cast<std::size_t>(r.index)];
    r.image->name = std::move(entry.name);
    r.image->wrap_u = entry.wrap_u;
    r.image->wrap_v = entry.wrap_v;
    entry = std::move(*r.image);
    if (!entry.primaries_note.empty()) scene_.warnings.push_back(entry.primaries_note);
    if (r.check) r.check(entry);
  }
}

const TextureImage& TextureCache::image(int index) {
  finish();
  return scene_.textures.at(static_cast<std::size_t>(index));
}

int TextureCache::add_with_uv_transform(int index, double scale_u, double scale_v, double offset_u,
                                        double offset_v_upward) {
  TextureImage copy = image(index);  // the texels again, with this addressing
  copy.scale_u = static_cast<float>(scale_u);
  copy.scale_v = static_cast<float>(scale_v);
  copy.offset_u = static_cast<float>(offset_u);
  copy.offset_v = static_cast<float>(1.0 - scale_v - offset_v_upward);
  scene_.textures.push_back(std::move(copy));
  return static_cast<int>(scene_.textures.size() - 1);
}

void TextureCache::rethrow_first_error(std::exception_ptr error) {
  finish();  // throws the first failure among the images asked for before `error`
  std::rethrow_exception(error);
}

}  // namespace prism::loaders
