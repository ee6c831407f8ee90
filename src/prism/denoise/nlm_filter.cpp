#include "prism/denoise/nlm_filter.h"

#include <algorithm>
#include <bit>
#include <cstdint>

#include "prism/core/error.h"
#include "prism/core/parallel.h"

namespace prism::denoise {
namespace {

// Distances are clamped here, so that the weight never underflows: exp(−30) ≈ 9e-14 is
// negligible beside the centre pixel's weight of 1 even for a neighbour 10⁹ times brighter
// (a light beside a dark wall changes by 1e-4 of its value), and the weight loop has no
// branch, so it vectorises.
constexpr float kWeightCutoff = 30.0f;
// ε of the colour distance's denominator (Rousselle et al. 2012): keeps noise-free
// (zero-variance) pixel pairs finite and makes any difference between them decisive.
constexpr float kVarianceEpsilon = 1e-10f;
// Output rows per parallel task; fixed, so the split never depends on the thread count.
constexpr int kBandRows = 32;

// exp(−a) for 0 ≤ a ≤ kWeightCutoff, written without branches or library calls so that the
// weight loop vectorises: 2^(−n) from the exponent bits times a degree-6 Taylor polynomial
// of e^(−g), g ∈ [0, ln 2) (relative error below 1.6e-5, g⁷/7!), exactly 1 at a = 0.
inline float exp_negative(float a) {
  const float t = a * 1.44269504f;  // a / ln 2
  const int n = static_cast<int>(t);
  const float g = (t - static_cast<float>(n)) * 0.693147181f;
  const float p =
      1.0f - g * (1.0f - g * (0.5f - g * (1.0f / 6 - g * (1.0f / 24 - g * (1.0f / 120 - g * (1.0f / 720))))));
  return p * std::bit_cast<float>(static_cast<std::uint32_t>(127 - n) << 23);
}

// One channel with `pad` pixels of clamp-to-edge border on every side, so that patches
// around pixels near the border read defined values.
struct PaddedPlane {
  int stride = 0, pad = 0;
  std::vector<float> v;
  const float* row(int y) const { return v.data() + static_cast<std::size_t>(y + pad) * stride + pad; }
};

PaddedPlane pad_plane(const std::vector<float>& plane, int width, int height, int pad) {
  PaddedPlane p;
  p.stride = width + 2 * pad;
  p.pad = pad;
  p.v.resize(static_cast<std::size_t>(p.stride) * (height + 2 * pad));
  for (int y = -pad; y < height + pad; ++y) {
    const int sy = std::clamp(y, 0, height - 1);
    float* dst = p.v.data() + static_cast<std::size_t>(y + pad) * p.stride;
    for (int x = -pad; x < width + pad; ++x) dst[x + pad] = plane[static_cast<std::size_t>(sy) * width + std::clamp(x, 0, width - 1)];
  }
  return p;
}

// 1 / (k_f² max(τ, |∇f|²)) per pixel, with central differences (one-sided at the border).
std::vector<float> feature_inverse_scale(const NlmFeature& f, int width, int height, const NlmParameters& o) {
  std::vector<float> out(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, width - 1);
      const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, height - 1);
      float g2 = 0.0f;
      for (const auto& c : f.channels) {
        const float gx = (c[static_cast<std::size_t>(y) * width + x1] - c[static_cast<std::size_t>(y) * width + x0]) /
                         static_cast<float>(std::max(x1 - x0, 1));
        const float gy = (c[static_cast<std::size_t>(y1) * width + x] - c[static_cast<std::size_t>(y0) * width + x]) /
                         static_cast<float>(std::max(y1 - y0, 1));
        g2 += gx * gx + gy * gy;
      }
      const float k = o.feature_sensitivity;
      out[static_cast<std::size_t>(y) * width + x] = 1.0f / (k * k * std::max(o.feature_floor, g2));
    }
  return out;
}

struct Context {
  const NlmImage& image;
  const NlmParameters& o;
  std::array<PaddedPlane, 3> color, variance;
  std::vector<std::vector<float>> inverse_scale;  // per feature, per pixel
};

