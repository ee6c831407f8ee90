#pragma once
// What happens at a surface hit, for every integrator: the material's textures filtered at
// the ray cone's level of detail (Akenine-Möller et al. 2021, "Improved Shader and Texture
// Level of Detail Using Ray Cones"), normal, bump and clear-coat normal maps, anisotropy,
// the material point and the BSDF assembled from it (material_bsdf.h), the emitted
// radiance of textured emitters, and the first-hit AOVs. The wavefront integrator and the
// reference path tracer both shade through this class, so the two differ only in how they
// order the work, never in what a hit does.
//
// Conventions: `cone_width` is the ray cone's width at the hit in scene units, `ray` the
// ray that found it (unit direction); nothing here touches random numbers.
#include <cstdint>
#include <optional>
#include <vector>

#include "prism/bsdf/bsdf.h"
#include "prism/bsdf/microfacet_normal_mapping.h"
#include "prism/bsdf/normal_mapping_model.h"
#include "prism/core/frame.h"
#include "prism/core/mat3.h"
#include "prism/core/ray.h"
#include "prism/render/aov.h"
#include "prism/render/color_context.h"
#include "prism/render/material_bsdf.h"
#include "prism/render/surface_interaction.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_sampling.h"

namespace prism {

struct Hit;

template <class Mode>
class SurfaceShading {
 public:
  // `mip_pyramids`: one per Scene::textures entry (PreparedScene::mip_pyramids()).
  SurfaceShading(const Scene& scene, const std::vector<MipPyramid>& mip_pyramids, const ColorContext<Mode>& colors,
                 NormalMapping normal_mapping);

  // An anisotropic material's direction at the hit (world space, from the unmapped tangent
  // space, render/anisotropy.h) and its strength (after the texture's B).
  struct AnisotropyAtHit {
    Vec3f direction;
    float strength;
  };
  // The shading frame after the material's maps and anisotropy.
  struct MappedFrame {
    Frame unmapped;  // si.shading before any map
    // With microfacet normal mapping: the mapped frame as a facet of a microsurface around
    // the unmapped normal (si.shading then stays unmapped); nothing otherwise.
    std::optional<bsdf::NormalMapMicrosurface> microsurface;
    std::optional<AnisotropyAtHit> anisotropy;  // nothing where the surface has no usable tangent
  };
  // Applies the material's anisotropy direction and its normal and bump maps to si.shading.
  MappedFrame map_frame(const Material& material, SurfaceInteraction& si, float cone_width, const Ray& ray) const;

  // The BSDF at the hit, for the path's wavelengths (a plain diffuse material's is the
  // same Lambertian lobe, which integrators may build directly). A clear-coat normal map's
  // frame is kept in `coat_frame`, which must outlive the BSDF.
  bsdf::Bsdf<Mode::kChannels> bsdf(const Material& material, const SurfaceInteraction& si, float cone_width,
                                   const Ray& ray, const Wavelengths<Mode>& wl, const MappedFrame& mapped,
                                   std::optional<Frame>& coat_frame) const;

  // Whether the hit sees the material's emission (front faces, or both sides).
  static bool emits_toward(const Material& material, const SurfaceInteraction& si) {
    return material.is_emissive() && (si.front_face || material.emission.two_sided);
  }
  // Emitted radiance of an emissive material with an emission texture (and uvs): the texel
  // at `uv`, filtered at `level_of_detail`, multiplies the emission colour; untextured
  // emitters give their emission spectrum (ColorContext::emission).
  Spectrum<Mode> textured_emitted_radiance(std::uint32_t material, Vec2f uv, float level_of_detail,
                                           const Wavelengths<Mode>& wl) const;
  // The emission texture's level of detail where a hit on an emitter is counted alone
  // (camera rays, after delta bounces: the ray cone's); where it is combined with light
  // sampling, 0, the finest level, as light sampling evaluates it at its sampled point, so
  // both techniques estimate one function and MIS stays unbiased. 0 without a texture.
  float emission_level_of_detail(const Material& material, const SurfaceInteraction& si, float cone_width,
                                 bool counted_alone) const;

