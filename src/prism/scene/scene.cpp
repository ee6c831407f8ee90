#include "prism/scene/scene.h"

#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/spectrum_table_checks.h"

namespace prism {

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

const TextureImage* environment_map(const Scene& scene) {
  for (const Light& l : scene.lights) {
    if (l.type != LightType::environment) continue;
    const auto index = static_cast<std::size_t>(l.environment_texture);
    return l.environment_texture >= 0 && index < scene.textures.size() ? &scene.textures[index] : nullptr;
  }
  return nullptr;
}

void validate_scene(const Scene& scene) {
  if (scene.meshes.empty() || scene.triangle_count() == 0)
    throw SceneError(fmt::format("scene '{}' has no triangles", scene.name));
  for (const auto& mesh : scene.meshes) {
    if (mesh.indices.size() % 3 != 0)
      throw SceneError(fmt::format("mesh '{}': index count {} is not a multiple of 3", mesh.name,
                                   mesh.indices.size()));
    if (mesh.material >= scene.materials.size())
      throw SceneError(fmt::format("mesh '{}': material index {} out of range", mesh.name, mesh.material));
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= mesh.positions.size())
        throw SceneError(fmt::format("mesh '{}': index {} at position {} out of range (vertices: {})",
                                     mesh.name, mesh.indices[i], i, mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      if (!is_finite(mesh.positions[i]))
        throw SceneError(fmt::format("mesh '{}': vertex {} is not finite", mesh.name, i));
  }
  for (const auto& m : scene.materials) validate_material(m);
  for (const auto& l : scene.lights) {
    if (!l.spectrum) continue;
    if (l.type == LightType::environment && l.environment_texture >= 0)
      throw SceneError(fmt::format("light '{}': an environment map takes no spectrum (its texels are its colours)",
                                   l.name));
    validate_spectrum(*l.spectrum, fmt::format("light '{}'", l.name), kNoSpectrumMaximum);
  }
}

void validate_material(const Material& m) {
  if (!is_finite(m.base_color) || !is_finite(m.emission.color) || !std::isfinite(m.emission.luminance_nits) ||
      m.emission.luminance_nits < 0.0f)
    throw SceneError(fmt::format("material '{}' has non-finite values", m.name));
  if (m.base_color_spectrum) validate_spectrum(*m.base_color_spectrum, fmt::format("material '{}'", m.name), 1.0);
  if (m.base_color_space != ColorPickerSpace::srgb && m.base_color_spectrum)
    throw SceneError(fmt::format("material '{}': a measured base colour has no colour space", m.name));
  if (m.emission.spectrum)
    validate_spectrum(*m.emission.spectrum, fmt::format("material '{}'", m.name), kNoSpectrumMaximum);
}


void validate_spectrum(const color::PiecewiseLinearSpectrum& s, std::string_view owner, double max_value) {
  const std::string problem = spectrum_table_problem(s.wavelengths_nm(), s.values(), max_value);
  if (!problem.empty()) throw SceneError(fmt::format("{}: {}", owner, problem));
}

}  // namespace prism