// Per-pixel colour distance (summed over channels, before the patch mean) for pixels
// x ∈ [x_begin, x_end) of row y and their partners at (dx, dy).
void color_distance_row(const Context& c, int y, int x_begin, int x_end, int dx, int dy, float* d) {
  const float alpha = c.o.variance_cancellation, k2 = c.o.color_sensitivity * c.o.color_sensitivity;
  const int n = x_end - x_begin;
  std::fill(d, d + n, 0.0f);
  for (int ch = 0; ch < 3; ++ch) {
    const float* up = c.color[ch].row(y) + x_begin;
    const float* uq = c.color[ch].row(y + dy) + x_begin + dx;
    const float* vp = c.variance[ch].row(y) + x_begin;
    const float* vq = c.variance[ch].row(y + dy) + x_begin + dx;
    for (int i = 0; i < n; ++i) {
      const float diff = up[i] - uq[i];
      const float num = diff * diff - alpha * (vp[i] + vq[i]);
      d[i] += num / (kVarianceEpsilon + k2 * (vp[i] + vq[i]));
    }
  }
}

struct BandAccumulator {
  std::vector<float> weight;
  std::array<std::vector<float>, 3> sum;
};

// Box sum over 2f + 1 consecutive values, each output summed in the same order (k outer so
// that the loop over i vectorises).
void box_sum_row(const float* __restrict in, std::size_t stride, int f, int n, float* __restrict out) {
  for (int i = 0; i < n; ++i) out[i] = in[i];
  for (int k = 1; k <= 2 * f; ++k) {
    const float* row = in + static_cast<std::size_t>(k) * stride;
    for (int i = 0; i < n; ++i) out[i] += row[i];
  }
}

// The feature term max_j Φ_j² for the pixels p0 … p0 + n − 1 of one row and their partners
// at q0 …: normal (3 channels), depth (1) and albedo (3) in one pass, so that the loop
// vectorises and nothing but Φ² is stored.
void feature_distance_row(const Context& c, std::size_t p0, std::size_t q0, int n, float* __restrict phi) {
  const auto& f = c.image.features;
  const float* __restrict n0 = f[0].channels[0].data();
  const float* __restrict n1 = f[0].channels[1].data();
  const float* __restrict n2 = f[0].channels[2].data();
  const float* __restrict z = f[1].channels[0].data();
  const float* __restrict a0 = f[2].channels[0].data();
  const float* __restrict a1 = f[2].channels[1].data();
  const float* __restrict a2 = f[2].channels[2].data();
  const float* __restrict sn = c.inverse_scale[0].data() + p0;
  const float* __restrict sz = c.inverse_scale[1].data() + p0;
  const float* __restrict sa = c.inverse_scale[2].data() + p0;
  const auto sq = [](float d) { return d * d; };
  for (int i = 0; i < n; ++i) {
    const std::size_t p = p0 + i, q = q0 + i;
    const float dn = (sq(n0[p] - n0[q]) + sq(n1[p] - n1[q]) + sq(n2[p] - n2[q])) * sn[i];
    const float dz = sq(z[p] - z[q]) * sz[i];
    const float da = (sq(a0[p] - a0[q]) + sq(a1[p] - a1[q]) + sq(a2[p] - a2[q])) * sa[i];
    phi[i] = std::max(std::max(dn, dz), da);
  }
}

struct Scratch {
  std::vector<float> dist, box_h, patch, phi;
};

// w = exp(−max(d_c², Φ²)) for one row of pixels, added with w·u(q) to the sums.
void add_weighted_row(int n, const float* __restrict patch, float patch_norm, const float* __restrict phi,
                      const float* __restrict u0, const float* __restrict u1, const float* __restrict u2,
                      float* __restrict weight, float* __restrict s0, float* __restrict s1, float* __restrict s2) {
  for (int i = 0; i < n; ++i) {
    const float d2 = std::max(patch[i] * patch_norm, 0.0f);
    const float wt = exp_negative(std::min(std::max(d2, phi[i]), kWeightCutoff));
    weight[i] += wt;
    s0[i] += wt * u0[i];
    s1[i] += wt * u1[i];
    s2[i] += wt * u2[i];
  }
}

