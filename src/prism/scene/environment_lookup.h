#pragma once
// Radiance of an environment map between its texels: bilinear filtering with the texel
// neighbours each mapping has across its borders, and the mean of that filtered function
// over a texel, from which the map's sampling distribution is built (light_sampler.cpp).
//
// Every estimator of the light an environment gives — a camera ray that escapes, a BSDF
// sample that escapes, next-event estimation's sample of the map — reads the one function
// environment_radiance_bilinear, and the sampling density is positive wherever it is
// (texel weights are its mean over the texel, which is positive wherever the function is
// somewhere on the texel), so light sampling alone is unbiased as well as MIS.
#include <span>
#include <utility>

#include "prism/core/vec.h"
#include "prism/scene/light.h"
#include "prism/scene/texture.h"

namespace prism {

// The texel (x', y') that stands for (x, y) when x or y lies up to one texel outside a
// width × height map. Equirectangular: u is periodic (φ wraps), v is clamped at the poles.
// Equal-area octahedral: each border folds onto itself about its midpoint, as the sphere
// continues there (pbrt-v4's WrapMode::OctahedralSphere).
std::pair<int, int> environment_texel_address(EnvironmentMapping mapping, int x, int y, int width, int height);

// Linear RGB (the map's texel space, unscaled) at uv ∈ [0,1]², interpolated bilinearly
// between the four texel centres around uv (texel (x, y)'s centre at ((x + ½)/width,
// (y + ½)/height)), neighbours across the borders by environment_texel_address.
Vec3f environment_radiance_bilinear(const TextureImage& map, EnvironmentMapping mapping, Vec2f uv);

// The mean over texel (x, y)'s area of the bilinear interpolation of `values` (one per
// texel, row-major, width × height): Σ w(dx) w(dy) values(x + dx, y + dy) over dx, dy ∈
// {−1, 0, 1}, with w = (1/8, 3/4, 1/8) — the integral of a linear ramp from each half of
// the texel to its neighbour's centre — and neighbours by environment_texel_address.
double environment_texel_mean(std::span<const float> values, EnvironmentMapping mapping, int x, int y, int width,
                              int height);

}  // namespace prism
