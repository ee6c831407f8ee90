#pragma once
// Arbitrary output variables (AOVs): per-pixel data about the first surface each camera
// ray sees, kept beside the beauty for denoisers, compositing and debug views.
//   albedo  reflectance of the first hit — base colour × base-colour texture — in the film's
//           colour space (working RGB; for spectral films CIE XYZ relative to E, where a
//           white reflector is (1, 1, 1)), so it converts to output spaces like the beauty.
//           Delta and named-metal first hits follow Open Image Denoise's guidance that
//           perfect specular surfaces have albedo 1 (or their tint) rather than the
//           albedo of what they show: a mirror and a Schlick conductor give their tint
//           (base colour), a dielectric or a measured-IOR metal gives 1; nothing is
//           followed past the first hit.
//   normal  world-space unit shading normal of the first hit, turned towards the camera;
//           (0, 0, 0) for a camera ray that escapes.
//   depth   distance along the (unit) camera ray to the first hit, in scene units; pixels
//           average it over the samples that hit something (+inf where none did, the
//           usual "no surface" value of an EXR Z channel).
//   variance  of the beauty's pixel mean, per channel of the output space (EXR `--exr-space`):
//           the film keeps the full second-moment matrix of the film-space samples (the
//           three cross sums beside the beauty's squares), because per-channel variances do
//           not convert through a 3×3 colour matrix; Var(m_k·x̄) = m_kᵀ C m_k / n is exact
//           for any output row m_k. Not a first-hit AOV: it describes the whole estimate.
//   sample-count  the number of samples in the pixel's mean (the film's count, which it
//           keeps anyway: nothing more is allocated); with adaptive sampling
//           (adaptive_sampling.h) it shows where the samples went.
// Each AOV is averaged over the pixel's samples with the beauty's box filter; a sample
// whose beauty is discarded as NaN/Inf is discarded from the AOVs too.
#include <string>

#include "prism/core/vec.h"

namespace prism {

struct AovSet {
  bool albedo = false;
  bool normal = false;
  bool depth = false;
  bool variance = false;
  bool sample_count = false;
  bool any() const { return albedo || normal || depth || variance || sample_count; }
  bool first_hit() const { return albedo || normal || depth; }
  bool operator==(const AovSet&) const = default;
  // One bit per AOV (albedo 1, normal 2, depth 4, variance 8, sample-count 16): checkpoints
  // and fingerprints store it.
  static constexpr unsigned kAllBits = 31u;
  unsigned bits() const {
    return (albedo ? 1u : 0u) | (normal ? 2u : 0u) | (depth ? 4u : 0u) | (variance ? 8u : 0u) |
           (sample_count ? 16u : 0u);
  }
  static AovSet from_bits(unsigned bits) {
    return {(bits & 1u) != 0, (bits & 2u) != 0, (bits & 4u) != 0, (bits & 8u) != 0, (bits & 16u) != 0};
  }
};

// "albedo,normal,depth,variance,sample-count" (any non-empty subset, any order, each at
// most once); throws UsageError naming the bad entry and the valid names.
AovSet parse_aov_list(const std::string& text);
// "albedo,normal,depth,variance,sample-count" order; "" for the empty set.
std::string format_aov_list(const AovSet& aovs);

// What one sample's camera ray saw first (written by the integrator, added by the film).
struct AovSample {
  Vec3f albedo{0.0f};  // film colour space; 0 on a miss
  Vec3f normal{0.0f};  // unit, towards the camera; 0 on a miss
  float depth_scene_units = 0.0f;
  bool hit = false;    // depth counts only when the ray hit a surface
};

}  // namespace prism
