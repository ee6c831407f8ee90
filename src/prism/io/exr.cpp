#include "prism/io/exr.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <Imath/half.h>
#include <fmt/format.h>

#include <exception>
#include <tuple>
#include <utility>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/openexr_header.h"

namespace prism {
namespace {

// `names.size()` interleaved channels of `type` (`sample_bytes` each) at `base`, whose
// first pixel is (min_x, min_y); missing channels read as 0.
Imf::FrameBuffer interleaved_frame_buffer(char* base, Imf::PixelType type, std::size_t sample_bytes, int width,
                                          int min_x, int min_y, const std::vector<std::string>& names) {
  // OpenEXR addresses pixels by absolute data-window coordinates: shift the base pointer.
  const std::size_t x_stride = names.size() * sample_bytes, y_stride = x_stride * static_cast<std::size_t>(width);
  char* origin = base - static_cast<std::ptrdiff_t>(min_x) * static_cast<std::ptrdiff_t>(x_stride) -
                 static_cast<std::ptrdiff_t>(min_y) * static_cast<std::ptrdiff_t>(y_stride);
  Imf::FrameBuffer fb;
  for (std::size_t c = 0; c < names.size(); ++c)
    fb.insert(names[c], Imf::Slice(type, origin + c * sample_bytes, x_stride, y_stride, 1, 1, 0.0));
  return fb;
}

// `names.size()` interleaved float channels.
Imf::FrameBuffer float_frame_buffer(float* base, int width, int min_x, int min_y, const std::vector<std::string>& names) {
  return interleaved_frame_buffer(reinterpret_cast<char*>(base), Imf::FLOAT, sizeof(float), width, min_x, min_y, names);
}

Imf::FrameBuffer rgb_frame_buffer(float* base, int width, int min_x, int min_y) {
  return float_frame_buffer(base, width, min_x, min_y, {"R", "G", "B"});
}

// The data window's width and height, refused when absurd before anything is allocated
// (the same limit as textures).
std::pair<int, int> checked_size(const Imath::Box2i& dw) {
  const long width = static_cast<long>(dw.max.x) - dw.min.x + 1, height = static_cast<long>(dw.max.y) - dw.min.y + 1;
  constexpr long kMaxSide = 32768;
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
    throw IoError(fmt::format("image size {}x{} is out of range", width, height));
  return {static_cast<int>(width), static_cast<int>(height)};
}

// The same for half-float pixels (written only; pixels start at (0, 0)).
Imf::FrameBuffer rgb_half_frame_buffer(half* base, int width) {
  const std::size_t x_stride = 3 * sizeof(half), y_stride = x_stride * static_cast<std::size_t>(width);
  Imf::FrameBuffer fb;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c)
    fb.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(base) + c * sizeof(half), x_stride, y_stride));
  return fb;
}

}  // namespace

void write_exr(const std::filesystem::path& path, const ImageRgbF& image, const ExrChromaticities& c,
               const ExrMetadata& metadata, const ExrWriteOptions& options,
               const std::vector<ExrChannelGroup>& extra_channels) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != 3u * image.width * image.height)
    throw IoError(fmt::format("cannot write '{}': image has inconsistent size", path.string()));
  for (const auto& g : extra_channels)
    if (g.names.empty() || g.pixels.size() != g.names.size() * image.width * image.height)
      throw IoError(fmt::format("cannot write '{}': extra channels have inconsistent size", path.string()));
  AtomicFile file(path);
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const bool as_half = options.pixel_type == ExrPixelType::half;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(as_half ? Imf::HALF : Imf::FLOAT));
    for (const auto& g : extra_channels)
      for (const auto& name : g.names) {
        if (header.channels().findChannel(name) != nullptr)
          throw IoError(fmt::format("channel '{}' is given twice", name));
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      }
    Imf::addChromaticities(header, Imf::Chromaticities(Imath::V2f(c.red_x, c.red_y), Imath::V2f(c.green_x, c.green_y),
                                                       Imath::V2f(c.blue_x, c.blue_y), Imath::V2f(c.white_x, c.white_y)));
    for (const auto& [k, v] : metadata.strings) header.insert(k, Imf::StringAttribute(v));
    for (const auto& [k, v] : metadata.ints) header.insert(k, Imf::IntAttribute(v));
    for (const auto& [k, v] : metadata.doubles) header.insert(k, Imf::DoubleAttribute(v));
    if (options.white_luminance_nits) Imf::addWhiteLuminance(header, static_cast<float>(*options.white_luminance_nits));
    std::vector<float> pixels;
    std::vector<half> half_pixels;
    Imf::OutputFile out(file.temporary_path().c_str(), header);
    Imf::FrameBuffer fb;
    if (as_half) {
      half_pixels.assign(image.rgb.begin(), image.rgb.end());
      fb = rgb_half_frame_buffer(half_pixels.data(), image.width);
    } else {
      pixels = image.rgb;
      fb = rgb_frame_buffer(pixels.data(), image.width, 0, 0);
    }
    // OpenEXR only reads through the slices' pointers while writing; the const_cast never
    // leads to a write.
    for (const auto& g : extra_channels) {
      const Imf::FrameBuffer extra = float_frame_buffer(const_cast<float*>(g.pixels.data()), image.width, 0, 0, g.names);
      for (auto it = extra.begin(); it != extra.end(); ++it) fb.insert(it.name(), it.slice());
    }
    out.setFrameBuffer(fb);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot write '{}': {}", path.string(), e.what()));
  }
  file.commit();
}

