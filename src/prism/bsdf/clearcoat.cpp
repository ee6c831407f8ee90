#include "prism/bsdf/clearcoat.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "prism/bsdf/fresnel.h"

namespace prism::bsdf {
namespace {

constexpr int kGrid = 32;        // nodes per axis: cos θ and r at i / (kGrid − 1)
constexpr int kQuadrature = 16;  // midpoint rule over the unit square of VNDF numbers, per axis
// Node 0 of cos θ stands for grazing light; the VNDF estimator needs cos θ > 0.
constexpr float kGrazingCos = 1e-3f;

// E(μ, r) at one node: the midpoint rule over kQuadrature² VNDF samples of the estimator
// F(wo·h) G2(wo, wi) / G1(wo) (what VNDF sampling's f cos θi / pdf is, Heitz 2018 §2).
// r = 0 is the smooth interface, F(μ) exactly.
float albedo_at_node(float cos_theta, float r) {
  if (r == 0.0f) return fresnel_dielectric(cos_theta, Clearcoat::kIor);
  const auto d = MicrofacetDistribution::isotropic(MicrofacetType::ggx, r * r);
  const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta)), 0.0f, cos_theta);
  const float g1_o = d.G1(wo);
  double sum = 0.0;
  for (int a = 0; a < kQuadrature; ++a)
    for (int b = 0; b < kQuadrature; ++b) {
      const Vec2f u((static_cast<float>(a) + 0.5f) / kQuadrature, (static_cast<float>(b) + 0.5f) / kQuadrature);
      const Vec3f h = d.sample_vndf_heitz2018(wo, u);
      const Vec3f wi = reflect(wo, h);
      if (wi.z <= 0.0f) continue;
      sum += fresnel_dielectric(dot(wo, h), Clearcoat::kIor) * d.G2(wo, wi) / g1_o;
    }
  return static_cast<float>(sum / (kQuadrature * kQuadrature));
}

struct AlbedoTable {
  std::array<float, kGrid * kGrid> values{};  // [cos index][r index]
  AlbedoTable() {
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const float mu = std::max(kGrazingCos, static_cast<float>(i) / (kGrid - 1));
        values[static_cast<std::size_t>(i * kGrid + j)] = albedo_at_node(mu, static_cast<float>(j) / (kGrid - 1));
      }
  }
  float at(int i, int j) const { return values[static_cast<std::size_t>(i * kGrid + j)]; }
};

}  // namespace

float coat_directional_albedo(float cos_theta, float perceptual_roughness) {
  static const AlbedoTable table;  // built once, thread-safe (C++11 static initialisation)
  const float x = std::clamp(std::abs(cos_theta), 0.0f, 1.0f) * (kGrid - 1);
  const float y = std::clamp(perceptual_roughness, 0.0f, 1.0f) * (kGrid - 1);
  const int i = std::min(static_cast<int>(x), kGrid - 2), j = std::min(static_cast<int>(y), kGrid - 2);
  const float fx = x - static_cast<float>(i), fy = y - static_cast<float>(j);
  const float low = table.at(i, j) + fy * (table.at(i, j + 1) - table.at(i, j));
  const float high = table.at(i + 1, j) + fy * (table.at(i + 1, j + 1) - table.at(i + 1, j));
  return low + fx * (high - low);
}

float Clearcoat::albedo(const Vec3f& wo) const {
  const float cos_o = abs_cos_theta(frame ? frame->to_local(wo) : wo);
  // A smooth coat reflects exactly F; the table would interpolate it.
  const float e = is_smooth() ? fresnel_dielectric(cos_o, kIor) : coat_directional_albedo(cos_o, perceptual_roughness);
  return weight * e;
}

float Clearcoat::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (is_smooth()) return 0.0f;
  if (frame) {
    // In the coat's frame, with its cosine for the base's (see the header); on the base's
    // side of wo only.
    if (!same_hemisphere(wo, wi) || wi.z == 0.0f) return 0.0f;
    const Vec3f o = frame->to_local(wo), i = frame->to_local(wi);
    return untilted_eval(o, i) * (std::abs(i.z) / std::abs(wi.z));
  }
  return untilted_eval(wo, wi);
}

float Clearcoat::untilted_eval(const Vec3f& wo, const Vec3f& wi) const {
  const auto r = upper_reflection(wo, wi);
  if (!r) return 0.0f;
  return weight * fresnel_dielectric(dot(r->o, r->h), kIor) * distribution.D(r->h) * distribution.G2(r->o, r->i) /
         (4.0f * r->o.z * r->i.z);
}

float Clearcoat::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (is_smooth()) return 0.0f;
  if (frame && !same_hemisphere(wo, wi)) return 0.0f;  // sample_direction drops those
  // Solid-angle densities do not depend on the frame they are written in.
  const auto r = frame ? upper_reflection(frame->to_local(wo), frame->to_local(wi)) : upper_reflection(wo, wi);
  return r ? distribution.pdf_microfacet_normal(r->o, r->h) * reflection_jacobian(r->o, r->h) : 0.0f;
}

std::optional<Vec3f> Clearcoat::sample_direction(const Vec3f& wo, Vec2f u) const {
  if (wo.z == 0.0f) return std::nullopt;
  const Vec3f local_o = frame ? frame->to_local(wo) : wo;
  if (local_o.z == 0.0f) return std::nullopt;
  Vec3f i;
  if (is_smooth()) {
    i = Vec3f(-local_o.x, -local_o.y, local_o.z);
  } else {
    const Vec3f o = local_o.z < 0.0f ? flip_z(local_o) : local_o;
    i = reflect(o, distribution.sample_microfacet_normal(o, u));
    if (i.z <= 0.0f) return std::nullopt;
    if (local_o.z < 0.0f) i = flip_z(i);
  }
  if (!frame) return i;
  const Vec3f wi = frame->to_world(i);
  // Reflected about a tilted normal, a direction can leave below the base's surface.
  if (!same_hemisphere(wo, wi) || wi.z == 0.0f) return std::nullopt;
  return wi;
}

}  // namespace prism::bsdf
