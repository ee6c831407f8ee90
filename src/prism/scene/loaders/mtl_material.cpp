#include "prism/scene/loaders/mtl_material.h"

#include <algorithm>
#include <cmath>

#include <tiny_obj_loader.h>

#include "prism/scene/emission.h"

namespace prism::loaders {
namespace {

Vec3f rgb(const tinyobj::real_t* v) {
  const auto clean = [](float x) { return std::isfinite(x) ? std::max(x, 0.0f) : 0.0f; };
  return {clean(v[0]), clean(v[1]), clean(v[2])};
}

float finite_or(float x, float fallback) { return std::isfinite(x) ? x : fallback; }

}  // namespace

float roughness_from_phong_exponent(float ns) {
  if (!std::isfinite(ns)) return 0.0f;
  const float alpha = std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f));
  return std::sqrt(std::min(alpha, 1.0f));
}

Material material_from_mtl(const tinyobj::material_t& mtl, std::vector<std::string>& ignored) {
  Material m;
  m.name = mtl.name;
  const Vec3f kd = rgb(mtl.diffuse), ks = rgb(mtl.specular), ke = rgb(mtl.emission);
  const float roughness = roughness_from_phong_exponent(mtl.shininess);
  const int illum = mtl.illum;
  if (illum == 4 || illum == 6 || illum == 7 || illum == 9) {
    // Refraction illumination models: glass with the file's Ni.
    m.type = MaterialType::dielectric;
    m.base_color = max_component(ks) > 0.0f ? ks : Vec3f(1.0f);
    const float ior = finite_or(mtl.ior, 1.5f);
    m.ior = ior >= 1.0f && ior <= 10.0f ? ior : 1.5f;
    m.roughness = mtl.shininess >= 1000.0f ? 0.0f : roughness;
  } else if (max_component(kd) == 0.0f && max_component(ks) > 0.0f && mtl.diffuse_texname.empty()) {
    // Specular only: a metal with F0 = Ks (a mirror when the lobe is a delta).
    m.type = illum == 3 && mtl.shininess >= 1000.0f ? MaterialType::mirror : MaterialType::conductor;
    m.base_color = ks;
    m.roughness = roughness;
  } else if (max_component(ks) > 0.0f) {
    // Diffuse plus a specular lobe: the glTF dielectric layering (F0 = 0.04); the
    // magnitude of Ks is not representable and only switches the lobe on.
    m.type = MaterialType::metallic_roughness;
    m.base_color = kd;
    m.metallic = 0.0f;
    m.roughness = roughness;
  } else {
    m.type = MaterialType::diffuse;
    m.base_color = kd;
  }
  // The PBR extension (as Blender and three.js write it): Pr (perceptual roughness) and Pm
  // (metallic) make glTF's metallic-roughness model of Kd, instead of the Phong reading of
  // Ks and Ns. tinyobjloader gives 0 for what a file leaves out, so "Pr 0" and "Pm 0"
  // alone (a smooth dielectric) read as absent.
  const float pr = finite_or(mtl.roughness, 0.0f), pm = finite_or(mtl.metallic, 0.0f);
  if ((pr != 0.0f || pm != 0.0f) && m.type != MaterialType::dielectric) {
    m.type = MaterialType::metallic_roughness;
    m.base_color = kd;
    m.roughness = std::clamp(pr, 0.0f, 1.0f);
    m.metallic = std::clamp(pm, 0.0f, 1.0f);
  }
  // A diffuse texture with Kd = 0 would be black: many exporters write Kd 0 with map_Kd.
  if (!mtl.diffuse_texname.empty() && max_component(kd) == 0.0f && m.type != MaterialType::conductor)
    m.base_color = Vec3f(1.0f);
  m.base_color = min(m.base_color, Vec3f(1.0f));
  const float d = finite_or(mtl.dissolve, 1.0f);
  if (d < 1.0f && m.type != MaterialType::dielectric) {
    m.alpha_mode = AlphaMode::blend;
    m.opacity = std::clamp(d, 0.0f, 1.0f);
  }
  if (max_component(ke) > 0.0f) {
    // Ke is read as linear Rec.709 radiance in nits, as the built-in Cornell box's light.
    m.emission.color = ke;
    m.emission.luminance_nits = static_cast<float>(relative_luminance(ke, ColorPickerSpace::srgb));
  } else if (!mtl.emissive_texname.empty()) {
    m.emission.color = Vec3f(1.0f);
    m.emission.luminance_nits = 1.0f;
  }
  if (!mtl.displacement_texname.empty()) ignored.push_back("disp");
  if (!mtl.specular_texname.empty()) ignored.push_back("map_Ks");
  if (!mtl.alpha_texname.empty()) ignored.push_back("map_d");
  if (!mtl.ambient_texname.empty()) ignored.push_back("map_Ka");
  // The PBR extension's clear coat: Pc its weight, Pcr its roughness (as Blender and
  // three.js read them), on anything but glass.
  const float coat = std::clamp(finite_or(mtl.clearcoat_thickness, 0.0f), 0.0f, 1.0f);
  if (coat > 0.0f && m.type != MaterialType::dielectric) {
    m.clearcoat = coat;
    m.clearcoat_roughness = std::clamp(finite_or(mtl.clearcoat_roughness, 0.0f), 0.0f, 1.0f);
  } else if (coat > 0.0f || mtl.clearcoat_roughness != 0.0f) {
    ignored.push_back(coat > 0.0f ? "Pc on glass" : "Pcr without Pc");
  }
  // The rest of the PBR extension (Ps, the maps: Prism's metallic-roughness texture is one
  // image, G and B) and a coloured transmission filter are not read; exporters write a
  // white Tf for every material.
  if (mtl.sheen != 0.0f || !mtl.roughness_texname.empty() || !mtl.metallic_texname.empty() ||
      !mtl.sheen_texname.empty())
    ignored.push_back("PBR extension (Ps, map_Pr, map_Pm, map_Ps)");
  if (m.type == MaterialType::dielectric && (pr != 0.0f || pm != 0.0f)) ignored.push_back("Pr/Pm on glass");
  if (rgb(mtl.transmittance) != Vec3f(1.0f) && rgb(mtl.transmittance) != Vec3f(0.0f)) ignored.push_back("Tf");
  return m;
}

}  // namespace prism::loaders
