#include "prism/bsdf/sheen.h"

#include <array>

namespace prism::bsdf {
namespace {

// Estevez & Kulla 2017, table 1 (as KHR_materials_sheen restates it): the fitted
// L(x) = a / (1 + b x^c) + d x + e of ln Λ, at α = 0 and α = 1, mixed by (1 − α)².
float fitted_l(float x, float alpha) {
  const float t = (1.0f - alpha) * (1.0f - alpha);
  const auto mix = [t](float at_one, float at_zero) { return at_one + t * (at_zero - at_one); };
  const float a = mix(21.5473f, 25.3245f), b = mix(3.82987f, 3.32435f), c = mix(0.19823f, 0.16801f);
  const float d = mix(-1.97760f, -1.27393f), e = mix(-4.32054f, -4.85967f);
  return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}

constexpr int kGrid = 32;
constexpr int kThetaSteps = 64;  // midpoint rule in t, cos θi = t² (dense at grazing)
constexpr int kPhiSteps = 32;    // midpoint rule over φ ∈ [0, π]; the lobe is symmetric in φ

float roughness_at(int j) {
  return kMinSheenPerceptualRoughness + (1.0f - kMinSheenPerceptualRoughness) * static_cast<float>(j) / (kGrid - 1);
}

// E at one node: ∫ f cos θi dω with dω = d(cos θi) dφ = 2t dt dφ, doubled for φ ∈ [π, 2π].
// Λ(cos θo) is the node's and Λ(cos θi) the row's: only D is evaluated per direction.
float albedo_at_node(float cos_theta, float perceptual_roughness) {
  const float alpha = perceptual_roughness * perceptual_roughness;
  const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta)), 0.0f, cos_theta);
  const float lambda_o = sheen_lambda(wo.z, alpha);
  double sum = 0.0;
  for (int a = 0; a < kThetaSteps; ++a) {
    const float t = (static_cast<float>(a) + 0.5f) / kThetaSteps;
    const float cos_i = t * t, sin_i = std::sqrt(std::max(0.0f, 1.0f - cos_i * cos_i));
    const float lambda_i = sheen_lambda(cos_i, alpha);
    for (int b = 0; b < kPhiSteps; ++b) {
      const float phi = std::numbers::pi_v<float> * (static_cast<float>(b) + 0.5f) / kPhiSteps;
      const Vec3f wi(sin_i * std::cos(phi), sin_i * std::sin(phi), cos_i);
      sum += double(charlie_sheen(wo, wi, alpha, lambda_o, lambda_i)) * cos_i * 2.0 * t;
    }
  }
  return static_cast<float>(sum * 2.0 * (1.0 / kThetaSteps) * (std::numbers::pi / kPhiSteps));
}

struct AlbedoTable {
  std::array<float, kGrid * kGrid> values{};  // [√μ index][r index]
  AlbedoTable() {
    for (int i = 0; i < kGrid; ++i) {
      const float s = static_cast<float>(i) / (kGrid - 1);
      const float mu = std::max(s * s, 1e-4f);  // V needs cos θo > 0
      for (int j = 0; j < kGrid; ++j) values[static_cast<std::size_t>(i * kGrid + j)] = albedo_at_node(mu, roughness_at(j));
    }
  }
  float at(int i, int j) const { return values[static_cast<std::size_t>(i * kGrid + j)]; }
};

}  // namespace

// Λ(cos θ), the paper's §3 extension of the fit past cos θ = 0.5 (symmetric in ln Λ).
float sheen_lambda(float cos_theta, float alpha) {
  return cos_theta < 0.5f ? std::exp(fitted_l(cos_theta, alpha))
                          : std::exp(2.0f * fitted_l(0.5f, alpha) - fitted_l(1.0f - cos_theta, alpha));
}

// D(h) V(wo, wi) for directions above the surface, given Λ at both.
float charlie_sheen(const Vec3f& wo, const Vec3f& wi, float alpha, float lambda_o, float lambda_i) {
  const Vec3f h = normalize(wo + wi);
  const float sin2_h = std::max(0.0f, 1.0f - h.z * h.z);
  const float inv_alpha = 1.0f / alpha;
  const float d = (2.0f + inv_alpha) * std::pow(sin2_h, 0.5f * inv_alpha) * (0.5f * std::numbers::inv_pi_v<float>);
  const float v = 1.0f / ((1.0f + lambda_o + lambda_i) * 4.0f * wo.z * wi.z);
  return d * v;
}

float charlie_sheen_brdf(const Vec3f& wo, const Vec3f& wi, float alpha) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  return charlie_sheen(wo, wi, alpha, sheen_lambda(wo.z, alpha), sheen_lambda(wi.z, alpha));
}

float sheen_directional_albedo(float cos_theta, float perceptual_roughness) {
  static const AlbedoTable table;  // built once, thread-safe (C++11 static initialisation)
  const float x = std::sqrt(std::clamp(std::abs(cos_theta), 0.0f, 1.0f)) * (kGrid - 1);
  const float r = std::clamp(perceptual_roughness, kMinSheenPerceptualRoughness, 1.0f);
  const float y = (r - kMinSheenPerceptualRoughness) / (1.0f - kMinSheenPerceptualRoughness) * (kGrid - 1);
  const int i = std::min(static_cast<int>(x), kGrid - 2), j = std::min(static_cast<int>(y), kGrid - 2);
  const float fx = x - static_cast<float>(i), fy = y - static_cast<float>(j);
  const float low = table.at(i, j) + fy * (table.at(i, j + 1) - table.at(i, j));
  const float high = table.at(i + 1, j) + fy * (table.at(i + 1, j + 1) - table.at(i + 1, j));
  return low + fx * (high - low);
}

}  // namespace prism::bsdf
