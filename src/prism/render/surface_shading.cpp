#include "prism/render/surface_shading.h"

#include <cmath>

#include "prism/accel/embree_accel.h"
#include "prism/core/frame.h"
#include "prism/render/anisotropy.h"
#include "prism/render/bump_mapping.h"
#include "prism/render/normal_mapping.h"
#include "prism/scene/emission.h"

namespace prism {

template <class Mode>
SurfaceShading<Mode>::SurfaceShading(const Scene& scene, const std::vector<MipPyramid>& mip_pyramids,
                                     const ColorContext<Mode>& colors, NormalMapping normal_mapping)
    : scene_(scene), textures_(mip_pyramids), colors_(colors), normal_mapping_(normal_mapping),
      tables_(scene.materials) {
  if (mip_pyramids.size() != scene.textures.size())
    throw std::invalid_argument("SurfaceShading: one mip pyramid per scene texture expected");
  for (const Material& m : scene.materials) {
    const bool textured = m.emission.texture >= 0 && static_cast<std::size_t>(m.emission.texture) < scene.textures.size();
    const ColorPickerSpace texel_space =
        textured ? scene.textures[static_cast<std::size_t>(m.emission.texture)].texel_space : ColorPickerSpace::srgb;
    textured_emission_.push_back(
        textured_emission_matrix(m.emission, picker_color_space(m.emission.color_space), texel_space));
  }
}

template <class Mode>
typename SurfaceShading<Mode>::MappedFrame SurfaceShading<Mode>::map_frame(const Material& material,
                                                                           SurfaceInteraction& si, float cone_width,
                                                                           const Ray& ray) const {
  MappedFrame mapped{si.shading, std::nullopt, std::nullopt};
  if (__builtin_expect(material.has_anisotropy(), 0)) mapped.anisotropy = anisotropy_at_hit(material, si, cone_width, ray);
  if (material.normal_texture >= 0 || material.bump_texture >= 0)
    mapped.microsurface =
        apply_maps(material, si, cone_width, ray, mapped.anisotropy ? &mapped.anisotropy->direction : nullptr);
  else if (mapped.anisotropy)
    si.shading = frame_along(si.shading, mapped.anisotropy->direction);
  return mapped;
}

template <class Mode>
bsdf::Bsdf<Mode::kChannels> SurfaceShading<Mode>::bsdf(const Material& material, const SurfaceInteraction& si,
                                                       float cone_width, const Ray& ray, const Wavelengths<Mode>& wl,
                                                       const MappedFrame& mapped,
                                                       std::optional<Frame>& own_coat_frame) const {
  MaterialPoint point = material_point(material, si, cone_width, ray);
  if (mapped.anisotropy) point.anisotropy = mapped.anisotropy->strength;
  // A sheen's colour and a tinted specular F0 are upsampled here, where the path's
  // wavelengths are known (rare: only the materials that have them pay for it).
  LayerColors<Mode> layer_colors;
  if (__builtin_expect(point.has_sheen(), 0)) layer_colors.sheen = colors_.reflectance(point.sheen_color, wl);
  if (__builtin_expect(point.has_tinted_specular(), 0) && material.type == MaterialType::metallic_roughness)
    layer_colors.specular_f0 = colors_.reflectance(tables_.dielectric_f0(si.material, point.specular_color), wl);
  auto b = make_bsdf<Mode>(material, si.material, base_color(material, si, cone_width, ray, wl), point, wl, tables_,
                           layer_colors);
  // The coat's own normal map (KHR_materials_clearcoat's clearcoatNormalTexture), in the
  // base's frame; not on a microsurface (microfacet normal mapping shades the base alone).
  if (__builtin_expect(material.clearcoat_normal_texture >= 0, 0) && b.coat.present() && !mapped.microsurface) {
    own_coat_frame = coat_frame(material, si, mapped.unmapped, cone_width, ray);
    if (own_coat_frame) b.coat.frame = &*own_coat_frame;
  }
  return b;
}

template <class Mode>
float SurfaceShading<Mode>::emission_level_of_detail(const Material& material, const SurfaceInteraction& si,
                                                     float cone_width, bool counted_alone) const {
  const int texture = material.emission.texture;
  if (!counted_alone || !has_texture(texture, si.mesh)) return 0.0f;
  return mip_level_from_ray_cone(textures_[static_cast<std::size_t>(texture)], cone_width,
                                 std::abs(si.cos_wo_geometric), si.uv_area, si.world_area);
}

template <class Mode>
Spectrum<Mode> SurfaceShading<Mode>::base_color(const Material& m, const SurfaceInteraction& si, float cone_width,
                                                     const Ray& ray, const Wavelengths<Mode>& wl) const {
  // Untextured materials (most vertices) skip the texture lookup's call chain.
  if (m.base_color_texture >= 0)
    if (const auto rgb = textured_base_color(m, si, cone_width, ray))
      return colors_.reflectance(*rgb, wl, m.base_color_space);
  return colors_.base_color(si.material, wl);
}

template <class Mode>
bool SurfaceShading<Mode>::has_texture(int texture, std::uint32_t mesh) const {
  return texture >= 0 && static_cast<std::size_t>(texture) < textures_.size() && !scene_.meshes[mesh].uvs.empty();
}

template <class Mode>
TexelRgba SurfaceShading<Mode>::texel_at(int texture, Vec2f uv, float level_of_detail) const {
  const auto t = static_cast<std::size_t>(texture);
  return sample_trilinear(textures_[t], apply_uv_transform(scene_.textures[t], uv), level_of_detail);
}

template <class Mode>
std::optional<TexelRgba> SurfaceShading<Mode>::texel_at_hit(int texture, const SurfaceInteraction& si,
                                                                 float cone_width, const Ray& ray) const {
  if (!has_texture(texture, si.mesh)) return std::nullopt;
  return texel_at(texture, si.uv, level_of_detail_at_hit(texture, si, cone_width, ray));
}

template <class Mode>
float SurfaceShading<Mode>::level_of_detail_at_hit(int texture, const SurfaceInteraction& si, float cone_width,
                                                        const Ray& ray) const {
  return mip_level_from_ray_cone(textures_[static_cast<std::size_t>(texture)], cone_width,
                                 std::abs(dot(ray.direction, si.geometric_normal)), si.uv_area, si.world_area);
}

template <class Mode>
std::optional<Vec3f> SurfaceShading<Mode>::textured_base_color(const Material& m, const SurfaceInteraction& si,
                                                                   float cone_width, const Ray& ray) const {
  const auto texel = texel_at_hit(m.base_color_texture, si, cone_width, ray);
  if (!texel) return std::nullopt;
  // Grey and two-channel textures come expanded to (g, g, g) (texture_sampling.h).
  Vec3f rgb((*texel)[0], (*texel)[1], (*texel)[2]);
  // Texels are Rec.709, or an OpenEXR's in the wide-gamut material's own space (the loader
  // asked for it, texture.h's TextureContent): in the material's space before its factor
  // multiplies them (Material::base_color_space; Rec.709 lies inside both wide spaces, so
  // only round-off is clipped).
  const ColorPickerSpace texel_space = scene_.textures[static_cast<std::size_t>(m.base_color_texture)].texel_space;
  if (texel_space != m.base_color_space)
    rgb = max(Vec3f(picker_space_conversion(texel_space, m.base_color_space) * Vec3d(rgb)), Vec3f(0.0f));
  return rgb * m.base_color;
}

template <class Mode>
std::optional<Frame> SurfaceShading<Mode>::tangent_space_mapped_frame(int texture, float scale,
                                                                         const SurfaceInteraction& si,
                                                                         const Frame& unmapped, float cone_width,
                                                                         const Ray& ray) const {
  const auto texel = texel_at_hit(texture, si, cone_width, ray);
  if (!texel) return std::nullopt;
  Frame frame = unmapped;
  float sign = si.bitangent_sign;
  if (!si.tangent_from_mesh) {
    // No per-vertex tangents: the triangle's dP/du, made perpendicular to the normal.
    Vec3f dpdu;
    if (!triangle_tangent(scene_.meshes[si.mesh], si.triangle, dpdu, sign)) return std::nullopt;
    const auto with_tangent = Frame::from_normal_and_tangent(frame.n, dpdu);
    if (!with_tangent) return std::nullopt;
    frame = *with_tangent;
  }
  return normal_mapped_frame(frame, sign, Vec3f((*texel)[0], (*texel)[1], (*texel)[2]), scale, si.geometric_normal);
}

template <class Mode>
void SurfaceShading<Mode>::apply_normal_map(const Material& m, SurfaceInteraction& si, float cone_width,
                                                 const Ray& ray) const {
  if (const auto frame = tangent_space_mapped_frame(m.normal_texture, m.normal_scale, si, si.shading, cone_width, ray))
    si.shading = *frame;
}

template <class Mode>
std::optional<Frame> SurfaceShading<Mode>::coat_frame(const Material& m, const SurfaceInteraction& si,
                                                           const Frame& unmapped, float cone_width,
                                                           const Ray& ray) const {
  const auto coat = tangent_space_mapped_frame(m.clearcoat_normal_texture, m.clearcoat_normal_scale, si, unmapped,
                                               cone_width, ray);
  if (!coat) return std::nullopt;
  const Frame& base = si.shading;
  return Frame{base.to_local(coat->s), base.to_local(coat->t), base.to_local(coat->n)};
}

template <class Mode>
void SurfaceShading<Mode>::apply_bump_map(const Material& m, SurfaceInteraction& si, float cone_width,
                                               const Ray& ray) const {
  if (!has_texture(m.bump_texture, si.mesh)) return;
  Vec3f dpdu, dpdv;
  float det = 0.0f;
  if (!triangle_position_derivatives(scene_.meshes[si.mesh], si.triangle, dpdu, dpdv, det)) return;
  const float lod = level_of_detail_at_hit(m.bump_texture, si, cone_width, ray);
  // Finite differences over half the ray footprint in uv (pbrt-v4: ½(|∂u/∂x| + |∂u/∂y|)),
  // the footprint being the cone's width times the triangle's uv per scene unit, and at
  // least half a texel of the finest level.
  const float uv_per_unit = si.world_area > 0.0f ? std::sqrt(si.uv_area / si.world_area) : 0.0f;
  const float half_footprint = 0.5f * cone_width * uv_per_unit;
  const TextureImage& image = scene_.textures[static_cast<std::size_t>(m.bump_texture)];
  const float du = std::max(half_footprint, 0.5f / static_cast<float>(image.width));
  const float dv = std::max(half_footprint, 0.5f / static_cast<float>(image.height));
  const float h = texel_at(m.bump_texture, si.uv, lod)[0];
  const float h_u = texel_at(m.bump_texture, Vec2f(si.uv.x + du, si.uv.y), lod)[0];
  const float h_v = texel_at(m.bump_texture, Vec2f(si.uv.x, si.uv.y + dv), lod)[0];
  const Vec3f n = bumped_normal(si.shading.n, dpdu, dpdv, m.bump_scale * (h_u - h) / du, m.bump_scale * (h_v - h) / dv);
  si.shading = frame_around_normal(si.shading, n, si.geometric_normal);
}

template <class Mode>
std::optional<typename SurfaceShading<Mode>::AnisotropyAtHit> SurfaceShading<Mode>::anisotropy_at_hit(
    const Material& m, const SurfaceInteraction& si, float cone_width, const Ray& ray) const {
  const auto space = surface_tangent_space(scene_.meshes[si.mesh], si.triangle, si.shading, si.tangent_from_mesh,
                                           si.bitangent_sign);
  if (!space) return std::nullopt;
  std::optional<Vec2f> rg;
  float strength = m.anisotropy;
  if (const auto texel = texel_at_hit(m.anisotropy_texture, si, cone_width, ray)) {
    rg = Vec2f((*texel)[0], (*texel)[1]);
    strength *= (*texel)[2];
  }
  const Vec2f d = anisotropy_direction_in_tangent_space(m.anisotropy_rotation_rad, rg);
  return AnisotropyAtHit{space->tangent * d.x + space->bitangent * d.y, strength};
}

template <class Mode>
std::optional<bsdf::NormalMapMicrosurface> SurfaceShading<Mode>::apply_maps(const Material& m,
                                                                               SurfaceInteraction& si,
                                                                               float cone_width, const Ray& ray,
                                                                               const Vec3f* anisotropy_direction) const {
  Frame unmapped = si.shading;
  if (m.normal_texture >= 0) apply_normal_map(m, si, cone_width, ray);
  if (m.bump_texture >= 0) apply_bump_map(m, si, cone_width, ray);
  // The lobe's frame runs along the anisotropy direction about whichever normal shades
  // (the mapped one; the unmapped one the microsurface is expressed in).
  if (anisotropy_direction) {
    unmapped = frame_along(unmapped, *anisotropy_direction);
    si.shading = frame_along(si.shading, *anisotropy_direction);
  }
  // Microfacet normal mapping: the mapped frame becomes facet p of a microsurface around
  // the unmapped normal, and the vertex is shaded in the unmapped frame. Dielectrics (the
  // only materials whose BSDFs transmit, material_bsdf.h) stay classic.
  if (normal_mapping_ != NormalMapping::microfacet || m.type == MaterialType::dielectric) return std::nullopt;
  auto microsurface = bsdf::NormalMapMicrosurface::between(unmapped, si.shading);
  if (microsurface) si.shading = unmapped;
  return microsurface;
}

template <class Mode>
MaterialPoint SurfaceShading<Mode>::material_point(const Material& m, const SurfaceInteraction& si,
                                                        float cone_width, const Ray& ray) const {
  if (const MaterialPoint* fixed = tables_.fixed_point(si.material)) return *fixed;
  MaterialPoint point = untextured_point(m);
  // glTF 2.0 §3.9.2: metallicRoughnessTexture's G channel scales roughnessFactor, B scales
  // metallicFactor (linear data). Grey textures expand to (g, g, g), so both use g.
  if (m.metallic_roughness_texture >= 0)
    if (const auto texel = texel_at_hit(m.metallic_roughness_texture, si, cone_width, ray)) {
      point.roughness *= (*texel)[1];
      point.metallic *= (*texel)[2];
    }
  // KHR_materials_clearcoat: clearcoatTexture's R channel scales clearcoatFactor,
  // clearcoatRoughnessTexture's G channel scales clearcoatRoughnessFactor.
  if (point.clearcoat > 0.0f) {
    if (m.clearcoat_texture >= 0)
      if (const auto texel = texel_at_hit(m.clearcoat_texture, si, cone_width, ray)) point.clearcoat *= (*texel)[0];
    if (m.clearcoat_roughness_texture >= 0)
      if (const auto texel = texel_at_hit(m.clearcoat_roughness_texture, si, cone_width, ray))
        point.clearcoat_roughness *= (*texel)[1];
  }
  // KHR_materials_sheen: sheenColorTexture (sRGB-encoded colour, decoded to linear)
  // multiplies sheenColorFactor, sheenRoughnessTexture's A channel sheenRoughnessFactor.
  if (__builtin_expect(point.has_sheen(), 0)) {
    if (m.sheen_color_texture >= 0)
      if (const auto texel = texel_at_hit(m.sheen_color_texture, si, cone_width, ray))
        point.sheen_color *= Vec3f((*texel)[0], (*texel)[1], (*texel)[2]);  // greys come expanded
    if (m.sheen_roughness_texture >= 0)
      if (const auto texel = texel_at_hit(m.sheen_roughness_texture, si, cone_width, ray))
        point.sheen_roughness *= (*texel)[3];
  }
  // KHR_materials_specular: specularTexture's A channel scales specularFactor,
  // specularColorTexture (sRGB-encoded colour, decoded to linear) specularColorFactor.
  if (m.specular_texture >= 0)
    if (const auto texel = texel_at_hit(m.specular_texture, si, cone_width, ray)) point.specular *= (*texel)[3];
  if (m.specular_color_texture >= 0)
    if (const auto texel = texel_at_hit(m.specular_color_texture, si, cone_width, ray))
      point.specular_color *= Vec3f((*texel)[0], (*texel)[1], (*texel)[2]);  // greys come expanded
  // KHR_materials_iridescence: iridescenceTexture's R channel scales iridescenceFactor;
  // iridescenceThicknessTexture's G channel mixes the thickness range's ends.
  if (__builtin_expect(point.iridescence > 0.0f, 0)) {
    if (m.iridescence_texture >= 0)
      if (const auto texel = texel_at_hit(m.iridescence_texture, si, cone_width, ray)) point.iridescence *= (*texel)[0];
    if (m.iridescence_thickness_texture >= 0)
      if (const auto texel = texel_at_hit(m.iridescence_thickness_texture, si, cone_width, ray))
        point.iridescence_thickness_nm =
            m.iridescence_thickness_min_nm + (*texel)[1] * (m.iridescence_thickness_max_nm - m.iridescence_thickness_min_nm);
  }
  return point;
}

template <class Mode>
Spectrum<Mode> SurfaceShading<Mode>::textured_emitted_radiance(std::uint32_t material, Vec2f uv,
                                                                    float level_of_detail,
                                                                    const Wavelengths<Mode>& wl) const {
  const int texture = scene_.materials[material].emission.texture;
  if (texture < 0 || static_cast<std::size_t>(texture) >= textures_.size()) return colors_.emission(material, wl);
  const TexelRgba t = texel_at(texture, uv, level_of_detail);
  const bool colour = scene_.textures[static_cast<std::size_t>(texture)].channels >= 3;
  const Vec3d texel = colour ? Vec3d(t[0], t[1], t[2]) : Vec3d(t[0]);
  // Radiance in nits in the emission colour's space, then the transport's own conversion
  // (as for environment texels): RGB modes convert to the working space, spectral modes
  // upsample with that space's table and the E-relative scaling, so a grey texel gives the
  // same spectrum as the untextured emitter, to the table's accuracy.
  return colors_.rgb_radiance(Vec3f(textured_emission_[material] * texel), wl,
                              scene_.materials[material].emission.color_space);
}

template <class Mode>
void SurfaceShading<Mode>::first_hit_aovs(AovSample& a, const Ray& ray, const Hit* hit, float cone_spread) const {
  a = AovSample{};
  if (hit == nullptr) return;  // escaped: zero albedo and normal, no depth
  SurfaceInteraction si = surface_interaction(scene_, *hit, ray);
  const Material& m = scene_.materials[si.material];
  // The camera ray's cone width at the hit, as shade() computes it for the texture LOD.
  const float cone_width = cone_spread * hit->t;
  // The normal AOV shows the normal- or bump-mapped normal.
  if (m.normal_texture >= 0) apply_normal_map(m, si, cone_width, ray);
  if (m.bump_texture >= 0) apply_bump_map(m, si, cone_width, ray);
  // Open Image Denoise's documentation asks for albedo 1 (or the surface's tint) on perfect
  // specular surfaces rather than the albedo of what they reflect or transmit; following
  // the path to its next non-delta hit would tie the AOV to the transport's random numbers.
  // Mirrors and Schlick conductors are tinted by base colour; glass and metals given by a
  // measured complex IOR have no base colour, so they are white.
  Vec3f albedo(1.0f);
  ColorPickerSpace space = ColorPickerSpace::srgb;
  const bool untinted =
      m.type == MaterialType::dielectric || (m.type == MaterialType::conductor && tables_.conductor(si.material));
  if (!untinted) {
    albedo = textured_base_color(m, si, cone_width, ray).value_or(m.base_color);
    space = m.base_color_space;
  }
  a.albedo = Vec3f(colors_.reflectance_to_film(albedo, space));
  // Facing the camera: the frame keeps the mesh's orientation, which is arbitrary for
  // two-sided surfaces seen from behind.
  const Vec3f n = si.shading.n;
  a.normal = dot(n, ray.direction) > 0.0f ? -n : n;
  a.depth_scene_units = hit->t;  // camera rays have unit directions (camera_rays.cpp)
  a.hit = true;
}

template class SurfaceShading<SpectralMode<3>>;
template class SurfaceShading<SpectralMode<4>>;
template class SurfaceShading<SpectralMode<8>>;
template class SurfaceShading<RgbMode>;

}  // namespace prism
