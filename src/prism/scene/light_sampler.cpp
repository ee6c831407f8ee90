#include "prism/scene/light_sampler.h"

#include <algorithm>

#include "prism/sampling/warps.h"
#include "prism/scene/emission.h"

namespace prism {

LightSampler::LightSampler(const Scene& scene) {
  first_light_of_mesh_.assign(scene.meshes.size(), -1);
  std::vector<double> power;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    const Material& material = scene.materials[mesh.material];
    if (!material.is_emissive()) continue;
    first_light_of_mesh_[m] = static_cast<std::int64_t>(triangles_.size());
    // Radiance in linear Rec.709, the foundation film's space.
    const Vec3f L(emission_radiance_rgb(material.emission, color::color_space("srgb")));
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3f& p0 = mesh.positions[mesh.indices[3 * t + 0]];
      const Vec3f& p1 = mesh.positions[mesh.indices[3 * t + 1]];
      const Vec3f& p2 = mesh.positions[mesh.indices[3 * t + 2]];
      const Vec3f n = cross(p1 - p0, p2 - p0);
      const float twice_area = length(n);
      const float area = 0.5f * twice_area;
      triangles_.push_back({p0, p1 - p0, p2 - p0, twice_area > 0.0f ? n / twice_area : Vec3f(0.0f), L, area});
      // Zero-area triangles get zero power and are never chosen.
      power.push_back(static_cast<double>(area) * (L.x + L.y + L.z) / 3.0);
    }
  }
  double total = 0.0;
  for (double p : power) total += p;
  cdf_.resize(power.size());
  pmf_.resize(power.size());
  double running = 0.0;
  for (std::size_t i = 0; i < power.size(); ++i) {
    running += power[i];
    pmf_[i] = total > 0.0 ? static_cast<float>(power[i] / total) : 0.0f;
    cdf_[i] = total > 0.0 ? static_cast<float>(running / total) : 0.0f;
  }
  if (!cdf_.empty() && total > 0.0) cdf_.back() = 1.0f;
  if (total <= 0.0) {
    triangles_.clear();
    cdf_.clear();
    pmf_.clear();
    first_light_of_mesh_.assign(scene.meshes.size(), -1);
  }
}

LightSample LightSampler::sample(float u_select, Vec2f u_point) const {
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_select);
  std::size_t index = std::min<std::size_t>(static_cast<std::size_t>(it - cdf_.begin()), cdf_.size() - 1);
  while (pmf_[index] == 0.0f && index > 0) --index;  // float ties at the top of the CDF
  const EmissiveTriangle& tri = triangles_[index];
  const Vec2f b = sample_uniform_triangle(u_point);
  return {tri.p0 + tri.e1 * b.x + tri.e2 * b.y, tri.normal, tri.radiance, pmf_[index] / tri.area};
}

float LightSampler::pdf_area(std::uint32_t mesh, std::uint32_t triangle) const {
  if (mesh >= first_light_of_mesh_.size() || first_light_of_mesh_[mesh] < 0) return 0.0f;
  const auto index = static_cast<std::size_t>(first_light_of_mesh_[mesh]) + triangle;
  const EmissiveTriangle& tri = triangles_[index];
  return tri.area > 0.0f ? pmf_[index] / tri.area : 0.0f;
}

}  // namespace prism
