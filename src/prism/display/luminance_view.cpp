#include "prism/display/luminance_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace prism::display {
namespace {

struct Stop {
  double t;
  Vec3d srgb;
};
constexpr std::array<Stop, 6> kRamp{{{0.0, {0.05, 0.0, 0.35}},
                                     {0.2, {0.0, 0.35, 1.0}},
                                     {0.4, {0.0, 0.85, 0.45}},
                                     {0.6, {1.0, 0.9, 0.0}},
                                     {0.8, {1.0, 0.15, 0.0}},
                                     {1.0, {1.0, 1.0, 1.0}}}};

Vec3d ramp(double t) {
  t = std::clamp(t, 0.0, 1.0);
  for (std::size_t i = 1; i < kRamp.size(); ++i)
    if (t <= kRamp[i].t) {
      const double u = (t - kRamp[i - 1].t) / (kRamp[i].t - kRamp[i - 1].t);
      return kRamp[i - 1].srgb * (1.0 - u) + kRamp[i].srgb * u;
    }
  return kRamp.back().srgb;
}

constexpr int kLegendScale = 2;
constexpr int kLegendHeightPx = 8 + 4 + kGlyphHeightPx * kLegendScale + 6;

}  // namespace

LuminanceScale luminance_scale_for(const std::vector<float>& y) {
  std::vector<float> positive;
  for (float v : y)
    if (v > 0.0f && std::isfinite(v)) positive.push_back(v);
  if (positive.empty()) return {-2, 2};
  const std::size_t p1 = positive.size() / 100;
  std::nth_element(positive.begin(), positive.begin() + static_cast<std::ptrdiff_t>(p1), positive.end());
  const float lo = positive[p1];
  const float hi = *std::max_element(positive.begin(), positive.end());
  int a = static_cast<int>(std::floor(std::log10(lo))), b = static_cast<int>(std::ceil(std::log10(hi)));
  if (b - a < 2) b = a + 2;
  if (b - a > 8) a = b - 8;
  return {a, b};
}

Vec3d false_colour(double y, const LuminanceScale& s) {
  if (!(y > 0.0)) return {0, 0, 0};
  const double t = (std::log10(y) - s.min_decade) / (s.max_decade - s.min_decade);
  if (t < 0.0) return {0, 0, 0};
  if (t > 1.0) return {1, 1, 1};
  // One band per decade: quantise to the band's centre so decades read as distinct colours,
  // with a gentle ramp inside the band to keep gradients visible.
  const int decades = s.max_decade - s.min_decade;
  const double band = std::min(std::floor(t * decades), decades - 1.0);
  const double inside = t * decades - band;
  return ramp((band + 0.25 + 0.5 * inside) / decades);
}

std::string decade_label(int d) {
  // Built by appending: GCC 12 warns falsely on string operator+ here (-Wrestrict, bug 105329).
  std::string label;
  if (d >= 0 && d <= 4) {
    label.push_back('1');
    label.append(static_cast<std::size_t>(d), '0');
  } else if (d < 0 && d >= -3) {
    label.append("0.");
    label.append(static_cast<std::size_t>(-d - 1), '0');
    label.push_back('1');
  } else {
    label.append("1E");
    label.append(std::to_string(d));
  }
  return label;
}

Canvas luminance_false_colour_view(const std::vector<float>& y, int width, int height, const LuminanceScale& s) {
  Canvas canvas(width, height + kLegendHeightPx, {0.08, 0.08, 0.08});
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) canvas.set(px, py, false_colour(y[std::size_t(py) * width + px], s));
  // Legend: the colour bar across the width (less margins), a tick per decade, labels.
  const int margin = 12, bar_top = height + 4, bar_bottom = bar_top + 8;
  const int x0 = margin, x1 = std::max(margin + 1, width - margin - text_width_px("NIT", kLegendScale) - text_width_px("1E-4", kLegendScale) / 2 - 10);
  const int decades = s.max_decade - s.min_decade;
  for (int px = x0; px < x1; ++px) {
    const double t = (px - x0 + 0.5) / (x1 - x0);
    canvas.fill_rect(px, bar_top, px + 1, bar_bottom, false_colour(std::pow(10.0, s.min_decade + t * decades), s));
  }
  int last_label_end = -1000;
  for (int d = 0; d <= decades; ++d) {
    const int tx = x0 + static_cast<int>(std::lround(double(d) / decades * (x1 - x0 - 1)));
    canvas.fill_rect(tx, bar_top - 2, tx + 1, bar_bottom + 2, {1, 1, 1});
    const std::string label = decade_label(s.min_decade + d);
    const int lw = text_width_px(label, kLegendScale);
    const int lx = std::clamp(tx - lw / 2, 0, width - lw);
    if (lx > last_label_end + 4) last_label_end = lx + canvas.draw_text(lx, bar_bottom + 4, label, {1, 1, 1}, kLegendScale);
  }
  canvas.draw_text(width - margin - text_width_px("NIT", kLegendScale), bar_bottom + 4, "NIT", {1, 1, 1}, kLegendScale);
  return canvas;
}

}  // namespace prism::display
