#include "prism/display/rendering_pipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/display/agx.h"
#include "prism/display/display_primaries.h"
#include "prism/display/pbr_neutral.h"
#include "prism/display/resampling.h"

namespace prism::display {
namespace {

constexpr std::size_t kPixelsPerTask = 16384;

void check_settings(const DisplaySettings& s, DisplayEncoding encoding) {
  const std::string name(rendering_name(s.rendering));
  require_rendering_target(s.rendering, s.odt);
  if (s.blue_correction != 0.0)
    throw UsageError("--blue-correction is an ACES 1 LMT: it does not apply to --rendering " + name);
  if (s.overlay) throw UsageError("--overlay composites in the ACES 1 ODT: it needs --rendering aces1");
  if (s.display_primaries && encoding == DisplayEncoding::scrgb)
    throw UsageError("scRGB is defined on Rec.709 primaries: --display-primaries needs another encoding");
}

}  // namespace

Vec3d rendering_display_linear(Rendering rendering, const Vec3d& rec709_linear) {
  switch (rendering) {
    case Rendering::agx: return agx_display_linear(rec709_linear);
    case Rendering::pbr_neutral: return pbr_neutral(rec709_linear);
    case Rendering::aces1: break;
  }
  throw UsageError("rendering_display_linear: aces1 runs through AcesOutputTransform");
}

DisplayImage apply_rendering_pipeline(const ImageRgbF& film_in, const color::ColorSpace& film_space,
                                      const DisplaySettings& s) {
  const OdtDescription& target = odt_description(s.odt);
  DisplayImage out;
  out.encoding = s.encoding.value_or(default_encoding(s.rendering, s.odt));
  check_settings(s, out.encoding);
  out.white_nits = target.white_nits;
  out.y_max_nits = target.white_nits;
  out.exposure_scale = exposure_scale(s, film_in, film_space);
  out.width = upscaled_size(film_in.width, s.render_scale);
  out.height = upscaled_size(film_in.height, s.render_scale);

  // Output primaries: the user's display, Rec.709 for scRGB, else the target's.
  const color::ColorSpace& rec709 = color::color_space("srgb");
  const color::ColorSpace& target_space = color::color_space(target.display_space);
  Mat3 to_output;
  if (s.display_primaries) {
    out.primaries = s.display_primaries->name;
    to_output = gamut_remap_matrix(target_space, *s.display_primaries) * color::conversion_matrix(rec709, target_space);
  } else if (out.encoding == DisplayEncoding::scrgb) {
    out.primaries = "srgb";
    to_output = Mat3::identity();
  } else {
    out.primaries = std::string(target.display_space);
    to_output = color::conversion_matrix(rec709, target_space);
  }
  for (auto& row : to_output.m)
    for (double& v : row) v *= target.white_nits;

  // Exposure (and bloom, which thresholds exposed values) in the film's space, then to Rec.709.
  Mat3 to_rec709 = color::conversion_matrix(film_space, rec709);
  const ImageRgbF* film = &film_in;
  ImageRgbF exposed;
  if (s.bloom.strength > 0.0) {
    exposed = film_in;
    for (float& v : exposed.rgb) v = std::isfinite(v) ? static_cast<float>(v * out.exposure_scale) : 0.0f;
    exposed = apply_bloom(exposed, s.bloom);
    film = &exposed;
  } else {
    for (auto& row : to_rec709.m)
      for (double& v : row) v *= out.exposure_scale;
  }

  // Display light (nits, output primaries) at the film's size.
  const std::size_t n_in = static_cast<std::size_t>(film->width) * film->height;
  ImageRgbF light{film->width, film->height, std::vector<float>(3 * n_in)};
  const bool clip = s.display_primaries.has_value();
  parallel_for(n_in, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec3d rgb{film->rgb[3 * i], film->rgb[3 * i + 1], film->rgb[3 * i + 2]};
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(rgb[c])) rgb[c] = 0.0;  // NaN/inf samples show as black
      const Vec3d nits = to_output * rendering_display_linear(s.rendering, to_rec709 * rgb);
      for (int c = 0; c < 3; ++c)
        light.rgb[3 * i + c] = static_cast<float>(clip ? std::clamp(nits[c], 0.0, target.white_nits) : nits[c]);
    }
  });
  if (light.width != out.width || light.height != out.height) light = upscale_bilinear(light, out.width, out.height);

  out.nits = std::move(light.rgb);
  out.code.resize(out.nits.size());
  parallel_for(out.nits.size(), kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out.code[i] = static_cast<float>(encode_display_nits(out.encoding, out.nits[i], out.white_nits));
  });
  return out;
}

}  // namespace prism::display
