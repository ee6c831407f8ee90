#pragma once
// What the channels of a spectrum sample mean, for each transport mode: how authored
// colours (sRGB reflectances, emitters in a colour-picker space with a luminance) become
// per-path spectra, and how a path's radiance becomes film values.
//   spectral: channels are N sampled wavelengths; reflectances are upsampled (Jakob–Hanika
//             2019 table of the material's base-colour space, of an environment map's
//             texel space for its radiance, sRGB for other textures and colours, fitted
//             relative to E so that a flat white light films the colour
//             itself; or Mallett–Yuksel 2019, whose sRGB basis takes wide-gamut colours
//             clipped to Rec.709); emitters follow the emission rule of
//             color/emission_spectrum.h (E-relative), fitted in their own colour space so
//             that a wide-gamut lamp is not clipped to the working gamut; the film holds
//             683·XYZ (Y in nits), relative to illuminant E.
//   rgb:      channels are the working space's R, G, B; reflectances are converted from
//             their primaries (Bradford between whites; a wide-gamut one clipped to the
//             working gamut, where spectral transport renders it whole); emitters, an
//             environment map's and an emission texture's radiance from their own space
//             (Bradford), not clipped; the film holds working RGB with Y in nits.
// Spectra a scene gives as data (scene/spectral_inputs.h) are white-balanced to the working
// white W, the same convention the emission rule follows for colours:
//   spectral: a reflectance R(λ) is used as measured; an emitter's SPD S(λ) becomes
//             L(λ) = K S(λ)/W(λ), K such that 683 ∫ L ȳ dλ is its luminance, so an emitter
//             whose SPD is the working white's (D65 for sRGB) is the flat spectrum, neutral,
//             exactly as a working-white colour is; its spikes stay where they are;
//   rgb:      R becomes the working RGB spectral transport films it as under a white light
//             (XYZ under E, adapted E → W by Bradford), S the working RGB of its CIE XYZ
//             (W itself → white), scaled to the luminance.
// Reflectances agree exactly under a white light; emitters up to the difference between a
// von Kries (Bradford) adaptation and the spectral division
// (tests/render/spectral_inputs_render_test.cpp measures both).
#include <array>
#include <cstdint>
#include <vector>

#include "prism/color/cie_1931.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/sigmoid_polynomial.h"
#include "prism/color/visible_spectrum_table.h"
#include "prism/render/transport_mode.h"
#include "prism/scene/scene.h"

namespace prism {

// The colour space a film's values are in: for spectral films, CIE XYZ relative to E.
color::ColorSpace film_color_space(const TransportSettings& settings);

// Emitter ids: materials are [0, materials), non-geometric lights follow.
inline std::uint32_t light_emitter_id(const Scene& scene, std::size_t light) {
  return static_cast<std::uint32_t>(scene.materials.size() + light);
}

template <class Mode>
class ColorContext;

template <int N>
class ColorContext<SpectralMode<N>> {
 public:
  using Mode = SpectralMode<N>;
  ColorContext(const Scene& scene, const TransportSettings& settings);

