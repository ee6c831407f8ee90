#pragma once
// Khronos PBR Neutral tone mapper (KhronosGroup/ToneMapping, PBR_Neutral/README.md, 2024):
// linear Rec.709 (≥ 0) → display-linear Rec.709 in [0, 1], relative to the display's white.
//
//   x = min(R, G, B);  f = x − x²/(4·F90) if x < 2·F90, else F90     (F90 = 0.04)
//   c = c_in − f;      p = max(c)
//   p < K_s (= 0.8 − F90): c_out = c
//   else: p_n = 1 − (1 − K_s)² / (p + 1 − 2·K_s)                      (new peak)
//         g = 1 − 1 / (K_d·(p − p_n) + 1)                             (K_d = 0.15)
//         c_out = (1 − g)·c·p_n/p + g·p_n                             (toward white)
//
// So base colours in [0.08, 0.8] come out exactly 0.04 darker (F90, the specular
// reflectance the tone mapper compensates), with no hue shift anywhere.
#include "prism/core/vec.h"

namespace prism::display {

inline constexpr double kPbrNeutralF90 = 0.04;
inline constexpr double kPbrNeutralStartCompression = 0.8 - kPbrNeutralF90;  // K_s
inline constexpr double kPbrNeutralDesaturation = 0.15;                        // K_d

// Negative and non-finite channels read as 0 (the specification's domain is ≥ 0).
Vec3d pbr_neutral(const Vec3d& rec709_linear);

}  // namespace prism::display
