#include "prism/display/display_pipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <oneapi/tbb/parallel_for.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/display/aces_output_kernel.h"
#include "prism/display/blue_light_lmt.h"
#include "prism/display/display_primaries.h"
#include "prism/display/rendering_pipeline.h"
#include "prism/display/resampling.h"
#include "prism/display/dither.h"
#include "prism/display/exposure.h"
#include "prism/display/exposure_metering.h"

namespace prism::display {

namespace {

// Pixels per parallel task: large enough that scheduling is noise, small enough that a
// 4K image makes ~500 tasks for any thread count.
constexpr std::size_t kPixelsPerTask = 16384;

// The exact path: AcesOutputTransform per pixel in double, as the CTL reads.
void apply_reference(const ImageRgbF& film, const Mat3& to_aces, const AcesOutputTransform& transform,
                     const Mat3& display_to_output, const DisplaySettings& s, DisplayImage& out) {
  const OdtDescription& odt = transform.description();
  // RRT + ODT up to the normalised AP1 step, at the render size.
  const std::size_t n_in = static_cast<std::size_t>(film.width) * film.height;
  ImageRgbF cv{film.width, film.height, std::vector<float>(3 * n_in)};
  tbb::parallel_for(std::size_t{0}, n_in, [&](std::size_t i) {
    Vec3d rgb{film.rgb[3 * i], film.rgb[3 * i + 1], film.rgb[3 * i + 2]};
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(rgb[c])) rgb[c] = 0.0;  // NaN/inf samples show as black, not as noise
    const Vec3d v = transform.normalized_ap1(to_aces * rgb);
    for (int c = 0; c < 3; ++c) cv.rgb[3 * i + c] = static_cast<float>(v[c]);
  });
  if (out.width != cv.width || out.height != cv.height) cv = upscale_bilinear(cv, out.width, out.height);

  // Overlay, display light, gamut remap, encoding — at the output size.
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  const double remap_peak = odt.white_nits;
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    Vec3d c{cv.rgb[3 * i], cv.rgb[3 * i + 1], cv.rgb[3 * i + 2]};
    double peak = odt.white_nits;
    if (s.overlay) {
      const UiOverlay& o = *s.overlay;
      const Vec3d ui{o.ap1[3 * i], o.ap1[3 * i + 1], o.ap1[3 * i + 2]};
      const UiComposite comp = composite_ui(c, ui, o.alpha[i], odt.white_nits, o.ui_nits, o.blend_power);
      c = comp.cv_ap1;
      peak = comp.peak_nits;
    }
    Vec3d nits = display_to_output * transform.display_nits_from_normalized(c, peak);
    if (s.display_primaries)
      for (int k = 0; k < 3; ++k) nits[k] = std::clamp(nits[k], 0.0, remap_peak);
    for (int k = 0; k < 3; ++k) {
      out.nits[3 * i + k] = static_cast<float>(nits[k]);
      out.code[3 * i + k] = static_cast<float>(encode_display_nits(out.encoding, nits[k], out.white_nits));
    }
  });
}

}  // namespace

double exposure_scale(const DisplaySettings& s, const ImageRgbF& film, const color::ColorSpace& film_space) {
  if (s.exposure_ev100 && s.auto_exposure) throw UsageError("give either an EV100 or auto exposure, not both");
  if (s.exposure_ev100) return exposure_scale_from_ev100(*s.exposure_ev100);
  if (s.auto_exposure) {
    // The metering rule of exposure_metering.h; without coverage every finite pixel counts.
    if (!s.metering_coverage.empty() &&
        s.metering_coverage.size() != static_cast<std::size_t>(film.width) * film.height)
      throw UsageError("the metering coverage has " + std::to_string(s.metering_coverage.size()) +
                       " values for a film of " + std::to_string(film.width) + "x" + std::to_string(film.height));
    MeteringSettings metering;
    metering.key = s.auto_exposure_key;
    const Vec3d luminance_row = film_space.rgb_to_xyz.row(1);
    return exposure_scale_from_ev100(meter_exposure(film, luminance_row, s.metering_coverage, metering).ev100);
  }
  return 1.0;
}

Mat3 film_to_aces_matrix(const color::ColorSpace& film_space, double blue_correction) {
  const Mat3 to_ap0 = color::conversion_matrix(film_space, color::color_space("aces2065-1"), color::Cat::bradford);
  return blue_correction_matrix(blue_correction) * to_ap0;
}

