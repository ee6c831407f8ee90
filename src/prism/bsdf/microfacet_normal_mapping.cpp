// Microfacet normal mapping over the shading point's BSDF, instantiated for the
// integrator's spectrum sizes: N = 3 (RGB mode and 3-wavelength spectral), 4 and 8.
#include "prism/bsdf/microfacet_normal_mapping.h"

#include "prism/bsdf/bsdf.h"

namespace prism::bsdf {

template <int N>
color::SampledSpectrum<N> microsurface_eval(const Bsdf<N>& facet, const NormalMapMicrosurface& surface,
                                            const Vec3f& wo, const Vec3f& wi) {
  return MicrofacetNormalMapped<N, Bsdf<N>>(facet, surface).eval(wo, wi);
}

template <int N>
float microsurface_pdf(const Bsdf<N>& facet, const NormalMapMicrosurface& surface, const Vec3f& wo, const Vec3f& wi) {
  return MicrofacetNormalMapped<N, Bsdf<N>>(facet, surface).pdf(wo, wi);
}

template <int N>
std::optional<BsdfSample<N>> microsurface_sample(const Bsdf<N>& facet, const NormalMapMicrosurface& surface,
                                                 const Vec3f& wo, float u_lobe, Vec2f u, Vec2f u_facet) {
  return MicrofacetNormalMapped<N, Bsdf<N>>(facet, surface).sample(wo, u_lobe, u, u_facet);
}

#define PRISM_MICROSURFACE_INSTANTIATE(N)                                                                       \
  template color::SampledSpectrum<N> microsurface_eval(const Bsdf<N>&, const NormalMapMicrosurface&,            \
                                                       const Vec3f&, const Vec3f&);                             \
  template float microsurface_pdf(const Bsdf<N>&, const NormalMapMicrosurface&, const Vec3f&, const Vec3f&);    \
  template std::optional<BsdfSample<N>> microsurface_sample(const Bsdf<N>&, const NormalMapMicrosurface&,       \
                                                            const Vec3f&, float, Vec2f, Vec2f);
PRISM_MICROSURFACE_INSTANTIATE(3)
PRISM_MICROSURFACE_INSTANTIATE(4)
PRISM_MICROSURFACE_INSTANTIATE(8)
#undef PRISM_MICROSURFACE_INSTANTIATE

}  // namespace prism::bsdf
