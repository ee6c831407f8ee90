#include "prism/io/png_hdr.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/libpng_support.h"

namespace prism {
namespace {

using libpng::ErrorState;
using libpng::FileCloser;

// One ancillary chunk for png_set_unknown_chunks; `data` must outlive the write.
png_unknown_chunk make_chunk(const char (&name)[5], std::uint8_t* data, std::size_t size) {
  png_unknown_chunk c{};
  std::memcpy(c.name, name, 5);
  c.data = data;
  c.size = size;
  c.location = PNG_HAVE_IHDR;  // before PLTE and IDAT, as PNG-3 requires for all three
  return c;
}

// As in png.cpp: the libpng calls live in a frame with only trivially destructible
// objects, so the longjmp out of it is well defined.
bool write_all(std::FILE* fp, const EncodedImage& image, const PngColorMetadata& meta, png_unknown_chunk* chunks,
               int n_chunks, png_textp text, int n_text, png_bytep* rows, ErrorState& err) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &err, libpng::on_error, libpng::on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, fp);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
               image.bit_depth, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (meta.srgb_chunk) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (!meta.icc_profile.empty())
    png_set_iCCP(png, info, meta.icc_profile_name.c_str(), PNG_COMPRESSION_TYPE_BASE, meta.icc_profile.data(),
                 static_cast<png_uint_32>(meta.icc_profile.size()));
  if (n_chunks > 0) {
    // cICP is not safe-to-copy (4th letter upper case): libpng writes such unknown chunks
    // only when told to keep them always.
    static const png_byte kNames[] = "cICP\0mDCv\0cLLi";
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_ALWAYS, kNames, 3);
    png_set_unknown_chunks(png, info, chunks, n_chunks);
    for (int i = 0; i < n_chunks; ++i) png_set_unknown_chunk_location(png, info, i, PNG_HAVE_IHDR);
  }
  if (n_text > 0) png_set_text(png, info, text, n_text);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png_with_color_metadata(const std::filesystem::path& path, const EncodedImage& image,
                                   const PngColorMetadata& meta) {
  if (image.width <= 0 || image.height <= 0 || image.channels != 3 ||
      (image.bit_depth != 8 && image.bit_depth != 16) ||
      image.samples.size() != static_cast<std::size_t>(image.width) * image.height * 3)
    throw IoError(fmt::format("cannot write '{}': image must be 8- or 16-bit RGB of consistent size", path.string()));
  if (meta.srgb_chunk && !meta.icc_profile.empty())
    throw IoError(fmt::format("cannot write '{}': a PNG has an sRGB chunk or an ICC profile, not both", path.string()));

  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3 * (image.bit_depth / 8);
  std::vector<png_byte> bytes(row_bytes * image.height);
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    const std::uint16_t v = image.samples[i];
    if (image.bit_depth == 8) {
      bytes[i] = static_cast<png_byte>(v > 255 ? 255 : v);
    } else {  // big-endian 16-bit samples
      bytes[2 * i] = static_cast<png_byte>(v >> 8);
      bytes[2 * i + 1] = static_cast<png_byte>(v & 0xff);
    }
  }
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = bytes.data() + y * row_bytes;

  std::array<std::uint8_t, 4> cicp{};
  std::array<std::uint8_t, 24> mdcv{};
  std::array<std::uint8_t, 8> clli{};
  std::vector<png_unknown_chunk> chunks;
  if (meta.cicp) {
    cicp = cicp_chunk_data(*meta.cicp);
    chunks.push_back(make_chunk("cICP", cicp.data(), cicp.size()));
  }
  if (meta.mastering_display) {
    mdcv = mdcv_chunk_data(*meta.mastering_display);
    chunks.push_back(make_chunk("mDCv", mdcv.data(), mdcv.size()));
  }
  if (meta.content_light_level) {
    clli = clli_chunk_data(*meta.content_light_level);
    chunks.push_back(make_chunk("cLLi", clli.data(), clli.size()));
  }

  AtomicFile file(path);
  std::unique_ptr<std::FILE, FileCloser> fp(std::fopen(file.temporary_path().c_str(), "wb"));
  if (!fp) throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  std::vector<png_text> text = libpng::text_chunks(meta.text);
  ErrorState err;
  if (!write_all(fp.get(), image, meta, chunks.data(), static_cast<int>(chunks.size()), text.data(),
                 static_cast<int>(text.size()), rows.data(), err))
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), err.message));
  if (std::fflush(fp.get()) != 0 || std::ferror(fp.get()))
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  fp.reset();
  file.commit();
}

}  // namespace prism