DisplayImage apply_display_pipeline(const ImageRgbF& film_in, const color::ColorSpace& film_space,
                                    const DisplaySettings& s) {
  if (s.rendering != Rendering::aces1) return apply_rendering_pipeline(film_in, film_space, s);
  const OdtDescription& odt = odt_description(s.odt);
  DisplayImage out;
  out.encoding = s.encoding.value_or(odt.default_encoding);
  out.white_nits = odt.white_nits;
  out.y_max_nits = odt.white_nits;
  out.exposure_scale = exposure_scale(s, film_in, film_space);
  out.width = upscaled_size(film_in.width, s.render_scale);
  out.height = upscaled_size(film_in.height, s.render_scale);
  if (s.overlay && (s.overlay->width != out.width || s.overlay->height != out.height))
    throw UsageError("the overlay is " + std::to_string(s.overlay->width) + "x" + std::to_string(s.overlay->height) +
                     " but the output is " + std::to_string(out.width) + "x" + std::to_string(out.height));
  if (s.display_primaries && out.encoding == DisplayEncoding::scrgb)
    throw UsageError("scRGB is defined on Rec.709 primaries: --display-primaries needs another encoding");

  // Primaries of the output: the user's display, Rec.709 for scRGB, else the ODT's.
  const color::ColorSpace& odt_space = color::color_space(odt.display_space);
  const bool to_rec709 = out.encoding == DisplayEncoding::scrgb && odt.display_space != "srgb";
  Mat3 display_to_output = Mat3::identity();
  if (s.display_primaries) {
    out.primaries = s.display_primaries->name;
    display_to_output = gamut_remap_matrix(odt_space, *s.display_primaries);
  } else {
    out.primaries = to_rec709 ? "srgb" : std::string(odt.display_space);
    if (to_rec709) display_to_output = color::conversion_matrix(odt_space, color::color_space("srgb"));
  }

  // Exposure (and bloom, which thresholds exposed values) in the film's space.
  Mat3 to_aces = film_to_aces_matrix(film_space, s.blue_correction);
  ImageRgbF exposed;
  const ImageRgbF* film = &expose_and_bloom(film_in, out.exposure_scale, s.bloom, exposed, to_aces);
  const AcesOutputTransform transform(s.odt, s.stretch_black.value_or(true));
  const std::size_t n_in = static_cast<std::size_t>(film->width) * film->height;
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  const double remap_peak = odt.white_nits;
  out.code.resize(3 * n);
  out.nits.resize(3 * n);
  if (s.reference_path) {
    apply_reference(*film, to_aces, transform, display_to_output, s, out);
    return out;
  }

  AcesKernelSettings ks;
  ks.film_to_aces = to_aces;
  ks.display_to_output = display_to_output;
  ks.clamp_output = s.display_primaries.has_value();
  ks.clamp_nits = remap_peak;
  ks.encoding = out.encoding;
  ks.white_nits = out.white_nits;
  const AcesOutputKernel kernel(transform, ks);
  const bool same_size = out.width == film->width && out.height == film->height;
  if (same_size && !s.overlay) {
    // One pass: each block goes film → normalised code → light → code while in cache.
    parallel_for(n, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
      float cv[3 * AcesOutputKernel::kBlock];
      for (std::size_t i = begin; i < end; i += AcesOutputKernel::kBlock) {
        const std::size_t m = std::min(AcesOutputKernel::kBlock, end - i);
        kernel.normalized_ap1(&film->rgb[3 * i], cv, m);
        kernel.display(cv, nullptr, &out.nits[3 * i], &out.code[3 * i], m);
      }
    });
    return out;
  }
  ImageRgbF cv{film->width, film->height, std::vector<float>(3 * n_in)};
  parallel_for(n_in, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    kernel.normalized_ap1(&film->rgb[3 * begin], &cv.rgb[3 * begin], end - begin);
  });
  if (!same_size) cv = upscale_bilinear(cv, out.width, out.height);
  std::vector<float> peak;
  if (s.overlay) {
    peak.resize(n);
    const UiOverlay& o = *s.overlay;
    parallel_for(n, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const Vec3d c{cv.rgb[3 * i], cv.rgb[3 * i + 1], cv.rgb[3 * i + 2]};
        const Vec3d ui{o.ap1[3 * i], o.ap1[3 * i + 1], o.ap1[3 * i + 2]};
        const UiComposite comp = composite_ui(c, ui, o.alpha[i], odt.white_nits, o.ui_nits, o.blend_power);
        for (int k = 0; k < 3; ++k) cv.rgb[3 * i + k] = static_cast<float>(comp.cv_ap1[k]);
        peak[i] = static_cast<float>(comp.peak_nits);
      }
    });
  }
  parallel_for(n, kPixelsPerTask, [&](std::size_t begin, std::size_t end) {
    kernel.display(&cv.rgb[3 * begin], s.overlay ? &peak[begin] : nullptr, &out.nits[3 * begin],
                   &out.code[3 * begin], end - begin);
  });
  return out;
}

EncodedImage quantise_display_image(const DisplayImage& image, int bit_depth, std::uint64_t seed) {
  if (is_float_encoding(image.encoding))
    throw UsageError("encoding '" + std::string(display_encoding_name(image.encoding)) +
                     "' is floating point: write it to an EXR file");
  if (bit_depth != 8 && bit_depth != 10 && bit_depth != 12 && bit_depth != 16)
    throw UsageError("bit depth must be 8, 10, 12 or 16, got " + std::to_string(bit_depth));
  EncodedImage out;
  out.width = image.width;
  out.height = image.height;
  out.channels = 3;
  out.bit_depth = bit_depth;
  out.samples.resize(image.code.size());
  const bool dither = bit_depth <= 10;
  for (std::size_t i = 0; i < image.code.size(); ++i)
    out.samples[i] = quantise_code(image.code[i], bit_depth, dither ? triangular_dither_lsb(seed, i) : 0.0);
  return out;
}

}  // namespace prism::display
