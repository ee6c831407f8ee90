#include "prism/scene/texture_file.h"

#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <half.h>
#include <fmt/format.h>
#include <stb_image.h>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>
#include <fstream>
#include <memory>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/core/half_float.h"
#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/io/openexr_header.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/emission.h"
#include "prism/scene/image_color_tags.h"
#include "prism/io/radiance_hdr_reader.h"
#include "prism/scene/texture_primaries.h"

namespace prism {
namespace {

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

bool starts_with(std::span<const unsigned char> bytes, std::string_view magic) {
  return bytes.size() >= magic.size() && std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

// What stb reports of a PNG or JPEG from its header: the size, channels and the bytes of
// each decoded sample (2: 16-bit PNG, 1: 8-bit), and the channels Prism has it decode.
// Nothing when the header does not read (stbi_failure_reason says why) or the data is over
// 2 GiB.
//
// An RGB JPEG is decoded as RGBA and its constant alpha dropped in the copy: stb_image
// converts YCbCr to RGB with SSE2 only when it writes four channels per pixel (its
// stbi__YCbCr_to_RGB_simd handles step 4 alone), and its scalar conversion for three, the
// same fixed-point arithmetic (stb keeps the two equal on purpose), was a fifth of
// DamagedHelmet's start-up. TextureFile.RgbJpegTexelsAreStbsThreeChannelDecode checks the
// texels against stb's three-channel decode.
struct StbHeader {
  int width = 0, height = 0, channels = 0, decoded_channels = 0, decoded_bytes_per_sample = 1;
};
std::optional<StbHeader> stb_header(std::span<const unsigned char> bytes) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) return std::nullopt;
  const int size = static_cast<int>(bytes.size());
  StbHeader h;
  if (!stbi_info_from_memory(bytes.data(), size, &h.width, &h.height, &h.channels)) return std::nullopt;
  h.decoded_bytes_per_sample = stbi_is_16_bit_from_memory(bytes.data(), size) ? 2 : 1;
  h.decoded_channels = detect_image_format(bytes) == ImageFileFormat::jpeg && h.channels == 3 ? 4 : h.channels;
  return h;
}

// The texels stay (8-bit codes as they are, anything else as floats); the decoder's own
// buffer of `decoded_bytes_per_sample` bytes per sample, `decoded_channels` samples per
// texel, lives only while decoding.
TextureMemoryNeed texel_memory(const StbHeader& header) {
  const auto texels = static_cast<std::uint64_t>(header.width) * static_cast<std::uint64_t>(header.height);
  const std::uint64_t kept_bytes_per_sample = header.decoded_bytes_per_sample == 1 ? 1 : sizeof(float);
  return {texels * static_cast<std::uint64_t>(header.channels) * kept_bytes_per_sample,
          texels * static_cast<std::uint64_t>(header.decoded_channels) *
              static_cast<std::uint64_t>(header.decoded_bytes_per_sample)};
}

// An OpenEXR texture keeps its colour channels (RGB, or Y alone), as halves (2 bytes per
// sample) where the file stores them as HALF, as floats otherwise, read straight into place.
TextureMemoryNeed openexr_memory(long width, long height, int channels, bool half) {
  const std::uint64_t samples = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) *
                                static_cast<std::uint64_t>(channels);
  return {samples * (half ? sizeof(std::uint16_t) : sizeof(float)), 0};
}

void reserve_texels(const TextureLimits& limits, const StbHeader& header, std::string_view name) {
  if (!limits.budget) return;
  const TextureMemoryNeed need = texel_memory(header);
  limits.budget->reserve(need.texel_bytes, need.transient_bytes,
                         fmt::format("texture '{}' ({}x{}, {} channels)", name, header.width, header.height,
                                     header.channels));
}

