// The atrium's procedural textures and alpha-masked foliage, written as GLB, JSON and
// pbrt-v4 and loaded back: the same textures, the same cut-outs, the same image.
#include "prism/scene/loaders/atrium_textures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>

#include "loader_test_files.h"
#include "prism/accel/embree_accel.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/atrium_generator.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/surface_alpha.h"
#include "support/film_statistics.h"

namespace prism::loaders {
namespace {

constexpr const char* kFormats[] = {"atrium.glb", "atrium.json", "atrium.pbrt"};

void write_scene(const Scene& scene, const std::filesystem::path& path) {
  if (path.extension() == ".glb") write_scene_glb(scene, path);
  else if (path.extension() == ".json") write_scene_json(scene, path);
  else write_scene_pbrt(scene, path);
}

// The loaded scene's alpha-tested material and a mesh that uses it.
const TriangleMesh* foliage_mesh(const Scene& scene) {
  for (const TriangleMesh& mesh : scene.meshes)
    if (has_alpha_coverage(scene.materials[mesh.material])) return &mesh;
  return nullptr;
}

TEST(AtriumTextures, SizedDeterministicAndTheLeafMaskIsBinary) {
  const TextureImage floor = make_floor_tile_texture(), wall = make_wall_block_texture(), leaf = make_leaf_texture();
  EXPECT_EQ(floor.linear_values(), make_floor_tile_texture().linear_values());
  EXPECT_EQ(leaf.linear_values(), make_leaf_texture().linear_values());
  EXPECT_EQ(floor.width, 512);
  EXPECT_EQ(floor.channels, 3);
  EXPECT_EQ(wall.width, 512);
  EXPECT_EQ(wall.channels, 3);
  ASSERT_EQ(leaf.channels, 4);
  ASSERT_EQ(leaf.width, 256);
  std::size_t opaque = 0;
  for (int y = 0; y < leaf.height; ++y)
    for (int x = 0; x < leaf.width; ++x) {
      const float a = leaf.value((static_cast<std::size_t>(y) * leaf.width + x) * 4 + 3);
      ASSERT_TRUE(a == 0.0f || a == 1.0f) << x << "," << y;
      if (x == 0 || y == 0 || x == leaf.width - 1 || y == leaf.height - 1) {
        EXPECT_EQ(a, 0.0f) << "border " << x << "," << y;
      }
      opaque += a == 1.0f;
    }
  // A sprig, not a full or empty card: between 10 % and 60 % of the texels are leaf.
  const double coverage = static_cast<double>(opaque) / (leaf.width * leaf.height);
  EXPECT_GT(coverage, 0.1);
  EXPECT_LT(coverage, 0.6);
  // Tiles vary: the mean colour of two tiles of the same kind differs.
  const auto texel = [&](int x, int y, int c) { return floor.value((static_cast<std::size_t>(y) * 512 + x) * 3 + c); };
  EXPECT_NE(texel(64, 64, 0), texel(64 + 256, 64, 0));
}

TEST(AtriumGenerator, TexturedSurfacesHaveUvsAndTheFoliageIsMasked) {
  const Scene s = generate_atrium(kAtriumMinTriangles);
  ASSERT_EQ(s.textures.size(), 3u);
  for (const TriangleMesh& mesh : s.meshes)
    if (s.materials[mesh.material].base_color_texture >= 0) {
      EXPECT_EQ(mesh.uvs.size(), mesh.positions.size()) << mesh.name;
    }
  const TriangleMesh* foliage = foliage_mesh(s);
  ASSERT_NE(foliage, nullptr);
  const Material& leaves = s.materials[foliage->material];
  EXPECT_EQ(leaves.alpha_mode, AlphaMode::mask);
  EXPECT_EQ(leaves.alpha_cutoff, 0.5f);
  EXPECT_EQ(s.textures[static_cast<std::size_t>(leaves.base_color_texture)].channels, 4);
  // Foliage is a small part of the budget: 8 plants of 3 cards.
  EXPECT_EQ(foliage->triangle_count(), 8u * 3u * 2u);
  // `prism info` reports the textures and the alpha-tested material.
  const std::string info = format_scene_summary(s);
  EXPECT_NE(info.find("1 emissive, 1 alpha-tested)"), std::string::npos) << info;
  // 8-bit sRGB codes, a byte per sample: 256 KiB and 768 KiB.
  EXPECT_NE(info.find("texture leaves 256x256x4 8-bit sRGB 0.25 MiB"), std::string::npos) << info;
  EXPECT_NE(info.find("texture floor-tiles 512x512x3 8-bit sRGB 0.75 MiB"), std::string::npos) << info;
}

// Each format loads back with the textures bit for bit (8-bit sRGB codes survive the
// float round trip) and the foliage alpha-tested by a texture whose alpha is the leaf's.
TEST(AtriumRoundTrip, TexturesAndCutOutsSurviveEveryFormat) {
  const Scene original = generate_atrium(kAtriumMinTriangles);
  const TextureImage& leaf = original.textures[2];
  test::ScratchFolder dir;
  for (const char* name : kFormats) {
    SCOPED_TRACE(name);
    write_scene(original, dir / name);
    const Scene loaded = load_scene((dir / name).string());
    // GLB and JSON: the three textures; pbrt-v4 adds the alpha image and the RGBA
    // reflectance+alpha Prism makes from the pair (pbrt_alpha.cpp).
    ASSERT_EQ(loaded.textures.size(), std::string(name).ends_with(".pbrt") ? 5u : 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(loaded.textures[i].width, original.textures[i].width) << i;
      EXPECT_EQ(loaded.textures[i].height, original.textures[i].height) << i;
      EXPECT_EQ(loaded.textures[i].channels, original.textures[i].channels) << i;
      EXPECT_TRUE(loaded.textures[i].linear_values() == original.textures[i].linear_values())
          << "texture " << i << " changed";
    }
    const TriangleMesh* foliage = foliage_mesh(loaded);
    ASSERT_NE(foliage, nullptr);
    const Material& m = loaded.materials[foliage->material];
    // pbrt-v4's alpha is stochastic (BLEND); with a 0/1 mask it cuts where MASK does.
    EXPECT_EQ(m.alpha_mode, std::string(name).ends_with(".pbrt") ? AlphaMode::blend : AlphaMode::mask);
    if (m.alpha_mode == AlphaMode::mask) {
      EXPECT_EQ(m.alpha_cutoff, 0.5f);
    }
    ASSERT_GE(m.base_color_texture, 0);
    const TextureImage& t = loaded.textures[static_cast<std::size_t>(m.base_color_texture)];
    ASSERT_EQ(t.channels, 4);
    EXPECT_TRUE(t.linear_values() == leaf.linear_values()) << "the foliage texture is not the leaf's RGBA";
    // The cards keep their corners and uvs (pbrt-v4: written as v_pbrt = 1 − v, read back).
    const TriangleMesh& cards = *foliage_mesh(original);
    ASSERT_EQ(foliage->positions.size(), cards.positions.size());
    ASSERT_EQ(foliage->uvs.size(), cards.uvs.size());
    for (std::size_t i = 0; i < cards.uvs.size(); ++i) {
      EXPECT_NEAR(length(foliage->positions[i] - cards.positions[i]), 0.0f, 1e-6f) << i;
      EXPECT_NEAR(foliage->uvs[i].x, cards.uvs[i].x, 1e-6f) << i;
      EXPECT_NEAR(foliage->uvs[i].y, cards.uvs[i].y, 1e-6f) << i;  // 1 − (1 − v) may round by an ulp
    }
    int textured = 0;
    for (const Material& mat : loaded.materials) textured += mat.base_color_texture >= 0;
    EXPECT_GE(textured, 3);
  }
}

// Same triangle count → byte-identical files, textures included.
TEST(AtriumRoundTrip, WritingTwiceGivesIdenticalFiles) {
  const Scene a = generate_atrium(kAtriumMinTriangles), b = generate_atrium(kAtriumMinTriangles);
  test::ScratchFolder first, second;
  for (const char* name : kFormats) write_scene(a, first / name), write_scene(b, second / name);
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(first.path()))
    files[entry.path().filename().string()] = test::read_bytes(entry.path());
  // 3 scenes, the 3 PNGs JSON and pbrt share (same stem, same names and bytes), pbrt's alpha PNG.
  EXPECT_EQ(files.size(), 3u + 3u + 1u);
  std::size_t second_count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(second.path())) {
    ++second_count;
    const std::string file = entry.path().filename().string();
    ASSERT_TRUE(files.count(file)) << file;
    EXPECT_TRUE(files[file] == test::read_bytes(entry.path())) << file << " differs";
  }
  EXPECT_EQ(second_count, files.size());
}

