#include "prism/scene/scene_summary.h"

#include <fmt/format.h>

#include "prism/scene/emission.h"
#include "prism/scene/surface_alpha.h"
#include "prism/scene/type_names.h"

namespace prism {

std::string_view material_type_name(MaterialType type) { return enum_name(kMaterialTypeNames, type); }

std::string_view light_type_name(LightType type) { return enum_name(kLightTypeNames, type); }

SceneSummary summarize_scene(const Scene& scene) {
  SceneSummary s;
  s.triangles = scene.triangle_count();
  s.meshes = scene.meshes.size();
  s.instances = scene.instances.size();
  if (scene.instances.empty()) {
    s.placed_triangles = s.triangles;
  } else {
    for (const auto& i : scene.instances)
      if (i.mesh < scene.meshes.size()) s.placed_triangles += scene.meshes[i.mesh].triangle_count();
  }
  s.cameras = scene.cameras.empty() ? 1 : scene.cameras.size();
  s.textures = scene.textures.size();
  for (const auto& t : scene.textures) s.texture_bytes += t.memory_bytes();
  for (const auto& m : scene.materials) {
    ++s.materials_by_type[std::string(material_type_name(m.type))];
    if (m.is_emissive()) ++s.emissive_materials;
    if (has_alpha_coverage(m)) ++s.alpha_tested_materials;
    if (m.normal_texture >= 0) ++s.normal_mapped_materials;
    if (m.bump_texture >= 0) ++s.bump_mapped_materials;
    if (m.absorbs_inside()) ++s.absorbing_materials;
    if (m.has_clearcoat()) ++s.coated_materials;
    if (m.has_sheen()) ++s.sheened_materials;
    if (m.has_iridescence()) ++s.iridescent_materials;
    if (m.has_anisotropy()) ++s.anisotropic_materials;
    if (m.base_color_space != ColorPickerSpace::srgb) ++s.wide_gamut_materials;
    if (m.base_color_spectrum || m.emission.spectrum) ++s.spectral_materials;
  }
  for (const auto& l : scene.lights) {
    ++s.lights_by_type[std::string(light_type_name(l.type))];
    if (l.spectrum) ++s.spectral_lights;
  }
  return s;
}

namespace {

std::string counts(const std::map<std::string, std::size_t>& by_type) {
  std::string out;
  for (const auto& [name, n] : by_type) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, name);
  return out.empty() ? "none" : out;
}

std::string mebibytes(std::size_t bytes) { return fmt::format("{:.2f} MiB", static_cast<double>(bytes) / (1 << 20)); }

}  // namespace

std::string format_scene_summary(const Scene& scene) {
  const SceneSummary s = summarize_scene(scene);
  std::string out = fmt::format("scene {}\n", scene.name);
  out += fmt::format("triangles {} ({} placed)\n", s.triangles, s.placed_triangles);
  out += fmt::format("meshes {}\n", s.meshes);
  out += fmt::format("instances {}\n", s.instances);
  std::string extras;  // what only some scenes have
  if (s.alpha_tested_materials) extras += fmt::format(", {} alpha-tested", s.alpha_tested_materials);
  if (s.normal_mapped_materials) extras += fmt::format(", {} normal-mapped", s.normal_mapped_materials);
  if (s.bump_mapped_materials) extras += fmt::format(", {} bump-mapped", s.bump_mapped_materials);
  if (s.absorbing_materials) extras += fmt::format(", {} absorbing inside", s.absorbing_materials);
  if (s.coated_materials) extras += fmt::format(", {} clear-coated", s.coated_materials);
  if (s.sheened_materials) extras += fmt::format(", {} with sheen", s.sheened_materials);
  if (s.iridescent_materials) extras += fmt::format(", {} iridescent", s.iridescent_materials);
  if (s.anisotropic_materials) extras += fmt::format(", {} anisotropic", s.anisotropic_materials);
  if (s.wide_gamut_materials) extras += fmt::format(", {} wide-gamut", s.wide_gamut_materials);
  if (s.spectral_materials) extras += fmt::format(", {} with spectra", s.spectral_materials);
  out += fmt::format("materials {} ({}; {} emissive{})\n", scene.materials.size(), counts(s.materials_by_type),
                     s.emissive_materials, extras);
  out += fmt::format("lights {} ({}{})\n", scene.lights.size(), counts(s.lights_by_type),
                     s.spectral_lights ? fmt::format("; {} with spectra", s.spectral_lights) : std::string());
  out += fmt::format("textures {} ({})\n", s.textures, mebibytes(s.texture_bytes));
  for (const auto& t : scene.textures) {
    const char* storage = t.has_rgbe()                          ? "RGBE"
                          : t.has_halves()                      ? "half"
                          : !t.has_codes()                        ? "float"
                          : t.encoding == TextureEncoding::srgb ? "8-bit sRGB"
                                                                : "8-bit linear";
    // Texels outside Rec.709's primaries (an OpenEXR kept in a wide-gamut material's space)
    // say which.
    const std::string space =
        t.texel_space == ColorPickerSpace::srgb ? std::string() : fmt::format(" {}", picker_space_label(t.texel_space));
    out += fmt::format("  texture {} {}x{}x{} {}{} {}\n", t.name, t.width, t.height, t.channels, storage, space,
                       mebibytes(t.memory_bytes()));
  }
  const auto camera_line = [](const Camera& c) {
    return fmt::format("  camera {} {} fov {:.4g} deg{}\n", c.name.empty() ? "default" : c.name,
                       c.aperture_radius > 0.0f ? "thin lens" : "pinhole", c.fov_degrees,
                       c.f_number > 0.0f ? fmt::format(", f/{:.3g} {:.4g} s ISO {:.4g}", c.f_number, c.shutter_seconds, c.iso)
                                         : std::string());
  };
  out += fmt::format("cameras {}\n", s.cameras);
  if (scene.cameras.empty()) out += camera_line(scene.camera);
  for (const auto& c : scene.cameras) out += camera_line(c);
  if (!scene.material_variants.empty()) {
    out += fmt::format("material variants {} (--variant NAME)\n", scene.material_variants.size());
    for (const auto& v : scene.material_variants) out += fmt::format("  variant {}\n", v);
  }
  out += fmt::format("resolution {}x{}\n", scene.default_width, scene.default_height);
  if (scene.default_normal_mapping)
    out += fmt::format("normal mapping {}\n", normal_mapping_name(*scene.default_normal_mapping));
  out += fmt::format("warnings {}\n", scene.warnings.size());
  for (const auto& w : scene.warnings) out += fmt::format("  warning: {}\n", w);
  return out;
}

}  // namespace prism
