#include "prism/io/radiance_hdr_writer.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/radiance_rle.h"

namespace prism {
namespace {

bool is_identity(const Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (m(r, c) != (r == c ? 1.0 : 0.0)) return false;
  return true;
}

// Appends one component of a scanline (every 4th byte from `first`) in the "new" run-length
// encoding: a run of 4 or more equal bytes becomes (128 + count, value), count ≤ 127; the
// bytes between runs are dumps (count, bytes...), count ≤ 128.
void append_component(std::string& out, const std::vector<unsigned char>& scanline, std::size_t first, std::size_t width) {
  const auto at = [&](std::size_t x) { return scanline[4 * x + first]; };
  std::size_t x = 0;
  while (x < width) {
    // The next run of at least 4 from here on, if any.
    std::size_t run_start = x, run_length = 0;
    for (; run_start < width; ++run_start) {
      run_length = 1;
      while (run_start + run_length < width && run_length < 127 && at(run_start + run_length) == at(run_start))
        ++run_length;
      if (run_length >= 4) break;
    }
    if (run_start >= width) run_start = width, run_length = 0;
    while (x < run_start) {  // dumps up to the run
      const std::size_t count = std::min<std::size_t>(128, run_start - x);
      out += static_cast<char>(count);
      for (std::size_t i = 0; i < count; ++i) out += static_cast<char>(at(x + i));
      x += count;
    }
    if (run_length >= 4) {
      out += static_cast<char>(128 + run_length);
      out += static_cast<char>(at(run_start));
      x = run_start + run_length;
    }
  }
}

}  // namespace

RgbeBytes encode_rgbe(float r, float g, float b) {
  const auto usable = [](float v) { return std::isfinite(v) && v > 0.0f ? static_cast<double>(v) : 0.0; };
  const double c[3] = {usable(r), usable(g), usable(b)};
  const double largest = std::max({c[0], c[1], c[2]});
  // Below the smallest normal exponent (2^-128 · 255/256) the pixel is black.
  if (!(largest >= 0x1p-128)) return {};
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest = m · 2^exponent, m ∈ [0.5, 1)
  // Mantissas in units of 2^(exponent − 8); rounding the largest up to 256 moves it to the
  // next exponent.
  if (std::nearbyint(std::ldexp(largest, 8 - exponent)) >= 256.0) ++exponent;
  if (exponent > 127) {  // beyond the format: the largest representable value, 255 · 2^119
    exponent = 127;
  }
  RgbeBytes out;
  unsigned char* bytes[3] = {&out.r, &out.g, &out.b};
  for (int k = 0; k < 3; ++k)
    *bytes[k] = static_cast<unsigned char>(std::min(255.0, std::nearbyint(std::ldexp(c[k], 8 - exponent))));
  out.e = static_cast<unsigned char>(exponent + 128);
  return out;
}

RadianceWriteReport write_radiance_hdr(const std::filesystem::path& path, const ImageRgbF& image,
                                       const color::ColorSpace& space, std::string_view software) {
  if (image.width < 1 || image.height < 1 || image.rgb.size() != 3u * image.width * image.height)
    throw UsageError(fmt::format("cannot write '{}': an image of {}x{} pixels", path.string(), image.width, image.height));
  const bool xyz = is_identity(space.rgb_to_xyz);
  if (xyz && (std::abs(space.white.x - 1.0 / 3.0) > 1e-9 || std::abs(space.white.y - 1.0 / 3.0) > 1e-9))
    throw UsageError(fmt::format("cannot write '{}': Radiance XYZ is relative to the equal-energy white, not {} ({:.4f}, "
                                 "{:.4f})",
                                 path.string(), space.name, space.white.x, space.white.y));
  std::string out = "#?RADIANCE\n";
  out += fmt::format("SOFTWARE={}\n", software);
  if (xyz) {
    out += "FORMAT=32-bit_rle_xyze\n";
  } else {
    out += "FORMAT=32-bit_rle_rgbe\n";
    out += fmt::format("PRIMARIES= {:g} {:g} {:g} {:g} {:g} {:g} {:g} {:g}\n", space.red.x, space.red.y,
                       space.green.x, space.green.y, space.blue.x, space.blue.y, space.white.x, space.white.y);
  }
  out += fmt::format("\n-Y {} +X {}\n", image.height, image.width);

  RadianceWriteReport report;
  const auto width = static_cast<std::size_t>(image.width);
  const bool run_length = radiance_scanline_is_run_length(width);
  std::vector<unsigned char> scanline(4 * width);
  for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y) {
    for (std::size_t x = 0; x < width; ++x) {
      const float* p = image.rgb.data() + 3 * (y * width + x);
      if (!(p[0] >= 0.0f && p[1] >= 0.0f && p[2] >= 0.0f && std::isfinite(p[0]) && std::isfinite(p[1]) &&
            std::isfinite(p[2])))
        ++report.clipped_pixels;
      const RgbeBytes b = encode_rgbe(p[0], p[1], p[2]);
      scanline[4 * x] = b.r, scanline[4 * x + 1] = b.g, scanline[4 * x + 2] = b.b, scanline[4 * x + 3] = b.e;
    }
    if (!run_length) {
      out.append(reinterpret_cast<const char*>(scanline.data()), scanline.size());
      continue;
    }
    out += std::string{2, 2, static_cast<char>(width >> 8), static_cast<char>(width & 0xff)};
    for (std::size_t k = 0; k < 4; ++k) append_component(out, scanline, k, width);
  }

  AtomicFile file(path);
  {
    std::ofstream f(file.temporary_path(), std::ios::binary | std::ios::trunc);
    if (!f) throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
    f.write(out.data(), static_cast<std::streamsize>(out.size()));
    f.flush();
    if (!f) throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  }
  file.commit();
  return report;
}

}  // namespace prism