// Decodes 16-bit codes to linear floats: colour channels through the curves of the
// image's colour tags where it has them (image_color_tags.h), else through the sRGB EOTF
// when asked, alpha always linearly (8-bit codes are kept and decoded at lookup the same way).
void decode_16_bit_codes(const std::uint16_t* codes, TextureImage& image, TextureEncoding encoding,
                         const ImageColorTags* tags) {
  constexpr unsigned kMaxCode = 65535;
  const int c = image.channels;
  const bool tagged = tags && !tags->srgb;
  const int curves = tagged && c >= 3 ? 3 : 1;
  std::vector<std::vector<float>> luts(static_cast<std::size_t>(curves), std::vector<float>(kMaxCode + 1));
  for (int k = 0; k < curves; ++k)
    for (unsigned i = 0; i <= kMaxCode; ++i) {
      const double v = static_cast<double>(i) / kMaxCode;
      luts[static_cast<std::size_t>(k)][i] = static_cast<float>(tagged                              ? decode_tagged_code(*tags, k, i, kMaxCode)
                                                                : encoding == TextureEncoding::srgb ? color::srgb_decode(v)
                                                                                                    : v);
    }
  image.texels.resize(static_cast<std::size_t>(image.width) * image.height * c);
  for (std::size_t i = 0; i < image.texels.size(); ++i) {
    const int channel = static_cast<int>(i % static_cast<std::size_t>(c));
    image.texels[i] = is_alpha_channel(channel, c)
                          ? static_cast<float>(codes[i] / static_cast<double>(kMaxCode))
                          : luts[static_cast<std::size_t>(std::min(channel, curves - 1))][codes[i]];
  }
}

// An 8-bit image whose tags are not sRGB: its codes decoded through the tags' curves into
// half floats (linear; alpha linearly), 2 bytes a sample instead of the code's 1.
void decode_tagged_8_bit_codes(TextureImage& image, const ImageColorTags& tags, const TextureLimits& limits) {
  const int c = image.channels;
  if (limits.budget)
    limits.budget->reserve(image.codes.size() * sizeof(std::uint16_t), 0,
                           fmt::format("texture '{}' ({}x{}, {} channels, decoded to half floats for its colour "
                                       "tags)",
                                       image.name, image.width, image.height, c));
  std::array<std::array<std::uint16_t, 256>, 4> luts;
  for (int k = 0; k < c; ++k)
    for (unsigned code = 0; code < 256; ++code)
      luts[static_cast<std::size_t>(k)][code] =
          Imath::half(static_cast<float>(is_alpha_channel(k, c) ? code / 255.0
                                                                 : decode_tagged_code(tags, std::min(k, 2), code, 255)))
              .bits();
  image.halves.resize(image.codes.size());
  for (std::size_t i = 0; i < image.codes.size(); ++i)
    image.halves[i] = luts[i % static_cast<std::size_t>(c)][image.codes[i]];
  image.codes = {};
}

// The space a tagged colour texture's RGB goes into: the one `content` asks for, or for
// color_own_gamut the smallest of Rec.709, Rec.2020 and ACEScg that holds its primaries.
ColorPickerSpace tagged_texel_space(const ImageColorTags& tags, TextureContent content) {
  if (content != TextureContent::color_own_gamut) return requested_space(content);
  return smallest_picker_space_holding(
      [&](const color::ColorSpace& candidate) { return image_color_conversion(tags, candidate); });
}

// A decoded colour texture after its tags: linear RGB converted into the space its use asks
// for (nothing for grey images, whose values are achromatic in every space), and the
// loader's note of what was done or passed over.
void convert_tagged_texels(TextureImage& image, const ImageColorTags& tags, TextureContent content) {
  std::string note;
  if (!tags.srgb) {
    std::size_t clipped = 0;
    if (image.channels >= 3) {
      const ColorPickerSpace target = tagged_texel_space(tags, content);
      clipped = convert_texels(image, image_color_conversion(tags, picker_color_space(target)), target);
    }
    note = fmt::format("texture '{}': {} decoded{}{}", image.name, tags.source,
                       image.channels >= 3 ? fmt::format(" and converted to {}", picker_space_label(image.texel_space))
                                           : std::string(" (grey)"),
                       clipped_texels_text(clipped, image));
  }
  if (!tags.passed_over.empty())
    note += (note.empty() ? fmt::format("texture '{}': ", image.name) : std::string("; ")) + tags.passed_over +
            (tags.srgb ? "; read as sRGB" : "");
  image.primaries_note = note;
}

// stb_image reads past the end of its input as zeros, so a truncated .hdr or JPEG would
// decode "successfully" with black pixels. Feeding it through callbacks lets us notice
// that it asked for bytes the file does not have.
class StbInput {
 public:
  explicit StbInput(std::span<const unsigned char> bytes) : bytes_(bytes) {}

