#include "prism/display/aces_output_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>

#include "prism/display/aces_common.h"
#include "prism/display/aces_rrt.h"

namespace prism::display {
namespace {

using Block3 = float[3][AcesOutputKernel::kBlock];

// Table resolution. Linear interpolation in x over a segment of relative width 2^-k errs by
// ≤ |p(p − 1)|/8 · 2^-2k of the value for a local log–log slope p. The tone curves need
// 2^9 segments per octave: their output passes the display matrices, where a saturated
// colour's small channel is the difference of large AP1 values (×~1000 for bright cyan on
// an sRGB display), so 1e-6 of relative error there shows (measured by the kernel test:
// 5e-5 of code at 2^7, 4e-6 at 2^9). The encodings are applied last, to the light itself:
// 2^8 keeps them below 1e-6 of code.
constexpr int kToneSegmentsPerOctaveLog2 = 9;
constexpr int kEncodeSegmentsPerOctaveLog2 = 8;

// Tone curves: below HALF_MIN = 2^-24 the CTL floors the input (C5 and SSTS), so the table
// starts there; the RRT clamps AP1 to HALF_MAX < 2^16. The table holds the square root of
// the normalised curve: the curve leaves its black floor (0) with zero log–log slope, as
// a·(x − x_floor)², where a chord of the curve itself would err by a·h²/4 — nothing in
// absolute terms, but BT.1886's and PQ's roots near black turn 1e-9 of light into 3e-4 of
// code. Its square root rises linearly from the floor's end, where anchor_zero puts a knot.
const Log2SpacedTable& sqrt_tone_table(const AcesOutputTransform& exact) {
  static std::array<std::once_flag, 16> once;
  static std::array<std::unique_ptr<Log2SpacedTable>, 16> tables;
  const auto id = static_cast<std::size_t>(exact.description().id);
  std::call_once(once[id], [&] {
    const AcesOutputTransform t(exact.description().id);  // the curve does not depend on stretch_black
    tables[id] = std::make_unique<Log2SpacedTable>(
        [&](double x) { return std::sqrt(std::max(t.normalized_tone_curve(x), 0.0)); }, -24, 16,
        kToneSegmentsPerOctaveLog2);
    tables[id]->anchor_zero(t.normalized_tone_curve_floor_end());
  });
  return *tables[id];
}

// Dim surround: Y ≤ 1 (display white) in practice, tabulated up to the CTL's clamp at
// HALF_MAX < 2^16; below 2^-60 the linear tail toward f(0) = 0 only touches pixels darker
// than any code value resolves.
// Y^0.9811 is almost linear in log–log, so 16 segments per octave are plenty (≤ 1e-7).
const Log2SpacedTable& dim_table() {
  static const Log2SpacedTable t([](double y) { return dim_surround_luminance(y); }, -60, 16, 4);
  return t;
}

// Encodings, sampled from encode_display_nits itself. Relative encodings are tabulated on
// nits / white in [0, 1] (2^-60: BT.1886's γ-2.4 root is 3e-8 there, so the linear tail to
// 0 costs nothing; sRGB is linear there anyway); ST 2084 on nits in [0, 10000] (at 2^-40 nit
// the PQ code is within 1e-6 of its value at 0).
const Log2SpacedTable* encode_table(DisplayEncoding e) {
  static std::array<std::once_flag, 8> once;  // one per DisplayEncoding (6 today)
  static std::array<std::unique_ptr<Log2SpacedTable>, 8> tables;
  if (e == DisplayEncoding::scrgb) return nullptr;  // linear
  const auto id = static_cast<std::size_t>(e);
  std::call_once(once[id], [&] {
    // With white = 1 the relative encodings take nits / white; PQ ignores white.
    const auto encode = [e](double x) { return encode_display_nits(e, x, 1.0); };
    const bool pq = e == DisplayEncoding::pq;
    tables[id] = std::make_unique<Log2SpacedTable>(encode, pq ? -40 : -60, pq ? 14 : 0, kEncodeSegmentsPerOctaveLog2);
  });
  return tables[id].get();
}

void to_float(const Mat3& m, float (&out)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = static_cast<float>(m.m[i][j]);
}

bool is_identity(const Mat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (m.m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

// out = m · in over a whole SoA block (in and out may alias: each pixel is read first).
void apply(const float (&m)[3][3], Block3& v) {
  for (std::size_t i = 0; i < AcesOutputKernel::kBlock; ++i) {
    const float r = v[0][i], g = v[1][i], b = v[2][i];
    v[0][i] = m[0][0] * r + m[0][1] * g + m[0][2] * b;
    v[1][i] = m[1][0] * r + m[1][1] * g + m[1][2] * b;
    v[2][i] = m[2][0] * r + m[2][1] * g + m[2][2] * b;
  }
}

// The red modifier's hue weight (RRT_Common.ctl: cubic_basis_shaper(center_hue(rgb_2_hue(aces),
// RRT_RED_HUE), RRT_RED_WIDTH)) with atan2 by a polynomial. The hue is atan2(√3(g − b),
// 2r − g − b); the angle is reduced to [0, π/4] by symmetry and then to |z| ≤ tan(π/12) with
// atan z = π/6 + atan((√3 z − 1)/(z + √3)), where atan's Taylor series to z⁹ errs by
// ≤ |z|¹¹/11 < 5e-8 rad. The B-spline bump is written by distance u from its centre in
// knots: 1.5·(3u³ − 6u² + 4)/6 for u < 1, 1.5·(2 − u)³/6 for u < 2 (the same four pieces).
float red_hue_weight(float r, float g, float b) {
  constexpr float kSqrt3 = std::numbers::sqrt3_v<float>;
  constexpr float kTanPi12 = 2.0f - std::numbers::sqrt3_v<float>;
  constexpr float kPi = std::numbers::pi_v<float>;
  const float x = 2.0f * r - g - b, y = kSqrt3 * (g - b);
  const float ax = std::fabs(x), ay = std::fabs(y);
  const float hi = std::max(ax, ay), lo = std::min(ax, ay);
  // Both sides of every select are computed, so the loop stays branch-free (vectorised).
  const float z = lo / std::max(hi, std::numeric_limits<float>::min());  // hi = 0: 0
  const bool reduced = z > kTanPi12;
  const float z_reduced = (kSqrt3 * z - 1.0f) / (z + kSqrt3);
  const float zr = reduced ? z_reduced : z;
  const float z2 = zr * zr;
  float a = zr * (1.0f + z2 * (-1.0f / 3.0f + z2 * (1.0f / 5.0f + z2 * (-1.0f / 7.0f + z2 * (1.0f / 9.0f)))));
  a = reduced ? a + kPi / 6.0f : a;
  a = ay > ax ? kPi / 2.0f - a : a;
  a = x < 0.0f ? kPi - a : a;
  a = y < 0.0f ? -a : a;
  const float hue_deg = a * (180.0f / kPi) - static_cast<float>(rrt::kRedHueDegrees);
  const float u = std::fabs(hue_deg) * (4.0f / static_cast<float>(rrt::kRedWidthDegrees));
  const float near = (u * u * (3.0f * u - 6.0f) + 4.0f) / 6.0f, far = (2.0f - u) * (2.0f - u) * (2.0f - u) / 6.0f;
  const float w = u < 1.0f ? near : (u < 2.0f ? far : 0.0f);
  return hi > 0.0f ? 1.5f * w : 0.0f;  // achromatic: the CTL's NaN hue, weight 0
}

}  // namespace

struct AcesOutputKernel::Block {
  alignas(64) Block3 v;   // the pixels, SoA
  alignas(64) float peak[kBlock];
  std::uint8_t exact[kBlock];
};

AcesOutputKernel::AcesOutputKernel(const AcesOutputTransform& exact, const AcesKernelSettings& s)
    : exact_(&exact), odt_(&exact.description()), s_(s) {
  const AcesMatrices& m = aces_matrices();
  to_float(s.film_to_aces, film_to_aces_);
  to_float(m.ap0_to_ap1 * s.film_to_aces, film_to_ap1_);
  to_float(m.ap0_to_ap1, ap0_to_ap1_);
  to_float(saturation_matrix(rrt::kSatFactor, m.ap1_luminance), rrt_desat_);
  to_float(sdr_odt_desaturation(), odt_desat_);
  for (int c = 0; c < 3; ++c) ap1_luminance_[c] = static_cast<float>(m.ap1_luminance[c]);
  if (odt_->id == OdtId::none) {
    to_float(exact.ap1_to_display(), to_display_);
  } else if (odt_->hdr) {
    to_float(exact.limit_xyz_to_rgb() * m.ap1_to_xyz, to_display_);
    to_float(exact.xyz_to_display() * m.d60_to_d65 * exact.limit_rgb_to_xyz(), limit_to_display_);
  } else {
    to_float(exact.xyz_to_display() * m.d60_to_d65 * m.ap1_to_xyz, to_display_);
  }
  to_float(s.display_to_output, display_to_output_);
  has_output_matrix_ = !is_identity(s.display_to_output);
  sqrt_tone_ = odt_->id == OdtId::none ? nullptr : &sqrt_tone_table(exact);
  dim_ = odt_->id == OdtId::none || odt_->hdr ? nullptr : &dim_table();
  encode_ = encode_table(s.encoding);
}

void AcesOutputKernel::normalized_ap1(const float* film_rgb, float* cv_ap1, std::size_t pixels) const {
  for (std::size_t i = 0; i < pixels; i += kBlock)
    normalized_block(film_rgb + 3 * i, cv_ap1 + 3 * i, std::min(kBlock, pixels - i));
}

void AcesOutputKernel::display(const float* cv_ap1, const float* peak_nits, float* nits, float* code,
                               std::size_t pixels) const {
  for (std::size_t i = 0; i < pixels; i += kBlock)
    display_block(cv_ap1 + 3 * i, peak_nits ? peak_nits + i : nullptr, nits + 3 * i, code + 3 * i,
                  std::min(kBlock, pixels - i));
}

// RRT_Common.ctl rrt_sweeteners on a block of ACES2065-1 pixels, in place, to AP1 rendering
// space; marks pixels outside float's comfortable range for the reference path.
void AcesOutputKernel::sweeteners(Block& b) const {
  constexpr float kGlowGain = static_cast<float>(rrt::kGlowGain), kGlowMid = static_cast<float>(rrt::kGlowMid);
  constexpr float kRedPivot = static_cast<float>(rrt::kRedPivot);
  constexpr float kRedScale = static_cast<float>(rrt::kRedScale);
  constexpr float kRangeLimit = 0x1p40f;  // yc's products stay ≤ 2^81, far from float's 2^128
  for (std::size_t i = 0; i < kBlock; ++i) {
    float r = b.v[0][i], g = b.v[1][i], bl = b.v[2][i];
    const float hi = std::max(r, std::max(g, bl)), lo = std::min(r, std::min(g, bl));
    b.exact[i] = !(std::max(hi, -lo) <= kRangeLimit);  // also catches Inf/NaN from the matrix
    // rgb_2_saturation (TINY = 1e-10, max floored at 1e-2) and sigmoid_shaper((sat − 0.4)/0.2).
    const float sat = (std::max(hi, 1e-10f) - std::max(lo, 1e-10f)) / std::max(hi, 1e-2f);
    const float sx = (sat - 0.4f) / 0.2f;
    const float st = std::max(1.0f - std::fabs(sx) * 0.5f, 0.0f);
    const float sign = sx > 0.0f ? 1.0f : (sx < 0.0f ? -1.0f : 0.0f);
    const float s = (1.0f + sign * (1.0f - st * st)) * 0.5f;
    // rgb_2_yc (radius weight 1.75) and glow_fwd.
    const float chroma = std::sqrt(std::max(0.0f, bl * (bl - g) + g * (g - r) + r * (r - bl)));
    const float yc = (bl + g + r + 1.75f * chroma) / 3.0f;
    const float gain = kGlowGain * s;
    const float fade = gain * (kGlowMid / std::max(yc, 1e-30f) - 0.5f);
    const float glow = yc <= 2.0f / 3.0f * kGlowMid ? gain : (yc >= 2.0f * kGlowMid ? 0.0f : fade);
    r *= 1.0f + glow;
    g *= 1.0f + glow;
    bl *= 1.0f + glow;
    // Red modifier with the saturation measured before the glow (CTL order).
    r += red_hue_weight(r, g, bl) * sat * (kRedPivot - r) * (1.0f - kRedScale);
    b.v[0][i] = std::max(r, 0.0f);
    b.v[1][i] = std::max(g, 0.0f);
    b.v[2][i] = std::max(bl, 0.0f);
  }
  // RRT.ctl: AP0 → AP1, clamp to [0, HALF_MAX], global desaturation RRT_SAT_FACTOR 0.96.
  apply(ap0_to_ap1_, b.v);
  constexpr float kHalfMaxF = static_cast<float>(kHalfMax);
  for (auto& channel : b.v)
    for (float& v : channel) v = std::min(std::max(v, 0.0f), kHalfMaxF);
  apply(rrt_desat_, b.v);
}

void AcesOutputKernel::normalized_block(const float* film_rgb, float* cv_ap1, std::size_t n) const {
  Block b;
  for (std::size_t i = 0; i < kBlock; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = i < n ? film_rgb[3 * i + c] : 0.0f;
      // NaN/Inf samples show as black, not as noise (exponent bits all set: not finite).
      b.v[c][i] = (std::bit_cast<std::uint32_t>(v) & 0x7f800000u) == 0x7f800000u ? 0.0f : v;
    }
  if (odt_->id == OdtId::none) {
    apply(film_to_ap1_, b.v);
    // Beyond float's range (|film| near FLT_MAX): the reference, in double, like the rest.
    for (std::size_t i = 0; i < kBlock; ++i)
      b.exact[i] = !(std::max({std::fabs(b.v[0][i]), std::fabs(b.v[1][i]), std::fabs(b.v[2][i])}) <=
                     std::numeric_limits<float>::max());
  } else {
    apply(film_to_aces_, b.v);
    sweeteners(b);
    // Per AP1 channel: SDR segmented_spline_c5_fwd then, after the RRT's AP1 → AP0 and the
    // ODT's AP0 → AP1 (inverse matrices, folded away), segmented_spline_c9_fwd
    // (ACESlib.Tonescales.ctl) and Y_2_linCV(48, 0.02); HDR ssts (ACESlib.SSTS.ctl) and
    // Y_2_linCV(Y_MAX, Y_MIN) (ACESlib.OutputTransforms.ctl).
    for (auto& channel : b.v)
      for (float& v : channel) {
        const float root = std::max((*sqrt_tone_)(v), 0.0f);
        v = root * root;
      }
    if (dim_) {
      // darkSurround_to_dimSurround as a scale by Y^0.9811 / Y (xy kept), then desaturation.
      for (std::size_t i = 0; i < kBlock; ++i) {
        const float y = ap1_luminance_[0] * b.v[0][i] + ap1_luminance_[1] * b.v[1][i] + ap1_luminance_[2] * b.v[2][i];
        const float scale = y > 0.0f ? (*dim_)(y) / y : 0.0f;
        for (int c = 0; c < 3; ++c) b.v[c][i] *= scale;
      }
      apply(odt_desat_, b.v);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) cv_ap1[3 * i + c] = b.v[c][i];
  // Out-of-range pixels: the reference, from the film value exactly as the pipeline reads it.
  for (std::size_t i = 0; i < n; ++i) {
    if (!b.exact[i]) continue;
    Vec3d rgb;
    for (int c = 0; c < 3; ++c) rgb[c] = std::isfinite(film_rgb[3 * i + c]) ? film_rgb[3 * i + c] : 0.0;
    const Vec3d v = exact_->normalized_ap1(s_.film_to_aces * rgb);
    for (int c = 0; c < 3; ++c) cv_ap1[3 * i + c] = static_cast<float>(v[c]);
  }
}

// AcesOutputTransform::display_nits_from_normalized, then the pipeline's output matrix and
// clamp, then encode_display_nits. SDR (ODT.Academy.*_100nits_dim.ctl): AP1 → XYZ →
// Bradford D60 → D65 → display RGB as one matrix, clamp [0, 1], × peak. HDR
// (ACESlib.OutputTransforms.ctl): limit_to_primaries (AP1 → XYZ → limiting RGB, clamp), then
// limiting RGB → XYZ → Bradford → display RGB as one matrix, clamp ≥ 0, linCV_2_Y.
void AcesOutputKernel::display_block(const float* cv_ap1, const float* peak_nits, float* nits, float* code,
                                     std::size_t n) const {
  Block b;
  const float white = static_cast<float>(odt_->white_nits);
  for (std::size_t i = 0; i < kBlock; ++i) {
    for (int c = 0; c < 3; ++c) b.v[c][i] = i < n ? cv_ap1[3 * i + c] : 0.0f;
    b.peak[i] = peak_nits && i < n ? peak_nits[i] : white;
  }
  apply(to_display_, b.v);
  if (odt_->id == OdtId::none) {
    for (auto& channel : b.v)
      for (std::size_t i = 0; i < kBlock; ++i) channel[i] *= b.peak[i];
  } else if (!odt_->hdr) {
    for (auto& channel : b.v)
      for (std::size_t i = 0; i < kBlock; ++i)
        channel[i] = std::min(std::max(channel[i], 0.0f), white / b.peak[i]) * b.peak[i];
  } else {
    for (auto& channel : b.v)
      for (std::size_t i = 0; i < kBlock; ++i) channel[i] = std::min(std::max(channel[i], 0.0f), white / b.peak[i]);
    apply(limit_to_display_, b.v);
    const float y_min = exact_->stretch_black() ? 0.0f : static_cast<float>(odt_->y_min_nits);
    for (auto& channel : b.v)
      for (std::size_t i = 0; i < kBlock; ++i) channel[i] = std::max(channel[i], 0.0f) * (b.peak[i] - y_min) + y_min;
  }
  if (has_output_matrix_) apply(display_to_output_, b.v);
  if (s_.clamp_output) {
    const float hi = static_cast<float>(s_.clamp_nits);
    for (auto& channel : b.v)
      for (float& v : channel) v = std::min(std::max(v, 0.0f), hi);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) nits[3 * i + c] = b.v[c][i];
  if (!encode_) {
    const float scale = static_cast<float>(encode_display_nits(s_.encoding, 1.0, s_.white_nits));  // linear
    for (auto& channel : b.v)
      for (float& v : channel) v *= scale;
  } else {
    const float to_input = s_.encoding == DisplayEncoding::pq ? 1.0f : static_cast<float>(1.0 / s_.white_nits);
    for (auto& channel : b.v)
      for (float& v : channel) v = (*encode_)(v * to_input);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) code[3 * i + c] = b.v[c][i];
}

}  // namespace prism::display
