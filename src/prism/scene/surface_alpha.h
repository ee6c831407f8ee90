#pragma once
// Alpha coverage of surfaces (glTF alphaMode, OBJ `d`, JSON `alpha_mode`): the fraction of
// a surface point that is there. MASK cuts out where alpha < cutoff; BLEND is treated as
// stochastic coverage (Enderton et al. 2010, "Stochastic Transparency"): a ray passes a
// point with probability 1 − alpha, which renders the blend unbiasedly without sorting.
// The accelerator applies both in its intersection filters, so camera, continuation and
// shadow rays all see the same cut-outs.
#include <cstdint>

#include "prism/scene/scene.h"

namespace prism {

// True when `material` can let rays through at all (mask, or blend with opacity or a
// texture that may be below 1).
bool has_alpha_coverage(const Material& material);

// opacity × the base-colour texture's alpha at barycentrics (b1, b2) of vertices 1 and 2
// of `triangle` (bilinear at full resolution, so cut-out edges stay sharp).
float surface_alpha(const Scene& scene, const TriangleMesh& mesh, std::uint32_t triangle, float b1, float b2);

// Whether a ray meets the surface point: MASK compares with the cutoff; BLEND compares
// alpha with `u`, a uniform number in [0, 1) that must depend only on the ray and the
// primitive (so every thread and every repetition decides the same way).
bool surface_alpha_accepts(const Material& material, float alpha, float u);

}  // namespace prism
