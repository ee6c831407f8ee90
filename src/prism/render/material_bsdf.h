#pragma once
// From a scene Material to the bsdf/ module's BSDF at one shading point, for one path's
// wavelengths (spectral) or the working space's channels (RGB).
//
// RGB transport has no wavelengths, so spectral material data is evaluated at
// representative wavelengths: complex IORs of metals at 630, 532 and 465 nm (the
// dominant wavelengths of Rec.709-like primaries), and a dispersive glass at its d-line
// index n(587.6 nm) in every channel — dispersion needs spectral transport.
#include <array>
#include <optional>
#include <vector>

#include "prism/bsdf/bsdf.h"
#include "prism/bsdf/ior.h"
#include "prism/render/transport_mode.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/material.h"

namespace prism {

inline constexpr std::array<float, 3> kRgbRepresentativeWavelengthsNm = {630.0f, 532.0f, 465.0f};
inline constexpr float kDLineWavelengthNm = 587.56f;

// A material's scalar parameters at one shading point, after its textures (glTF's
// metallicRoughnessTexture multiplies the factors: G channel roughness, B metallic).
struct MaterialPoint {
  float roughness = 0.5f;  // perceptual roughness r; α = r²
  float metallic = 0.0f;
  float clearcoat = 0.0f;            // the coat's weight
  float clearcoat_roughness = 0.0f;  // its perceptual roughness
  Vec3f sheen_color{0.0f};           // the sheen's colour (linear Rec.709); black: none
  float sheen_roughness = 0.0f;
  float specular = 1.0f;             // metallic_roughness' specular layer: its weight
  Vec3f specular_color{1.0f};        // and its colour (KHR_materials_specular)
  float iridescence = 0.0f;          // the thin film's weight (KHR_materials_iridescence); 0: none
  float iridescence_thickness_nm = 0.0f;
  // Anisotropy strength a (render/anisotropy.h; the integrator sets it, with the shading
  // frame's s along the direction, where the material has anisotropy); 0: isotropic.
  float anisotropy = 0.0f;

  bool has_sheen() const { return max_component(sheen_color) > 0.0f; }
  // A specular colour that is not a grey needs its own spectrum (make_bsdf's specular_f0).
  bool has_tinted_specular() const {
    return specular_color.x != specular_color.y || specular_color.y != specular_color.z;
  }
};
inline MaterialPoint untextured_point(const Material& m) {
  return {m.roughness,
          m.metallic,
          m.has_clearcoat() ? m.clearcoat : 0.0f,
          m.clearcoat_roughness,
          m.has_sheen() ? m.sheen_color : Vec3f(0.0f),
          m.sheen_roughness,
          m.specular,
          m.type == MaterialType::metallic_roughness ? m.specular_color : Vec3f(1.0f),
          m.has_iridescence() ? m.iridescence : 0.0f,
          m.iridescence_thickness_max_nm};
}

// Whether a texture varies the material's shading point (what material_point() in
// render/wavefront_integrator.cpp reads beside the base colour and the maps).
bool has_point_texture(const Material& m);

// Whether every hit on the material shades as a bare Lambertian lobe of its untextured base
// colour, what make_bsdf gives it: diffuse, without coat or sheen, and without a texture
// of any kind (base colour, point, normal, bump, emission), so also without anisotropy
// (which only microfacet lobes have). The integrator shades such hits on a path built for
// that lobe alone (WavefrontIntegrator::shade_surface), with the same operations.
bool is_plain_diffuse(const Material& m);

// Per-material data resolved once per render (measured metal tables, fixed shading points).
class MaterialTables {
 public:
  explicit MaterialTables(const std::vector<Material>& materials);
  const bsdf::ConductorIor* conductor(std::uint32_t material) const {
    return conductors_[material] ? &*conductors_[material] : nullptr;
  }
  // A metallic_roughness material's dielectric F0 (bsdf/metallic_roughness.h) for a
  // specular colour (KHR_materials_specular): min(((η − 1)/(η + 1))² × colour, 1) per
  // component, in double so that η = 1.5 and white give 0.04f exactly, the glTF constant.
  Vec3f dielectric_f0(std::uint32_t material, const Vec3f& specular_color) const;
  // The material's shading point where no texture varies it (its untextured_point), so
  // shading copies it instead of testing every texture slot; null where a texture does.
  const MaterialPoint* fixed_point(std::uint32_t material) const {
    return point_is_fixed_[material] ? &points_[material] : nullptr;
  }

 private:
  std::vector<std::optional<bsdf::ConductorIor>> conductors_;
  std::vector<double> fresnel_f0_;  // ((η − 1)/(η + 1))²
  std::vector<MaterialPoint> points_;          // untextured_point of each material
  std::vector<std::uint8_t> point_is_fixed_;   // no texture of the point's parameters
};

// The colours of a shading point beside its base colour, in the transport's terms
// (upsampled, or in the working space), each read only where the point has it:
//   sheen        point.sheen_color, where point.has_sheen();
//   specular_f0  tables.dielectric_f0(material, point.specular_color), where
//                point.has_tinted_specular() on a metallic_roughness material (a grey F0 is
//                the same number in every channel and needs no conversion).
template <class Mode>
struct LayerColors {
  Spectrum<Mode> sheen{0.0f};
  Spectrum<Mode> specular_f0{0.0f};
};

template <class Mode>
bsdf::Bsdf<Mode::kChannels> make_bsdf(const Material& material, std::uint32_t material_index,
                                      const Spectrum<Mode>& base_color, const MaterialPoint& point,
                                      const Wavelengths<Mode>& wavelengths, const MaterialTables& tables,
                                      const LayerColors<Mode>& layer_colors = {});

}  // namespace prism
