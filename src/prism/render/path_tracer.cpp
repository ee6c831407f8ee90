#include "prism/render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "prism/core/frame.h"
#include "prism/sampling/warps.h"

namespace prism {
namespace {

struct SurfacePoint {
  Vec3f position;
  Vec3f normal;  // unit geometric normal of the front face (counter-clockwise winding)
};

SurfacePoint surface_point(const Scene& scene, const Hit& hit) {
  const TriangleMesh& mesh = scene.meshes[hit.mesh];
  const Vec3f& p0 = mesh.positions[mesh.indices[3 * hit.triangle + 0]];
  const Vec3f& p1 = mesh.positions[mesh.indices[3 * hit.triangle + 1]];
  const Vec3f& p2 = mesh.positions[mesh.indices[3 * hit.triangle + 2]];
  // Position from barycentrics rather than origin + t·direction: it lies on the plane
  // to float precision, which keeps the self-intersection offset small.
  return {p0 * (1.0f - hit.u - hit.v) + p1 * hit.u + p2 * hit.v, normalize(cross(p1 - p0, p2 - p0))};
}

// Offsets a ray origin off the surface along the normal, scaled to the coordinates'
// magnitude so it stays above float rounding (about 2^-23 relative) at any scene scale.
Vec3f offset_origin(const Vec3f& p, const Vec3f& n_towards) {
  const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
  return p + n_towards * (magnitude * 1e-5f);
}

}  // namespace

Vec3f trace_path(const PathContext& context, Ray ray, Pcg32& rng) {
  const Scene& scene = context.scene;
  const PathTracerSettings& settings = context.settings;
  const bool use_nee = settings.estimator != LightEstimator::bsdf_only && !context.lights.empty();
  Vec3f radiance(0.0f), throughput(1.0f);
  float previous_bsdf_pdf = 0.0f;  // solid-angle pdf of the direction that led here
  Vec3f previous_position;

  for (int depth = 0;; ++depth) {
    Hit hit;
    if (!context.accel.intersect(ray, hit)) break;  // no environment light yet
    const SurfacePoint sp = surface_point(scene, hit);
    const std::uint32_t material_index = scene.meshes[hit.mesh].material;
    const Material& material = scene.materials[material_index];
    const Vec3f& emitted = context.emitted_radiance[material_index];
    const Vec3f wo = -ray.direction;
    const float cos_wo = dot(sp.normal, wo);

    if (material.is_emissive() && cos_wo > 0.0f) {
      if (depth == 0 || !use_nee) {
        radiance += throughput * emitted;
      } else if (settings.estimator == LightEstimator::mis) {
        // Density with which NEE would have produced this point, in solid angle at the
        // previous vertex: p_A · r² / cos θ_light.
        const float r2 = length_squared(sp.position - previous_position);
        const float light_pdf = context.lights.pdf_area(hit.mesh, hit.triangle) * r2 / cos_wo;
        radiance += throughput * emitted * power_heuristic(previous_bsdf_pdf, light_pdf);
      }
    }
    if (depth + 1 > settings.max_depth) break;

    // Lambertian surfaces scatter from both sides: shade in the hemisphere of wo.
    const Vec3f n = cos_wo >= 0.0f ? sp.normal : -sp.normal;
    const Vec3f f = material.base_color * std::numbers::inv_pi_v<float>;

    if (use_nee) {
      const float u_select = rng.next_float();
      const Vec2f u_point(rng.next_float(), rng.next_float());
      const LightSample ls = context.lights.sample(u_select, u_point);
      Vec3f to_light = ls.position - sp.position;
      const float distance2 = length_squared(to_light);
      const float distance = std::sqrt(distance2);
      to_light /= distance;
      const float cos_surface = dot(n, to_light);
      const float cos_light = -dot(ls.normal, to_light);
      if (cos_surface > 0.0f && cos_light > 0.0f && ls.pdf_area > 0.0f) {
        const Vec3f origin = offset_origin(sp.position, n);
        const Vec3f target = offset_origin(ls.position, ls.normal);
        const Vec3f segment = target - origin;
        const float segment_length = length(segment);
        const Ray shadow{origin, segment / segment_length, 0.0f, segment_length * (1.0f - 1e-4f)};
        if (!context.accel.occluded(shadow)) {
          const float light_pdf = ls.pdf_area * distance2 / cos_light;
          const float weight = settings.estimator == LightEstimator::mis
                                   ? power_heuristic(light_pdf, cosine_hemisphere_pdf(cos_surface))
                                   : 1.0f;
          radiance += throughput * f * ls.radiance * (cos_surface * weight / light_pdf);
        }
      }
    }

    // Cosine-weighted continuation: f·cos/pdf reduces to the albedo.
    const Vec3f local = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f wi = Frame::from_normal(n).to_world(local);
    previous_bsdf_pdf = cosine_hemisphere_pdf(local.z);
    if (previous_bsdf_pdf <= 0.0f) break;
    throughput *= material.base_color;
    previous_position = sp.position;

    // Russian roulette (Arvo & Kirk 1990): survive with probability max throughput,
    // dividing by it keeps the estimator unbiased.
    if (depth + 1 >= settings.russian_roulette_depth) {
      const float survive = std::min(1.0f, max_component(throughput));
      if (rng.next_float() >= survive) break;
      throughput /= survive;
    }
    ray = Ray{offset_origin(sp.position, n), wi};
  }
  return radiance;
}

}  // namespace prism