// Barycentrics (b1, b2) of `p` in the triangle (a, b, c) of the plane.
Vec2f barycentrics(Vec2f a, Vec2f b, Vec2f c, Vec2f p) {
  const Vec2f e1(b.x - a.x, b.y - a.y), e2(c.x - a.x, c.y - a.y), d(p.x - a.x, p.y - a.y);
  const float det = e1.x * e2.y - e1.y * e2.x;
  return {(d.x * e2.y - d.y * e2.x) / det, (e1.x * d.y - e1.y * d.x) / det};
}

// A ray through a transparent leaf texel passes the card; one through a leaf stops on it.
// Texels are chosen with a uniform 3 × 3 neighbourhood so bilinear alpha is exactly 0 or 1.
TEST(AtriumRoundTrip, RaysPassTransparentLeafTexelsInEveryFormat) {
  const Scene original = generate_atrium(kAtriumMinTriangles);
  test::ScratchFolder dir;
  for (const char* name : kFormats) {
    SCOPED_TRACE(name);
    write_scene(original, dir / name);
    const Scene scene = load_scene((dir / name).string());
    const TriangleMesh* foliage = foliage_mesh(scene);
    ASSERT_NE(foliage, nullptr);
    const auto mesh_index = static_cast<std::uint32_t>(foliage - scene.meshes.data());
    const TextureImage& t = scene.textures[static_cast<std::size_t>(scene.materials[foliage->material].base_color_texture)];
    const std::uint32_t* v = foliage->indices.data();  // triangle 0
    const Vec3f p[3] = {foliage->positions[v[0]], foliage->positions[v[1]], foliage->positions[v[2]]};
    const Vec2f uv[3] = {foliage->uvs[v[0]], foliage->uvs[v[1]], foliage->uvs[v[2]]};
    const auto alpha = [&](int x, int y) { return t.value((static_cast<std::size_t>(y) * t.width + x) * 4 + 3); };
    std::optional<Vec2f> through[2];  // barycentrics at a transparent [0] and an opaque [1] texel
    for (int y = 1; y + 1 < t.height; ++y)
      for (int x = 1; x + 1 < t.width; ++x) {
        const float a = alpha(x, y);
        const int kind = a == 1.0f ? 1 : 0;
        if (through[kind]) continue;
        bool uniform = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) uniform &= alpha(x + dx, y + dy) == a;
        const Vec2f at((static_cast<float>(x) + 0.5f) / t.width, (static_cast<float>(y) + 0.5f) / t.height);
        const Vec2f b = barycentrics(uv[0], uv[1], uv[2], at);
        // Well inside the triangle and away from the line where the crossed cards meet.
        if (uniform && b.x > 0.05f && b.y > 0.05f && b.x + b.y < 0.95f && std::abs(at.x - 0.5f) > 0.15f) through[kind] = b;
      }
    ASSERT_TRUE(through[0] && through[1]);
    const EmbreeAccel accel(scene);
    const Vec3f n = normalize(cross(p[1] - p[0], p[2] - p[0]));
    constexpr float kStandoff = 0.03f;  // metres in front of the card
    for (int kind = 0; kind < 2; ++kind) {
      const Vec2f b = *through[kind];
      const Vec3f point = p[0] * (1.0f - b.x - b.y) + p[1] * b.x + p[2] * b.y;
      const Ray ray{point + n * kStandoff, -n, 0.0f, 2.0f * kStandoff};
      Hit hit;
      const bool hit_card = accel.intersect(ray, hit) && hit.mesh == mesh_index && hit.triangle == 0 &&
                            std::abs(hit.t - kStandoff) < 1e-4f;
      EXPECT_EQ(hit_card, kind == 1) << (kind ? "opaque" : "transparent") << " texel";
      if (kind == 1) {
        EXPECT_TRUE(accel.occluded(ray));
      }
    }
  }
}