  // The first-hit AOVs of a camera ray (conventions in aov.h); `hit` null where it escaped.
  void first_hit_aovs(AovSample& aovs, const Ray& ray, const Hit* hit, float cone_spread) const;

  Spectrum<Mode> base_color(const Material& material, const SurfaceInteraction& si, float cone_width, const Ray& ray,
                            const Wavelengths<Mode>& wl) const;
  // Roughness and metallic after the metallic-roughness texture (G, B; linear), and the
  // other layers' textured parameters.
  MaterialPoint material_point(const Material& material, const SurfaceInteraction& si, float cone_width,
                               const Ray& ray) const;
  bool has_texture(int texture, std::uint32_t mesh) const;
  const MaterialTables& tables() const { return tables_; }

 private:
  // Base colour × texel of a textured material, in the material's base_color_space;
  // nothing when untextured.
  std::optional<Vec3f> textured_base_color(const Material& material, const SurfaceInteraction& si, float cone_width,
                                           const Ray& ray) const;
  // Texture `texture` at the hit, filtered at the ray cone's level of detail; nothing when
  // the index is unset or the mesh has no uvs. Every material texture uses this LOD.
  std::optional<TexelRgba> texel_at_hit(int texture, const SurfaceInteraction& si, float cone_width,
                                        const Ray& ray) const;
  TexelRgba texel_at(int texture, Vec2f uv, float level_of_detail) const;
  // The mip level a hit's ray cone covers in `texture` (which the mesh must have uvs for).
  float level_of_detail_at_hit(int texture, const SurfaceInteraction& si, float cone_width, const Ray& ray) const;
  // Applies the normal and bump maps (and the anisotropy direction) to si.shading; with
  // microfacet normal mapping (and a material that does not transmit), returns the
  // microsurface of the mapped frame instead and leaves si.shading unmapped.
  [[gnu::noinline]] std::optional<bsdf::NormalMapMicrosurface> apply_maps(const Material& material,
                                                                          SurfaceInteraction& si, float cone_width,
                                                                          const Ray& ray,
                                                                          const Vec3f* anisotropy_direction) const;
  [[gnu::noinline]] std::optional<AnisotropyAtHit> anisotropy_at_hit(const Material& material,
                                                                    const SurfaceInteraction& si, float cone_width,
                                                                    const Ray& ray) const;
  // Replaces si.shading by the material's normal-mapped frame, where it has a normal map.
  void apply_normal_map(const Material& material, SurfaceInteraction& si, float cone_width, const Ray& ray) const;
  // `unmapped` perturbed by tangent-space normal map `texture` (scaled by `scale`) at the
  // hit, in world space; nothing without the texel or a tangent.
  std::optional<Frame> tangent_space_mapped_frame(int texture, float scale, const SurfaceInteraction& si,
                                                  const Frame& unmapped, float cone_width, const Ray& ray) const;
  // The coat's frame from the material's clearcoat normal map, around the unmapped normal,
  // in si.shading's local coordinates (bsdf::Clearcoat::frame).
  [[gnu::noinline]] std::optional<Frame> coat_frame(const Material& material, const SurfaceInteraction& si,
                                                    const Frame& unmapped, float cone_width, const Ray& ray) const;
  // Replaces si.shading by the material's bump-mapped frame, where it has a bump map.
  void apply_bump_map(const Material& material, SurfaceInteraction& si, float cone_width, const Ray& ray) const;

  const Scene& scene_;
  const std::vector<MipPyramid>& textures_;  // one per Scene::textures entry
  const ColorContext<Mode>& colors_;
  NormalMapping normal_mapping_;
  MaterialTables tables_;
  // Per material: texel → radiance in the emission colour's space (scene/emission.h).
  std::vector<Mat3> textured_emission_;
};

}  // namespace prism
