// First-hit AOVs (render/aov.h): analytic values on the Cornell box, determinism, and
// that they leave the beauty alone.
#include "prism/render/aov.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/render/aov_images.h"
#include "prism/render/memory_estimate.h"
#include "prism/render/renderer.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {
namespace {

constexpr AovSet kAllAovs{true, true, true};

RenderSettings aov_settings(int width, int height, int spp) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.samples_per_pixel = spp;
  s.samples_per_pass = 2;
  s.seed = 5;
  s.aovs = kAllAovs;
  return s;
}

// The Cornell box without its two blocks: the centre sees the back wall, the lower middle
// the floor.
Scene empty_cornell_box() {
  Scene scene = make_cornell_box();
  std::erase_if(scene.meshes, [](const TriangleMesh& m) { return m.name == "short-block" || m.name == "tall-block"; });
  return scene;
}

TEST(AovList, ParsesSubsetsAndRejectsBadNames) {
  EXPECT_EQ(parse_aov_list("albedo,normal,depth"), kAllAovs);
  EXPECT_EQ(parse_aov_list("depth,albedo"), (AovSet{true, false, true}));
  EXPECT_EQ(parse_aov_list("normal"), (AovSet{false, true, false}));
  EXPECT_EQ(format_aov_list(parse_aov_list("depth,normal")), "normal,depth");
  EXPECT_EQ(parse_aov_list("variance,albedo"), (AovSet{true, false, false, true}));
  EXPECT_EQ(format_aov_list(parse_aov_list("variance,depth")), "depth,variance");
  for (const char* bad : {"", "albedo,", "Albedo", "z", "normal,normal", "albedo normal"})
    EXPECT_THROW(parse_aov_list(bad), UsageError) << bad;
  for (unsigned bits = 0; bits < 16; ++bits) EXPECT_EQ(AovSet::from_bits(bits).bits(), bits);
}

// Rows 19–24 and columns 28–35 of a 64² render look at the back wall through
// tan θ_y ∈ [0.08, 0.15], tan θ_x ∈ [−0.05, 0.05] (fov 39.3°): above the tall block's top
// (y = 330) all along the ray, well inside the wall.
void expect_white_wall_albedo(TransportKind kind) {
  const Scene scene = make_cornell_box();
  RenderSettings s = aov_settings(64, 64, 4);
  s.transport.kind = kind;
  const RenderResult r = render(scene, s);
  const Mat3 to_srgb = color::conversion_matrix(r.film_space, color::color_space("srgb"));
  const AovImages aov = film_aov_images(r.film, to_srgb);
  const Vec3f white = scene.materials[0].base_color;  // measured reflectance of the pbrt-v4 box
  for (int y = 19; y <= 24; ++y)
    for (int x = 28; x <= 35; ++x)
      for (int c = 0; c < 3; ++c) {
        // Stored in the film space in single precision, then converted back in double
        // (spectral: sRGB → XYZ-E → sRGB, Bradford both ways) and rounded again: the
        // XYZ → sRGB rows have Σ|m| ≈ 5.3, so 5.3 · 0.75 · 2⁻²⁴ + 2⁻²⁴ ≈ 3e-7 at most.
        const std::size_t i = static_cast<std::size_t>(y) * 64 + x;
        EXPECT_NEAR(aov.albedo.rgb[3 * i + c], white[c], 4e-7) << "pixel " << x << "," << y << " channel " << c;
      }
}

TEST(Aov, AlbedoOfTheWhiteWallIsItsReflectanceRgb) { expect_white_wall_albedo(TransportKind::rgb); }
TEST(Aov, AlbedoOfTheWhiteWallIsItsReflectanceSpectral) { expect_white_wall_albedo(TransportKind::spectral); }

TEST(Aov, FloorNormalIsUp) {
  // Rows 52–58 of 64 look down through tan θ_y ∈ [−0.30, −0.22]: they meet the floor
  // (y = 0) at z ∈ [110, 441], inside the box.
  const RenderResult r = render(empty_cornell_box(), aov_settings(64, 64, 4));
  for (int y = 52; y <= 58; ++y)
    for (int x = 28; x <= 35; ++x) {
      const Vec3d n = r.film.normal_mean(static_cast<std::size_t>(y) * 64 + x);
      // The floor's vertices all have y = 0, so the cross product is exactly vertical and
      // normalising it rounds once: one float ulp of 1 at most.
      EXPECT_NEAR(n.x, 0.0, 1e-7);
      EXPECT_NEAR(n.y, 1.0, 1.2e-7);
      EXPECT_NEAR(n.z, 0.0, 1e-7);
    }
}