// The three files describe the same scene: 64×36 renders agree within noise. glTF has no
// environment, so the GLB scene gets the generator's sky (the only thing it cannot carry).
TEST(AtriumRoundTrip, ThreeFormatsRenderTheSameImage) {
  const Scene original = generate_atrium(kAtriumMinTriangles);
  test::ScratchFolder dir;
  std::vector<RenderResult> renders;
  RenderSettings s;
  s.width = 64;
  s.height = 36;
  s.samples_per_pixel = 32;
  s.path.max_depth = 5;
  for (const char* name : kFormats) {
    write_scene(original, dir / name);
    Scene loaded = load_scene((dir / name).string());
    if (std::string(name).ends_with(".glb")) loaded.lights = original.lights;
    s.seed = renders.size() + 1;  // independent renders, so their variances add
    renders.push_back(render(loaded, s));
  }
  // Whole image and quadrants, 3 channels, 2 pairs: 30 comparisons at 5σ raise a false
  // alarm with probability below 2e-5 (normal means; 32 spp × 576+ pixels per block). At
  // 32 spp 5σ is 3–7 % of a block's mean: opaque (uncut) foliage cards fail it; the
  // ~1 % of glTF metallic-roughness in place of Lambert would not.
  const int w = s.width, h = s.height;
  const int regions[5][4] = {{0, 0, w, h}, {0, 0, w / 2, h / 2}, {w / 2, 0, w, h / 2}, {0, h / 2, w / 2, h}, {w / 2, h / 2, w, h}};
  for (std::size_t other = 0; other < 2; ++other)
    for (const auto& r : regions) {
      const auto a = test::block_estimate(renders[2].film, r[0], r[1], r[2], r[3]);
      const auto b = test::block_estimate(renders[other].film, r[0], r[1], r[2], r[3]);
      for (int c = 0; c < 3; ++c) {
        const double sigma = std::sqrt(a.variance[c] + b.variance[c]);
        EXPECT_GT(a.mean[c], 0.0);
        EXPECT_LE(std::abs(a.mean[c] - b.mean[c]), 5.0 * sigma)
            << kFormats[other] << " vs pbrt, region (" << r[0] << "," << r[1] << ") channel " << c << ": " << b.mean[c]
            << " vs " << a.mean[c] << " (σ " << sigma << ")";
      }
    }
}

}  // namespace
}  // namespace prism::loaders
