#pragma once
// Floats in lanes: one value per path, for code that takes several paths through the same
// scalar steps at once (the wavefront integrator's plain diffuse hits,
// render/wavefront_plain_lanes.cpp). A lane's result is the scalar code's, bit for bit,
// where the operations come in the same order:
// - + − × ÷ and the square root are IEEE single precision and correctly rounded, in a lane
//   as in a scalar register (addps … sqrtps against addss … sqrtss);
// - there is no fused multiply-add (the build does not enable FMA, and GCC contracts
//   nothing it cannot emit);
// - min, max and the selects are the comparisons std::min, std::max and `c ? a : b` make,
//   not minps / maxps, which differ from them on signed zeros and NaNs.
// GCC's vector extensions (also Clang's): SSE2 on x86-64, plain loops elsewhere.
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism::lanes {

inline constexpr int kWidth = 4;
using Float = float __attribute__((vector_size(16)));
using Mask = std::int32_t __attribute__((vector_size(16)));  // a comparison's: all bits set where true

inline Float splat(float x) { return Float{x, x, x, x}; }
inline Mask splat_mask(std::int32_t x) { return Mask{x, x, x, x}; }
inline Mask all_lanes(bool on) { return splat_mask(on ? -1 : 0); }
inline Mask as_mask(Float f) { return reinterpret_cast<Mask>(f); }
inline Float as_float(Mask m) { return reinterpret_cast<Float>(m); }

// `m ? a : b`, lane by lane.
inline Float select(Mask m, Float a, Float b) { return as_float((m & as_mask(a)) | (~m & as_mask(b))); }
// std::max(a, b) = a < b ? b : a; std::min(a, b) = b < a ? b : a.
inline Float max(Float a, Float b) { return select(a < b, b, a); }
inline Float min(Float a, Float b) { return select(b < a, b, a); }
inline Float abs(Float x) { return as_float(as_mask(x) & splat_mask(0x7fffffff)); }
// std::copysign(1.0f, x).
inline Float copysign_one(Float x) {
  return as_float((as_mask(x) & splat_mask(std::int32_t(0x80000000u))) | splat_mask(0x3f800000));
}
inline Mask is_inf(Float x) { return abs(x) == splat(INFINITY); }

inline Float sqrt(Float x) {
#if defined(__SSE2__)
  return reinterpret_cast<Float>(_mm_sqrt_ps(reinterpret_cast<__m128>(x)));
#else
  for (int k = 0; k < kWidth; ++k) x[k] = std::sqrt(x[k]);
  return x;
#endif
}

// Vec3f in lanes, with vec.h's operations in vec.h's order.
struct Vec3 {
  Float x, y, z;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(const Vec3& a, Float s) { return {a.x * s, a.y * s, a.z * s}; }
inline Float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Float length(const Vec3& a) { return sqrt(dot(a, a)); }
inline Vec3 select(Mask m, const Vec3& a, const Vec3& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}

}  // namespace prism::lanes
