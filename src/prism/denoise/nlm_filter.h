#pragma once
// Non-local means with feature buffers: the filter of Rousselle, Manzi and Zwicker, "Robust
// Denoising using Feature and Color Information", Pacific Graphics 2013 (and its colour
// term from Rousselle, Knaus and Zwicker, "Adaptive Rendering with Non-Local Means
// Filtering", SIGGRAPH Asia 2012). The output pixel p is the weighted mean of the colours
// u(q) of the pixels q in a (2r+1)² search window, with weight
//   w(p, q) = min(w_c, w_f) = exp(−max(d_c², Φ²))
// Colour (patch) distance, over the (2f+1)² patches around p and q and the 3 channels i:
//   d_c² = max(0, mean over patch and channels of
//          [(u_i(p) − u_i(q))² − α (V_i(p) + V_i(q))] / [ε + k_c² (V_i(p) + V_i(q))])
// with V the variance of the pixel means: the numerator subtracts the expected squared
// difference that noise alone gives, E[(u(p) − u(q))²] = (μ(p) − μ(q))² + V(p) + V(q)
// (α = 1 removes it), the denominator measures distances in units of the noise. Rousselle
// et al. subtract V(p) + min(V(p), V(q)) instead; that asymmetry lets bright, noisier
// pixels take in darker neighbours more readily than the reverse, and lowered the mean of
// a noisy image whose noise grows with its value by 1.7 % (the symmetric form: +0.3 %). Feature distance, pixel to pixel, the largest over features j:
//   Φ_j² = |f_j(p) − f_j(q)|² / (k_f² max(τ, |∇f_j(p)|²))
// (the paper's feature-variance terms vanish here: the features are nearly noise-free pixel
// means of first-hit quantities). Normalising by the feature's own gradient keeps smoothly
// varying features (depth along a receding wall) from isolating every pixel, while a
// discontinuity (a silhouette, a crease) is many gradients away from the far side.
//
// Work is split into bands of rows; every output pixel sums its window in one fixed order
// of offsets, so the result is bitwise the same for any thread count.
#include <array>
#include <vector>

namespace prism::denoise {

struct NlmParameters {
  // Defaults chosen by measurement on rendered scenes (docs/denoising.md, "Choices").
  int search_radius = 5;                // r: window (2r+1)²
  int patch_radius = 1;                 // f: patch (2f+1)²
  float color_sensitivity = 0.45f;      // k_c (Rousselle et al. 2013, §5)
  float variance_cancellation = 1.0f;   // α
  float feature_sensitivity = 0.6f;     // k_f (Rousselle et al. 2013, §5)
  float feature_floor = 1e-3f;          // τ, in squared feature units
};

// A guide image with `channels` planar channels (width × height each).
struct NlmFeature {
  std::vector<std::vector<float>> channels;
};

struct NlmImage {
  int width = 0, height = 0;
  std::array<std::vector<float>, 3> color;     // planar
  std::array<std::vector<float>, 3> variance;  // planar, of the pixel means
  std::vector<NlmFeature> features;  // exactly: normal (3 channels), depth (1), albedo (3)
};

// The filtered colour, planar. Requires consistent sizes (the caller checks); throws Error
// for another set of features.
std::array<std::vector<float>, 3> nlm_feature_filter(const NlmImage& image, const NlmParameters& parameters);

}  // namespace prism::denoise
