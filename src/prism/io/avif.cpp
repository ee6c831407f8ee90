#include "prism/io/avif.h"

#include <avif/avif.h>
#include <fmt/format.h>

#include <cstdio>
#include <memory>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"

namespace prism {
namespace {

struct ImageDeleter {
  void operator()(avifImage* p) const { avifImageDestroy(p); }
};
struct EncoderDeleter {
  void operator()(avifEncoder* p) const { avifEncoderDestroy(p); }
};
struct DecoderDeleter {
  void operator()(avifDecoder* p) const { avifDecoderDestroy(p); }
};
using ImagePtr = std::unique_ptr<avifImage, ImageDeleter>;

void check(avifResult r, const std::filesystem::path& path, const char* what) {
  if (r != AVIF_RESULT_OK) throw IoError(fmt::format("cannot {} '{}': {}", what, path.string(), avifResultToString(r)));
}

// Decodes into `image`; returns the decoder's image (owned by the decoder).
ImagePtr decode(const std::filesystem::path& path) {
  std::unique_ptr<avifDecoder, DecoderDeleter> decoder(avifDecoderCreate());
  ImagePtr image(avifImageCreateEmpty());
  if (!decoder || !image) throw IoError("libavif: out of memory");
  check(avifDecoderReadFile(decoder.get(), image.get(), path.c_str()), path, "read");
  return image;
}

}  // namespace

void write_avif(const std::filesystem::path& path, const EncodedImage& in, const CicpInfo& cicp) {
  if (in.channels != 3) throw UsageError("AVIF output takes RGB images");
  if (in.bit_depth != 10 && in.bit_depth != 12) throw UsageError("AVIF bit depth must be 10 or 12");
  if (in.width <= 0 || in.height <= 0 || in.samples.size() != 3u * in.width * in.height)
    throw IoError(fmt::format("cannot write '{}': image has inconsistent size", path.string()));
  ImagePtr image(avifImageCreate(static_cast<uint32_t>(in.width), static_cast<uint32_t>(in.height),
                                 static_cast<uint32_t>(in.bit_depth), AVIF_PIXEL_FORMAT_YUV444));
  if (!image) throw IoError("libavif: out of memory");
  image->colorPrimaries = static_cast<avifColorPrimaries>(cicp.color_primaries);
  image->transferCharacteristics = static_cast<avifTransferCharacteristics>(cicp.transfer_characteristics);
  // Identity (H.273 MC 0): the planes hold G, B, R themselves; no YUV rounding.
  image->matrixCoefficients = AVIF_MATRIX_COEFFICIENTS_IDENTITY;
  image->yuvRange = cicp.video_full_range ? AVIF_RANGE_FULL : AVIF_RANGE_LIMITED;

  avifRGBImage rgb;
  avifRGBImageSetDefaults(&rgb, image.get());
  rgb.format = AVIF_RGB_FORMAT_RGB;
  rgb.depth = static_cast<uint32_t>(in.bit_depth);
  avifRGBImageAllocatePixels(&rgb);
  for (int y = 0; y < in.height; ++y) {
    auto* row = reinterpret_cast<std::uint16_t*>(rgb.pixels + std::size_t(y) * rgb.rowBytes);
    for (int i = 0; i < 3 * in.width; ++i) row[i] = in.samples[std::size_t(y) * 3 * in.width + i];
  }
  const avifResult converted = avifImageRGBToYUV(image.get(), &rgb);
  avifRGBImageFreePixels(&rgb);
  check(converted, path, "convert for");

  std::unique_ptr<avifEncoder, EncoderDeleter> encoder(avifEncoderCreate());
  if (!encoder) throw IoError("libavif: out of memory");
  encoder->minQuantizer = AVIF_QUANTIZER_LOSSLESS;
  encoder->maxQuantizer = AVIF_QUANTIZER_LOSSLESS;
  encoder->speed = AVIF_SPEED_FASTEST;
  avifRWData output = AVIF_DATA_EMPTY;
  const avifResult encoded = avifEncoderWrite(encoder.get(), image.get(), &output);
  if (encoded != AVIF_RESULT_OK) {
    avifRWDataFree(&output);
    check(encoded, path, "encode");
  }
  AtomicFile file(path);
  std::FILE* fp = std::fopen(file.temporary_path().c_str(), "wb");
  const bool ok = fp != nullptr && std::fwrite(output.data, 1, output.size, fp) == output.size;
  const bool closed = fp != nullptr && std::fclose(fp) == 0;
  avifRWDataFree(&output);
  if (!ok || !closed) throw IoError(fmt::format("cannot write '{}'", path.string()));
  file.commit();
}

AvifInfo read_avif_info(const std::filesystem::path& path) {
  const ImagePtr image = decode(path);
  AvifInfo info;
  info.width = static_cast<int>(image->width);
  info.height = static_cast<int>(image->height);
  info.bit_depth = static_cast<int>(image->depth);
  info.cicp.color_primaries = static_cast<std::uint8_t>(image->colorPrimaries);
  info.cicp.transfer_characteristics = static_cast<std::uint8_t>(image->transferCharacteristics);
  info.cicp.matrix_coefficients = static_cast<std::uint8_t>(image->matrixCoefficients);
  info.cicp.video_full_range = image->yuvRange == AVIF_RANGE_FULL ? 1 : 0;
  info.yuv444 = image->yuvFormat == AVIF_PIXEL_FORMAT_YUV444;
  return info;
}

EncodedImage read_avif(const std::filesystem::path& path) {
  const ImagePtr image = decode(path);
  avifRGBImage rgb;
  avifRGBImageSetDefaults(&rgb, image.get());
  rgb.format = AVIF_RGB_FORMAT_RGB;
  avifRGBImageAllocatePixels(&rgb);
  const avifResult r = avifImageYUVToRGB(image.get(), &rgb);
  EncodedImage out;
  out.width = static_cast<int>(image->width);
  out.height = static_cast<int>(image->height);
  out.bit_depth = static_cast<int>(image->depth);
  out.channels = 3;
  if (r == AVIF_RESULT_OK)
    for (int y = 0; y < out.height; ++y) {
      const auto* row = reinterpret_cast<const std::uint16_t*>(rgb.pixels + std::size_t(y) * rgb.rowBytes);
      out.samples.insert(out.samples.end(), row, row + 3 * out.width);
    }
  avifRGBImageFreePixels(&rgb);
  check(r, path, "convert");
  return out;
}

}  // namespace prism
