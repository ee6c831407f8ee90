// The wavefront integrator held to the reference path tracer (render/reference_path_tracer.h)
// per pixel: two renders with independent seeds estimate the same image, so the difference
// of their pixel means divided by its standard error is close to a standard normal variate
// wherever the two agree in expectation, and a bias in the fast integrator (a wrong MIS
// weight, a lost lobe, a missed emitter) shows up as a shift of those Z scores.
//
// Three statistics per scene and transport mode:
//  - the whole image: Σ(mean_w − mean_r) / sqrt(Σ var_w + Σ var_r) per channel, |Z| < 4.5;
//  - 8×8-pixel blocks, the same statistic per block, |Z| < 5 for all of them (with at most
//    3 × 8 × 8 channels-blocks a scene, a standard normal exceeds 5 with probability
//    < 4e-4 for the whole test);
//  - per pixel, the fraction with |Z| > 4 below 2 % (a normal variate: 6e-5; Monte Carlo
//    pixel means at 128 spp have heavier tails than that, and the sample variance of a pixel
//    whose few bright samples were all missed is an underestimate, hence the loose bound;
//    a bias of a few standard errors moves far more than 2 % of the pixels past 4).
// The renders use different seeds, so the two estimates are independent and the variances add.
// At 64×64 pixels and 128 spp the image mean's standard error is about 0.5 % (Cornell box,
// material test, the glTF model; 3–4 % for the dispersion prism's caustics), so a bias of
// about 2.5 % of the image fails the image test; a local one fails a block: a 3 % loss in
// the plain diffuse lanes' light samples moved the Cornell box's worst block from |Z| 3.7
// to 5.5 (its image from 0.7 to 2.3), and the test failed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/load_scene.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

struct ReferenceAgreement {
  double image_z = 0.0;        // largest |Z| of the whole image's channels
  double worst_block_z = 0.0;  // largest |Z| of any 8×8 block's channel
  double outlier_fraction = 0.0;  // pixels' channels with |Z| > 4
  double relative_error = 0.0;    // the image mean's standard error over its value (green)
};

ReferenceAgreement compare_to_reference(const Film& a, const Film& b) {
  ReferenceAgreement result;
  constexpr int kBlock = 8;
  Vec3d image_difference, image_variance, image_sum;
  std::size_t outliers = 0, tested = 0;
  for (int by = 0; by < a.height(); by += kBlock)
    for (int bx = 0; bx < a.width(); bx += kBlock) {
      Vec3d block_difference, block_variance;
      for (int y = by; y < std::min(by + kBlock, a.height()); ++y)
        for (int x = bx; x < std::min(bx + kBlock, a.width()); ++x) {
          const std::size_t p = static_cast<std::size_t>(y) * a.width() + x;
          const Vec3d d = a.mean(p) - b.mean(p);
          const Vec3d v = a.variance_of_mean(p) + b.variance_of_mean(p);
          block_difference += d;
          image_sum += a.mean(p);
          block_variance += v;
          for (int c = 0; c < 3; ++c) {
            if (!(v[c] > 0.0)) continue;  // a constant pixel in both (the void, a flat light)
            ++tested;
            outliers += std::abs(d[c]) / std::sqrt(v[c]) > 4.0;
          }
        }
      image_difference += block_difference;
      image_variance += block_variance;
      for (int c = 0; c < 3; ++c)
        if (block_variance[c] > 0.0)
          result.worst_block_z =
              std::max(result.worst_block_z, std::abs(block_difference[c]) / std::sqrt(block_variance[c]));
    }
  for (int c = 0; c < 3; ++c)
    if (image_variance[c] > 0.0)
      result.image_z = std::max(result.image_z, std::abs(image_difference[c]) / std::sqrt(image_variance[c]));
  result.relative_error = std::sqrt(image_variance.y) / std::max(image_sum.y, 1e-30);
  result.outlier_fraction = tested > 0 ? static_cast<double>(outliers) / static_cast<double>(tested) : 0.0;
  return result;
}

RenderSettings settings_for(TransportKind kind, int size, int spp) {
  RenderSettings s;
  s.width = size;
  s.height = size;
  s.samples_per_pixel = spp;
  s.transport.kind = kind;
  s.path.max_depth = 64;  // the whole light transport, roulette ending the paths
  // Independent samples: a pixel's sample variance / n is then its mean's variance. (With
  // the stratified Sobol' sampler the true error is well below that estimate, which makes
  // the Z scores small and the test blind to biases of a few tenths of a per cent.)
  s.path.sampler = SamplerKind::independent;
  return s;
}

