#pragma once
// A bare Lambertian lobe with the interface the integrator uses of Bsdf (bsdf.h): what a
// Bsdf holding only that lobe (no coat, no sheen) does, without the tests for the layers
// and the other lobes. The integrator shades hits on plain diffuse materials with it
// (render/material_bsdf.h, is_plain_diffuse); the answers are the same bits as the Bsdf's
// (plain_diffuse_bsdf_test).
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/lambertian.h"

namespace prism::bsdf {

template <int N>
struct PlainDiffuseBsdf {
  Lambertian<N> lobe;

  static constexpr bool is_specular() { return false; }
  static constexpr bool uses_lobe_sample() { return false; }
  static constexpr bool uses_direction_sample() { return true; }
  static constexpr bool is_dispersive() { return false; }

  // As Bsdf::eval_with_pdf: the pdf only where wanted and the value is not black.
  color::SampledSpectrum<N> eval_with_pdf(const Vec3f& wo, const Vec3f& wi, bool want_pdf, float& pdf_out) const {
    const color::SampledSpectrum<N> f = lobe.eval(wo, wi);
    if (want_pdf && !f.is_black()) pdf_out = lobe.pdf(wo, wi);
    return f;
  }
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u) const {
    return lobe.sample(wo, u_lobe, u);
  }
};

}  // namespace prism::bsdf
