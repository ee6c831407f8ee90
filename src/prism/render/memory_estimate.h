#pragma once
// What a render will hold in memory, estimated from the scene and settings before any of
// it is allocated, so that a render that cannot fit is refused with a clear message
// instead of being killed by the OOM killer hours later (--memory-limit).
#include <cstdint>
#include <string>

#include "prism/core/memory_budget.h"  // format_bytes
#include "prism/render/renderer.h"
#include "prism/scene/scene.h"

namespace prism {

struct MemoryEstimate {
  std::uint64_t film = 0;       // sums, squared sums (2 × Vec3d) and counts (u32) per pixel, plus AOV sums
  // Wavefront path state, about 290 B per slot, and its camera packets: a tile per thread
  // (or a slot per pixel).
  std::uint64_t path_pool = 0;
  std::uint64_t images = 0;     // output conversion buffers (float RGB per pixel, twice)
  std::uint64_t textures = 0;   // loaded texels, the renderer's copy (if copied) and mip levels 1 and up
  std::uint64_t meshes = 0;     // vertex and index arrays, loaded and (if copied or instanced) flattened, plus the BVH
  std::uint64_t total() const { return film + path_pool + images + textures + meshes; }
};

// Bytes per pixel and per triangle the estimate assumes (documented in docs/reliability.md).
inline constexpr std::uint64_t kFilmBytesPerPixel = 2 * 3 * sizeof(double) + sizeof(std::uint32_t);
// AOV sums per pixel (film.h FilmAovSums) and the per-slot first-hit record (aov.h) the
// integrator keeps while any AOV is on.
inline constexpr std::uint64_t kAlbedoBytesPerPixel = 3 * sizeof(double);
inline constexpr std::uint64_t kNormalBytesPerPixel = 3 * sizeof(double);
inline constexpr std::uint64_t kDepthBytesPerPixel = sizeof(double) + sizeof(std::uint32_t);
inline constexpr std::uint64_t kCrossSumBytesPerPixel = 3 * sizeof(double);  // variance AOV
inline constexpr std::uint64_t kAovBytesPerSlot = 32;  // sizeof(AovSample), checked in memory_estimate.cpp
inline constexpr std::uint64_t kPathPoolBytesPerSlot = 290;  // 4 wavelengths, with the interior medium (σ, flag) and the emission cache
inline constexpr std::uint64_t kImageBytesPerPixel = 2 * 3 * sizeof(float);
// Output conversion buffers per AOV channel (one float image per channel, like the beauty).
inline constexpr std::uint64_t kAovImageBytesPerChannel = sizeof(float);
inline constexpr std::uint64_t kBvhBytesPerTriangle = 96;  // Embree BVH4 with triangle data

// How the render gets the scene: render(const Scene&) copies it into its prepared scene
// (the viewer, the library's default), render(Scene&&) takes it over (`prism render`), so
// the loaded meshes and texels are held once instead of twice.
enum class SceneHandover { copied, moved };

MemoryEstimate estimate_render_memory(const Scene& scene, const RenderSettings& settings,
                                      SceneHandover handover = SceneHandover::copied);

// 90 % of physical memory (sysconf), or 0 when the platform does not say.
std::uint64_t default_memory_limit();

// Parses "BYTES" or a number with a K, M, G or T suffix (binary: K = 1024; an optional
// trailing "B" or "iB" is accepted, e.g. "512M", "1.5G", "4GiB"). Throws UsageError.
std::uint64_t parse_memory_size(const std::string& text);

// Throws Error (exit 1 in the CLI) naming the estimate, its parts and the limit when the
// estimate exceeds `limit_bytes` (0: default_memory_limit()).
void check_render_memory(const Scene& scene, const RenderSettings& settings, std::uint64_t limit_bytes,
                         SceneHandover handover = SceneHandover::copied);

}  // namespace prism
