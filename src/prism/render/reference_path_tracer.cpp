#include "prism/render/reference_path_tracer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "prism/core/parallel.h"
#include "prism/render/surface_interaction.h"
#include "prism/render/volume_absorption.h"
#include "prism/sampling/warps.h"

namespace prism {

template <class Mode>
ReferencePathTracer<Mode>::ReferencePathTracer(const Scene& scene, const EmbreeAccel& accel,
                                               const std::vector<MipPyramid>& mip_pyramids, const LightSampler& lights,
                                               const PinholeCamera& camera, const ColorContext<Mode>& colors,
                                               const PathSettings& settings, int width, int height, std::uint64_t seed)
    : shading_(scene, mip_pyramids, colors, settings.normal_mapping), scene_(scene), accel_(accel), lights_(lights),
      camera_(camera), colors_(colors), settings_(settings), width_(width), height_(height), seed_(seed),
      use_nee_(settings.estimator != LightEstimator::bsdf_only && !lights.empty()),
      weight_bsdf_hits_(settings.estimator == LightEstimator::mis) {}

template <class Mode>
PassStatistics ReferencePathTracer<Mode>::render_samples(Film& film, std::uint32_t first_sample, std::uint32_t count,
                                                         int, const std::function<void()>*,
                                                         const std::uint8_t* active) {
  std::atomic<std::uint64_t> rays{0}, shadow_rays{0}, invalid{0};
  const auto width = static_cast<std::uint32_t>(width_);
  const bool keep_aovs = film.aovs().first_hit();
  parallel_for(static_cast<std::size_t>(height_), 1, [&](std::size_t row_begin, std::size_t row_end) {
    Counts counts;
    std::uint64_t local_invalid = 0;
    for (std::size_t y = row_begin; y < row_end; ++y)
      for (std::uint32_t x = 0; x < width; ++x) {
        const auto pixel = static_cast<std::uint32_t>(y) * width + x;
        if (active && !active[pixel]) continue;
        for (std::uint32_t s = first_sample; s < first_sample + count; ++s) {
          const PixelSample sample{seed_, pixel, width, s};
          const CameraSamples u = camera_samples(settings_.sampler, sample, camera_.has_lens());
          const Ray ray = camera_.generate_ray(static_cast<float>(x) + u.pixel_jitter.x,
                                               static_cast<float>(y) + u.pixel_jitter.y, u.lens);
          Wavelengths<Mode> wl = colors_.sample_wavelengths(s, u.wavelength);
          AovSample aovs;
          const Spectrum<Mode> L = radiance(sample, ray, wl, keep_aovs ? &aovs : nullptr, counts);
          const Vec3d value = colors_.to_film(L, wl);
          if (!is_finite(value)) {
            ++local_invalid;  // never written to the film, as in the wavefront integrator
            continue;
          }
          film.add_sample(pixel, value);
          if (keep_aovs) film.add_aov_sample(pixel, aovs);
        }
      }
    rays += counts.rays;
    shadow_rays += counts.shadow_rays;
    invalid += local_invalid;
  });
  PassStatistics stats;
  stats.rays = rays.load();
  stats.shadow_rays = shadow_rays.load();
  stats.invalid_samples = invalid.load();
  const std::size_t pixels =
      active ? static_cast<std::size_t>(std::count_if(active, active + film.pixel_count(), [](std::uint8_t a) { return a != 0; }))
             : film.pixel_count();
  stats.completed_samples = std::uint64_t{count} * pixels;
  return stats;
}

template <class Mode>
Spectrum<Mode> ReferencePathTracer<Mode>::radiance(const PixelSample& sample, Ray ray, Wavelengths<Mode>& wl,
                                                   AovSample* aovs, Counts& counts) const {
  Spectrum<Mode> L(0.0f);
  PathState path;
  path.cone_spread = camera_.pixel_spread_angle();
  for (int depth = 0;; ++depth) {
    Hit hit;
    const bool found = accel_.intersect(ray, hit);
    ++counts.rays;
    if (depth == 0 && aovs) shading_.first_hit_aovs(*aovs, ray, found ? &hit : nullptr, path.cone_spread);
    // Beer–Lambert over the segment that ran inside an absorbing dielectric.
    if (path.interior_sigma)
      path.throughput *= beer_lambert_transmittance(*path.interior_sigma,
                                                    found ? hit.t : std::numeric_limits<float>::infinity());
    if (!found) return L + path.throughput * escaped_radiance(ray.direction, path, wl);

    SurfaceInteraction si = surface_interaction(scene_, hit, ray);
    const Material& material = scene_.materials[si.material];
    path.cone_width += path.cone_spread * hit.t;
    const typename SurfaceShading<Mode>::MappedFrame mapped = shading_.map_frame(material, si, path.cone_width, ray);
    if (SurfaceShading<Mode>::emits_toward(material, si))
      L += path.throughput * emitted_radiance(hit, si, path, wl);
    if (depth + 1 > settings_.max_depth) return L;

    std::optional<Frame> coat_frame;  // outlives the BSDF, which may point at it
    const bsdf::Bsdf<Mode::kChannels> bsdf = shading_.bsdf(material, si, path.cone_width, ray, wl, mapped, coat_frame);
    // Hero wavelength after a dispersive event (Wilkie et al. 2014): only the first
    // wavelength carries an estimate from here on.
    if constexpr (Mode::kSpectral)
      if (Mode::kChannels > 1 && bsdf.is_dispersive() && wl.pdf[1] != 0.0f) colors_.terminate_secondary(wl);
    const Vec3f wo_local = si.shading.to_local(-ray.direction);
    const BounceSamples u = bounce_samples(settings_.sampler, sample, depth);
    if (use_nee_ && !bsdf.is_specular())
      L += direct_light(si, bsdf, mapped.microsurface, wo_local, u, path, wl, counts);

    // Continue the path by sampling the BSDF (on the microsurface with microfacet normal
    // mapping, whose facet choice has dimensions of its own).
    const auto bs = mapped.microsurface
                        ? microsurface_sample(bsdf, *mapped.microsurface, wo_local, u.lobe, u.direction,
                                              sample_2d(settings_.sampler, sample,
                                                        kFirstFacetDimension + 2 * static_cast<std::uint32_t>(depth)))
                        : bsdf.sample(wo_local, u.lobe, u.direction);
    if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) return L;
    const Vec3f wi = si.shading.to_world(bs->wi);
    // A direction on another geometric side than its shading side would pass through the mesh.
    if ((dot(wi, si.geometric_normal) > 0.0f) != (bs->wi.z > 0.0f)) return L;
    path.throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
    path.eta_scale *= bs->eta * bs->eta;
    // Refraction into a solid dielectric through its front face enters its medium; any
    // other refraction through it leaves (media do not nest; thin walls have no inside).
    if (bs->is_transmission && material.type == MaterialType::dielectric && !material.thin_walled) {
      path.interior_sigma.reset();
      if (si.front_face && material.absorbs_inside())
        path.interior_sigma =
            absorption_coefficient(colors_.reflectance(material.attenuation_color, wl), material.attenuation_distance);
    }
    path.previous_pdf = bs->pdf;
    path.previous_specular = bs->is_specular;
    // After a glossy or diffuse bounce the ray cone widens to about the lobe's extent.
    if (!bs->is_specular) path.cone_spread = std::max(path.cone_spread, 0.05f);
    path.previous_position = si.position;
    path.previous_normal = si.shading.n;

    // Russian roulette (Arvo & Kirk 1990) on the throughput without refraction's 1/η².
    if (depth + 1 >= settings_.russian_roulette_depth) {
      float max_throughput = 0.0f;
      for (int i = 0; i < Mode::kChannels; ++i) max_throughput = std::max(max_throughput, path.throughput[i]);
      const float survive = std::min(1.0f, max_throughput * path.eta_scale);
      if (u.roulette >= survive) return L;
      path.throughput *= 1.0f / survive;
    }
    ray = Ray{offset_ray_origin(si.position, si.geometric_normal, wi), wi};
  }
}

