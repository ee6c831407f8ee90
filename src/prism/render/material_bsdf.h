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

// Per-material data resolved once per render (measured metal tables).
class MaterialTables {
 public:
  explicit MaterialTables(const std::vector<Material>& materials);
  const bsdf::ConductorIor* conductor(std::uint32_t material) const {
    return conductors_[material] ? &*conductors_[material] : nullptr;
  }
  // A metallic_roughness material's dielectric F0 (bsdf/metallic_roughness.h).
  float dielectric_f0(std::uint32_t material) const { return dielectric_f0_[material]; }

 private:
  std::vector<std::optional<bsdf::ConductorIor>> conductors_;
  std::vector<float> dielectric_f0_;
};

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

  bool has_sheen() const { return max_component(sheen_color) > 0.0f; }
};
inline MaterialPoint untextured_point(const Material& m) {
  return {m.roughness, m.metallic, m.has_clearcoat() ? m.clearcoat : 0.0f, m.clearcoat_roughness,
          m.has_sheen() ? m.sheen_color : Vec3f(0.0f), m.sheen_roughness};
}

// `sheen_color` is point.sheen_color in the transport's terms (upsampled, or in the working
// space); read only where point.has_sheen().
template <class Mode>
bsdf::Bsdf<Mode::kChannels> make_bsdf(const Material& material, std::uint32_t material_index,
                                      const Spectrum<Mode>& base_color, const MaterialPoint& point,
                                      const Wavelengths<Mode>& wavelengths, const MaterialTables& tables,
                                      const Spectrum<Mode>& sheen_color = Spectrum<Mode>(0.0f));

}  // namespace prism