  // `decoded_channels` per pixel in the result (stb converts), 0 for the file's own.
  template <typename Pixel>
  std::unique_ptr<Pixel, StbFree> decode(Pixel* (*load)(const stbi_io_callbacks*, void*, int*, int*, int*, int),
                                         int& width, int& height, int& channels, int decoded_channels = 0) {
    position_ = 0;
    ran_past_end_ = false;
    const stbi_io_callbacks callbacks{&StbInput::read, &StbInput::skip, &StbInput::eof};
    std::unique_ptr<Pixel, StbFree> pixels(load(&callbacks, this, &width, &height, &channels, decoded_channels));
    return pixels;
  }
  bool ran_past_end() const { return ran_past_end_; }

 private:
  static int read(void* user, char* data, int size) {
    auto* self = static_cast<StbInput*>(user);
    const std::size_t n = std::min(static_cast<std::size_t>(std::max(size, 0)), self->bytes_.size() - self->position_);
    if (size > 0 && n == 0) self->ran_past_end_ = true;
    std::memcpy(data, self->bytes_.data() + self->position_, n);
    self->position_ += n;
    return static_cast<int>(n);
  }
  static void skip(void* user, int n) {
    auto* self = static_cast<StbInput*>(user);
    const long target = static_cast<long>(self->position_) + n;
    if (target > static_cast<long>(self->bytes_.size())) self->ran_past_end_ = true;
    self->position_ = static_cast<std::size_t>(std::clamp(target, 0L, static_cast<long>(self->bytes_.size())));
  }
  static int eof(void* user) {
    const auto* self = static_cast<StbInput*>(user);
    return self->position_ >= self->bytes_.size() ? 1 : 0;
  }

  std::span<const unsigned char> bytes_;
  std::size_t position_ = 0;
  bool ran_past_end_ = false;
};