  // `u` is the sample's primary number of wavelength sampling, uniform in [0, 1).
  Wavelengths<Mode> sample_wavelengths(std::uint64_t sample_index, double u) const;
  // Two samples' (the same values as two calls, in less time).
  void sample_wavelength_pair(const std::uint64_t (&sample_index)[2], const double (&u)[2], Wavelengths<Mode>& first,
                              Wavelengths<Mode>& second) const;
  // A reflectance given in `space` (sRGB: textures, tints, sheens) upsampled with that
  // space's table.
  Spectrum<Mode> reflectance(const Vec3f& rgb, const Wavelengths<Mode>& w,
                             ColorPickerSpace space = ColorPickerSpace::srgb) const;
  // base_color, emission and to_film run at every vertex or sample of every path: inline
  // below, so the spectra stay in registers instead of passing through memory at each call.
  Spectrum<Mode> base_color(std::uint32_t material, const Wavelengths<Mode>& w) const;
  // Emitted radiance (or intensity / illuminance for delta lights) of an emitter.
  Spectrum<Mode> emission(std::uint32_t emitter, const Wavelengths<Mode>& w) const;
  // Radiance given as linear RGB in nits in `space` (an emission texture's, in its emission
  // colour's space; an environment map's, in its texel space): upsampled with that space's Jakob–Hanika table
  // (E-relative, like the emission rule) at half the largest channel and scaled so that a
  // grey texel becomes the flat spectrum of the same luminance; a colour films as itself
  // to the table's accuracy.
  Spectrum<Mode> rgb_radiance(const Vec3f& linear_nits, const Wavelengths<Mode>& w,
                              ColorPickerSpace space = ColorPickerSpace::srgb) const;
  // An environment map's texel radiance (LightSample::rgb), in the map's texel space.
  Spectrum<Mode> environment_radiance(const Vec3f& linear_nits, const Wavelengths<Mode>& w) const {
    return rgb_radiance(linear_nits, w, environment_space_);
  }
  Vec3d to_film(const Spectrum<Mode>& value, const Wavelengths<Mode>& w) const;
  // A linear reflectance in `space` (the albedo AOV) as film values: CIE XYZ relative to E,
  // with Bradford adaptation from the space's white, so a white reflector is (1, 1, 1).
  Vec3d reflectance_to_film(const Vec3f& rgb, ColorPickerSpace space = ColorPickerSpace::srgb) const {
    return to_film_[static_cast<std::size_t>(space)] * Vec3d(rgb);
  }
  // Keeps only channel 0's wavelength after a dispersive event (hero wavelength, Wilkie
  // et al. 2014): the other channels' pdfs become 0 and channel 0's estimate must become
  // the one-sample estimator f(λ0)/p0(λ0), with p0 the density λ0 was actually drawn with
  // (slot 0's technique). Stored as pdf = p0/N because the film averages over N channels.
  // For hero sampling p0 equals the stored pdf (pbrt-v4's TerminateSecondary divides it by
  // N); for cosh3 the stored balance-heuristic pdf is not λ0's density and must be replaced.
  void terminate_secondary(Wavelengths<Mode>& w) const;

 private:
  Spectrum<Mode> mallett_yuksel_base_color(std::uint32_t material, const Wavelengths<Mode>& w) const;
  // spectrum_tables_[table] at the path's wavelengths.
  Spectrum<Mode> tabulated(std::int32_t table, const Wavelengths<Mode>& w) const {
    Spectrum<Mode> s;
    s = Spectrum<Mode>(spectrum_tables_[static_cast<std::size_t>(table)].evaluate(w.wavelength_nm));
    return s;
  }

  TransportSettings settings_;
  ColorPickerSpace environment_space_;  // environment_map(scene)'s texel space
  std::array<Mat3, 3> to_film_;  // per ColorPickerSpace
  // The upsampling tables per ColorPickerSpace, found once: JakobHanikaTable::get looks the
  // space up by name and takes a lock, which every textured shading point and environment
  // lookup paid (and every thread contended for) when it was called per lookup. sRGB's is
  // always there; another space's is null unless a material's base colour, a textured
  // lamp or the environment map is in it.
  std::array<const color::JakobHanikaTable*, 3> tables_;
  std::array<Mat3, 3> to_srgb_;                           // per ColorPickerSpace (Mallett–Yuksel)
  std::vector<color::SigmoidPolynomial> base_color_jh_;
  std::vector<Vec3d> base_color_my_weights_;  // mallett_yuksel_weights_under_e
  std::vector<color::EmissionSpectrum> emitters_;
  // Spectra given as data: per material and per emitter an index into spectrum_tables_ (−1:
  // the colour's upsampled spectrum above); emitters' tables hold L(λ) with K applied.
  std::vector<std::int32_t> base_color_table_, emitter_table_;
  std::vector<color::VisibleSpectrumTable> spectrum_tables_;
};

template <int N>
inline Spectrum<SpectralMode<N>> ColorContext<SpectralMode<N>>::base_color(std::uint32_t material,
                                                                            const Wavelengths<Mode>& w) const {
  if (const std::int32_t table = base_color_table_[material]; table >= 0) return tabulated(table, w);
  if (settings_.upsampling == Upsampling::mallett_yuksel) return mallett_yuksel_base_color(material, w);
  Spectrum<Mode> s;
  s = Spectrum<Mode>(color::evaluate_sigmoid_polynomial(base_color_jh_[material], w.wavelength_nm));
  return s;
}

template <int N>
inline Spectrum<SpectralMode<N>> ColorContext<SpectralMode<N>>::emission(std::uint32_t emitter,
                                                                          const Wavelengths<Mode>& w) const {
  if (const std::int32_t table = emitter_table_[emitter]; table >= 0) return tabulated(table, w);
  const color::EmissionSpectrum& e = emitters_[emitter];
  Spectrum<Mode> s;
  s = Spectrum<Mode>(color::evaluate_sigmoid_polynomial(e.shape, w.wavelength_nm, static_cast<float>(e.scale)));
  return s;
}

template <int N>
inline Vec3d ColorContext<SpectralMode<N>>::to_film(const Spectrum<Mode>& value, const Wavelengths<Mode>& w) const {
  // Y in nits: the emission rule scales spectra so that 683 ∫ L ȳ dλ is the luminance.
  return color::to_xyz(value, w) * color::kMaxLuminousEfficacyLmPerW;
}

template <>
class ColorContext<RgbMode> {
 public:
  using Mode = RgbMode;
  ColorContext(const Scene& scene, const TransportSettings& settings);

