#include "prism/display/spectral_locus.h"

#include <algorithm>
#include <cmath>

#include "prism/color/cie_1931.h"

namespace prism::display {
namespace {

double distance_to_segment(color::Chromaticity p, color::Chromaticity a, color::Chromaticity b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace

const std::vector<color::Chromaticity>& spectral_locus_xy() {
  static const std::vector<color::Chromaticity> locus = [] {
    std::vector<color::Chromaticity> pts;
    for (int nm = 380; nm <= 700; ++nm) pts.push_back(color::XYZ_to_xy(color::cie1931_xyz_bar(nm)));
    return pts;
  }();
  return locus;
}

bool inside_spectral_locus(color::Chromaticity p, double tolerance) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  const auto& poly = spectral_locus_xy();
  // Even–odd ray casting along +x over the closed polygon (the last edge is the purple line).
  bool inside = false;
  double nearest = INFINITY;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const color::Chromaticity a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    nearest = std::min(nearest, distance_to_segment(p, a, b));
  }
  return inside || nearest <= tolerance;
}

}  // namespace prism::display
