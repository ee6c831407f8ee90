#include "prism/render/color_context.h"

#include <algorithm>
#include <optional>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/cie_1931.h"
#include "prism/color/illuminants.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/mallett_yuksel.h"
#include "prism/scene/emission.h"

namespace prism {
namespace {

struct EmitterColor {
  Vec3f color;
  ColorPickerSpace space;
  float value;  // nits, candela or lux: the spectrum is normalised the same way
  const color::PiecewiseLinearSpectrum* spectrum;  // given as data instead of the colour, or null
};

std::vector<EmitterColor> emitter_colors(const Scene& scene) {
  std::vector<EmitterColor> out;
  for (const Material& m : scene.materials)
    out.push_back({m.emission.color, m.emission.color_space, m.is_emissive() ? m.emission.luminance_nits : 0.0f,
                   m.emission.spectrum ? &*m.emission.spectrum : nullptr});
  for (const Light& l : scene.lights)
    out.push_back({l.color, l.color_space, l.intensity, l.spectrum ? &*l.spectrum : nullptr});
  return out;
}

// L(λ) = K S(λ)/W(λ) with 683 ∫ L ȳ dλ = `value` (color_context.h): the table of a spectral
// emitter given as data, white-balanced to the working white's SPD W.
color::VisibleSpectrumTable balanced_emission_table(const color::PiecewiseLinearSpectrum& spd,
                                                    const color::DenseSpectrum& white, double value) {
  const auto balanced = [&](double nm) { return spd(nm) / white(nm); };
  const double y = color::spectrum_to_xyz(balanced).y;
  const double k = y > 0.0 ? value / (color::kMaxLuminousEfficacyLmPerW * y) : 0.0;
  return color::VisibleSpectrumTable(balanced, k);
}

// The working white's SPD (illuminant_for_white: for a white with no CIE table, a Newton
// fit), found on first use: only scenes with spectra given as data need it.
class WorkingWhiteSpd {
 public:
  explicit WorkingWhiteSpd(const color::ColorSpace& working) : working_(working) {}
  const color::DenseSpectrum& get() {
    if (!spd_) spd_ = color::illuminant_for_white(working_.white);
    return *spd_;
  }

