#pragma once
// The image fingerprint: a hash of everything that decides a render's pixels, carried by
// checkpoints and partial renders so that only compatible states are resumed or merged
// (docs/reliability.md). A scene or settings field that changes pixels must be hashed
// here; tests/render/image_fingerprint_test.cpp fails when a scene struct grows without
// this file being reviewed.
#include <cstdint>

namespace prism {

struct Scene;
struct RenderSettings;

// A fingerprint of everything that determines the pixel values of sample i: the scene,
// image size, seed and path settings, sampler included (not spp, threads or time limits),
// and the AOV set when it is not empty (the files then hold more layers). Checkpoints and
// partial renders carry it so that only compatible states are resumed or merged.
std::uint64_t image_fingerprint(const Scene& scene, const RenderSettings& settings);

}  // namespace prism
