#pragma once
// The integrator's BSDF at a hit, in the local shading frame (z = normal, wo.z > 0).
// Lambertian and perfect mirror; the microfacet materials of the bsdf/ module replace the
// fallback for the other material types.
#include <cmath>
#include <numbers>
#include <optional>

#include "prism/render/transport_mode.h"
#include "prism/sampling/warps.h"
#include "prism/scene/material.h"

namespace prism {

template <class Mode>
struct BsdfSample {
  Vec3f wi;
  Spectrum<Mode> f;  // BSDF value; the cosine is applied by the caller
  float pdf = 0.0f;  // solid angle; for delta lobes the discrete probability
  bool is_specular = false;
};

template <class Mode>
class SurfaceBsdf {
 public:
  enum class Lobe { lambertian, mirror };
  SurfaceBsdf(Lobe lobe, const Spectrum<Mode>& reflectance) : lobe_(lobe), reflectance_(reflectance) {}

  bool is_specular() const { return lobe_ == Lobe::mirror; }

  Spectrum<Mode> eval(const Vec3f& wo, const Vec3f& wi) const {
    if (lobe_ == Lobe::mirror || wo.z <= 0.0f || wi.z <= 0.0f) return Spectrum<Mode>(0.0f);
    return reflectance_ * std::numbers::inv_pi_v<float>;
  }
  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (lobe_ == Lobe::mirror || wo.z <= 0.0f) return 0.0f;
    return cosine_hemisphere_pdf(wi.z);
  }
  std::optional<BsdfSample<Mode>> sample(const Vec3f& wo, float, Vec2f u) const {
    if (wo.z <= 0.0f) return std::nullopt;
    if (lobe_ == Lobe::mirror) {
      // f = R δ(wi − mirror(wo)) / cos θi; with pdf 1 the caller's f·cos/pdf is R.
      const Vec3f wi(-wo.x, -wo.y, wo.z);
      return BsdfSample<Mode>{wi, reflectance_ * (1.0f / wi.z), 1.0f, true};
    }
    const Vec3f wi = sample_cosine_hemisphere(u);
    const float pdf = cosine_hemisphere_pdf(wi.z);
    if (pdf <= 0.0f) return std::nullopt;
    return BsdfSample<Mode>{wi, reflectance_ * std::numbers::inv_pi_v<float>, pdf, false};
  }

 private:
  Lobe lobe_;
  Spectrum<Mode> reflectance_;
};

template <class Mode>
SurfaceBsdf<Mode> make_surface_bsdf(const Material& material, const Spectrum<Mode>& base_color) {
  using Lobe = typename SurfaceBsdf<Mode>::Lobe;
  return SurfaceBsdf<Mode>(material.type == MaterialType::mirror ? Lobe::mirror : Lobe::lambertian, base_color);
}

}  // namespace prism
