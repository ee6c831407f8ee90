#include "prism/scene/light_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "prism/core/frame.h"
#include "prism/sampling/warps.h"

namespace prism {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float radians(float degrees) { return degrees * kPi / 180.0f; }

// Smooth spot falloff between the outer and inner cone (a Hermite smoothstep in cos θ,
// as glTF's KHR_lights_punctual recommends a smooth transition).
float spot_falloff(float cos_theta, float cos_outer, float cos_inner) {
  if (cos_theta >= cos_inner) return 1.0f;
  if (cos_theta <= cos_outer) return 0.0f;
  const float t = (cos_theta - cos_outer) / (cos_inner - cos_outer);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

LightSampler::LightSampler(const Scene& scene, const Bounds3f& world) {
  first_triangle_of_mesh_.assign(scene.meshes.size(), -1);
  std::vector<double> power;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    const Material& material = scene.materials[mesh.material];
    if (!material.is_emissive()) continue;
    first_triangle_of_mesh_[m] = static_cast<std::int64_t>(emitters_.size());
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3f& p0 = mesh.positions[mesh.indices[3 * t + 0]];
      const Vec3f& p1 = mesh.positions[mesh.indices[3 * t + 1]];
      const Vec3f& p2 = mesh.positions[mesh.indices[3 * t + 2]];
      const Vec3f n = cross(p1 - p0, p2 - p0);
      const float twice_area = length(n);
      Emitter e{};
      e.kind = Kind::triangle;
      e.emitter = mesh.material;
      e.p0 = p0;
      e.e1 = p1 - p0;
      e.e2 = p2 - p0;
      e.normal = twice_area > 0.0f ? n / twice_area : Vec3f(0.0f);
      e.area = 0.5f * twice_area;
      e.two_sided = material.emission.two_sided;
      emitters_.push_back(e);
      // Lambertian emitter: Φ = π · L · A per emitting side. Zero-area triangles get
      // zero power and are never chosen.
      power.push_back(kPi * double(material.emission.luminance_nits) * e.area * (e.two_sided ? 2.0 : 1.0));
    }
  }
  const Vec3f diagonal = world.empty() ? Vec3f(1.0f) : world.diagonal();
  const float world_radius = 0.5f * length(diagonal);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    if (light.type == LightType::environment) continue;  // environment maps: integrator issue, not yet
    Emitter e{};
    e.emitter = static_cast<std::uint32_t>(scene.materials.size() + l);
    e.position = light.position;
    const float len = length(light.direction);
    e.axis = len > 0.0f ? light.direction / len : Vec3f(0.0f, -1.0f, 0.0f);
    const double intensity = std::max(0.0f, light.intensity);
    switch (light.type) {
      case LightType::point:
        e.kind = Kind::point;
        power.push_back(4.0 * kPi * intensity);  // Φ = 4π I
        break;
      case LightType::spot: {
        e.kind = Kind::spot;
        e.cos_inner = std::cos(radians(light.spot_inner_angle_degrees));
        e.cos_outer = std::cos(radians(std::max(light.spot_outer_angle_degrees, light.spot_inner_angle_degrees)));
        // Φ ≈ 2π I (1 − cos θ_mid): the cone half-way through the falloff.
        const double cos_mid = 0.5 * (double(e.cos_inner) + e.cos_outer);
        power.push_back(2.0 * kPi * intensity * (1.0 - cos_mid));
        break;
      }
      case LightType::directional: {
        e.kind = Kind::directional;
        const float half_angle = 0.5f * radians(std::clamp(light.angular_diameter_degrees, 0.0f, 180.0f));
        e.cos_max = std::cos(half_angle);
        const float sin2 = 1.0f - e.cos_max * e.cos_max;
        // Illuminance E = ∫_cone L cos θ dω = L π sin²θmax for a disc seen head-on.
        e.disc_radiance_scale = sin2 > 0.0f ? 1.0f / (kPi * sin2) : 1.0f;
        power.push_back(intensity * kPi * double(world_radius) * world_radius);  // E over the scene's disc
        break;
      }
      case LightType::environment: break;
    }
    emitters_.push_back(e);
  }

  double total = 0.0;
  for (double p : power) total += p;
  if (!(total > 0.0)) {
    emitters_.clear();
    first_triangle_of_mesh_.assign(scene.meshes.size(), -1);
    return;
  }
  double running = 0.0;
  for (double p : power) {
    running += p;
    selection_pmf_.push_back(static_cast<float>(p / total));
    selection_cdf_.push_back(static_cast<float>(running / total));
  }
  selection_cdf_.back() = 1.0f;
}

