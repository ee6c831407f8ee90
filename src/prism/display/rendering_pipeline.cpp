#include "prism/display/rendering_pipeline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/display/agx.h"
#include "prism/display/bloom.h"
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
  if (s.stretch_black) throw UsageError("--odt-stretch-black and --no-odt-stretch-black are ACES 1 settings");
  if (s.peak_nits && s.rendering != Rendering::aces2) throw UsageError("--peak-nits needs --rendering aces2");
  if (s.display_primaries && encoding == DisplayEncoding::scrgb)
    throw UsageError("scRGB is defined on Rec.709 primaries: --display-primaries needs another encoding");
}

// The light of one pixel under the rendering, in its light space: agx/pbr-neutral take linear
// Rec.709 and return light relative to white (× white_nits here); aces2 takes ACES2065-1 and
// returns nits in the target's primaries.
struct RenderingLight {
  Rendering rendering;
  double white_nits;
  std::optional<Aces2OutputTransform> aces2;
  Vec3d operator()(const Vec3d& in) const {
    if (aces2) return aces2->display_nits(in);
    const Vec3d rel = rendering_display_linear(rendering, in);
    return {rel[0] * white_nits, rel[1] * white_nits, rel[2] * white_nits};
  }
};

}  // namespace

Vec3d rendering_display_linear(Rendering rendering, const Vec3d& rec709_linear) {
  switch (rendering) {
    case Rendering::agx: return agx_display_linear(rec709_linear);
    case Rendering::pbr_neutral: return pbr_neutral(rec709_linear);
    case Rendering::aces1:
    case Rendering::aces2: break;
  }
  throw UsageError("rendering_display_linear: only agx and pbr-neutral are relative renderings");
}

Aces2Parameters aces2_parameters(const DisplaySettings& s) {
  const Aces2Preset preset = aces2_preset(s.odt);
  const double peak = s.peak_nits.value_or(preset.peak_nits);
  if (!(peak >= 100.0 && peak <= 10000.0)) throw UsageError("--peak-nits must be in [100, 10000]");
  return {peak, std::string(preset.limiting_primaries), std::string(odt_description(s.odt).display_space)};
}

DisplayImage apply_rendering_pipeline(const ImageRgbF& film_in, const color::ColorSpace& film_space,
                                      const DisplaySettings& s) {
  const OdtDescription& target = odt_description(s.odt);
  DisplayImage out;
  out.encoding = s.encoding.value_or(default_encoding(s.rendering, s.odt));
  check_settings(s, out.encoding);
  const bool aces2 = s.rendering == Rendering::aces2;
  RenderingLight light_of{s.rendering, target.white_nits, std::nullopt};
  if (aces2) light_of.aces2.emplace(aces2_parameters(s));
  // The display's peak: relative encodings put code 1 there; gamut remaps clip to it.
  const double peak = aces2 ? light_of.aces2->parameters().peak_luminance_nits : target.white_nits;
  out.white_nits = peak;
  out.y_max_nits = peak;
  out.exposure_scale = exposure_scale(s, film_in, film_space);
  out.width = upscaled_size(film_in.width, s.render_scale);
  out.height = upscaled_size(film_in.height, s.render_scale);

  // Output primaries: the user's display, Rec.709 for scRGB, else the target's.
  const color::ColorSpace& rec709 = color::color_space("srgb");
  const color::ColorSpace& target_space = color::color_space(target.display_space);
  const color::ColorSpace& light_space = aces2 ? target_space : rec709;
  Mat3 to_output;
  if (s.display_primaries) {
    out.primaries = s.display_primaries->name;
    to_output = gamut_remap_matrix(target_space, *s.display_primaries) * color::conversion_matrix(light_space, target_space);
  } else if (out.encoding == DisplayEncoding::scrgb) {
    out.primaries = "srgb";
    to_output = color::conversion_matrix(light_space, rec709);
  } else {
    out.primaries = std::string(target.display_space);
    to_output = color::conversion_matrix(light_space, target_space);
  }

  // Exposure (and bloom, which thresholds exposed values) in the film's space, then to the
  // rendering's input space.
  Mat3 to_input = color::conversion_matrix(film_space, color::color_space(aces2 ? "aces2065-1" : "srgb"));
  ImageRgbF exposed;
  const ImageRgbF* film = &expose_and_bloom(film_in, out.exposure_scale, s.bloom, exposed, to_input);

  // Display light (nits, output primaries) at the film's size.
  const std::size_t n_in = static_cast<std::size_t>(film->width) * film->height;
  ImageRgbF light{film->width, film->height, std::vector<float>(3 * n_in)};
  const bool clip = s.display_primaries.has_value();
  parallel_for(n_in, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec3d rgb{film->rgb[3 * i], film->rgb[3 * i + 1], film->rgb[3 * i + 2]};
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(rgb[c])) rgb[c] = 0.0;  // NaN/inf samples show as black
      const Vec3d nits = to_output * light_of(to_input * rgb);
      for (int c = 0; c < 3; ++c) light.rgb[3 * i + c] = static_cast<float>(clip ? std::clamp(nits[c], 0.0, peak) : nits[c]);
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

ImageRgbF aces2_inverse(const ImageRgbF& code, DisplayEncoding encoding, const DisplaySettings& s) {
  if (s.rendering != Rendering::aces2) throw UsageError("--inverse needs --rendering aces2");
  require_rendering_target(s.rendering, s.odt);
  const Aces2OutputTransform transform(aces2_parameters(s));
  const double peak = transform.parameters().peak_luminance_nits;
  const color::ColorSpace& target_space = color::color_space(odt_description(s.odt).display_space);
  const Mat3 to_target = encoding == DisplayEncoding::scrgb
                             ? color::conversion_matrix(color::color_space("srgb"), target_space)
                             : Mat3::identity();
  ImageRgbF aces{code.width, code.height, std::vector<float>(code.rgb.size())};
  parallel_for(code.rgb.size() / 3, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec3d nits;
      for (int c = 0; c < 3; ++c) {
        const double v = std::isfinite(code.rgb[3 * i + c]) ? code.rgb[3 * i + c] : 0.0;
        nits[c] = decode_display_nits(encoding, v, peak);
      }
      const Vec3d a = transform.aces_from_display_nits(to_target * nits);
      for (int c = 0; c < 3; ++c) aces.rgb[3 * i + c] = static_cast<float>(a[c]);
    }
  });
  return aces;
}

}  // namespace prism::display