// Walks a JPEG's marker segments (ITU-T T.81 §B.1: 0xFF marker, 2-byte big-endian length
// including itself; entropy-coded data after SOS runs until a marker that is not a stuffed
// 0xFF00 or an RSTn) and checks every Huffman table (DHT, §B.2.4.2: class/id byte, 16 code
// counts, then that many symbols) before stb_image sees it. stb_image (Debian's) builds
// its code-size list in a 257-entry array without checking that the 16 counts sum to at
// most 256, so a corrupt DHT writes past it (found by the fuzz_image_readers target).
// Each scan (SOS, §B.2.3: Ns, then per component its selector byte Td<<4|Ta, then Ss, Se,
// Ah<<4|Al) may only select tables defined earlier: stb_image keeps its four DC and four
// AC tables in uninitialised memory and decodes with whatever is there (an index of 637
// into a 256-entry array, found by the same target). In a progressive frame (SOF2) a scan
// needs its DC table when it codes DC coefficients for the first time (Ss = 0, Ah = 0; a
// DC refinement reads raw bits) and its AC table when it codes any AC coefficient (Se > 0),
// as in §G.1.2. In a sequential frame (SOF0, SOF1) every scan codes whole blocks (the
// spectral selection must be 0..63, §B.2.3, and stb_image decodes all 64 coefficients
// whatever it says), so every component needs both tables: a baseline scan declaring
// Se = 0 with an undefined AC table was decoded with it (index −1, found by the same target).
void check_jpeg_huffman_tables(std::span<const unsigned char> bytes, std::string_view name) {
  const auto corrupt = [&](std::string_view why) {
    throw IoError(fmt::format("cannot read image '{}': corrupt JPEG ({})", name, why));
  };
  std::array<bool, 4> dc_defined{};
  std::array<bool, 4> ac_defined{};
  bool progressive = false;  // the frame's SOF: stb_image reads SOF0, SOF1 and SOF2
  std::size_t pos = 2;  // after SOI
  while (pos + 1 < bytes.size()) {
    if (bytes[pos] != 0xFF) {
      ++pos;  // entropy-coded data, or fill
      continue;
    }
    const unsigned char marker = bytes[pos + 1];
    if (marker == 0xFF || marker == 0x00 || (marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {
      pos += marker == 0xFF ? 1 : 2;  // fill byte, stuffed zero, RSTn or TEM: no length
      continue;
    }
    if (marker == 0xD9) return;  // EOI
    if (pos + 4 > bytes.size()) return;  // truncated: stb_image reports it
    const std::size_t length = (std::size_t{bytes[pos + 2]} << 8) | bytes[pos + 3];
    if (length < 2) corrupt("segment length below 2");
    const std::size_t end = std::min(bytes.size(), pos + 2 + length);
    if (marker == 0xC0 || marker == 0xC1 || marker == 0xC2) progressive = marker == 0xC2;
    if (marker == 0xC4) {
      std::size_t t = pos + 4;
      while (t < end) {
        if (t + 17 > end) corrupt("Huffman table header runs past its segment");
        std::size_t codes = 0;
        for (int i = 1; i <= 16; ++i) codes += bytes[t + static_cast<std::size_t>(i)];
        if (codes > 256) corrupt(fmt::format("Huffman table with {} codes, at most 256", codes));
        const unsigned table_class = bytes[t] >> 4;
        const unsigned table_id = bytes[t] & 15u;
        if (table_class > 1 || table_id > 3) corrupt("Huffman table class or id out of range");
        (table_class == 0 ? dc_defined : ac_defined)[table_id] = true;
        t += 17 + codes;
      }
    }
    if (marker == 0xDA) {
      const std::size_t components_at = pos + 4;
      if (components_at >= end) corrupt("scan header runs past its segment");
      const std::size_t components = bytes[components_at];
      const std::size_t spectral_at = components_at + 1 + 2 * components;
      if (spectral_at + 3 > end) corrupt("scan header runs past its segment");
      const bool needs_dc = !progressive || (bytes[spectral_at] == 0 && (bytes[spectral_at + 2] >> 4) == 0);
      const bool needs_ac = !progressive || bytes[spectral_at + 1] > 0;
      for (std::size_t c = 0; c < components; ++c) {
        const unsigned selectors = bytes[components_at + 2 + 2 * c];
        if (needs_dc && ((selectors >> 4) > 3 || !dc_defined[selectors >> 4]))
          corrupt(fmt::format("scan uses DC Huffman table {} before it is defined", selectors >> 4));
        if (needs_ac && ((selectors & 15u) > 3 || !ac_defined[selectors & 15u]))
          corrupt(fmt::format("scan uses AC Huffman table {} before it is defined", selectors & 15u));
      }
    }
    pos += 2 + length;
  }
}

// The PNG without its zero-length IDAT chunks, or nothing when it has none. An empty IDAT
// carries no image data (PNG: the image is the concatenation of all IDAT data), so dropping
// it changes nothing; stb_image (Debian's) would memcpy zero bytes to a null buffer for an
// empty first IDAT (UBSan nonnull-attribute, found by the fuzz_image_readers target).
// Also refuses a chunk whose declared length runs past the end of the file: stb_image
// grows its IDAT buffer to the declared length before reading (a 2 GB realloc for a few
// bytes of input, found by the same fuzz target). Every chunk whose 8-byte header (length,
// type) is there is checked, also one that ends the file before its CRC: stb_image acts on
// the header alone (the second such input from the fuzzer had 3 bytes after the header).
std::optional<std::vector<unsigned char>> without_empty_idat_chunks(std::span<const unsigned char> bytes,
                                                                    std::string_view name) {
  constexpr std::size_t kSignature = 8;
  std::vector<std::pair<std::size_t, std::size_t>> empty;  // [begin, end) of each empty IDAT
  for (std::size_t pos = kSignature; pos + 8 <= bytes.size();) {
    const std::size_t length = (std::size_t{bytes[pos]} << 24) | (std::size_t{bytes[pos + 1]} << 16) |
                               (std::size_t{bytes[pos + 2]} << 8) | bytes[pos + 3];
    if (bytes.size() - pos < 12 || length > bytes.size() - pos - 12)
      throw IoError(fmt::format("cannot read image '{}': corrupt or truncated PNG (a chunk claims {} bytes, more "
                                "than the file holds)",
                                name, length));
    if (length == 0 && std::memcmp(bytes.data() + pos + 4, "IDAT", 4) == 0) empty.emplace_back(pos, pos + 12);
    pos += 12 + length;
  }
  if (empty.empty()) return std::nullopt;
  std::vector<unsigned char> out;
  out.reserve(bytes.size());
  std::size_t from = 0;
  for (const auto& [begin, end] : empty) {
    out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(from), bytes.begin() + static_cast<std::ptrdiff_t>(begin));
    from = end;
  }
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(from), bytes.end());
  return out;
}

bool radiance_rec709_primaries(const RadianceHeader& header) {
  return !header.xyz && (!header.primaries || same_primaries(*header.primaries, color::color_space("srgb")));
}

