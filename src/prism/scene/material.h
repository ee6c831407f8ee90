#pragma once
// Materials as plain data: a closed set of types (no virtual calls per ray; the
// integrator dispatches on `type`). Colours are linear and authored with Rec.709/sRGB
// primaries unless a field says otherwise; the integrator converts them to its transport
// mode (upsampled spectra or the working RGB space).
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "prism/color/spectrum.h"
#include "prism/core/vec.h"
#include "prism/scene/color_picker_space.h"

namespace prism {

enum class MaterialType : std::uint8_t {
  diffuse,             // Lambertian, reflectance = base_color
  mirror,              // perfect specular reflection, tinted by base_color
  conductor,           // rough (GGX) metal: Schlick from F0 = base_color, or complex IOR by name
  dielectric,          // smooth or rough glass; constant or dispersive IOR; transmission tinted by base_color
  metallic_roughness,  // glTF 2.0: Lambert + GGX specular, dielectric F0 0.04 blended by metallic
};

enum class MicrofacetModel : std::uint8_t { ggx, beckmann, blinn_phong };
enum class ConductorFresnel : std::uint8_t { schlick, complex_ior };
enum class DispersionModel : std::uint8_t { none, cauchy, sellmeier };
enum class AlphaMode : std::uint8_t { opaque, mask, blend };

// Diffuse emission from the front face: `color` gives the chromaticity (in
// `color_space`), `luminance_nits` the luminance of the emitted radiance.
struct Emission {
  Vec3f color{0.0f};
  ColorPickerSpace color_space = ColorPickerSpace::srgb;
  float luminance_nits = 0.0f;
  int texture = -1;  // optional emissive texture (linear), multiplies color
  bool two_sided = false;
  // The relative spectral power distribution, where the scene gives one instead of a colour
  // (scene/spectral_inputs.h); `color` then holds its Rec.709 approximation. Spectral
  // transport renders it as given (white-balanced to the working white, render/color_context.h).
  std::optional<color::PiecewiseLinearSpectrum> spectrum;

  bool is_emissive() const { return luminance_nits > 0.0f && max_component(color) > 0.0f; }
  bool operator==(const Emission&) const = default;
};

// A member that changes how a diffuse material shades must also disqualify it in
// is_plain_diffuse (render/material_bsdf.cpp), or the integrator's plain diffuse path
// ignores it.
struct Material {
  std::string name;
  MaterialType type = MaterialType::diffuse;
  Vec3f base_color{0.8f};        // albedo / specular tint / F0 / glass tint (1: clear), linear, in base_color_space
  int base_color_texture = -1;   // index into Scene::textures; multiplies base_color
  // The primaries base_color is given with (white (1, 1, 1) is the perfect reflector in
  // each): wide-gamut albedos reach colours outside Rec.709 (render/color_context.h upsamples
  // them with their own space's table). A texture's texels (Rec.709, or an OpenEXR's held in
  // a wide space, TextureImage::texel_space) are converted to this space and multiply
  // base_color there (exact for grey factors; glTF's product otherwise has no meaning
  // across spaces). srgb where base_color_spectrum is given.
  ColorPickerSpace base_color_space = ColorPickerSpace::srgb;
  // Measured reflectance in [0, 1] instead of an RGB base colour (no texture then);
  // base_color holds its colour under a white light (scene/spectral_inputs.h).
  std::optional<color::PiecewiseLinearSpectrum> base_color_spectrum;
  float roughness = 0.5f;        // perceptual roughness r; microfacet α = r²
  // Anisotropic roughness (glTF KHR_materials_anisotropy) of the microfacet lobe of
  // metallic_roughness, conductor and dielectric materials (GGX or Beckmann; Blinn-Phong
  // stays isotropic): with strength a = `anisotropy` ∈ [0, 1], α along the anisotropy
  // direction is mix(r², 1, a²) and across it r² (render/anisotropy.h). The direction is
  // the surface's tangent (+u: the mesh's tangents, else dP/du, else the first edge),
  // turned by anisotropy_rotation_rad towards the bitangent. anisotropy_texture (linear)
  // replaces (1, 0) by its RG × 2 − 1 in that turned tangent space and multiplies a by B.
  float anisotropy = 0.0f;
  float anisotropy_rotation_rad = 0.0f;
  int anisotropy_texture = -1;
  float metallic = 0.0f;
  int metallic_roughness_texture = -1;  // glTF layout: G = roughness, B = metallic
  // Tangent-space normal map (glTF normalTexture; linear RGB = normal · ½ + ½ in the frame
  // tangent +u, bitangent up the image, vertex normal); its x and y are scaled by
  // normal_scale. Needs uvs; render/normal_mapping.h.
  int normal_texture = -1;
  float normal_scale = 1.0f;
  // Bump map: a height field over the surface, in scene units = bump_scale × the texel's
  // first channel (linear). Needs uvs; render/bump_mapping.h.
  int bump_texture = -1;
  float bump_scale = 1.0f;
  MicrofacetModel microfacet = MicrofacetModel::ggx;

  // Conductors: Schlick with F0 = base_color, or spectral η, k of a named metal
  // ("Au", "Ag", "Cu", "Al").
  ConductorFresnel conductor_fresnel = ConductorFresnel::schlick;
  std::string conductor_name;

