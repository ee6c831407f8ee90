// --memory-limit: a render whose estimated memory exceeds the limit is refused before
// anything large is allocated; ordinary renders pass; sizes parse with K/M/G/T suffixes.
#include "prism/render/memory_estimate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {
namespace {

constexpr std::uint64_t kGiB = 1ull << 30;

TEST(MemoryEstimate, FilmScalesWithPixelsAndPathPoolWithThreads) {
  const Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = 64;
  s.height = static_cast<int>(2 * kWavefrontTilePixels / 64 - 8);  // two tiles of the wavefront integrator
  const std::uint64_t pixels = static_cast<std::uint64_t>(s.width) * static_cast<std::uint64_t>(s.height);
  s.threads = 1;
  const MemoryEstimate e = estimate_render_memory(scene, s);
  EXPECT_EQ(e.film, pixels * (2 * 24 + 4));
  // One tile's path state per thread that runs tiles, camera packets included: no more
  // threads than tiles.
  const std::uint64_t tile_slot = kPathPoolBytesPerSlot + camera_packet_bytes_per_slot(kTileCameraPacketsPerBlock);
  EXPECT_EQ(e.path_pool, kWavefrontTilePixels * tile_slot);
  s.threads = 3;
  EXPECT_EQ(estimate_render_memory(scene, s).path_pool, 2 * kWavefrontTilePixels * tile_slot);
  s.width = s.height = 4000;
  s.threads = 2;
  EXPECT_EQ(estimate_render_memory(scene, s).path_pool, 2 * kWavefrontTilePixels * tile_slot)
      << "the path state must not grow with the image";
  // Passes that report every few bounces keep one whole-image queue: a slot per pixel.
  s.bounces_per_pass = 1;
  EXPECT_EQ(estimate_render_memory(scene, s).path_pool,
            4000u * 4000u * (kPathPoolBytesPerSlot + camera_packet_bytes_per_slot(kWholeImageCameraPacketsPerBlock)));
  s.bounces_per_pass = 0;
  s.width = 100;
  s.height = 50;
  s.threads = 1;
  EXPECT_GT(e.meshes, 0u);
  EXPECT_EQ(e.textures, 0u);  // the Cornell box has no textures
  EXPECT_EQ(e.total(), e.film + e.path_pool + e.images + e.textures + e.meshes);
}

TEST(MemoryEstimate, CountsTexturesAndInstancedMeshes) {
  Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = s.height = 8;
  const MemoryEstimate plain = estimate_render_memory(scene, s);
  TextureImage t;
  t.width = t.height = 256;
  t.channels = 4;
  t.texels.assign(256u * 256 * 4, 0.5f);
  scene.textures.push_back(t);
  scene.materials[0].base_color_texture = 0;
  const MemoryEstimate textured = estimate_render_memory(scene, s);
  EXPECT_EQ(plain.textures, 0u);
  // Copied into the prepared scene: loaded + copy + mip levels 1 and up (a third of the
  // image; level 0 is the texels themselves). Handed over: no copy.
  EXPECT_EQ(textured.textures, 2 * t.memory_bytes() + t.memory_bytes() / 3);
  EXPECT_EQ(estimate_render_memory(scene, s, SceneHandover::moved).textures, t.memory_bytes() + t.memory_bytes() / 3);
  // Used by no material (an environment map): no mip levels.
  scene.materials[0].base_color_texture = -1;
  EXPECT_EQ(estimate_render_memory(scene, s, SceneHandover::moved).textures, t.memory_bytes());
  // Ten instances of a one-triangle mesh: the loaded mesh, ten flattened copies and a
  // BVH over ten triangles.
  Scene tri;
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  tri.meshes.push_back(m);
  const std::uint64_t mesh_bytes = 3 * sizeof(Vec3f) + 3 * sizeof(std::uint32_t);
  EXPECT_EQ(estimate_render_memory(tri, s).meshes, 2 * mesh_bytes + kBvhBytesPerTriangle);
  EXPECT_EQ(estimate_render_memory(tri, s, SceneHandover::moved).meshes, mesh_bytes + kBvhBytesPerTriangle);
  for (int i = 0; i < 10; ++i) tri.instances.push_back(Instance{0, Transform{}});
  EXPECT_EQ(estimate_render_memory(tri, s).meshes, 11 * mesh_bytes + 10 * kBvhBytesPerTriangle);
  // Flattening builds the instances' meshes while the loaded one still exists.
  EXPECT_EQ(estimate_render_memory(tri, s, SceneHandover::moved).meshes, 11 * mesh_bytes + 10 * kBvhBytesPerTriangle);
}

TEST(MemoryEstimate, HugeRenderIsRefusedBeforeAllocation) {
  const Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = s.height = 30000;  // about 270 GB of film and path state
  s.samples_per_pixel = 1;
  s.memory_limit_bytes = kGiB;
  const auto start = std::chrono::steady_clock::now();
  try {
    render(scene, s);
    FAIL() << "a 30000x30000 render under a 1 GiB limit was not refused";
  } catch (const UsageError&) {
    FAIL() << "refusal must be an Error (exit 1), not a UsageError";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("memory limit of 1.00 GiB"), std::string::npos) << what;
    EXPECT_NE(what.find("30000x30000"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  // Refused before the ~40 GB film was touched: far faster than any allocation of it.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

TEST(MemoryEstimate, OrdinaryRenderPassesUnderTheDefaultAndAnExplicitLimit) {
  const Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = 32;
  s.height = 24;
  s.samples_per_pixel = 1;
  EXPECT_EQ(render(scene, s).passes_done, 1);  // default: 90 % of physical memory
  s.memory_limit_bytes = kGiB;
  EXPECT_EQ(render(scene, s).passes_done, 1);
  EXPECT_GT(default_memory_limit(), 0u);
}

TEST(MemoryEstimate, ParsesSizes) {
  EXPECT_EQ(parse_memory_size("1048576"), 1048576u);
  EXPECT_EQ(parse_memory_size("512K"), 512u * 1024);
  EXPECT_EQ(parse_memory_size("64M"), 64ull << 20);
  EXPECT_EQ(parse_memory_size("1G"), kGiB);
  EXPECT_EQ(parse_memory_size("1.5g"), kGiB * 3 / 2);
  EXPECT_EQ(parse_memory_size("4GiB"), 4 * kGiB);
  EXPECT_EQ(parse_memory_size("2GB"), 2 * kGiB);
  EXPECT_EQ(parse_memory_size("1T"), 1024 * kGiB);
  for (const char* bad : {"", "G", "-1G", "0", "1X", "1GG", "abc", "nan", "1e30T", " 1G"})
    EXPECT_THROW(parse_memory_size(bad), UsageError) << bad;
}

TEST(MemoryEstimate, FormatsBytes) {
  EXPECT_EQ(format_bytes(512), "512 B");
  EXPECT_EQ(format_bytes(kGiB), "1.00 GiB");
  EXPECT_EQ(format_bytes(3 * kGiB / 2), "1.50 GiB");
  EXPECT_EQ(format_bytes(100ull << 20), "100 MiB");
}

}  // namespace
}  // namespace prism