void expect_agreement(const Scene& scene, const std::string& label, int size = 64, int spp = 128) {
  for (const TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
    RenderSettings s = settings_for(kind, size, spp);
    s.seed = 1;
    const RenderResult fast = render(scene, s);
    s.integrator = IntegratorKind::reference;
    s.seed = 2;
    const RenderResult reference = render(scene, s);
    ASSERT_EQ(reference.invalid_samples, 0u) << label;
    EXPECT_EQ(reference.film.counts(), fast.film.counts()) << label;
    const ReferenceAgreement z = compare_to_reference(fast.film, reference.film);
    const std::string what = label + (kind == TransportKind::rgb ? ", rgb" : ", spectral");
    std::printf("%s: image |Z| %.2f (its standard error %.2f %%), worst block |Z| %.2f, pixels past |Z| 4: %.3f %%\n",
                what.c_str(), z.image_z, 100.0 * z.relative_error, z.worst_block_z, 100.0 * z.outlier_fraction);
    EXPECT_LT(z.image_z, 4.5) << what;
    EXPECT_LT(z.worst_block_z, 5.0) << what;
    EXPECT_LT(z.outlier_fraction, 0.02) << what;
  }
}

TEST(ReferencePathTracer, AgreesWithWavefrontOnTheCornellBox) { expect_agreement(make_cornell_box(), "cornell-box"); }

TEST(ReferencePathTracer, AgreesWithWavefrontOnTheMaterialTest) {
  expect_agreement(load_scene("material-test"), "material-test");
}

TEST(ReferencePathTracer, AgreesWithWavefrontOnTheDispersionPrism) {
  expect_agreement(load_scene("dispersion-prism"), "dispersion-prism");
}

// A textured, normal-mapped glTF model (NormalTangentTest) under an environment map with a
// small bright sun and a sky gradient: the shading seam's textures and maps, and the
// environment's importance sampling against the BSDF's.
TEST(ReferencePathTracer, AgreesWithWavefrontOnAnEnvironmentLitGltfModel) {
  test::ScratchFolder folder;
  ImageRgbF sky{64, 32, {}};
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x) {
      const bool sun = x >= 40 && x < 42 && y >= 8 && y < 10;
      const float up = 1.0f - static_cast<float>(y) / static_cast<float>(sky.height);
      for (const float v : {sun ? 400.0f : 0.2f + up, sun ? 380.0f : 0.3f + up, sun ? 350.0f : 0.5f + up})
        sky.rgb.push_back(v);
    }
  const auto sky_path = folder.path() / "sky.exr";
  write_exr(sky_path, sky, ExrChromaticities{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f});  // Rec.709
  Scene scene = load_scene(std::string(PRISM_SOURCE_DIR) + "/tests/data/gltf/NormalTangentTest/NormalTangentTest.gltf");
  apply_environment_override(scene, EnvironmentOverride{sky_path.string(), 1.0f, 30.0f});
  expect_agreement(scene, "NormalTangentTest under a sky");
}

TEST(ReferencePathTracer, ImageIsIndependentOfThreadCount) {
  RenderSettings s = settings_for(TransportKind::spectral, 24, 8);
  s.integrator = IntegratorKind::reference;
  s.threads = 1;
  const RenderResult one = render(make_cornell_box(), s);
  s.threads = 2;
  const RenderResult two = render(make_cornell_box(), s);
  EXPECT_EQ(one.film.sums(), two.film.sums());
}

TEST(ReferencePathTracer, FingerprintSaysWhichIntegratorRendered) {
  const Scene scene = make_cornell_box();
  RenderSettings s = settings_for(TransportKind::spectral, 24, 8);
  const std::uint64_t wavefront = image_fingerprint(scene, s);
  s.integrator = IntegratorKind::reference;
  EXPECT_NE(image_fingerprint(scene, s), wavefront);
  EXPECT_EQ(parse_integrator("reference"), IntegratorKind::reference);
  EXPECT_THROW(parse_integrator("bidirectional"), UsageError);
}

}  // namespace
}  // namespace prism
