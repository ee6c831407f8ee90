#include "prism/io/png.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/libpng_support.h"

namespace prism {
namespace {

using libpng::FileCloser;
using PngErrorState = libpng::ErrorState;

int color_type_for(int channels) {
  switch (channels) {
    case 1: return PNG_COLOR_TYPE_GRAY;
    case 2: return PNG_COLOR_TYPE_GRAY_ALPHA;
    case 3: return PNG_COLOR_TYPE_RGB;
    default: return PNG_COLOR_TYPE_RGB_ALPHA;
  }
}

}  // namespace

std::vector<png_text> libpng::text_chunks(const std::vector<PngText>& entries) {
  std::vector<png_text> text;
  for (const PngText& e : entries) {
    if (e.keyword.empty() || e.keyword.size() > 79)
      throw IoError(fmt::format("PNG text keyword '{}' must have 1 to 79 characters", e.keyword));
    png_text t{};
    t.compression = PNG_TEXT_COMPRESSION_NONE;
    t.key = const_cast<png_charp>(e.keyword.c_str());  // libpng copies; it does not write through these
    t.text = const_cast<png_charp>(e.text.c_str());
    t.text_length = e.text.size();
    text.push_back(t);
  }
  return text;
}

namespace {

// The libpng calls live in functions whose frames hold only trivially destructible
// objects, so longjmp out of them is well defined. Returns false on error.
bool write_rows(std::FILE* fp, const EncodedImage& image, bool srgb, png_bytep* rows, PngErrorState& err) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &err, libpng::on_error, libpng::on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, fp);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
               image.bit_depth, color_type_for(image.channels), PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, channels = 0;
  bool srgb = false;
};

// Reads the header and applies the expansions; rows are read by read_body.
bool read_header(png_structp png, png_infop info, std::FILE* fp, PngHeader& h) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, fp);
  png_set_user_limits(png, 32768, 32768);
  png_read_info(png, info);
  int color_type = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (depth == 16) png_set_swap(png);  // little-endian uint16 in memory
  png_read_update_info(png, info);
  h.width = png_get_image_width(png, info);
  h.height = png_get_image_height(png, info);
  h.bit_depth = png_get_bit_depth(png, info);
  h.channels = png_get_channels(png, info);
  h.srgb = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
  return true;
}

bool read_body(png_structp png, png_infop info, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

}  // namespace

void write_png(const std::filesystem::path& path, const EncodedImage& image, const PngWriteOptions& options) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
      (image.bit_depth != 8 && image.bit_depth != 16) ||
      image.samples.size() != static_cast<std::size_t>(image.width) * image.height * image.channels)
    throw IoError(fmt::format("cannot write '{}': image has inconsistent size or format", path.string()));

  const std::size_t row_samples = static_cast<std::size_t>(image.width) * image.channels;
  const std::size_t row_bytes = row_samples * (image.bit_depth / 8);
  std::vector<png_byte> bytes(row_bytes * image.height);
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    const std::uint16_t v = image.samples[i];
    if (image.bit_depth == 8) {
      bytes[i] = static_cast<png_byte>(v > 255 ? 255 : v);
    } else {  // PNG stores 16-bit samples big-endian
      bytes[2 * i] = static_cast<png_byte>(v >> 8);
      bytes[2 * i + 1] = static_cast<png_byte>(v & 0xff);
    }
  }
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = bytes.data() + y * row_bytes;

  AtomicFile file(path);
  std::unique_ptr<std::FILE, FileCloser> fp(std::fopen(file.temporary_path().c_str(), "wb"));
  if (!fp) throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  PngErrorState err;
  if (!write_rows(fp.get(), image, options.srgb_chunk, rows.data(), err))
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), err.message));
  if (std::fflush(fp.get()) != 0 || std::ferror(fp.get()))
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  fp.reset();
  file.commit();
}

PngFile read_png(const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, FileCloser> fp(std::fopen(path.c_str(), "rb"));
  if (!fp) throw IoError(fmt::format("cannot read '{}': {}", path.string(), std::strerror(errno)));
  png_byte signature[8] = {};
  if (std::fread(signature, 1, 8, fp.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
    throw IoError(fmt::format("cannot read '{}': not a PNG file", path.string()));
  std::rewind(fp.get());

  PngErrorState err;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &err, libpng::on_error, libpng::on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw IoError(fmt::format("cannot read '{}': out of memory", path.string()));
  }
  PngHeader h;
  bool ok = read_header(png, info, fp.get(), h);
  PngFile result;
  if (ok) {
    png_textp text = nullptr;
    const int n_text = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < n_text; ++i)
      result.text.push_back(PngText{text[i].key, std::string(text[i].text, text[i].text_length)});
  }
  std::vector<png_byte> bytes;
  if (ok) {
    const std::size_t row_bytes = static_cast<std::size_t>(h.width) * h.channels * (h.bit_depth / 8);
    bytes.resize(row_bytes * h.height);
    std::vector<png_bytep> rows(h.height);
    for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = bytes.data() + y * row_bytes;
    ok = read_body(png, info, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) throw IoError(fmt::format("cannot read '{}': {}", path.string(), err.message));

  EncodedImage& image = result.image;
  image.width = static_cast<int>(h.width);
  image.height = static_cast<int>(h.height);
  image.channels = h.channels;
  image.bit_depth = h.bit_depth;
  image.samples.resize(static_cast<std::size_t>(h.width) * h.height * h.channels);
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    if (h.bit_depth == 16) {
      std::uint16_t v;
      std::memcpy(&v, bytes.data() + 2 * i, 2);
      image.samples[i] = v;
    } else {
      image.samples[i] = bytes[i];
    }
  }
  result.has_srgb_chunk = h.srgb;
  return result;
}

}  // namespace prism
