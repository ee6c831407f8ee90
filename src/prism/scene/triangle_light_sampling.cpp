#include "prism/scene/triangle_light_sampling.h"

#include <algorithm>
#include <cmath>

#include "prism/sampling/bilinear_warp.h"
#include "prism/sampling/spherical_triangle.h"

namespace prism {
namespace {

// The spherical triangle to sample, or nothing when area sampling applies.
std::optional<SphericalTriangle> spherical_view(const TriangleLight& light, TriangleLightSampling strategy,
                                                const Vec3f& reference) {
  if (strategy == TriangleLightSampling::area) return std::nullopt;
  const Vec3d p0(light.p0);
  SphericalTriangle t = make_spherical_triangle(Vec3d(reference), p0, p0 + Vec3d(light.e1), p0 + Vec3d(light.e2));
  if (!(t.solid_angle_sr >= kMinSolidAngleSr && t.solid_angle_sr <= kMaxSolidAngleSr)) return std::nullopt;
  return t;
}

// Corner values of the bilinear warp: |cos| at the receiver towards the vertex each corner
// of Arvo's square maps to ((0,0) and (1,0) → B, (0,1) → A, (1,1) → C).
BilinearWeights receiver_cosine_weights(const SphericalTriangle& t, TriangleLightSampling strategy,
                                        const Vec3f& receiver_normal) {
  BilinearWeights w;
  if (strategy != TriangleLightSampling::solid_angle_cosine || receiver_normal == Vec3f(0.0f)) return w;
  const Vec3d n(receiver_normal);
  const auto weight = [&](const Vec3d& d) { return std::max(kMinReceiverCosineWeight, std::abs(dot(n, d))); };
  w.w00 = w.w10 = weight(t.b);
  w.w01 = weight(t.a);
  w.w11 = weight(t.c);
  return w;
}

// Cosine at the light towards the reference (`wi` points at the light); ≤ 0 when the
// emitting side faces away.
float light_cosine(const TriangleLight& light, const Vec3f& wi) {
  const float c = -dot(light.normal, wi);
  return light.two_sided ? std::abs(c) : c;
}

}  // namespace

std::optional<TriangleLightSample> sample_triangle_light(const TriangleLight& light, TriangleLightSampling strategy,
                                                         const Vec3f& reference, const Vec3f& receiver_normal,
                                                         Vec2f u) {
  if (!(light.area > 0.0f)) return std::nullopt;
  const std::optional<SphericalTriangle> t = spherical_view(light, strategy, reference);
  if (!t) return sample_triangle_light_by_area(light, reference, u);
  // The emitting side is the same for the whole (planar) triangle: test it once.
  const Vec3d centroid = Vec3d(light.p0) + (Vec3d(light.e1) + Vec3d(light.e2)) * (1.0 / 3.0);
  if (light_cosine(light, Vec3f(normalize(centroid - Vec3d(reference)))) <= 0.0f) return std::nullopt;

  const BilinearWeights weights = receiver_cosine_weights(*t, strategy, receiver_normal);
  const Vec2d warped = sample_bilinear(Vec2d(u.x, u.y), weights);
  const Vec3d w = sample_spherical_triangle(*t, warped);
  // The point on the triangle along w (Möller and Trumbore 1997), for the shadow ray and uv.
  const Vec3d e1(light.e1), e2(light.e2), origin(reference);
  const Vec3d pvec = cross(w, e2);
  const double det = dot(e1, pvec);
  if (det == 0.0) return std::nullopt;
  const Vec3d tvec = origin - Vec3d(light.p0);
  const Vec3d qvec = cross(tvec, e1);
  double b1 = std::max(0.0, dot(tvec, pvec) / det), b2 = std::max(0.0, dot(w, qvec) / det);
  if (b1 + b2 > 1.0) {
    const double sum = b1 + b2;
    b1 /= sum;
    b2 /= sum;
  }
  TriangleLightSample s;
  s.barycentric = Vec2f(static_cast<float>(b1), static_cast<float>(b2));
  s.position = Vec3f(Vec3d(light.p0) + e1 * b1 + e2 * b2);
  s.wi = Vec3f(w);
  s.distance = static_cast<float>(length(Vec3d(s.position) - origin));
  if (!(s.distance > 0.0f) || light_cosine(light, s.wi) <= 0.0f) return std::nullopt;
  s.pdf_sr = static_cast<float>(bilinear_pdf(warped, weights) / t->solid_angle_sr);
  return s;
}

float triangle_light_pdf(const TriangleLight& light, TriangleLightSampling strategy, const Vec3f& reference,
                         const Vec3f& receiver_normal, const Vec3f& position) {
  if (!(light.area > 0.0f)) return 0.0f;
  const Vec3f d = position - reference;
  const float d2 = length_squared(d);
  if (!(d2 > 0.0f)) return 0.0f;
  const Vec3f wi = d / std::sqrt(d2);
  const float cos_light = light_cosine(light, wi);
  if (cos_light <= 0.0f) return 0.0f;
  const std::optional<SphericalTriangle> t = spherical_view(light, strategy, reference);
  if (!t) return d2 / (cos_light * light.area);
  const BilinearWeights weights = receiver_cosine_weights(*t, strategy, receiver_normal);
  const bool uniform = weights.w00 == weights.w01 && weights.w00 == weights.w11;  // w10 = w00 always
  if (uniform) return static_cast<float>(1.0 / t->solid_angle_sr);  // no need to invert Arvo's map
  const Vec3d w = normalize(Vec3d(position) - Vec3d(reference));
  const double p_square = bilinear_pdf(invert_spherical_triangle_sample(*t, w), weights);
  return static_cast<float>(p_square / t->solid_angle_sr);
}

}  // namespace prism