  // Dielectrics: η at 587.6 nm (the d line) when dispersion is none; otherwise the
  // model's coefficients: Cauchy (A, B in µm²), Sellmeier (B1, B2, B3, C1, C2, C3 in µm²).
  float ior = 1.5f;
  DispersionModel dispersion = DispersionModel::none;
  std::array<float, 6> dispersion_coefficients{};
  bool thin_walled = false;  // glTF KHR_materials_volume absent: thin surface
  // Absorption inside a solid (not thin-walled) dielectric, by the Beer–Lambert law (glTF
  // KHR_materials_volume's attenuationColor and attenuationDistance): light that travels
  // attenuation_distance scene units through the interior keeps attenuation_color of
  // itself (linear Rec.709, each component in (0, 1]); infinite distance: clear.
  Vec3f attenuation_color{1.0f};
  float attenuation_distance = std::numeric_limits<float>::infinity();
  float transmission = 0.0f; // glTF KHR_materials_transmission factor (metallic_roughness)

  // metallic_roughness' dielectric specular layer (glTF KHR_materials_specular): its weight
  // specularFactor ∈ [0, 1] and its colour specularColorFactor (linear Rec.709, ≥ 0), which
  // scales F0 = ((ior − 1)/(ior + 1))² (KHR_materials_ior; 0.04 at the default 1.5) per
  // component, up to 1 (bsdf/metallic_roughness.h). The A channel of specular_texture
  // (linear) multiplies the weight; specular_color_texture (a colour, sRGB-encoded like
  // base_color_texture) the colour.
  float specular = 1.0f;
  Vec3f specular_color{1.0f};
  int specular_texture = -1;
  int specular_color_texture = -1;

  // Clear coat (glTF KHR_materials_clearcoat, pbrt-v4's coated materials): a colourless
  // η = 1.5 GGX layer of weight `clearcoat` ∈ [0, 1] and perceptual roughness
  // `clearcoat_roughness` ∈ [0, 1] over a diffuse, mirror, conductor or metallic_roughness
  // base (bsdf/clearcoat.h); dielectrics take none. The textures (linear) multiply the
  // factors: the R channel of clearcoat_texture, the G channel of clearcoat_roughness_texture.
  float clearcoat = 0.0f;
  float clearcoat_roughness = 0.0f;
  int clearcoat_texture = -1;
  int clearcoat_roughness_texture = -1;
  // The coat's own tangent-space normal map (glTF clearcoatNormalTexture, linear, like
  // normal_texture but for the coat alone, around the unmapped vertex normal; its x and y
  // scaled by clearcoat_normal_scale): bsdf/clearcoat.h. Not with microfacet normal mapping.
  int clearcoat_normal_texture = -1;
  float clearcoat_normal_scale = 1.0f;

  // Sheen (glTF KHR_materials_sheen): a velvet-like layer of fibres of colour `sheen_color`
  // (linear Rec.709, components in [0, 1]; black: none) and roughness `sheen_roughness`
  // ∈ [0, 1] over a diffuse, mirror, conductor or metallic_roughness base, under any clear
  // coat (bsdf/sheen.h); dielectrics take none. sheen_color_texture (a colour, sRGB-encoded
  // like base_color_texture) multiplies the colour, the A channel of
  // sheen_roughness_texture (linear) the roughness.
  Vec3f sheen_color{0.0f};
  float sheen_roughness = 0.0f;
  int sheen_color_texture = -1;
  int sheen_roughness_texture = -1;

  // Iridescence (glTF KHR_materials_iridescence): a thin film of weight `iridescence`
  // ∈ [0, 1] (0: none), index `iridescence_ior` ≥ 1 and a thickness in nm over a
  // metallic_roughness material's bases (bsdf/thin_film.h). The thickness is
  // iridescence_thickness_max_nm, or with iridescence_thickness_texture (its G channel,
  // linear) the mix of min and max by the texel; the R channel of iridescence_texture
  // (linear) multiplies the weight.
  float iridescence = 0.0f;
  float iridescence_ior = 1.3f;
  float iridescence_thickness_min_nm = 100.0f;
  float iridescence_thickness_max_nm = 400.0f;
  int iridescence_texture = -1;
  int iridescence_thickness_texture = -1;

  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;  // for AlphaMode::mask; alpha comes from base colour texture's A
  float opacity = 1.0f;       // constant alpha (AlphaMode::blend: stochastic coverage)

  Emission emission;

  bool is_emissive() const { return emission.is_emissive(); }
  bool has_clearcoat() const { return clearcoat > 0.0f && type != MaterialType::dielectric; }
  bool has_sheen() const { return max_component(sheen_color) > 0.0f && type != MaterialType::dielectric; }
  bool has_iridescence() const { return iridescence > 0.0f && type == MaterialType::metallic_roughness; }
  bool has_anisotropy() const {
    return anisotropy > 0.0f && microfacet != MicrofacetModel::blinn_phong &&
           (type == MaterialType::metallic_roughness || type == MaterialType::conductor ||
            type == MaterialType::dielectric);
  }
  // Whether paths inside this material lose light on the way (render/volume_absorption.h).
  bool absorbs_inside() const {
    return type == MaterialType::dielectric && !thin_walled && std::isfinite(attenuation_distance) &&
           min_component(attenuation_color) < 1.0f;
  }
};

}  // namespace prism