std::optional<LightSample> LightSampler::sample(const Vec3f& reference, float u_select, Vec2f u_point) const {
  if (empty()) return std::nullopt;
  const auto it = std::upper_bound(selection_cdf_.begin(), selection_cdf_.end(), u_select);
  std::size_t index = std::min<std::size_t>(static_cast<std::size_t>(it - selection_cdf_.begin()), selection_cdf_.size() - 1);
  if (selection_pmf_[index] == 0.0f) return std::nullopt;  // float ties at the top of the CDF
  std::optional<LightSample> s = sample_emitter(index, reference, u_point);
  if (s) s->pdf *= selection_pmf_[index];
  return s;
}

std::optional<LightSample> LightSampler::sample_emitter(std::size_t index, const Vec3f& reference, Vec2f u) const {
  const Emitter& e = emitters_[index];
  LightSample s;
  s.emitter = e.emitter;
  switch (e.kind) {
    case Kind::triangle: {
      if (e.area <= 0.0f) return std::nullopt;
      const Vec2f b = sample_uniform_triangle(u);
      s.position = e.p0 + e.e1 * b.x + e.e2 * b.y;
      s.normal = e.normal;
      Vec3f d = s.position - reference;
      const float d2 = length_squared(d);
      if (!(d2 > 0.0f)) return std::nullopt;
      s.distance = std::sqrt(d2);
      s.wi = d / s.distance;
      float cos_light = -dot(e.normal, s.wi);
      if (e.two_sided) cos_light = std::abs(cos_light);
      if (cos_light <= 0.0f) return std::nullopt;
      s.pdf = d2 / (cos_light * e.area);  // area → solid angle: p_A r² / cos θ_light
      return s;
    }
    case Kind::point:
    case Kind::spot: {
      const Vec3f d = e.position - reference;
      const float d2 = length_squared(d);
      if (!(d2 > 0.0f)) return std::nullopt;
      s.distance = std::sqrt(d2);
      s.wi = d / s.distance;
      s.position = e.position;
      s.is_delta = true;
      s.pdf = 1.0f;
      // Intensity I (cd) → irradiance-like I / r² at the reference point.
      s.scale = 1.0f / d2;
      if (e.kind == Kind::spot) s.scale *= spot_falloff(dot(-s.wi, e.axis), e.cos_outer, e.cos_inner);
      if (s.scale <= 0.0f) return std::nullopt;
      return s;
    }
    case Kind::directional: {
      s.distance = std::numeric_limits<float>::infinity();
      if (e.cos_max >= 1.0f) {
        s.wi = -e.axis;
        s.is_delta = true;
        s.pdf = 1.0f;
        return s;  // scale 1: the spectrum is the illuminance
      }
      const Vec3f local = sample_uniform_cone(u, e.cos_max);
      s.wi = Frame::from_normal(-e.axis).to_world(local);
      s.pdf = uniform_cone_pdf(e.cos_max);
      s.scale = e.disc_radiance_scale;
      return s;
    }
  }
  return std::nullopt;
}

float LightSampler::pdf_triangle(std::uint32_t mesh, std::uint32_t triangle, const Vec3f& reference,
                                 const Vec3f& position, float cos_light) const {
  if (mesh >= first_triangle_of_mesh_.size() || first_triangle_of_mesh_[mesh] < 0) return 0.0f;
  const auto index = static_cast<std::size_t>(first_triangle_of_mesh_[mesh]) + triangle;
  const Emitter& e = emitters_[index];
  const float c = e.two_sided ? std::abs(cos_light) : cos_light;
  if (e.area <= 0.0f || c <= 0.0f) return 0.0f;
  return selection_pmf_[index] * length_squared(position - reference) / (c * e.area);
}

std::vector<LightSampler::EscapedHit> LightSampler::escaped(const Vec3f& wi) const {
  std::vector<EscapedHit> hits;
  for (std::size_t i = 0; i < emitters_.size(); ++i) {
    const Emitter& e = emitters_[i];
    if (e.kind != Kind::directional || e.cos_max >= 1.0f) continue;
    if (dot(wi, -e.axis) < e.cos_max) continue;
    hits.push_back({e.emitter, e.disc_radiance_scale, selection_pmf_[i] * uniform_cone_pdf(e.cos_max)});
  }
  return hits;
}

}  // namespace prism