// A Radiance picture keeps its RGBE texels, 4 bytes each, read straight into place, unless
// a colour texture's must be converted (radiance_conversion): then they become float RGB
// (12 bytes a texel), the RGBE held only while they are converted. From the header alone,
// which does not know the texture's use, a conversion is assumed wherever one may happen.
// A file in another pixel order than "-Y H +X W" is read in its order first (4 bytes a
// texel more while it is put in rows).
TextureMemoryNeed radiance_memory(const RadianceHeader& header, bool converted) {
  const auto texels = static_cast<std::uint64_t>(header.width) * static_cast<std::uint64_t>(header.height);
  const std::uint64_t reordered = header.columns || header.bottom_up || header.right_to_left ? texels * 4 : 0;
  if (converted) return {texels * 3 * sizeof(float), texels * 4 + reordered};
  return {texels * 4, reordered};
}
bool radiance_may_convert(const RadianceHeader& header) {
  return !radiance_rec709_primaries(header) || radiance_texels_scaled(header);
}

// Whether a colour texture's texels change space going into `target` (XYZ always does).
bool radiance_changes_space(const RadianceHeader& header, const color::ColorSpace& file_space,
                            ColorPickerSpace target) {
  return header.xyz || !same_primaries(color::Primaries{file_space.red, file_space.green, file_space.blue,
                                                        file_space.white},
                                       picker_color_space(target));
}

// The matrix taking a colour texture's texels to radiance in the space `content` puts them
// in (`target`): the header's factors divided out (EXPOSURE and COLORCORR are what the
// texels were multiplied by), then the file's primaries (or XYZ) converted with Bradford
// between whites (where `changes_space`, radiance_changes_space's answer). Nothing where the
// texels are that already.
std::optional<Mat3> radiance_conversion(const RadianceHeader& header, const color::ColorSpace& file_space,
                                        ColorPickerSpace target, bool changes_space) {
  if (!changes_space && !radiance_texels_scaled(header)) return std::nullopt;
  return (changes_space ? color::conversion_matrix(file_space, picker_color_space(target)) : Mat3::identity()) *
         Mat3::diagonal(radiance_texel_factors(header));
}

// What was done to a converted Radiance texture, for the loader's warnings; nothing for
// Rec.709 texels put unscaled into a wider space without clipping, which lose nothing.
std::string radiance_note(const RadianceHeader& header, bool changed_space, const TextureImage& image,
                          std::size_t clipped) {
  const bool rec709 = radiance_rec709_primaries(header), scaled = radiance_texels_scaled(header);
  if (rec709 && !scaled && clipped == 0) return "";
  std::string note = fmt::format("texture '{}': ", image.name);
  note += header.xyz ? "CIE XYZ (FORMAT=32-bit_rle_xyze)"
          : rec709   ? "Rec.709 RGB"
                     : "RGB in the primaries of its PRIMARIES line (" + primaries_text(*header.primaries) + ")";
  note += changed_space ? fmt::format(" converted to {}", picker_space_label(image.texel_space))
                        : fmt::format(" kept in {}", picker_space_label(image.texel_space));
  if (scaled) {
    const auto& c = header.color_correction;
    note += fmt::format(", divided by its header's {} to radiance",
                        header.color_correction == std::array<double, 3>{1.0, 1.0, 1.0}
                            ? fmt::format("EXPOSURE {:g}", header.exposure)
                            : fmt::format("EXPOSURE {:g} and COLORCORR {:g} {:g} {:g}", header.exposure, c[0], c[1],
                                          c[2]));
  }
  return note + clipped_texels_text(clipped, image);
}

// Radiance pictures are read by Prism's own reader (io/radiance_hdr_reader.h): linear whatever the
// encoding asked. A colour texture's texels are radiance in the space `content` asks for
// (radiance_conversion); data is kept as stored.
TextureImage decode_radiance(std::span<const unsigned char> bytes, std::string_view name, const TextureLimits& limits,
                             TextureContent content) {
  const RadianceHeader header = read_radiance_header(bytes, name);
  check_image_dimensions(header.width, header.height, limits.max_dimension, name);
  std::optional<Mat3> conversion;
  ColorPickerSpace target = ColorPickerSpace::srgb;
  bool changes_space = false;
  if (is_color_content(content)) {
    const color::ColorSpace file_space = radiance_color_space(header, name);
    target = texel_space_for(content, file_space);
    changes_space = radiance_changes_space(header, file_space, target);
    conversion = radiance_conversion(header, file_space, target, changes_space);
  }
  if (limits.budget) {
    const TextureMemoryNeed need = radiance_memory(header, conversion.has_value());
    limits.budget->reserve(need.texel_bytes, need.transient_bytes,
                           fmt::format("texture '{}' ({}x{}, 3 channels)", name, header.width, header.height));
  }
  TextureImage image;
  image.name = std::string(name);
  image.rgbe = read_radiance_texels(bytes, header, name);
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  image.channels = 3;
  image.texel_space = target;
  if (conversion) {
    image.texels = radiance_texels_as_floats(image.rgbe, Vec3d(1.0));  // the factors are in the matrix
    image.rgbe = {};
    const std::size_t clipped = convert_texels(image, *conversion, target);
    image.primaries_note = radiance_note(header, changes_space, image, clipped);
  }
  return image;
}