template <class Mode>
Spectrum<Mode> ReferencePathTracer<Mode>::escaped_radiance(const Vec3f& direction, const PathState& path,
                                                           const Wavelengths<Mode>& wl) const {
  Spectrum<Mode> L(0.0f);
  lights_.visit_escaped(direction, [&](const LightSampler::EscapedHit& e) {
    float weight = 1.0f;
    if (!path.previous_specular && use_nee_)
      weight = weight_bsdf_hits_ ? power_heuristic(path.previous_pdf, e.pdf) : 0.0f;
    const Spectrum<Mode> Le =
        e.has_rgb ? colors_.environment_radiance(e.rgb, wl) : colors_.emission(e.emitter, wl) * e.scale;
    L += Le * weight;
  });
  return L;
}

template <class Mode>
Spectrum<Mode> ReferencePathTracer<Mode>::emitted_radiance(const Hit& hit, const SurfaceInteraction& si,
                                                           const PathState& path, const Wavelengths<Mode>& wl) const {
  float weight = 1.0f;
  if (!path.previous_specular && use_nee_) {
    // Light sampling could have found this point too: weigh the two techniques.
    weight = weight_bsdf_hits_ ? power_heuristic(path.previous_pdf,
                                                 lights_.pdf_triangle(hit.mesh, hit.triangle, path.previous_position,
                                                                      si.position, path.previous_normal))
                               : 0.0f;
  }
  const Material& material = scene_.materials[si.material];
  if (!shading_.has_texture(material.emission.texture, si.mesh)) return colors_.emission(si.material, wl) * weight;
  const float lod = shading_.emission_level_of_detail(material, si, path.cone_width, path.previous_specular);
  return shading_.textured_emitted_radiance(si.material, si.uv, lod, wl) * weight;
}