 private:
  const color::ColorSpace& working_;
  std::optional<color::DenseSpectrum> spd_;
};

// Working RGB of an emitter's SPD: its CIE XYZ scaled to Y = `value`, unadapted (W → white).
Vec3d emission_spectrum_rgb(const color::PiecewiseLinearSpectrum& spd, const color::ColorSpace& working,
                            double value) {
  const Vec3d xyz = color::spectrum_to_xyz(spd);
  if (!(xyz.y > 0.0)) return Vec3d(0.0);
  return working.xyz_to_rgb * (xyz * (value / xyz.y));
}

// conversion_matrix from each ColorPickerSpace (indexed by its value) to `target`.
std::array<Mat3, 3> conversions_to(const color::ColorSpace& target) {
  std::array<Mat3, 3> out;
  for (const ColorPickerSpace s : {ColorPickerSpace::srgb, ColorPickerSpace::acescg, ColorPickerSpace::rec2020})
    out[static_cast<std::size_t>(s)] = color::conversion_matrix(picker_color_space(s), target);
  return out;
}

ColorPickerSpace environment_space(const Scene& scene) {
  const TextureImage* map = environment_map(scene);
  return map ? map->texel_space : ColorPickerSpace::srgb;
}

}  // namespace

color::ColorSpace film_color_space(const TransportSettings& settings) {
  if (settings.kind == TransportKind::rgb) return color::color_space(settings.working_space);
  return color::xyz_space("xyz-e", color::kWhiteE);
}

template <int N>
ColorContext<SpectralMode<N>>::ColorContext(const Scene& scene, const TransportSettings& settings)
    : settings_(settings),
      environment_space_(environment_space(scene)),
      to_film_(conversions_to(film_color_space(settings))),
      to_srgb_(conversions_to(color::color_space("srgb"))) {
  // A wide-gamut colour is upsampled with its own space's table: the sRGB one would clip it
  // to Rec.709. Mallett–Yuksel's basis is sRGB's: the colour converted, clipped there.
  // The wide-gamut tables are found only where a material or the environment map needs
  // them (each is megabytes).
  tables_ = {&color::JakobHanikaTable::get("srgb"), nullptr, nullptr};
  const auto need_table = [&](ColorPickerSpace space) {
    if (!tables_[static_cast<std::size_t>(space)])
      tables_[static_cast<std::size_t>(space)] = &color::JakobHanikaTable::get(picker_space_name(space));
  };
  need_table(environment_space_);
  for (const Material& m : scene.materials) {
    if (m.emission.texture >= 0) need_table(m.emission.color_space);  // textured radiance (rgb_radiance)
    const std::size_t space = static_cast<std::size_t>(m.base_color_space);
    need_table(m.base_color_space);
    base_color_jh_.push_back(tables_[space]->lookup(Vec3d(m.base_color)));
    const Vec3d srgb = m.base_color_space == ColorPickerSpace::srgb ? Vec3d(m.base_color)
                                                                    : max(to_srgb_[space] * Vec3d(m.base_color), Vec3d(0.0));
    base_color_my_weights_.push_back(color::mallett_yuksel_weights_under_e(srgb));
    base_color_table_.push_back(-1);
    if (m.base_color_spectrum) {
      base_color_table_.back() = static_cast<std::int32_t>(spectrum_tables_.size());
      spectrum_tables_.emplace_back(*m.base_color_spectrum);
    }
  }
  const color::ColorSpace& working = color::color_space(settings.working_space);
  WorkingWhiteSpd white(working);
  for (const EmitterColor& e : emitter_colors(scene)) {
    emitter_table_.push_back(-1);
    if (e.spectrum && e.value > 0.0f) {
      emitter_table_.back() = static_cast<std::int32_t>(spectrum_tables_.size());
      spectrum_tables_.push_back(balanced_emission_table(*e.spectrum, white.get(), e.value));
    }
    // Fitted in the colour's own space (adapted from its white to E), not the working
    // space's: a wide-gamut emitter outside the working gamut would be clipped there, and
    // inside it the two agree (Bradford adaptations compose: white → working white → E is
    // white → E).
    emitters_.push_back(e.value > 0.0f ? color::emission_spectrum(Vec3d(e.color), picker_color_space(e.space), e.value)
                                       : color::EmissionSpectrum{});
  }
}

template <int N>
Wavelengths<SpectralMode<N>> ColorContext<SpectralMode<N>>::sample_wavelengths(std::uint64_t sample_index,
                                                                                double jitter) const {
  const double u = settings_.stratify_first_wavelengths ? color::stratified_wavelength_u(sample_index, jitter) : jitter;
  return color::sample_wavelengths<N>(settings_.wavelength_strategy, u);
}

template <int N>
void ColorContext<SpectralMode<N>>::sample_wavelength_pair(const std::uint64_t (&sample_index)[2], const double (&jitter)[2],
                                                           Wavelengths<Mode>& first, Wavelengths<Mode>& second) const {
  double u[2] = {jitter[0], jitter[1]};
  if (settings_.stratify_first_wavelengths)
    for (int k = 0; k < 2; ++k) u[k] = color::stratified_wavelength_u(sample_index[k], jitter[k]);
  color::sample_wavelength_pair<N>(settings_.wavelength_strategy, u, first, second);
}

template <int N>
Spectrum<SpectralMode<N>> ColorContext<SpectralMode<N>>::reflectance(const Vec3f& rgb, const Wavelengths<Mode>& w,
                                                                      ColorPickerSpace space) const {
  Spectrum<Mode> s;
  const auto index = static_cast<std::size_t>(space);
  if (settings_.upsampling == Upsampling::mallett_yuksel) {
    const Vec3d srgb = space == ColorPickerSpace::srgb ? Vec3d(rgb) : max(to_srgb_[index] * Vec3d(rgb), Vec3d(0.0));
    const color::MallettYukselSpectrum my{color::mallett_yuksel_weights_under_e(srgb)};
    for (int i = 0; i < N; ++i) s[i] = static_cast<float>(my(w.wavelength_nm[i]));
  } else {
    s = Spectrum<Mode>(color::evaluate_sigmoid_polynomial(tables_[index]->lookup(Vec3d(rgb)), w.wavelength_nm));
  }
  return s;
}

template <int N>
Spectrum<SpectralMode<N>> ColorContext<SpectralMode<N>>::mallett_yuksel_base_color(std::uint32_t material,
                                                                                    const Wavelengths<Mode>& w) const {
  Spectrum<Mode> s;
  const color::MallettYukselSpectrum my(base_color_my_weights_[material]);
  for (int i = 0; i < N; ++i) s[i] = static_cast<float>(my(w.wavelength_nm[i]));
  return s;
}

template <int N>
Spectrum<SpectralMode<N>> ColorContext<SpectralMode<N>>::rgb_radiance(const Vec3f& rgb, const Wavelengths<Mode>& w,
                                                                       ColorPickerSpace space) const {
  Spectrum<Mode> s;
  const float m = std::max({rgb.x, rgb.y, rgb.z});
  if (!(m > 0.0f)) return s;
  // Every space's table is fitted relative to E from its own white, so a grey is the flat
  // ½ in each, and the scaling below holds whatever the space.
  const color::SigmoidPolynomial c = tables_[static_cast<std::size_t>(space)]->lookup(Vec3d(rgb / (2.0f * m)));
  // 683 ∫ L ȳ ≈ Y(rgb): L(λ) = 2m s(λ) / (683 ∫ ȳ), exact for greys (s = ½).
  const double k = 2.0 * m / (color::kMaxLuminousEfficacyLmPerW * color::cie1931_y_integral());
  s = Spectrum<Mode>(color::evaluate_sigmoid_polynomial(c, w.wavelength_nm, static_cast<float>(k)));
  return s;
}

template <int N>
void ColorContext<SpectralMode<N>>::terminate_secondary(Wavelengths<Mode>& w) const {
  for (int i = 1; i < N; ++i) w.pdf[i] = 0.0f;
  const double p0 = color::wavelength_slot_pdf(settings_.wavelength_strategy, 0, w.wavelength_nm[0]);
  w.pdf[0] = static_cast<float>(p0 / N);
}

template class ColorContext<SpectralMode<3>>;
template class ColorContext<SpectralMode<4>>;
template class ColorContext<SpectralMode<8>>;

ColorContext<RgbMode>::ColorContext(const Scene& scene, const TransportSettings& settings)
    : environment_space_(environment_space(scene)) {
  const color::ColorSpace& working = color::color_space(settings.working_space);
  to_working_ = conversions_to(working);
  const Mat3 film_to_working = color::spectral_xyz_to_rgb_matrix(working);
  for (const Material& m : scene.materials) {
    base_colors_.push_back(reflectance(m.base_color, {}, m.base_color_space));
    if (!m.base_color_spectrum) continue;
    // What spectral transport films under a white (flat) light, in working RGB.
    const Vec3d rgb = film_to_working * color::reflectance_to_xyz(*m.base_color_spectrum,
                                                                  color::standard_illuminant(color::StandardIlluminant::e));
    // A measured colour outside the working gamut has negative channels: no reflectance is.
    for (int i = 0; i < 3; ++i) base_colors_.back()[i] = static_cast<float>(std::max(rgb[i], 0.0));
  }
  for (const EmitterColor& e : emitter_colors(scene)) {
    const Vec3d rgb = e.spectrum ? emission_spectrum_rgb(*e.spectrum, working, e.value)
                                 : emission_radiance_rgb(e.color, e.space, e.value, working);
    Spectrum<Mode> s;
    for (int i = 0; i < 3; ++i) s[i] = static_cast<float>(rgb[i]);
    emitters_.push_back(s);
  }
}

Spectrum<RgbMode> ColorContext<RgbMode>::reflectance(const Vec3f& color, const Wavelengths<Mode>&,
                                                     ColorPickerSpace space) const {
  Vec3d rgb = reflectance_to_film(color, space);
  // A wide-gamut colour outside the working gamut has negative channels there, and no
  // reflectance is negative (a negative albedo squared by two bounces would add light): it
  // is clipped to the working gamut, as a measured spectrum is below. Rec.709 lies inside
  // every working space, so sRGB colours are left as converted.
  if (space != ColorPickerSpace::srgb) rgb = max(rgb, Vec3d(0.0));
  Spectrum<Mode> s;
  for (int i = 0; i < 3; ++i) s[i] = static_cast<float>(rgb[i]);
  return s;
}

}  // namespace prism