// `format` (png or jpeg) is detect_image_format's answer for `bytes`, which the caller has.
TextureImage decode_with_stb(std::span<const unsigned char> bytes, ImageFileFormat format, std::string_view name,
                             TextureEncoding encoding, const TextureLimits& limits, TextureContent content,
                             ImageColorTagUse tag_use) {
  if (format == ImageFileFormat::jpeg) check_jpeg_huffman_tables(bytes, name);
  if (format == ImageFileFormat::png) {
    if (const auto cleaned = without_empty_idat_chunks(bytes, name))
      return decode_with_stb(*cleaned, format, name, encoding, limits, content, tag_use);
  }
  // A colour texture's tags (image_color_tags.h), read before the pixels: a refusal costs
  // no decode.
  std::optional<ImageColorTags> tags;
  if (tag_use == ImageColorTagUse::honour && encoding == TextureEncoding::srgb && is_color_content(content))
    tags = format == ImageFileFormat::png ? read_png_color_tags(bytes, name) : read_jpeg_color_tags(bytes, name);
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw IoError(fmt::format("cannot read image '{}': file too large", name));
  const auto header = stb_header(bytes);
  if (!header) throw IoError(fmt::format("cannot read image '{}': {}", name, stbi_failure_reason()));
  // Plain variables, not a structured binding: the lambda below captures them (clang 14
  // cannot capture bindings), and decode() writes them back.
  int width = header->width, height = header->height, channels = header->channels;
  const int decoded_bytes_per_sample = header->decoded_bytes_per_sample;
  check_image_dimensions(width, height, limits.max_dimension, name);
  reserve_texels(limits, *header, name);
  TextureImage image;
  image.name = std::string(name);
  StbInput input(bytes);
  const auto check = [&](const void* pixels) {
    if (!pixels) throw IoError(fmt::format("cannot read image '{}': {}", name, stbi_failure_reason()));
    if (input.ran_past_end()) throw IoError(fmt::format("cannot read image '{}': the file is truncated", name));
    image.width = width, image.height = height, image.channels = channels;
  };
  if (decoded_bytes_per_sample == 2) {
    const auto pixels = input.decode(&stbi_load_16_from_callbacks, width, height, channels);
    check(pixels.get());
    decode_16_bit_codes(pixels.get(), image, encoding, tags ? &*tags : nullptr);
  } else {
    const bool as_rgba = header->decoded_channels != header->channels;
    const auto pixels =
        input.decode(&stbi_load_from_callbacks, width, height, channels, as_rgba ? header->decoded_channels : 0);
    check(pixels.get());
    if (as_rgba && channels != 3)
      throw IoError(fmt::format("cannot read image '{}': its header and its data disagree on the channels", name));
    const auto texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (!as_rgba) {
      image.codes.assign(pixels.get(), pixels.get() + texels * static_cast<std::size_t>(channels));
    } else {  // RGBA from an RGB JPEG (stb_header): the alpha of 255 stays behind
      image.codes.resize(texels * 3);
      const unsigned char* rgba = pixels.get();
      unsigned char* rgb = image.codes.data();
      // Four bytes copied per texel, the fourth overwritten by the next texel's first (one
      // load and one store each instead of three); the last texel's three alone.
      for (std::size_t t = 0; t + 1 < texels; ++t) std::memcpy(rgb + 3 * t, rgba + 4 * t, 4);
      if (texels > 0) std::memcpy(rgb + 3 * (texels - 1), rgba + 4 * (texels - 1), 3);
    }
    image.encoding = encoding;
    if (tags && !tags->srgb) decode_tagged_8_bit_codes(image, *tags, limits);
  }
  if (tags) convert_tagged_texels(image, *tags, content);
  return image;
}

