#pragma once
// Reading texture images from files or memory: 8-bit PNG and JPEG images keep their codes
// (decoded at lookup, scene/texture.h), 16-bit PNGs are decoded to linear floats, float
// formats stay floats. Formats are recognised by their magic bytes, not the file name: PNG
// and JPEG (stb_image), Radiance .hdr (stb_image's RGBE reader) and OpenEXR (prism::read_exr).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>

#include "prism/core/memory_budget.h"
#include "prism/scene/texture.h"

namespace prism {

enum class ImageFileFormat : std::uint8_t { unknown, png, jpeg, radiance_hdr, openexr };

// Limits checked from an image's header, before its pixels are decoded.
struct TextureLimits {
  TextureLimits(int max_dimension_ = 32768, MemoryBudget* budget_ = nullptr)  // NOLINT: implicit from int
      : max_dimension(max_dimension_), budget(budget_) {}
  int max_dimension;       // wider or taller images are refused
  MemoryBudget* budget;    // when set: the texels (and the decoder's buffer) must fit
};
ImageFileFormat detect_image_format(std::span<const unsigned char> head);
// The same from a file's first bytes. Throws IoError "cannot read image '<path>': ..." for a
// missing, non-regular, unopenable or empty file.
ImageFileFormat detect_image_file_format(const std::filesystem::path& path);

// Throws IoError for a missing/unreadable/truncated/unrecognised file and for an image
// wider or taller than `limits.max_dimension`, and Error when its texels would exceed the
// memory budget (both checked from the header, before the pixels are allocated).
// `content`: a colour texture's texels are converted from the colour space their file
// names into Rec.709, or into the wide space a wide-gamut material's base colour or an
// environment map asks for (TextureContent; Bradford between whites; what falls outside
// the gamut is clipped, and TextureImage::primaries_note says so, or what else was done),
// and TextureImage::texel_space says which. The file's space is an OpenEXR's
// `chromaticities` attribute (Rec.709 without one), or a Radiance picture's PRIMARIES line
// or XYZE format (Rec.709 without either; its EXPOSURE and COLORCORR factors are divided
// out too, io/radiance_hdr_reader.h), or a PNG's or JPEG's colour tags (cICP, an ICC profile, sRGB,
// cHRM and gAMA; image_color_tags.h): an 8-bit image in sRGB, or without tags, keeps its
// codes; one whose tags say otherwise is decoded through their curves into half floats
// and converted. Data (normal, roughness, height maps) is read as stored.
TextureImage read_texture_file(const std::filesystem::path& path, TextureEncoding encoding,
                               const TextureLimits& limits, TextureContent content = TextureContent::data);

// Whether a PNG's or JPEG's colour tags are read (image_color_tags.h). glTF 2.0 §3.8.3
// says a glTF's images are sRGB whatever they say ("Any colorspace information (such as
// ICC profiles, intents, gamma values, etc.) from PNG or JPEG images MUST be ignored"); its
// loader passes `ignore`.
enum class ImageColorTagUse : std::uint8_t { honour, ignore };

// The same for PNG, JPEG and .hdr data already in memory (EXR needs a file); `name` is
// used in messages and as the texture's name.
TextureImage decode_texture_memory(std::span<const unsigned char> bytes, std::string_view name,
                                   TextureEncoding encoding, const TextureLimits& limits, TextureContent content,
                                   ImageColorTagUse tag_use = ImageColorTagUse::honour);

// What decode_texture_memory (or read_texture_file, for OpenEXR) reserves from a budget for
// `bytes`, read from the header: the texels as kept (a byte per sample of an 8-bit image, 4
// bytes per RGBE texel, a float otherwise), and the decoder's buffer, held only while it
// decodes. A Radiance picture whose header asks for a conversion counts float texels and
// its RGBE as the buffer, whatever the use (the most it can reserve). Nothing when the
// header cannot be read (the decode then reports why).
struct TextureMemoryNeed {
  std::uint64_t texel_bytes = 0, transient_bytes = 0;
};
std::optional<TextureMemoryNeed> texture_memory_need(std::span<const unsigned char> bytes);
// The same for a file; nothing for files that cannot be read or whose header does not
// read (read_texture_file then reports why).
std::optional<TextureMemoryNeed> texture_file_memory_need(const std::filesystem::path& path);

}  // namespace prism