TEST(Aov, DepthOfTheBackWallIsTheAnalyticDistance) {
  // 41 × 41 pinhole: the centre pixel (20, 20) straddles the optical axis, which meets the
  // back wall (z = 559.2) at distance D = 559.2 + 800 from the eye (z = −800). A ray at angle
  // θ from the axis travels D / cos θ; inside the pixel tan θ is at most √2 · tan(fov/2)/41.
  const Scene scene = empty_cornell_box();
  const RenderResult r = render(scene, aov_settings(41, 41, 16));
  const double d = 559.2 + 800.0;
  const double tan_half_fov = std::tan(scene.camera.fov_degrees * 0.5 * std::numbers::pi / 180.0);
  const double tan_max = std::sqrt(2.0) * tan_half_fov / 41.0;
  const std::size_t centre = 20 * 41 + 20;
  const double depth = r.film.depth_mean(centre);
  // Lower bound: the hit distance is a float near 1359 (ulp 1.2e-4).
  EXPECT_GE(depth, d - 2e-4);
  EXPECT_LE(depth, d * std::sqrt(1.0 + tan_max * tan_max) + 2e-4);
  EXPECT_EQ(r.film.depth_coverage(centre), 1.0);
  // The wall is a plane: depth · cos θ = D for every pixel; the pixel one to the left
  // must be deeper than the centre.
  EXPECT_GT(r.film.depth_mean(centre - 1), depth);
}

TEST(Aov, EscapedRaysGiveZeroAlbedoAndNormalAndInfiniteDepth) {
  Scene scene = make_cornell_box();
  scene.camera.target = scene.camera.eye - Vec3f(0, 0, 1);  // looking away from the box
  const RenderResult r = render(scene, aov_settings(8, 8, 2));
  for (std::size_t i = 0; i < r.film.pixel_count(); ++i) {
    EXPECT_EQ(r.film.albedo_mean(i), Vec3d(0.0));
    EXPECT_EQ(r.film.normal_mean(i), Vec3d(0.0));
    EXPECT_TRUE(std::isinf(r.film.depth_mean(i)) && r.film.depth_mean(i) > 0);
    EXPECT_EQ(r.film.depth_coverage(i), 0.0);
  }
}

TEST(Aov, BitwiseIndependentOfThreadsAndLeavesTheBeautyAlone) {
  const Scene scene = make_cornell_box();
  RenderSettings one = aov_settings(40, 32, 6);
  one.threads = 1;
  RenderSettings two = one;
  two.threads = 2;
  two.samples_per_pass = 3;  // grouping samples into passes must not matter either
  const RenderResult a = render(scene, one), b = render(scene, two);
  const FilmAovSums &x = a.film.aov_sums(), &y = b.film.aov_sums();
  EXPECT_EQ(x.set, kAllAovs);
  EXPECT_TRUE(x.albedo == y.albedo && x.normal == y.normal && x.depth == y.depth && x.depth_hits == y.depth_hits);
  RenderSettings plain = one;
  plain.aovs = {};
  const RenderResult c = render(scene, plain);
  EXPECT_FALSE(c.film.aovs().any());
  EXPECT_TRUE(c.film.aov_sums().albedo.empty());
  EXPECT_TRUE(a.film.sums() == c.film.sums() && a.film.counts() == c.film.counts())
      << "turning AOVs on changed the beauty";
}

TEST(Aov, MemoryEstimateCountsTheAovs) {
  const Scene scene = make_cornell_box();
  RenderSettings s = aov_settings(1000, 500, 1);
  s.threads = 2;  // the path state is one tile per thread
  s.aovs = {};
  const MemoryEstimate none = estimate_render_memory(scene, s);
  s.aovs = kAllAovs;
  const MemoryEstimate all = estimate_render_memory(scene, s);
  const std::uint64_t pixels = 500000;
  // Sums: albedo and normal 3 doubles, depth a double and a u32 hit count; the first-hit
  // record per slot; output images of 8 float channels.
  EXPECT_EQ(all.film - none.film, pixels * (24 + 24 + 12));
  EXPECT_EQ(all.path_pool - none.path_pool, 2 * kWavefrontTilePixels * kAovBytesPerSlot);
  EXPECT_EQ(all.images - none.images, pixels * 8 * 4);
  EXPECT_EQ(none.film, pixels * kFilmBytesPerPixel);
}

TEST(Aov, FingerprintCoversTheAovSetOnlyWhenNotEmpty) {
  const Scene scene = make_cornell_box();
  RenderSettings s = aov_settings(16, 16, 1);
  s.aovs = {};
  const std::uint64_t plain = image_fingerprint(scene, s);
  s.aovs.depth = true;
  const std::uint64_t depth = image_fingerprint(scene, s);
  s.aovs.albedo = true;
  EXPECT_NE(plain, depth);
  EXPECT_NE(depth, image_fingerprint(scene, s));
}

}  // namespace
}  // namespace prism
