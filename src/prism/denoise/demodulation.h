#pragma once
// Albedo demodulation: the denoiser filters irradiance-like radiance / albedo instead of
// radiance, and multiplies the pixel's own albedo back afterwards, so that texture detail
// the albedo carries is never averaged with its neighbours (Zimmer et al., "Path-space
// Motion Estimation and Decomposition for Robust Animation Filtering", EGSR 2015, §3; the
// "untextured illumination" of Bako et al. 2017's KPCN; Cycles and SVGF do the same).
// The divisor is the albedo itself, floored per channel so that near-black reflectors do
// not amplify their noise without bound, and 1 where the pixel saw no surface (a miss, or a
// black first hit), where nothing can be demodulated.
#include <vector>

namespace prism::denoise {

// Albedo channels below this are floored to it: a divisor of 1/100 still lets the filter
// share the irradiance of dark surfaces with their neighbours.
inline constexpr float kAlbedoFloor = 0.01f;

// Interleaved RGB divisors (3 per pixel) for interleaved RGB albedo.
std::vector<float> demodulation_divisors(const std::vector<float>& albedo);

}  // namespace prism::denoise
