// The Y_MIN..Y_MAX interpolation of the HDR Output Transforms belongs to the ODT, not to the
// encoding: a 16-bit Rec.2020 PQ PNG and a half-float scRGB EXR of the same image, each
// written to disk, read back and decoded to absolute CIE XYZ, show the same light.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/display/display_pipeline.h"
#include "prism/io/exr.h"
#include "prism/io/exr_scrgb.h"
#include "prism/io/png.h"
#include "prism/io/png_hdr.h"
#include "support/scratch_folder.h"

namespace prism::display {
namespace {

ImageRgbF test_film() {
  ImageRgbF film;
  film.width = 64;
  film.height = 4;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      // 20 stops from 0.0005 up; the first pixel of each row is black.
      const double v = x == 0 ? 0.0 : 0.0005 * std::pow(2.0, x * 20.0 / film.width);
      const double tint[4][3] = {{1, 1, 1}, {1, 0.2, 0.05}, {0.1, 0.9, 0.3}, {0.2, 0.3, 1}};
      for (int c = 0; c < 3; ++c) film.rgb.push_back(static_cast<float>(v * tint[y][c]));
    }
  return film;
}

void check_same_light(bool stretch_black) {
  const ImageRgbF film = test_film();
  const color::ColorSpace& rec709 = color::color_space("srgb");
  DisplaySettings s;
  s.odt = OdtId::rec2020_pq_1000nit;
  s.stretch_black = stretch_black;
  const test::ScratchFolder scratch;
  const auto png_path = scratch / "pq.png", exr_path = scratch / "scrgb.exr";

  const DisplayImage pq = apply_display_pipeline(film, rec709, s);
  PngColorMetadata meta;
  meta.cicp = CicpInfo{};
  write_png_with_color_metadata(png_path, quantise_display_image(pq, 16, 0), meta);
  s.encoding = DisplayEncoding::scrgb;
  const DisplayImage sc = apply_display_pipeline(film, rec709, s);
  ImageRgbF sc_img{sc.width, sc.height, sc.code};
  write_exr_scrgb(exr_path, sc_img);

  const PngFile png = read_png(png_path);
  const ExrFile exr = read_exr(exr_path);
  const double white = read_exr_white_luminance(exr_path);
  EXPECT_EQ(white, 80.0);
  const Mat3 rec2020_to_xyz = color::color_space("rec2020").rgb_to_xyz;
  double max_rel = 0.0;
  for (std::size_t i = 0; i < png.image.samples.size() / 3; ++i) {
    Vec3d pq_rgb, sc_rgb;
    for (int c = 0; c < 3; ++c) {
      pq_rgb[c] = color::pq_decode_nits(png.image.samples[3 * i + c] / 65535.0);
      sc_rgb[c] = exr.image.rgb[3 * i + c] * white;
    }
    const Vec3d a = rec2020_to_xyz * pq_rgb, b = rec709.rgb_to_xyz * sc_rgb;
    // Quantisation: half float keeps 11 significant bits (relative 2^-11 ≈ 4.9e-4); a 16-bit
    // PQ step is < 2.5e-4 relative above 0.01 nit. Below that, half subnormals and PQ's
    // toe allow 2e-4 nit absolute. Both errors add, in XYZ mixing channels of one pixel.
    for (int k = 0; k < 3; ++k) {
      const double tol = 1.5e-3 * std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}) + 2e-4;
      EXPECT_NEAR(a[k], b[k], tol) << "pixel " << i << " component " << k;
      max_rel = std::max(max_rel, std::fabs(a[k] - b[k]) / (std::fabs(a.y) + 1e-3));
    }
    // Black shows at Y_MIN = 0.0001 nit without stretching, at 0 with it (either file).
    if (i == 0) {
      EXPECT_NEAR(b.y, stretch_black ? 0.0 : 0.0001, 2e-6);
    }
  }
  std::printf("[ equiv ] stretch_black=%d: PQ PNG vs scRGB EXR max |ΔXYZ|/Y %.2e\n", stretch_black, max_rel);
}

TEST(DisplayLightEquivalence, PqPngAndScrgbExrShowTheSameLight) { check_same_light(true); }
TEST(DisplayLightEquivalence, AlsoWithoutStretchedBlack) { check_same_light(false); }

TEST(DisplayPipeline, FilmWhiteMapsToAcesWhite) {
  // Bradford from D65 to the ACES white: Rec.709 (1,1,1) → AP0 (1,1,1).
  const Vec3d w = film_to_aces_matrix(color::color_space("srgb"), 0.0) * Vec3d{1, 1, 1};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], 1.0, 1e-9);
}

}  // namespace
}  // namespace prism::display
