// pbrt-v4 participating media, as far as Prism renders them: a homogeneous medium that
// only absorbs (σ_s = 0, no emission), given as the interior of a shape made of solid
// glass, is that glass's Beer–Lambert absorption (Material::attenuation_color/_distance,
// render/volume_absorption.h). pbrt-v4 spells glass with absorbing insides this way
// (pbrt-v4 User's Guide, "Media": MakeNamedMedium, MediumInterface "interior" "exterior").
// Everything else about media (scattering, emission, measured presets, grids, media
// around shapes or around the camera) is not rendered and is warned, never silently
// dropped.
#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/pbrt_builder.h"

namespace prism::loaders {

void PbrtBuilder::make_medium(const std::string& name, const PbrtParams& params) {
  if (media_.contains(name))
    throw SceneError(fmt::format("{}:{}: medium \"{}\" is defined twice", params.source, params.line, name));
  PbrtMedium medium;
  const std::string type = params.get_string("type", "");
  if (type != "homogeneous") {
    medium.unsupported = type.empty() ? "a medium without a type" : fmt::format("a \"{}\" medium", type);
  } else if (params.has("preset")) {
    medium.unsupported = "a measured (preset) medium, which scatters";
  } else {
    // pbrt-v4's HomogeneousMedium::Create: σ_a and σ_s default to 1 per unit, both times
    // "scale" (default 1); "Le" × "Lescale" is emission.
    const double scale = params.get_float("scale", 1.0);
    // Prism holds σ_a per Rec.709 channel: one given in another ColorSpace is taken as its
    // Rec.709 colour (a colour, not a spectrum of coefficients: an approximation).
    const PbrtColor sigma_a_color = params.get_color("sigma_a", PbrtSpectrumUse::reflectance, state_.color_space,
                                                     approximations_)
                                        .value_or(PbrtColor{});
    const Vec3f sigma_a = Vec3f(max(picker_color_in_rec709(sigma_a_color.rgb, sigma_a_color.space), Vec3d(0.0)));
    if (sigma_a_color.space != ColorPickerSpace::srgb)
      approximations_.push_back(fmt::format("medium \"{}\" (line {}): sigma_a in {} as its Rec.709 colour", name,
                                            params.line, state_.color_space));
    const Vec3f sigma_s = params.get_color("sigma_s", PbrtSpectrumUse::reflectance, approximations_).value_or(Vec3f(1.0f));
    const Vec3f le = params.get_color("Le", PbrtSpectrumUse::illuminant, approximations_).value_or(Vec3f(0.0f));
    params.get_float("Lescale", 1.0);
    params.get_float("g", 0.0);  // the phase function's asymmetry: nothing scatters here
    if (!(scale >= 0.0) || !std::isfinite(scale) || !(min_component(sigma_a) >= 0.0f) || !is_finite(sigma_a))
      throw SceneError(fmt::format("{}:{}: medium \"{}\": sigma_a and scale must be finite and ≥ 0", params.source,
                                   params.line, name));
    medium.sigma_a = sigma_a * static_cast<float>(scale);
    if (max_component(sigma_s) * scale > 0.0) medium.unsupported = "a scattering medium (sigma_s > 0)";
    else if (max_component(le) > 0.0f) medium.unsupported = "an emitting medium (Le > 0)";
  }
  if (!medium.unsupported.empty())
    ignore(fmt::format("MakeNamedMedium \"{}\": {}; media are rendered only as absorption inside glass", name,
                       medium.unsupported),
           params);
  else
    note_unused("MakeNamedMedium", params);
  media_.emplace(name, std::move(medium));
}

void PbrtBuilder::medium_interface(const std::string& interior, const std::string& exterior, const PbrtParams& params) {
  for (const std::string& n : {interior, exterior})
    if (!n.empty() && !media_.contains(n))
      throw SceneError(fmt::format("{}:{}: medium \"{}\" is not defined", params.source, params.line, n));
  state_.interior_medium = interior;
  if (!exterior.empty())
    ignore(fmt::format("MediumInterface exterior medium \"{}\" (media around shapes or the camera)", exterior), params);
}

// The shape's material with its interior medium's absorption, where both allow it: a
// medium that only absorbs, inside a dielectric that has an inside (not thin). One derived
// material per (material, medium).
std::uint32_t PbrtBuilder::with_interior_medium(std::uint32_t material, const PbrtParams& shape_params) {
  if (state_.interior_medium.empty()) return material;
  const PbrtMedium& medium = media_.at(state_.interior_medium);
  if (!medium.unsupported.empty()) return material;  // warned where it was made
  const Material& base = scene_.materials[material];
  if (base.type != MaterialType::dielectric || base.thin_walled) {
    ignore(fmt::format("MediumInterface interior \"{}\" on a shape that is not solid glass", state_.interior_medium),
           shape_params);
    return material;
  }
  if (max_component(medium.sigma_a) == 0.0f) return material;  // clear
  const auto key = std::make_pair(material, state_.interior_medium);
  if (const auto it = absorbing_materials_.find(key); it != absorbing_materials_.end()) return it->second;
  Material m = base;
  m.name += "+" + state_.interior_medium;
  // σ per unit as the colour left after one unit: c = exp(−σ), d = 1 (σ = −ln c / d).
  // Past σ ≈ 69 the colour is below 1e-30, where the renderer clamps it anyway.
  for (std::size_t i = 0; i < 3; ++i) m.attenuation_color[i] = std::max(std::exp(-medium.sigma_a[i]), 1e-30f);
  m.attenuation_distance = 1.0f;
  scene_.materials.push_back(std::move(m));
  const auto index = static_cast<std::uint32_t>(scene_.materials.size() - 1);
  absorbing_materials_.emplace(key, index);
  return index;
}

}  // namespace prism::loaders
