#include "prism/render/memory_estimate.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/scene/material_textures.h"

namespace prism {
namespace {

static_assert(sizeof(AovSample) <= kAovBytesPerSlot, "the memory estimate must cover the first-hit record");

std::uint64_t mesh_bytes(const TriangleMesh& m) {
  return m.positions.size() * sizeof(Vec3f) + m.normals.size() * sizeof(Vec3f) + m.uvs.size() * sizeof(Vec2f) +
         m.tangents.size() * sizeof(Vec3f) + m.tangent_signs.size() * sizeof(float) + m.indices.size() * sizeof(std::uint32_t);
}

// Path state slots (wavefront_integrator.h): one tile's per thread that runs tiles, or one
// per pixel when passes report every few bounces (the whole-image lockstep queue).
std::uint64_t path_slots(const RenderSettings& s, std::uint64_t pixels) {
  if (s.bounces_per_pass > 0) return pixels;
  const std::uint64_t tiles = (pixels + kWavefrontTilePixels - 1) / kWavefrontTilePixels;
  const auto threads = static_cast<std::uint64_t>(s.threads > 0 ? s.threads : ThreadLimit::hardware_threads());
  return std::min(tiles, threads) * kWavefrontTilePixels;
}

}  // namespace

MemoryEstimate estimate_render_memory(const Scene& scene, const RenderSettings& settings, SceneHandover handover) {
  MemoryEstimate e;
  const std::uint64_t pixels = static_cast<std::uint64_t>(settings.width > 0 ? settings.width : 0) *
                               static_cast<std::uint64_t>(settings.height > 0 ? settings.height : 0);
  const AovSet& a = settings.aovs;
  const std::uint64_t aov_film = (a.albedo ? kAlbedoBytesPerPixel : 0) + (a.normal ? kNormalBytesPerPixel : 0) +
                                 (a.depth ? kDepthBytesPerPixel : 0) + (a.variance ? kCrossSumBytesPerPixel : 0);
  const std::uint64_t aov_channels =
      (a.albedo ? 3 : 0) + (a.normal ? 3 : 0) + (a.depth ? 2 : 0) + (a.variance ? 3 : 0);  // Z + coverage
  e.film = pixels * (kFilmBytesPerPixel + aov_film);
  const std::size_t camera_packets =
      settings.bounces_per_pass > 0 ? kWholeImageCameraPacketsPerBlock : kTileCameraPacketsPerBlock;
  e.path_pool = path_slots(settings, pixels) * (kPathPoolBytesPerSlot + camera_packet_bytes_per_slot(camera_packets) +
                                                (a.first_hit() ? kAovBytesPerSlot : 0));
  e.images = pixels * (kImageBytesPerPixel + aov_channels * kAovImageBytesPerChannel);

  // The loaded texels, the prepared scene's copy of them unless the scene is handed over,
  // and the mip levels above level 0 of the textures materials use (1/3 of the image; level
  // 0 is the texels themselves; environment maps have none; a Radiance image's levels are
  // floats, 12 bytes per texel against its 4, and a half-float image's 4 bytes per sample
  // against its 2).
  const bool copied = handover == SceneHandover::copied;
  const std::vector<bool> filtered = textures_used_by_materials(scene);
  std::uint64_t texels = 0, mip_levels = 0;
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    texels += scene.textures[t].memory_bytes();
    const TextureImage& image = scene.textures[t];
    if (filtered[t]) mip_levels += image.memory_bytes() * (image.has_rgbe() ? 3 : image.has_halves() ? 2 : 1) / 3;
  }
  e.textures = texels * (copied ? 2 : 1) + mip_levels;

  // The loaded meshes, the flattened copy (one mesh per instance; without instances a copy
  // only when the scene is copied, not handed over) and the BVH over it.
  std::uint64_t loaded = 0, loaded_triangles = 0;
  for (const auto& m : scene.meshes) {
    loaded += mesh_bytes(m);
    loaded_triangles += m.triangle_count();
  }
  std::uint64_t flat = copied ? loaded : 0, flat_triangles = loaded_triangles;
  if (!scene.instances.empty()) {
    flat = flat_triangles = 0;
    for (const auto& inst : scene.instances) {
      if (inst.mesh >= scene.meshes.size()) continue;  // validate_scene/flatten report it
      flat += mesh_bytes(scene.meshes[inst.mesh]);
      flat_triangles += scene.meshes[inst.mesh].triangle_count();
    }
  }
  e.meshes = loaded + flat + flat_triangles * kBvhBytesPerTriangle;
  return e;
}

std::uint64_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return static_cast<std::uint64_t>(pages) / 10 * 9 * static_cast<std::uint64_t>(page_size);
}

std::uint64_t parse_memory_size(const std::string& text) {
  const auto bad = [&] {
    return UsageError(fmt::format("--memory-limit '{}' is not a size (BYTES, or a number with K, M, G or T)", text));
  };
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (!std::isfinite(value) || value <= 0.0 || !std::isdigit(static_cast<unsigned char>(text[0]))) throw bad();
  std::string suffix = text.substr(used);
  for (auto& c : suffix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  double scale = 1.0;
  if (!suffix.empty() && std::string("KMGT").find(suffix[0]) != std::string::npos) {
    scale = std::pow(1024.0, static_cast<double>(std::string("KMGT").find(suffix[0]) + 1));
    suffix.erase(0, 1);
    if (suffix == "IB" || suffix == "B") suffix.clear();
  } else if (suffix == "B") {
    suffix.clear();
  }
  if (!suffix.empty()) throw bad();
  const double bytes = value * scale;
  if (bytes < 1.0 || bytes > 1.8e19) throw bad();
  return static_cast<std::uint64_t>(bytes);
}

void check_render_memory(const Scene& scene, const RenderSettings& settings, std::uint64_t limit_bytes,
                         SceneHandover handover) {
  const std::uint64_t limit = limit_bytes > 0 ? limit_bytes : default_memory_limit();
  if (limit == 0) return;  // physical memory unknown and no explicit limit
  const MemoryEstimate e = estimate_render_memory(scene, settings, handover);
  if (e.total() <= limit) return;
  throw Error(fmt::format(
      "render needs about {} (film {}, path pool {}, images {}, textures {}, meshes {}) for {}x{}, more than the "
      "memory limit of {}{}; reduce the resolution or scene, or raise --memory-limit",
      format_bytes(e.total()), format_bytes(e.film), format_bytes(e.path_pool), format_bytes(e.images),
      format_bytes(e.textures), format_bytes(e.meshes), settings.width, settings.height, format_bytes(limit),
      limit_bytes > 0 ? "" : " (90 % of physical memory)"));
}

}  // namespace prism