// The texels of an OpenEXR whose header check_openexr_header passed, as they are stored.
TextureImage read_openexr_texels(const std::filesystem::path& path, const OpenExrFirstPart& layout, long width,
                                 long height);

// The primaries an OpenEXR's `chromaticities` attribute names: a file without the
// attribute has OpenEXR's default, Rec.709 with D65.
Imf::Chromaticities file_chromaticities(const Imf::Header& header) {
  return Imf::hasChromaticities(header) ? Imf::chromaticities(header) : Imf::Chromaticities();
}

color::Primaries primaries_of(const Imf::Chromaticities& c) {
  return {{c.red.x, c.red.y}, {c.green.x, c.green.y}, {c.blue.x, c.blue.y}, {c.white.x, c.white.y}};
}

// The colour space of an OpenEXR's chromaticities (file_chromaticities).
color::ColorSpace openexr_primaries(const color::Primaries& p, const std::string& name) {
  try {
    return color::make_color_space(name, p);
  } catch (const Error& e) {
    throw IoError(fmt::format("cannot read image '{}': its chromaticities are no colour space ({})", name, e.what()));
  }
}

// A colour texture's texels follow its chromaticities into the space `content` asks for;
// data (normal maps, roughness) is read as stored.
TextureImage read_openexr(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                          const TextureLimits& limits, TextureContent content) {
  const std::string name = path.string();
  const int max_dimension = limits.max_dimension;
  const OpenExrFirstPart layout = check_openexr_header(bytes, max_dimension, name);
  long width = 0, height = 0;
  std::optional<Imf::Header> header;
  try {
    // Size check from the header alone; the pixels are read below.
    Imf::InputFile in(path.c_str());
    header = in.header();
    const Imath::Box2i dw = in.header().dataWindow();
    width = static_cast<long>(dw.max.x) - dw.min.x + 1, height = static_cast<long>(dw.max.y) - dw.min.y + 1;
    check_image_dimensions(width, height, max_dimension, name);
    if (layout.channels == 0)
      throw IoError(fmt::format("cannot read image '{}': it has no R, G, B or Y channel (a texture reads R, G, B, "
                                "or Y as grey)", name));
    if (limits.budget) {
      const TextureMemoryNeed need = openexr_memory(width, height, layout.channels, layout.half);
      limits.budget->reserve(need.texel_bytes, need.transient_bytes,
                             fmt::format("texture '{}' ({}x{}, {} channels)", name, width, height, layout.channels));
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read image '{}': {}", name, e.what()));
  }
  TextureImage image = read_openexr_texels(path, layout, width, height);
  if (is_color_content(content) && image.channels == 3) {
    // The file's colour space is built once, both to choose the target and to convert; a
    // conversion is needed where the primaries differ from the target's (Bradford between
    // whites).
    const color::Primaries file = primaries_of(file_chromaticities(*header));
    const color::ColorSpace file_space = openexr_primaries(file, name);
    const ColorPickerSpace target = texel_space_for(content, file_space);
    const color::ColorSpace& target_space = picker_color_space(target);
    if (same_primaries(file, target_space)) {
      image.texel_space = target;
    } else {
      // A Rec.709 file (labelled, or without the attribute) going into a wider space loses
      // nothing and gets no note; other primaries are named, and clipping is counted.
      const std::size_t clipped = convert_texels(image, color::conversion_matrix(file_space, target_space), target);
      const bool rec709 = same_primaries(file, color::color_space("srgb"));
      if (!rec709 || clipped)
        image.primaries_note =
            fmt::format("texture '{}': {} converted to {}{}", image.name,
                        rec709 ? std::string("Rec.709 RGB")
                               : "RGB in the primaries of its chromaticities (" + primaries_text(file) + ")",
                        picker_space_label(target), clipped_texels_text(clipped, image));
    }
  }
  return image;
}

TextureImage read_openexr_texels(const std::filesystem::path& path, const OpenExrFirstPart& layout, long width,
                                 long height) {
  const std::string name = path.string();
  TextureImage image;
  image.name = name;
  image.channels = layout.channels;
  const std::vector<std::string> names = layout.channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                                              : std::vector<std::string>{"Y"};
  // HALF channels stay half (read straight into place, 2 bytes per sample; lookups decode
  // each exactly, core/half_float.h); anything else becomes float texels (as does a file
  // whose channels OpenEXR finds otherwise than the header walk did: read_exr_halves checks
  // them again). Luminance-only files are one-channel (grey) textures.
  if (layout.half) {
    if (auto halves = read_exr_halves(path, names)) {
      image.width = halves->width;
      image.height = halves->height;
      image.halves = std::move(halves->values);
      return image;
    }
  }
  if (layout.channels == 3) {
    ExrFile exr = read_exr(path);
    image.width = exr.image.width;
    image.height = exr.image.height;
    image.texels = std::move(exr.image.rgb);
    return image;
  }
  auto luminance = read_exr_channels(path, names);
  if (!luminance) throw IoError(fmt::format("cannot read image '{}': its Y channel went missing", name));
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.texels = std::move(*luminance);
  return image;
}


}  // namespace

