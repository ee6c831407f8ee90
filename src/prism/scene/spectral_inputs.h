#pragma once
// Spectra a scene gives instead of RGB colours: the relative spectral power distribution of
// an emitter (a CIE illuminant by name, a black body, or measured values) and the measured
// reflectance of a material. The loaders turn every form into a piecewise-linear table
// (color::PiecewiseLinearSpectrum: linear between the points, the end values held outside);
// how each transport mode uses it is render/color_context.h's business. The colour helpers
// here give the RGB approximation the rest of the scene sees (Material::base_color,
// Emission::color: previews, light-power estimates, exporters to RGB-only formats).
#include <optional>
#include <string_view>
#include <utility>

#include "prism/color/spectrum.h"
#include "prism/core/vec.h"

namespace prism {

// "D65", "D50", "A", "E" (CIE standard illuminants) and "F1"…"F12" (CIE fluorescent
// FL1–FL12, also accepted as "FL1"…"FL12"), case-insensitive; nothing for other names.
std::optional<color::PiecewiseLinearSpectrum> named_emission_spectrum(std::string_view name);
inline constexpr std::string_view kEmissionSpectrumNames = "D65, D50, A, E, F1 to F12";

// Planck's law at `temperature_k`, tabulated at 1 nm over 360–830 nm (relative: any scale).
color::PiecewiseLinearSpectrum blackbody_emission_spectrum(double temperature_k);

// The emitter's colour as linear Rec.709 with largest channel 1: CIE XYZ of the SPD
// (1931 observer) in sRGB without adaptation, so D65 is white and illuminant A orange, as a
// camera balanced for D65 sees them; negative channels (colours outside Rec.709) clipped.
Vec3f emission_spectrum_srgb(const color::PiecewiseLinearSpectrum& spd);
// A reflectance's colour as linear Rec.709, clipped to [0, 1], as a spectral render films it
// under a white light: its XYZ under the flat spectrum (illuminant E, the neutral of the
// emission rule), adapted E → D65 by Bradford (color::spectral_xyz_to_rgb_matrix).
Vec3f reflectance_spectrum_srgb(const color::PiecewiseLinearSpectrum& reflectance);

// Gives an emitter (Emission, Light, or a loader's record with `color` and `spectrum`) its
// spectrum, and its colour the spectrum's Rec.709 approximation.
template <class Emitter>
void set_emission_spectrum(Emitter& emitter, color::PiecewiseLinearSpectrum spd) {
  emitter.color = emission_spectrum_srgb(spd);
  emitter.spectrum = std::move(spd);
}
// The same for a material's measured reflectance and its base colour.
template <class Surface>
void set_base_color_spectrum(Surface& material, color::PiecewiseLinearSpectrum reflectance) {
  material.base_color = reflectance_spectrum_srgb(reflectance);
  material.base_color_space = {};  // srgb: a spectrum has no primaries
  material.base_color_spectrum = std::move(reflectance);
}

}  // namespace prism
