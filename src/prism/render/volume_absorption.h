#pragma once
// Absorption inside solid dielectrics by the Beer–Lambert law, as glTF's
// KHR_materials_volume defines it: a medium of attenuation colour c and attenuation
// distance d has the absorption coefficient σ = −ln(c) / d per channel, and a path segment
// of length t inside it is weighted by T = exp(−σ t), so that light crossing d keeps c of
// itself (the extension's text: "the color that white light turns into due to absorption
// when reaching the attenuation distance"). No scattering: the interior is clear, only
// dimmed and coloured with depth. pbrt-v4 calls the same thing a homogeneous medium with
// σ_a = σ and σ_s = 0.
//
// Spectral transport upsamples c as a reflectance (values in [0, 1] at every wavelength,
// so σ ≥ 0) and takes σ(λ) per sampled wavelength; RGB transport applies the law per
// working-space channel.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "prism/color/sampled_spectrum.h"

namespace prism {

// σ per scene unit from c at the path's wavelengths (or channels) and d. A channel of c at
// 0 would make σ infinite and 0 · ∞ a NaN on a zero-length segment: c is clamped to
// 1e-30 (σ·d ≤ 69: after one attenuation distance 1e-30 of the light is left, nothing any
// film can show), and to 1 from above (values past 1 would be gain; the loaders refuse
// them, the clamp catches working-space conversions that overshoot by rounding).
template <int N>
color::SampledSpectrum<N> absorption_coefficient(const color::SampledSpectrum<N>& attenuation_color,
                                                 float attenuation_distance) {
  color::SampledSpectrum<N> sigma;
  for (std::size_t i = 0; i < static_cast<std::size_t>(N); ++i)
    sigma[i] = -std::log(std::clamp(attenuation_color[i], 1e-30f, 1.0f)) / attenuation_distance;
  return sigma;
}

// exp(−σ t) per channel. An infinite segment (a path that leaves an open mesh from
// inside) is fully absorbed in every channel that absorbs at all, and kept in those that do
// not (σ = 0: exp(−0 · ∞) would be a NaN).
template <int N>
color::SampledSpectrum<N> beer_lambert_transmittance(const color::SampledSpectrum<N>& sigma, float distance) {
  color::SampledSpectrum<N> t(1.0f);
  for (std::size_t i = 0; i < static_cast<std::size_t>(N); ++i)
    if (sigma[i] > 0.0f) t[i] = std::exp(-sigma[i] * distance);
  return t;
}

}  // namespace prism
