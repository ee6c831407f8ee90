#include "prism/display/chromaticity_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "prism/display/spectral_locus.h"

namespace prism::display {
namespace {

constexpr double kMaxX = 0.8, kMaxY = 0.9;
constexpr int kMarginPx = 28;  // left and bottom, for tick labels
constexpr int kTopPx = 8;
constexpr int kScale = 2;      // font scale

void draw_triangle(Canvas& c, const color::ColorSpace& s, int size, Vec3d colour) {
  const color::Chromaticity p[3] = {s.red, s.green, s.blue};
  for (int i = 0; i < 3; ++i) {
    const Vec3d a = chromaticity_to_canvas(p[i].x, p[i].y, size), b = chromaticity_to_canvas(p[(i + 1) % 3].x, p[(i + 1) % 3].y, size);
    c.draw_line(a.x, a.y, b.x, b.y, colour);
  }
}

}  // namespace

Vec3d chromaticity_to_canvas(double x, double y, int size) {
  const double h = size * kMaxY / kMaxX;
  return {kMarginPx + x / kMaxX * size, kTopPx + h - y / kMaxY * h, 0.0};
}

Canvas chromaticity_diagram(const ImageRgbF& film, const color::ColorSpace& film_space,
                            const color::ColorSpace& display_space, int size) {
  const int plot_h = static_cast<int>(std::lround(size * kMaxY / kMaxX));
  Canvas c(kMarginPx + size + 8, kTopPx + plot_h + kMarginPx, {0.06, 0.06, 0.07});
  // Grid and ticks every 0.1.
  for (int i = 0; i <= 9; ++i) {
    const double v = i / 10.0;
    char label[8];
    std::snprintf(label, sizeof label, "%.1f", v);
    if (v <= kMaxX + 1e-9) {
      const Vec3d a = chromaticity_to_canvas(v, 0, size), b = chromaticity_to_canvas(v, kMaxY, size);
      c.draw_line(a.x, a.y, b.x, b.y, {0.16, 0.16, 0.18});
      c.fill_rect(int(a.x), int(a.y), int(a.x) + 1, int(a.y) + 5, {0.8, 0.8, 0.8});
      c.draw_text(int(a.x) - text_width_px(label, kScale) / 2, int(a.y) + 7, label, {0.8, 0.8, 0.8}, kScale);
    }
    const Vec3d a = chromaticity_to_canvas(0, v, size), b = chromaticity_to_canvas(kMaxX, v, size);
    c.draw_line(a.x, a.y, b.x, b.y, {0.16, 0.16, 0.18});
    c.fill_rect(int(a.x) - 5, int(a.y), int(a.x), int(a.y) + 1, {0.8, 0.8, 0.8});
    if (i > 0) c.draw_text(1, int(a.y) - kGlyphHeightPx, label, {0.8, 0.8, 0.8}, kScale);
  }
  // Image pixels: a count per canvas pixel, shown as log brightness.
  std::vector<int> count(std::size_t(c.image.width) * c.image.height, 0);
  const Mat3& to_xyz = film_space.rgb_to_xyz;
  for (std::size_t i = 0; i + 2 < film.rgb.size(); i += 3) {
    const Vec3d XYZ = to_xyz * Vec3d{film.rgb[i], film.rgb[i + 1], film.rgb[i + 2]};
    const double sum = XYZ.x + XYZ.y + XYZ.z;
    if (!(XYZ.y > 0.0) || !(sum > 0.0) || !std::isfinite(sum)) continue;
    const Vec3d p = chromaticity_to_canvas(XYZ.x / sum, XYZ.y / sum, size);
    const int px = int(p.x), py = int(p.y);
    if (px >= 0 && py >= 0 && px < c.image.width && py < c.image.height) ++count[std::size_t(py) * c.image.width + px];
  }
  const int max_count = std::max(1, *std::max_element(count.begin(), count.end()));
  for (int py = 0; py < c.image.height; ++py)
    for (int px = 0; px < c.image.width; ++px)
      if (const int n = count[std::size_t(py) * c.image.width + px]) {
        const double b = 0.35 + 0.65 * std::log1p(n) / std::log1p(max_count);
        c.set(px, py, {b, b, 0.85 * b});
      }
  // Gamut triangles, then the locus on top.
  draw_triangle(c, color::color_space("aces2065-1"), size, {0.9, 0.2, 0.8});
  draw_triangle(c, color::color_space("acescg"), size, {0.55, 0.4, 1.0});
  draw_triangle(c, film_space, size, {1.0, 0.55, 0.1});
  draw_triangle(c, display_space, size, {0.2, 0.9, 0.3});
  const auto& locus = spectral_locus_xy();
  for (std::size_t i = 0; i < locus.size(); ++i) {
    const auto& a = locus[i];
    const auto& b = locus[(i + 1) % locus.size()];  // the last segment is the line of purples
    const Vec3d pa = chromaticity_to_canvas(a.x, a.y, size), pb = chromaticity_to_canvas(b.x, b.y, size);
    c.draw_line(pa.x, pa.y, pb.x, pb.y, {1, 1, 1});
  }
  // Legend, top right.
  const std::pair<const char*, Vec3d> legend[] = {{"WORKING", {1.0, 0.55, 0.1}},
                                                  {"ACES AP0", {0.9, 0.2, 0.8}},
                                                  {"ACES AP1", {0.55, 0.4, 1.0}},
                                                  {"DISPLAY", {0.2, 0.9, 0.3}},
                                                  {"PIXELS", {1.0, 1.0, 0.85}}};
  int ly = kTopPx + 6;
  const int lx = c.image.width - text_width_px("ACES AP0", kScale) - 30;
  for (const auto& [text, colour] : legend) {
    c.fill_rect(lx, ly + 2, lx + 12, ly + 8, colour);
    c.draw_text(lx + 18, ly, text, colour, kScale);
    ly += (kGlyphHeightPx + 3) * kScale;
  }
  return c;
}

}  // namespace prism::display
