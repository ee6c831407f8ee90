#pragma once
// Thin-film interference, glTF's KHR_materials_iridescence: a transparent film of index η_f
// and thickness d over a base of index η_b (soap bubbles, oil on water, anodised and heated
// metals). Light reflected at the film's top and at its floor interferes, so the surface's
// reflectance depends on the wavelength, the angle and d.
//
// At one wavelength λ the film's reflectance is the Airy sum of its multiple reflections
// (Born & Wolf, "Principles of Optics", §1.6.4 and §7.6.1):
//   r = (r₀₁ + r₁₂ e^{iδ}) / (1 + r₀₁ r₁₂ e^{iδ}),   δ = (2π/λ) 2 η_f d cos θ_f,
// for each polarisation, with r_ij the Fresnel amplitude coefficients of the air–film and
// film–base interfaces (complex indices and cosines throughout), and R = ½(|r_s|² + |r_p|²).
// d = 0 gives the bare base's Fresnel reflectance, η_f = 1 too; a film of the base's index
// the bare film's. Spectral transport evaluates this exactly at each path's wavelengths;
// RGB transport at the representative wavelengths of its channels (render/material_bsdf.h),
// where the extension's reference evaluates a Fourier fit of the same sum's XYZ integral
// (Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling of
// Varying Iridescence").
#include <complex>

#include "prism/color/sampled_spectrum.h"

namespace prism::bsdf {

// The film's unpolarised reflectance seen from air (η = 1) at incidence cos θ ∈ (0, 1],
// over a base of complex index η_b + i k_b. Thickness and wavelength in nm.
double thin_film_reflectance(double cos_theta, double wavelength_nm, double thickness_nm, double eta_film,
                             std::complex<double> eta_base);
// The same for a real base index: with η_f, η_b ≥ 1 in real arithmetic (one cosine, no
// complex exponential: the renderer's case); otherwise as above.
double thin_film_reflectance(double cos_theta, double wavelength_nm, double thickness_nm, double eta_film,
                             double eta_base);

// A film over metallic_roughness' two bases (bsdf/metallic_roughness.h), per channel: the
// dielectric base of index `dielectric_eta` (the material's IOR) and the metal base of
// per-channel index `metal_eta`, taken from the base colour as F0 = ((η − 1)/(η + 1))²
// (the extension's reference does the same: a real index, no absorption).
template <int N>
struct ThinFilm {
  float weight = 0.0f;  // iridescenceFactor, in [0, 1]; 0: no film
  float thickness_nm = 0.0f;
  float eta_film = 1.3f;
  float dielectric_eta = 1.5f;
  color::SampledSpectrum<N> wavelength_nm{550.0f};
  color::SampledSpectrum<N> metal_eta{1.0f};
  bool present() const { return weight > 0.0f; }
  color::SampledSpectrum<N> over_dielectric(float cos_theta) const {
    color::SampledSpectrum<N> r;
    for (int i = 0; i < N; ++i)
      r[i] = static_cast<float>(thin_film_reflectance(cos_theta, wavelength_nm[i], thickness_nm, eta_film, dielectric_eta));
    return r;
  }
  color::SampledSpectrum<N> over_metal(float cos_theta) const {
    color::SampledSpectrum<N> r;
    for (int i = 0; i < N; ++i)
      r[i] = static_cast<float>(thin_film_reflectance(cos_theta, wavelength_nm[i], thickness_nm, eta_film, metal_eta[i]));
    return r;
  }

  // Both at |cos θo|, kept for the vertex's next call: a shading vertex asks with one wo for
  // the sampling probabilities, f and pdf several times (sampling, NEE, MIS), as
  // Sheen::at_wo does. A BSDF is one vertex's, on one thread; a copy carries the cache along.
  struct AtWo {
    float cos_o = -1.0f;  // none yet
    color::SampledSpectrum<N> over_dielectric{0.0f}, over_metal{0.0f};
  };
  mutable AtWo at_wo_;
  const AtWo& at_wo(float cos_o, bool metal) const {
    if (cos_o != at_wo_.cos_o)
      at_wo_ = {cos_o, over_dielectric(cos_o), metal ? over_metal(cos_o) : color::SampledSpectrum<N>(0.0f)};
    return at_wo_;
  }
};

// The real index whose normal-incidence reflectance from air is f0 ∈ [0, 1): (1 + √f0)/(1 − √f0),
// f0 capped at 0.99 (η ≈ 400) so that white bases stay finite.
float eta_from_f0(float f0);

}  // namespace prism::bsdf
