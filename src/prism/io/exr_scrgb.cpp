#include "prism/io/exr_scrgb.h"

#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <fmt/format.h>

#include <exception>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/io/exr.h"

namespace prism {

void write_exr_scrgb(const std::filesystem::path& path, const ImageRgbF& image, double white_nits,
                     const ExrMetadata& metadata) {
  // scRGB uses the ITU-R BT.709 primaries and D65 white: take them from color/. Half floats,
  // as scRGB swap chains use.
  const color::ColorSpace& rec709 = color::color_space("srgb");
  const auto f = [](double v) { return static_cast<float>(v); };
  const ExrChromaticities c{f(rec709.red.x),   f(rec709.red.y),  f(rec709.green.x), f(rec709.green.y),
                            f(rec709.blue.x),  f(rec709.blue.y), f(rec709.white.x), f(rec709.white.y)};
  ExrWriteOptions options;
  options.pixel_type = ExrPixelType::half;
  options.white_luminance_nits = white_nits;
  write_exr(path, image, c, metadata, options);
}

double read_exr_white_luminance(const std::filesystem::path& path) {
  try {
    Imf::InputFile in(path.c_str());
    return Imf::hasWhiteLuminance(in.header()) ? Imf::whiteLuminance(in.header()) : 0.0;
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
}

}  // namespace prism
