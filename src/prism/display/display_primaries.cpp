#include "prism/display/display_primaries.h"

#include <cctype>
#include <cstdio>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/display/spectral_locus.h"

namespace prism::display {

color::ColorSpace parse_display_primaries(std::string_view spec) {
  std::string s(spec);
  // Bare numbers are the "xy:" form without its prefix.
  if (!s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.' || s[0] == '-')) s = "xy:" + s;
  color::ColorSpace space = color::parse_color_space(s);  // malformed, collinear, white outside
  const std::pair<const char*, color::Chromaticity> points[] = {
      {"red primary", space.red}, {"green primary", space.green}, {"blue primary", space.blue}, {"white point", space.white}};
  for (const auto& [what, c] : points)
    if (!inside_spectral_locus(c)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "display %s (%.4f, %.4f) lies outside the CIE 1931 spectral locus", what,
                    c.x, c.y);
      throw UsageError(buf);
    }
  return space;
}

Mat3 gamut_remap_matrix(const color::ColorSpace& odt_space, const color::ColorSpace& display) {
  return color::conversion_matrix(odt_space, display, color::Cat::bradford);
}

}  // namespace prism::display
