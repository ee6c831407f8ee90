#pragma once
// The display pipeline's per-pixel ACES work (film → ACES2065-1 → RRT + ODT → display light →
// encoding) on blocks of pixels in single precision: the fast path of apply_display_pipeline.
// AcesOutputTransform (double, per pixel, the CTL step by step) stays the reference; the
// test tests/display/aces_output_kernel_test.cpp bounds this kernel's code-value error
// against it. What differs from the reference, and why it is allowed:
//  - float instead of double: every stage is a 3×3 product, a clamp or a ratio, and ACES
//    values stay within [0, HALF_MAX] after the RRT's clamp; float keeps ~1e-7 relative
//    error, far below the 1e-4 code-value budget. Pixels whose film→ACES value leaves
//    |v| ≤ 2^40 (where the sweeteners' squares could overflow a float) take the reference.
//  - consecutive 3×3 products folded once per image (the film→ACES matrix with exposure; the
//    SDR ODT's AP1 → XYZ → D65 → display chain; the HDR limit-to-primaries pair; the RRT's
//    AP1 → AP0 and the ODT's AP0 → AP1, which cancel).
//  - the per-channel tone curves (C5 then C9 for SDR, SSTS for HDR; as their square root,
//    see aces_output_kernel.cpp) and the encodings (sRGB, BT.1886, ST 2084) tabulated in
//    Log2SpacedTable, sampled from the reference.
//  - the SDR dim-surround step (ODT_Common.ctl darkSurround_to_dimSurround: XYZ → xyY, Y^γ,
//    back) written as the equivalent scaling of the AP1 pixel by Y^γ / Y (it keeps x, y).
//  - the RRT red modifier's hue angle by a polynomial arctangent (≤ 1e-7 rad).
#include <cstddef>

#include "prism/core/mat3.h"
#include "prism/display/aces_output_transform.h"
#include "prism/display/display_encoding.h"
#include "prism/display/log2_spaced_table.h"

namespace prism::display {

struct AcesKernelSettings {
  Mat3 film_to_aces = Mat3::identity();        // exposure and LMT folded in
  Mat3 display_to_output = Mat3::identity();   // gamut remap / scRGB primaries
  bool clamp_output = false;                   // remap: clamp output light to [0, clamp_nits]
  double clamp_nits = 0.0;
  DisplayEncoding encoding = DisplayEncoding::srgb;
  double white_nits = 100.0;                   // light of code 1 for relative encodings
};

class AcesOutputKernel {
 public:
  static constexpr std::size_t kBlock = 128;  // pixels per SoA block (fits L1 with the tables)

  // `exact` must outlive the kernel (its ODT, and the reference for out-of-range pixels).
  AcesOutputKernel(const AcesOutputTransform& exact, const AcesKernelSettings& settings);

  // Film RGB (3 floats per pixel; NaN/Inf read as 0, as the pipeline always did) → the ODT's
  // normalised AP1 code (AcesOutputTransform::normalized_ap1), 3 floats per pixel.
  void normalized_ap1(const float* film_rgb, float* cv_ap1, std::size_t pixels) const;

  // Normalised AP1 code → display light in the output primaries (nits) and code values, 3
  // floats per pixel each. peak_nits: one per pixel (an overlay's), or null for the ODT's.
  void display(const float* cv_ap1, const float* peak_nits, float* nits, float* code, std::size_t pixels) const;

 private:
  struct Block;
  void sweeteners(Block& b) const;
  void normalized_block(const float* film_rgb, float* cv_ap1, std::size_t pixels) const;
  void display_block(const float* cv_ap1, const float* peak_nits, float* nits, float* code, std::size_t pixels) const;

  const AcesOutputTransform* exact_;
  const OdtDescription* odt_;
  AcesKernelSettings s_;
  float film_to_aces_[3][3];
  float film_to_ap1_[3][3];       // none: film → AP1 in one product
  float ap0_to_ap1_[3][3];
  float rrt_desat_[3][3];
  float odt_desat_[3][3];
  float ap1_luminance_[3];
  float to_display_[3][3];        // SDR: AP1 → display; HDR: AP1 → limiting primaries; none: AP1 → display
  float limit_to_display_[3][3];  // HDR: limiting primaries → XYZ → D65 → display
  float display_to_output_[3][3];
  bool has_output_matrix_;
  const Log2SpacedTable* sqrt_tone_;  // √normalized_tone_curve
  const Log2SpacedTable* dim_;        // dim_surround_luminance
  const Log2SpacedTable* encode_;     // encode_display_nits, relative encodings on nits / white
};

}  // namespace prism::display