ExrFile read_exr(const std::filesystem::path& path) {
  check_openexr_file_header(path);  // before OpenEXR allocates what a header declares
  ExrFile result;
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& header = in.header();
    const Imath::Box2i dw = header.dataWindow();
    const auto [width, height] = checked_size(dw);
    result.image.width = width;
    result.image.height = height;
    result.image.rgb.assign(3u * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
    // R, G and B (a missing one reads as 0); a luminance-only file (Y, no R, G or B) as grey.
    const Imf::ChannelList& channels = header.channels();
    const bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
    if (!rgb && !channels.findChannel("Y")) throw IoError("it has no R, G, B or Y channel");
    // (A frame buffer holds one slice per name: Y goes to R, then R is copied to G and B.)
    in.setFrameBuffer(float_frame_buffer(result.image.rgb.data(), width, dw.min.x, dw.min.y,
                                         rgb ? std::vector<std::string>{"R", "G", "B"}
                                             : std::vector<std::string>{"Y", "G", "B"}));
    in.readPixels(dw.min.y, dw.max.y);
    if (!rgb)
      for (std::size_t i = 0; i < result.image.rgb.size(); i += 3) {
        std::vector<float>& rgb_values = result.image.rgb;
        rgb_values[i + 1] = rgb_values[i + 2] = rgb_values[i];
      }
    if (Imf::hasChromaticities(header)) {
      const Imf::Chromaticities& ch = Imf::chromaticities(header);
      result.has_chromaticities = true;
      result.chromaticities = {ch.red.x, ch.red.y, ch.green.x, ch.green.y, ch.blue.x, ch.blue.y, ch.white.x, ch.white.y};
    }
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) result.metadata.strings[it.name()] = s->value();
      if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&it.attribute())) result.metadata.ints[it.name()] = i->value();
      if (const auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&it.attribute())) result.metadata.doubles[it.name()] = d->value();
    }
  } catch (const IoError& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
  return result;
}

namespace {

bool half_at_full_resolution(const Imf::Channel* c) {
  return c != nullptr && c->type == Imf::HALF && c->xSampling == 1 && c->ySampling == 1;
}

}  // namespace

std::optional<ExrHalves> read_exr_halves(const std::filesystem::path& path, const std::vector<std::string>& names) {
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& header = in.header();
    for (const std::string& name : names)
      if (!half_at_full_resolution(header.channels().findChannel(name))) return std::nullopt;
    const Imath::Box2i dw = header.dataWindow();
    ExrHalves result;
    std::tie(result.width, result.height) = checked_size(dw);
    const std::size_t texels = static_cast<std::size_t>(result.width) * static_cast<std::size_t>(result.height);
    result.values.assign(names.size() * texels, 0);
    // Imath's half is its 16 bits (a trivially copyable wrapper of imath_half_bits_t).
    static_assert(sizeof(half) == sizeof(std::uint16_t));
    in.setFrameBuffer(interleaved_frame_buffer(reinterpret_cast<char*>(result.values.data()), Imf::HALF,
                                               sizeof(std::uint16_t), result.width, dw.min.x, dw.min.y, names));
    in.readPixels(dw.min.y, dw.max.y);
    return result;
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
}

std::optional<std::vector<float>> read_exr_channels(const std::filesystem::path& path,
                                                    const std::vector<std::string>& names) {
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& header = in.header();
    for (const auto& n : names)
      if (header.channels().findChannel(n) == nullptr) return std::nullopt;
    const Imath::Box2i dw = header.dataWindow();
    const auto [width, height] = checked_size(dw);
    std::vector<float> pixels(names.size() * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
    in.setFrameBuffer(float_frame_buffer(pixels.data(), width, dw.min.x, dw.min.y, names));
    in.readPixels(dw.min.y, dw.max.y);
    return pixels;
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
}

std::optional<ImageRgbF> read_exr_vector_layer(const std::filesystem::path& path, const std::string& name) {
  check_openexr_file_header(path);
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& header = in.header();
    const std::vector<std::string> names = {name + ".x", name + ".y", name + ".z"};
    for (const std::string& n : names)
      if (header.channels().findChannel(n) == nullptr) return std::nullopt;
    const Imath::Box2i dw = header.dataWindow();
    ImageRgbF layer;
    std::tie(layer.width, layer.height) = checked_size(dw);  // as every reader here, before allocating
    layer.rgb.assign(3 * static_cast<std::size_t>(layer.width) * static_cast<std::size_t>(layer.height), 0.0f);
    in.setFrameBuffer(float_frame_buffer(layer.rgb.data(), layer.width, dw.min.x, dw.min.y, names));
    in.readPixels(dw.min.y, dw.max.y);
    return layer;
  } catch (const std::exception& e) {
    throw IoError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
}

}  // namespace prism
