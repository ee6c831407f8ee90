#include "prism/io/exr_scrgb.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <Imath/half.h>
#include <fmt/format.h>

#include <exception>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/io/atomic_file.h"

namespace prism {

void write_exr_scrgb(const std::filesystem::path& path, const ImageRgbF& image, double white_nits) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != 3u * image.width * image.height)
    throw IoError(fmt::format("cannot write '{}': image has inconsistent size", path.string()));
  AtomicFile file(path);
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::HALF));
    // scRGB uses the ITU-R BT.709 primaries and D65 white: take them from color/.
    const color::ColorSpace& rec709 = color::color_space("srgb");
    const auto xy = [](color::Chromaticity c) { return Imath::V2f(static_cast<float>(c.x), static_cast<float>(c.y)); };
    Imf::addChromaticities(header, Imf::Chromaticities(xy(rec709.red), xy(rec709.green), xy(rec709.blue), xy(rec709.white)));
    Imf::addWhiteLuminance(header, static_cast<float>(white_nits));
    // Half floats, as scRGB swap chains use (values beyond ±65504 saturate to ±inf).
    std::vector<half> pixels(image.rgb.begin(), image.rgb.end());
    const std::size_t xs = 3 * sizeof(half), ys = xs * static_cast<std::size_t>(image.width);
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      fb.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(pixels.data()) + c * sizeof(half), xs, ys));
    Imf::OutputFile out(file.temporary_path().c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), e.what()));
  }
  file.commit();
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
