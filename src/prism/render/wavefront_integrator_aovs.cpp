// First-hit AOVs of the wavefront integrator (conventions in aov.h). Kept apart from the
// transport code: shade() calls record_first_hit_aovs() once per camera ray, only when the
// film keeps AOVs, and nothing here touches the path's random numbers or radiance.
#include "prism/render/surface_interaction.h"
#include "prism/render/wavefront_integrator.h"

namespace prism {

template <class Mode>
void WavefrontIntegrator<Mode>::record_first_hit_aovs(AovSample& a, const Ray& ray, const Hit* hit,
                                                      float cone_spread) const {
  a = AovSample{};
  if (hit == nullptr) return;  // escaped: zero albedo and normal, no depth
  SurfaceInteraction si = surface_interaction(scene_, *hit, ray);
  const Material& m = scene_.materials[si.material];
  // The camera ray's cone width at the hit, as shade() computes it for the texture LOD.
  const float cone_width = cone_spread * hit->t;
  // The normal AOV shows the normal- or bump-mapped normal.
  if (m.normal_texture >= 0) apply_normal_map(m, si, cone_width, ray);
  if (m.bump_texture >= 0) apply_bump_map(m, si, cone_width, ray);
  // Open Image Denoise's documentation asks for albedo 1 (or the surface's tint) on perfect
  // specular surfaces rather than the albedo of what they reflect or transmit; following
  // the path to its next non-delta hit would tie the AOV to the transport's random numbers.
  // Mirrors and Schlick conductors are tinted by base colour; glass and metals given by a
  // measured complex IOR have no base colour, so they are white.
  Vec3f albedo(1.0f);
  ColorPickerSpace space = ColorPickerSpace::srgb;
  const bool untinted =
      m.type == MaterialType::dielectric || (m.type == MaterialType::conductor && tables_.conductor(si.material));
  if (!untinted) {
    albedo = textured_base_color(m, si, cone_width, ray).value_or(m.base_color);
    space = m.base_color_space;
  }
  a.albedo = Vec3f(colors_.reflectance_to_film(albedo, space));
  // Facing the camera: the frame keeps the mesh's orientation, which is arbitrary for
  // two-sided surfaces seen from behind.
  const Vec3f n = si.shading.n;
  a.normal = dot(n, ray.direction) > 0.0f ? -n : n;
  a.depth_scene_units = hit->t;  // camera rays have unit directions (camera_rays.cpp)
  a.hit = true;
}

template void WavefrontIntegrator<SpectralMode<3>>::record_first_hit_aovs(AovSample&, const Ray&, const Hit*,
                                                                          float) const;
template void WavefrontIntegrator<SpectralMode<4>>::record_first_hit_aovs(AovSample&, const Ray&, const Hit*,
                                                                          float) const;
template void WavefrontIntegrator<SpectralMode<8>>::record_first_hit_aovs(AovSample&, const Ray&, const Hit*,
                                                                          float) const;
template void WavefrontIntegrator<RgbMode>::record_first_hit_aovs(AovSample&, const Ray&, const Hit*, float) const;

}  // namespace prism
