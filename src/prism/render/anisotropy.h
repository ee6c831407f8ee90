#pragma once
// Anisotropic roughness as glTF's KHR_materials_anisotropy defines it: a strength a ∈ [0, 1]
// and a direction in the surface's tangent space (tangent t along +u, bitangent b), turned
// counter-clockwise from t by the rotation; a texture's RG (× 2 − 1) replaces (1, 0) before
// the turn and its B scales a. The microfacet lobe is stretched along that direction:
//   α_along = mix(α, 1, a²),  α_across = α,  α = r²,
// in a shading frame whose s axis is the direction made perpendicular to the (possibly
// normal-mapped) shading normal. pbrt-v4's uroughness/vroughness (α_u along dP/du, α_v along
// dP/dv) are the same model with the rotation 0 or π/2 (scene/loaders/pbrt_materials.cpp).
#include <algorithm>
#include <cmath>
#include <optional>

#include "prism/core/frame.h"
#include "prism/render/normal_mapping.h"
#include "prism/scene/scene.h"

namespace prism {

// (The α mapping itself is bsdf::anisotropic_alpha_along, bsdf/microfacet.h.)

// The direction in tangent space: `texture_rg` (each ∈ [0, 1], or none) as × 2 − 1, else
// (1, 0), turned counter-clockwise by `rotation_rad`. Not normalised (a texel may encode a
// short vector; only its direction matters).
inline Vec2f anisotropy_direction_in_tangent_space(float rotation_rad, const std::optional<Vec2f>& texture_rg) {
  const Vec2f d = texture_rg ? Vec2f(2.0f * texture_rg->x - 1.0f, 2.0f * texture_rg->y - 1.0f) : Vec2f(1.0f, 0.0f);
  const float c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  return {c * d.x - s * d.y, s * d.x + c * d.y};
}

// The surface's tangent space at a hit of `mesh`'s `triangle` whose shading frame is
// `frame`: the mesh's interpolated tangent where it has them (frame.s, `bitangent_sign`);
// else dP/du of the triangle's uvs with the handedness triangle_tangent gives; without uvs
// (or with degenerate ones) the first edge p1 − p0, which is dP/du of pbrt-v4's default
// triangle parametrisation (uv (0, 0), (1, 0), (1, 1)). World-space tangent and bitangent,
// both perpendicular to frame.n; nothing if the tangent lies along the normal.
struct TangentSpace {
  Vec3f tangent, bitangent;
};
inline std::optional<TangentSpace> surface_tangent_space(const TriangleMesh& mesh, std::uint32_t triangle,
                                                         const Frame& frame, bool tangent_from_mesh,
                                                         float bitangent_sign) {
  Vec3f t = frame.s;
  float sign = bitangent_sign;
  if (!tangent_from_mesh) {
    sign = 1.0f;
    if (mesh.uvs.empty() || !triangle_tangent(mesh, triangle, t, sign)) {
      const std::uint32_t* i = mesh.indices.data() + 3 * static_cast<std::size_t>(triangle);
      t = mesh.positions[i[1]] - mesh.positions[i[0]];
      sign = 1.0f;
    }
  }
  const auto turned = Frame::from_normal_and_tangent(frame.n, t);
  if (!turned) return std::nullopt;
  return TangentSpace{turned->s, turned->t * sign};
}

// `frame` turned about its normal so that s runs along `direction` (world space) projected
// into its tangent plane; `frame` itself where the direction is (nearly) along the normal.
inline Frame frame_along(const Frame& frame, const Vec3f& direction) {
  const auto turned = Frame::from_normal_and_tangent(frame.n, direction);
  return turned ? *turned : frame;
}

}  // namespace prism