  Wavelengths<Mode> sample_wavelengths(std::uint64_t, double) const { return {}; }
  void sample_wavelength_pair(const std::uint64_t (&)[2], const double (&)[2], Wavelengths<Mode>& first,
                              Wavelengths<Mode>& second) const {
    first = second = {};
  }
  Spectrum<Mode> reflectance(const Vec3f& rgb, const Wavelengths<Mode>& w,
                             ColorPickerSpace space = ColorPickerSpace::srgb) const;
  Spectrum<Mode> base_color(std::uint32_t material, const Wavelengths<Mode>&) const { return base_colors_[material]; }
  Spectrum<Mode> emission(std::uint32_t emitter, const Wavelengths<Mode>&) const { return emitters_[emitter]; }
  // Converted to the working space as an emitter's colour is (emission_radiance_rgb), and
  // not clipped: a colour outside the working gamut keeps its negative channel there, as
  // the same colour given to a constant sky or a lamp does. Transport is linear and every
  // reflectance it meets non-negative, so the film holds that colour itself, scaled; only
  // reflectances are clipped (a negative albedo would flip the sign of what it reflects).
  Spectrum<Mode> rgb_radiance(const Vec3f& linear_nits, const Wavelengths<Mode>&,
                              ColorPickerSpace space = ColorPickerSpace::srgb) const {
    const Vec3d rgb = to_working(linear_nits, space);
    Spectrum<Mode> s;
    for (int i = 0; i < 3; ++i) s[i] = static_cast<float>(rgb[i]);
    return s;
  }
  Spectrum<Mode> environment_radiance(const Vec3f& linear_nits, const Wavelengths<Mode>& w) const {
    return rgb_radiance(linear_nits, w, environment_space_);
  }
  Vec3d to_film(const Spectrum<Mode>& value, const Wavelengths<Mode>&) const { return {value[0], value[1], value[2]}; }
  // A linear reflectance in `space` (the albedo AOV) in the working space.
  Vec3d reflectance_to_film(const Vec3f& rgb, ColorPickerSpace space = ColorPickerSpace::srgb) const {
    return to_working(rgb, space);
  }
  void terminate_secondary(Wavelengths<Mode>&) const {}

 private:
  // A linear colour in `space` in the working space, unclipped.
  Vec3d to_working(const Vec3f& rgb, ColorPickerSpace space) const {
    return to_working_[static_cast<std::size_t>(space)] * Vec3d(rgb);
  }

  ColorPickerSpace environment_space_;  // environment_map(scene)'s texel space
  std::array<Mat3, 3> to_working_;  // per ColorPickerSpace; [srgb] converts textures and tints
  std::vector<Spectrum<Mode>> base_colors_;
  std::vector<Spectrum<Mode>> emitters_;
};

}  // namespace prism