template <class Mode>
Spectrum<Mode> ReferencePathTracer<Mode>::direct_light(const SurfaceInteraction& si,
                                                       const bsdf::Bsdf<Mode::kChannels>& bsdf,
                                                       const std::optional<bsdf::NormalMapMicrosurface>& microsurface,
                                                       const Vec3f& wo_local, const BounceSamples& u,
                                                       const PathState& path, const Wavelengths<Mode>& wl,
                                                       Counts& counts) const {
  const auto ls = lights_.sample(si.position, u.light_select, u.light, si.shading.n);
  if (!ls || !(ls->pdf > 0.0f)) return Spectrum<Mode>(0.0f);
  const Vec3f wi_local = si.shading.to_local(ls->wi);
  // The geometric and the shading side must agree, or light leaks through edges.
  if ((dot(ls->wi, si.geometric_normal) > 0.0f) != (wi_local.z > 0.0f)) return Spectrum<Mode>(0.0f);
  const bool weighted = !ls->is_delta && weight_bsdf_hits_;
  float bsdf_pdf = 0.0f;
  const Spectrum<Mode> f = microsurface ? microsurface_eval(bsdf, *microsurface, wo_local, wi_local)
                                        : bsdf.eval_with_pdf(wo_local, wi_local, weighted, bsdf_pdf);
  if (f.is_black()) return Spectrum<Mode>(0.0f);
  if (weighted && microsurface) bsdf_pdf = microsurface_pdf(bsdf, *microsurface, wo_local, wi_local);
  const float weight = weighted ? power_heuristic(ls->pdf, bsdf_pdf) : 1.0f;

  // The shadow ray, from just off the surface to just off the light's surface.
  const Vec3f origin = offset_ray_origin(si.position, si.geometric_normal, ls->wi);
  Ray shadow{origin, ls->wi, 0.0f, std::numeric_limits<float>::infinity()};
  if (!std::isinf(ls->distance)) {
    const Vec3f target = ls->is_delta ? ls->position : offset_ray_origin(ls->position, ls->normal, -ls->wi);
    const float length_to_target = length(target - origin);
    shadow = Ray{origin, (target - origin) / length_to_target, 0.0f, length_to_target * (1.0f - 1e-4f)};
  }
  ++counts.shadow_rays;
  if (accel_.occluded(shadow)) return Spectrum<Mode>(0.0f);

  const Spectrum<Mode> Le =
      ls->has_rgb ? colors_.environment_radiance(ls->rgb, wl)
                  : (ls->has_uv ? shading_.textured_emitted_radiance(ls->emitter, ls->uv, 0.0f, wl)
                                : colors_.emission(ls->emitter, wl)) *
                        ls->scale;
  Spectrum<Mode> contribution = path.throughput * f * Le * (std::abs(wi_local.z) * weight / ls->pdf);
  // A light inside the same absorbing medium: the shadow ray runs through it all the way.
  if (path.interior_sigma) contribution *= beer_lambert_transmittance(*path.interior_sigma, shadow.t_max);
  return contribution;
}

template class ReferencePathTracer<SpectralMode<3>>;
template class ReferencePathTracer<SpectralMode<4>>;
template class ReferencePathTracer<SpectralMode<8>>;
template class ReferencePathTracer<RgbMode>;

}  // namespace prism
