// The atrium's gold in GLB: glTF can only say "metal with base colour F0", so the writer
// gives the colour of gold's spectral normal-incidence reflectance, computed from the same
// η, k data (Johnson & Christy 1972) that the JSON and pbrt-v4 versions render with.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "loader_test_files.h"
#include "prism/bsdf/ior.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/color/spectrum.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/atrium_generator.h"
#include "prism/scene/loaders/gltf_writer.h"

namespace prism::loaders {
namespace {

// F0(λ) = ((η − 1)² + k²) / ((η + 1)² + k²) (Born & Wolf §14.2 at normal incidence), its
// XYZ under the flat spectrum E normalised to the perfect white, adapted E → D65 (Bradford)
// and taken to linear Rec.709 — the colour a spectral render films the conductor as under a
// white light: computed here in double precision from the tables, independently of the
// writer's code path.
Vec3d gold_f0_rec709() {
  const bsdf::ConductorIor au = bsdf::conductor_ior("Au");
  const auto f0 = [&](double nm) {
    const double n = au.eta(nm), k = au.k(nm);
    return ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
  };
  const Vec3d xyz = color::reflectance_to_xyz(f0, color::standard_illuminant(color::StandardIlluminant::e));
  return color::spectral_xyz_to_rgb_matrix(color::color_space("srgb")) * xyz;
}

TEST(AtriumGold, GlbBaseColourIsTheConductorsNormalIncidenceReflectance) {
  const Scene original = generate_atrium(kAtriumMinTriangles);
  test::ScratchFolder dir;
  write_scene_glb(original, dir / "atrium.glb");
  const Scene glb = load_scene((dir / "atrium.glb").string());
  const Material* gold = nullptr;
  for (const Material& m : glb.materials)
    if (m.name == "gold") gold = &m;
  ASSERT_NE(gold, nullptr);
  EXPECT_EQ(gold->type, MaterialType::metallic_roughness);
  EXPECT_FLOAT_EQ(gold->metallic, 1.0f);
  const Vec3d f0 = gold_f0_rec709();
  // Gold's F0 is more saturated than Rec.709 holds: its red is 1.044, beyond a glTF base
  // colour's [0, 1]. The writer clamps per channel (the nearest colour in the cube: Y
  // drops by 0.2126 × 0.044 ≈ 1 %); green and blue are inside.
  EXPECT_GT(f0.x, 1.0);
  EXPECT_LT(f0.x, 1.05);
  const Vec3d expected(1.0, f0.y, f0.z);
  for (int c = 1; c < 3; ++c) {
    ASSERT_GT(expected[c], 0.0);
    ASSERT_LT(expected[c], 1.0);
  }
  std::printf("gold F0, linear Rec.709 before the clamp: %.4f %.4f %.4f\n", f0.x, f0.y, f0.z);
  // The writer evaluates the Fresnel term in single precision and stores floats: 1e-5
  // is ~100 ε of values below 1. The old hand-picked (1, 0.78, 0.34) is off by more.
  EXPECT_NEAR(gold->base_color.x, expected.x, 1e-5);
  EXPECT_NEAR(gold->base_color.y, expected.y, 1e-5);
  EXPECT_NEAR(gold->base_color.z, expected.z, 1e-5);
  // Gold: red reflects most, blue least.
  EXPECT_GT(expected.x, expected.y);
  EXPECT_GT(expected.y, expected.z);
}

}  // namespace
}  // namespace prism::loaders
