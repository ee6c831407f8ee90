#pragma once
// Orthonormal frame around a unit normal. Construction follows Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited" (JCGT 6(1)): branchless and continuous
// except on the sign change of n.z.
#include <cmath>
#include <optional>

#include "prism/core/vec.h"

namespace prism {

struct Frame {
  Vec3f s, t, n;

  static Frame from_normal(const Vec3f& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {Vec3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
            Vec3f(b, sign + n.y * n.y * a, -n.y), n};
  }

  // The frame around the unit normal n whose tangent is t made perpendicular to n
  // (Gram–Schmidt); nothing where t lies along n (|t − n (n·t)| ≤ 10⁻⁴ |t|).
  static std::optional<Frame> from_normal_and_tangent(const Vec3f& n, const Vec3f& t) {
    const Vec3f s = t - n * dot(n, t);
    const float len = length(s);
    if (!(len > 1e-4f * length(t))) return std::nullopt;
    return Frame{s / len, cross(n, s / len), n};
  }

  // Always inlined: shading calls them three times per vertex, and GCC kept out-of-line
  // copies whose call, spills and reloads cost as much as the nine products (Callgrind,
  // docs/performance-design.md "Instruction cuts").
  [[gnu::always_inline]] Vec3f to_local(const Vec3f& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  [[gnu::always_inline]] Vec3f to_world(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace prism