// Adds the contributions of the partners at (dx, dy) to the output rows [y_begin, y_end)
// of the band starting at row band_y0.
void accumulate_offset(const Context& c, int band_y0, int y_begin, int y_end, int dx, int dy, BandAccumulator& acc,
                       Scratch& t) {
  const NlmImage& im = c.image;
  const int f = c.o.patch_radius, w = im.width;
  const int x_begin = std::max(0, -dx), x_end = std::min(w, w - dx), n = x_end - x_begin;
  const int dn = n + 2 * f, rows = y_end - y_begin + 2 * f;
  t.dist.resize(static_cast<std::size_t>(dn) * rows);
  t.box_h.resize(static_cast<std::size_t>(n) * rows);
  t.patch.resize(n);
  t.phi.resize(n);
  for (int r = 0; r < rows; ++r) {
    float* d = t.dist.data() + static_cast<std::size_t>(r) * dn;
    color_distance_row(c, y_begin - f + r, x_begin - f, x_end + f, dx, dy, d);
    box_sum_row(d, 1, f, n, t.box_h.data() + static_cast<std::size_t>(r) * n);
  }
  const float patch_norm = 1.0f / (3.0f * static_cast<float>((2 * f + 1) * (2 * f + 1)));
  for (int y = y_begin; y < y_end; ++y) {
    const std::size_t p0 = static_cast<std::size_t>(y) * w + x_begin, q0 = p0 + static_cast<std::ptrdiff_t>(dy) * w + dx;
    feature_distance_row(c, p0, q0, n, t.phi.data());
    box_sum_row(t.box_h.data() + static_cast<std::size_t>(y - y_begin) * n, n, f, n, t.patch.data());
    const std::size_t a0 = static_cast<std::size_t>(y - band_y0) * w + x_begin;
    add_weighted_row(n, t.patch.data(), patch_norm, t.phi.data(), im.color[0].data() + q0, im.color[1].data() + q0,
                     im.color[2].data() + q0, acc.weight.data() + a0, acc.sum[0].data() + a0, acc.sum[1].data() + a0,
                     acc.sum[2].data() + a0);
  }
}

}  // namespace

std::array<std::vector<float>, 3> nlm_feature_filter(const NlmImage& im, const NlmParameters& o) {
  const int w = im.width, h = im.height, r = o.search_radius, f = o.patch_radius;
  Context c{im, o, {}, {}, {}};
  for (int ch = 0; ch < 3; ++ch) {
    c.color[ch] = pad_plane(im.color[ch], w, h, r + f);
    c.variance[ch] = pad_plane(im.variance[ch], w, h, r + f);
  }
  if (im.features.size() != 3 || im.features[0].channels.size() != 3 || im.features[1].channels.size() != 1 ||
      im.features[2].channels.size() != 3)
    throw Error("nlm_feature_filter needs the features normal (3 channels), depth (1) and albedo (3)");
  for (const auto& feature : im.features) c.inverse_scale.push_back(feature_inverse_scale(feature, w, h, o));
  std::array<std::vector<float>, 3> out;
  for (auto& plane : out) plane.resize(static_cast<std::size_t>(w) * h);
  const std::size_t bands = static_cast<std::size_t>((h + kBandRows - 1) / kBandRows);
  parallel_for(bands, 1, [&](std::size_t begin, std::size_t end) {
    Scratch scratch;
    for (std::size_t b = begin; b < end; ++b) {
      const int y0 = static_cast<int>(b) * kBandRows, y1 = std::min(h, y0 + kBandRows);
      BandAccumulator acc;
      acc.weight.assign(static_cast<std::size_t>(y1 - y0) * w, 0.0f);
      for (auto& s : acc.sum) s.assign(acc.weight.size(), 0.0f);
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int ya = std::max(y0, -dy), yb = std::min(y1, h - dy);
          if (ya >= yb || std::abs(dx) >= w) continue;
          accumulate_offset(c, y0, ya, yb, dx, dy, acc, scratch);
        }
      for (std::size_t i = 0; i < acc.weight.size(); ++i)
        for (int ch = 0; ch < 3; ++ch)
          out[ch][static_cast<std::size_t>(y0) * w + i] = acc.sum[ch][i] / acc.weight[i];
    }
  });
  return out;
}

}  // namespace prism::denoise