ImageFileFormat detect_image_format(std::span<const unsigned char> head) {
  if (starts_with(head, "\x89PNG\r\n\x1a\n")) return ImageFileFormat::png;
  if (starts_with(head, "\xff\xd8\xff")) return ImageFileFormat::jpeg;
  if (starts_with(head, "#?RADIANCE") || starts_with(head, "#?RGBE")) return ImageFileFormat::radiance_hdr;
  if (starts_with(head, "\x76\x2f\x31\x01")) return ImageFileFormat::openexr;
  return ImageFileFormat::unknown;
}

TextureImage decode_texture_memory(std::span<const unsigned char> bytes, std::string_view name,
                                   TextureEncoding encoding, const TextureLimits& limits, TextureContent content,
                                   ImageColorTagUse tag_use) {
  switch (const ImageFileFormat format = detect_image_format(bytes)) {
    case ImageFileFormat::png:
    case ImageFileFormat::jpeg:
      return decode_with_stb(bytes, format, name, encoding, limits, content, tag_use);
    case ImageFileFormat::radiance_hdr:
      return decode_radiance(bytes, name, limits, content);
    case ImageFileFormat::openexr:
      throw IoError(fmt::format("cannot read image '{}': OpenEXR images are read from files only", name));
    case ImageFileFormat::unknown:
      break;
  }
  throw IoError(fmt::format("cannot read image '{}': not a PNG, JPEG, Radiance HDR or OpenEXR file (wrong magic)", name));
}

std::optional<TextureMemoryNeed> texture_memory_need(std::span<const unsigned char> bytes) {
  // The numbers decode_radiance, read_openexr and decode_with_stb reserve, from the same header.
  const ImageFileFormat format = detect_image_format(bytes);
  if (format == ImageFileFormat::radiance_hdr) {
    try {
      const RadianceHeader header = read_radiance_header(bytes, "");
      if (header.width < 1 || header.height < 1) return std::nullopt;
      return radiance_memory(header, radiance_may_convert(header));
    } catch (const IoError&) {
      return std::nullopt;
    }
  }
  if (format == ImageFileFormat::openexr) {  // read_openexr's half or float RGB texels
    try {
      const OpenExrFirstPart part = check_openexr_header(bytes, std::numeric_limits<int>::max(), "");
      if (part.channels == 0) return std::nullopt;  // read_openexr reports it
      return openexr_memory(part.width, part.height, part.channels, part.half);
    } catch (const IoError&) {
      return std::nullopt;
    }
  }
  if (format != ImageFileFormat::png && format != ImageFileFormat::jpeg) return std::nullopt;
  const auto header = stb_header(bytes);
  if (!header) return std::nullopt;
  return texel_memory(*header);
}

std::optional<TextureMemoryNeed> texture_file_memory_need(const std::filesystem::path& path) {
  try {
    return texture_memory_need(read_file_bytes(path, "image"));
  } catch (const IoError&) {
    return std::nullopt;
  }
}

ImageFileFormat detect_image_file_format(const std::filesystem::path& path) {
  std::array<unsigned char, 16> head{};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IoError(fmt::format("cannot read image '{}': {}", path.string(),
                              std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("cannot read image '{}': cannot open it", path.string()));
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (in.gcount() == 0) throw IoError(fmt::format("cannot read image '{}': the file is empty", path.string()));
  return detect_image_format(head);
}

TextureImage read_texture_file(const std::filesystem::path& path, TextureEncoding encoding,
                               const TextureLimits& limits, TextureContent content) {
  const ImageFileFormat format = detect_image_file_format(path);
  const std::vector<unsigned char> bytes = read_file_bytes(path, "image");
  if (format == ImageFileFormat::openexr)
    return read_openexr(path, bytes, limits, content);
  return decode_texture_memory(bytes, path.string(), encoding, limits, content);
}

}  // namespace prism
