#include "prism/render/material_bsdf.h"

#include <algorithm>

namespace prism {

bool has_point_texture(const Material& m) {
  return m.metallic_roughness_texture >= 0 || m.clearcoat_texture >= 0 || m.clearcoat_roughness_texture >= 0 ||
         m.sheen_color_texture >= 0 || m.sheen_roughness_texture >= 0 || m.specular_texture >= 0 ||
         m.specular_color_texture >= 0 || m.iridescence_texture >= 0 || m.iridescence_thickness_texture >= 0;
}

bool is_plain_diffuse(const Material& m) {
  // make_bsdf's diffuse return: no coat (clearcoat > 0) and no sheen in untextured_point.
  return m.type == MaterialType::diffuse && !m.has_clearcoat() && !m.has_sheen() && !has_point_texture(m) &&
         m.base_color_texture < 0 && m.normal_texture < 0 && m.bump_texture < 0 && m.clearcoat_normal_texture < 0 &&
         m.emission.texture < 0;
}

MaterialTables::MaterialTables(const std::vector<Material>& materials) {
  for (const Material& m : materials) {
    // The coat's albedo table (≈ 30 ms) is built here, before the render's threads start,
    // not by the first shading call that needs it.
    if (m.has_clearcoat()) bsdf::coat_directional_albedo(1.0f, m.clearcoat_roughness);
    if (m.has_sheen()) bsdf::sheen_directional_albedo(1.0f, m.sheen_roughness);  // likewise, its table
    points_.push_back(untextured_point(m));
    point_is_fixed_.push_back(has_point_texture(m) ? 0 : 1);
    const double r = (double(m.ior) - 1.0) / (double(m.ior) + 1.0);
    fresnel_f0_.push_back(r * r);
    if ((m.type == MaterialType::conductor) && m.conductor_fresnel == ConductorFresnel::complex_ior)
      conductors_.emplace_back(bsdf::conductor_ior(m.conductor_name));  // UsageError for unknown metals
    else
      conductors_.emplace_back(std::nullopt);
  }
}

Vec3f MaterialTables::dielectric_f0(std::uint32_t material, const Vec3f& specular_color) const {
  const double f0 = fresnel_f0_[material];
  const auto component = [&](float c) { return static_cast<float>(std::clamp(f0 * c, 0.0, 1.0)); };
  return {component(specular_color.x), component(specular_color.y), component(specular_color.z)};
}

namespace {

bsdf::MicrofacetType microfacet_type(MicrofacetModel m) {
  switch (m) {
    case MicrofacetModel::beckmann: return bsdf::MicrofacetType::beckmann;
    case MicrofacetModel::blinn_phong: return bsdf::MicrofacetType::blinn_phong;
    case MicrofacetModel::ggx: break;
  }
  return bsdf::MicrofacetType::ggx;
}

// The wavelength each channel stands for.
template <class Mode>
float channel_wavelength_nm(const Wavelengths<Mode>& w, int channel) {
  if constexpr (Mode::kSpectral) return w.wavelength_nm[static_cast<std::size_t>(channel)];
  else return kRgbRepresentativeWavelengthsNm[static_cast<std::size_t>(channel)];
}

// Anisotropy stretches a lobe along the frame's s axis (Blinn-Phong stays isotropic); one
// rule for every lobe, metallic_roughness' own distribution included.
bool is_anisotropic(const Material& m, const MaterialPoint& point) {
  return point.anisotropy > 0.0f && microfacet_type(m.microfacet) != bsdf::MicrofacetType::blinn_phong;
}
void stretch_anisotropic(bsdf::MicrofacetDistribution& d, float anisotropy) {
  d.alpha_y = std::max(d.alpha_y, bsdf::kMinAnisotropicAlpha);
  d.alpha_x = bsdf::anisotropic_alpha_along(d.alpha_y, anisotropy);
}

// The microfacet distribution of the conductor and dielectric lobes. glTF and pbrt give
// perceptual roughness r; the microfacet α is r² (Burley 2012).
bsdf::MicrofacetDistribution lobe_distribution(const Material& m, const MaterialPoint& point) {
  const float alpha = point.roughness * point.roughness;
  auto distribution = bsdf::MicrofacetDistribution::isotropic(microfacet_type(m.microfacet), alpha);
  if (is_anisotropic(m, point)) stretch_anisotropic(distribution, point.anisotropy);
  return distribution;
}

// The lobe alone. Each case builds only what its lobe reads: a mirror, a thin slab and a
// diffuse lobe no microfacet distribution. Not inlined, so that make_bsdf's diffuse return
// needs no stack frame (see there).
template <class Mode>
[[gnu::noinline]] bsdf::Bsdf<Mode::kChannels> base_bsdf(const Material& m, std::uint32_t material_index, const Spectrum<Mode>& base,
                                      const MaterialPoint& point, const Wavelengths<Mode>& w,
                                      const MaterialTables& tables, const LayerColors<Mode>& layer_colors) {
  constexpr int N = Mode::kChannels;
  switch (m.type) {
    case MaterialType::mirror: return {bsdf::SpecularReflection<N>{base}};
    case MaterialType::conductor: {
      if (const bsdf::ConductorIor* ior = tables.conductor(material_index)) {
        color::SampledSpectrum<N> eta, k;
        for (int c = 0; c < N; ++c) {
          const double nm = channel_wavelength_nm<Mode>(w, c);
          eta[c] = static_cast<float>(ior->eta(nm));
          k[c] = static_cast<float>(ior->k(nm));
        }
        return {bsdf::RoughConductor<N>{lobe_distribution(m, point), bsdf::ConductorFresnel<N>::complex_ior(eta, k)}};
      }
      return {bsdf::RoughConductor<N>{lobe_distribution(m, point), bsdf::ConductorFresnel<N>::schlick(base)}};
    }
    case MaterialType::dielectric: {
      color::SampledSpectrum<N> eta;
      for (int c = 0; c < N; ++c) {
        const double nm = Mode::kSpectral ? channel_wavelength_nm<Mode>(w, c) : kDLineWavelengthNm;
        eta[c] = static_cast<float>(dielectric_ior(m, nm));
      }
      // The base colour tints transmitted light (glTF KHR_materials_transmission, MTL Ks,
      // JSON base_color), clamped to [0, 1] so that no crossing adds energy.
      color::SampledSpectrum<N> tint;
      for (int c = 0; c < N; ++c) tint[c] = std::clamp(base[c], 0.0f, 1.0f);
      // Thin-walled (glTF transmission without KHR_materials_volume, pbrt's
      // thindielectric): a smooth slab, roughness ignored (bsdf/thin_dielectric.h).
      if (m.thin_walled) return {bsdf::ThinDielectric<N>{eta, tint}};
      return {bsdf::Dielectric<N>{eta, lobe_distribution(m, point), tint}};
    }
    case MaterialType::metallic_roughness: {
      const Vec3f f0 = tables.dielectric_f0(material_index, point.specular_color);
      const float metallic = std::clamp(point.metallic, 0.0f, 1.0f);
      const float weight = std::clamp(point.specular, 0.0f, 1.0f);
      auto lobe = point.has_tinted_specular()
                      ? bsdf::MetallicRoughness<N>::from_roughness(base, metallic, point.roughness,
                                                                  layer_colors.specular_f0, max_component(f0), weight)
                      : bsdf::MetallicRoughness<N>::from_roughness(base, metallic, point.roughness, f0.x, weight);
      // Its own α, which from_roughness keeps above kMinAlpha.
      if (is_anisotropic(m, point)) stretch_anisotropic(lobe.distribution, point.anisotropy);
      if (__builtin_expect(point.iridescence > 0.0f, 0)) {
        bsdf::ThinFilm<N>& film = lobe.film;
        film.weight = std::min(point.iridescence, 1.0f);
        film.thickness_nm = std::max(point.iridescence_thickness_nm, 0.0f);
        film.eta_film = m.iridescence_ior;
        film.dielectric_eta = m.ior;
        for (int c = 0; c < N; ++c) {
          film.wavelength_nm[c] = channel_wavelength_nm<Mode>(w, c);
          film.metal_eta[c] = bsdf::eta_from_f0(base[c]);
        }
      }
      return {lobe};
    }
    case MaterialType::diffuse: break;
  }
  return {bsdf::Lambertian<N>{base}};
}

}  // namespace

template <class Mode>
bsdf::Bsdf<Mode::kChannels> make_bsdf(const Material& m, std::uint32_t material_index, const Spectrum<Mode>& base,
                                      const MaterialPoint& point, const Wavelengths<Mode>& w,
                                      const MaterialTables& tables, const LayerColors<Mode>& layer_colors) {
  // A bare diffuse lobe, the commonest BSDF, is returned before the call that builds the
  // others: through it, a diffuse make_bsdf took 57 instructions, 6 of them for the stack
  // frame and saved registers of the other lobes (Callgrind; docs/performance-design.md "Instruction cuts").
  // base_bsdf returns the same lobe for it.
  if (m.type == MaterialType::diffuse && !(point.clearcoat > 0.0f) && !point.has_sheen())
    return {bsdf::Lambertian<Mode::kChannels>{base}};
  auto b = base_bsdf<Mode>(m, material_index, base, point, w, tables, layer_colors);
  // untextured_point() gives dielectrics no coat and no sheen.
  if (point.clearcoat > 0.0f)
    b.coat = bsdf::Clearcoat::make(std::min(point.clearcoat, 1.0f), std::clamp(point.clearcoat_roughness, 0.0f, 1.0f));
  if (point.has_sheen()) b.sheen = bsdf::Sheen<Mode::kChannels>::make(layer_colors.sheen, point.sheen_roughness);
  return b;
}

template bsdf::Bsdf<3> make_bsdf<SpectralMode<3>>(const Material&, std::uint32_t, const Spectrum<SpectralMode<3>>&, const MaterialPoint&,
                                                   const Wavelengths<SpectralMode<3>>&, const MaterialTables&, const LayerColors<SpectralMode<3>>&);
template bsdf::Bsdf<4> make_bsdf<SpectralMode<4>>(const Material&, std::uint32_t, const Spectrum<SpectralMode<4>>&, const MaterialPoint&,
                                                   const Wavelengths<SpectralMode<4>>&, const MaterialTables&, const LayerColors<SpectralMode<4>>&);
template bsdf::Bsdf<8> make_bsdf<SpectralMode<8>>(const Material&, std::uint32_t, const Spectrum<SpectralMode<8>>&, const MaterialPoint&,
                                                   const Wavelengths<SpectralMode<8>>&, const MaterialTables&, const LayerColors<SpectralMode<8>>&);
template bsdf::Bsdf<3> make_bsdf<RgbMode>(const Material&, std::uint32_t, const Spectrum<RgbMode>&, const MaterialPoint&,
                                          const Wavelengths<RgbMode>&, const MaterialTables&, const LayerColors<RgbMode>&);

}  // namespace prism
