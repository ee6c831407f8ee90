#include "prism/bsdf/dielectric.h"

#include <cmath>

namespace prism::bsdf::detail {

float rough_dielectric_f_pdf(const MicrofacetDistribution& dist, const Vec3f& wo,
                             const Vec3f& wi, float eta, TransportMode mode, float* pdf_out) {
  if (pdf_out) *pdf_out = 0.0f;
  const float cos_o = wo.z, cos_i = wi.z;
  if (cos_o == 0.0f || cos_i == 0.0f) return 0.0f;
  const bool reflection = cos_o * cos_i > 0.0f;
  // η_i / η_o: the IOR of wi's medium over wo's; 1 for reflection.
  const float etap = reflection ? 1.0f : (cos_o > 0.0f ? eta : 1.0f / eta);
  // Generalised half vector (Walter et al. 2007, eq. 16), oriented to the outside.
  Vec3f h = wi * etap + wo;
  if (length_squared(h) == 0.0f) return 0.0f;
  h = normalize(h);
  if (h.z < 0.0f) h = -h;
  const float wo_h = dot(wo, h), wi_h = dot(wi, h);
  // A microfacet is only seen (and only lights) from the side its macro-direction lies on.
  if (wo_h * cos_o <= 0.0f || wi_h * cos_i <= 0.0f) return 0.0f;
  const float F = fresnel_dielectric(wo_h, eta);
  const float D = dist.D(h);
  const float pdf_h = dist.pdf_microfacet_normal(wo, h);
  if (reflection) {
    if (pdf_out) *pdf_out = pdf_h * reflection_jacobian(wo, h) * F;
    return D * dist.G2(wo, wi) * F / (4.0f * std::abs(cos_o * cos_i));
  }
  // Walter et al. 2007, eq. 21 rewritten with etap = η_i/η_o:
  //   f = |wi·h||wo·h| / (|cos_i||cos_o|) · D G (1 − F) / (etap wi·h + wo·h)²   (radiance);
  // the importance (adjoint) form is this times etap².
  const float denom = etap * wi_h + wo_h;
  const float denom2 = denom * denom;
  if (denom2 == 0.0f) return 0.0f;
  // Jacobian of the refracted half vector, dωh/dωi = etap² |wi·h| / (etap wi·h + wo·h)²
  // (Walter et al. 2007, eq. 17).
  if (pdf_out) *pdf_out = pdf_h * etap * etap * std::abs(wi_h) / denom2 * (1.0f - F);
  float f = D * dist.G2_transmission(wo, wi) * (1.0f - F) * std::abs(wi_h * wo_h) /
            (std::abs(cos_i * cos_o) * denom2);
  if (mode == TransportMode::importance) f *= etap * etap;
  return f;
}

}  // namespace prism::bsdf::detail
