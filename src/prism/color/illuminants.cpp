// Standard illuminants from the embedded CIE tables, and a D65-derived SPD for any white.
#include "prism/color/illuminants.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "prism/color/tabulated_data.h"
#include "prism/core/error.h"

namespace prism::color {
namespace {

// Column `column` of a table whose column 0 is an evenly spaced wavelength.
DenseSpectrum from_table(const data::Table& t, int column = 1) {
  std::vector<double> values(static_cast<std::size_t>(t.rows));
  for (int i = 0; i < t.rows; ++i) values[static_cast<std::size_t>(i)] = t.at(i, column);
  return DenseSpectrum(t.at(0, 0), t.at(1, 0) - t.at(0, 0), std::move(values));
}

}  // namespace

const DenseSpectrum& standard_illuminant(StandardIlluminant illuminant) {
  static const DenseSpectrum d65 = from_table(data::illuminant_d65());
  static const DenseSpectrum d50 = from_table(data::illuminant_d50());
  static const DenseSpectrum a = from_table(data::illuminant_a());
  static const DenseSpectrum e = from_table(data::illuminant_e());
  switch (illuminant) {
    case StandardIlluminant::d65: return d65;
    case StandardIlluminant::d50: return d50;
    case StandardIlluminant::a: return a;
    case StandardIlluminant::e: return e;
  }
  return d65;
}

const DenseSpectrum& fluorescent_illuminant(int number) {
  if (number < 1 || number > 12)
    throw UsageError("no CIE fluorescent illuminant FL" + std::to_string(number) + " (known: FL1 to FL12)");
  static const std::vector<DenseSpectrum> fl = [] {
    std::vector<DenseSpectrum> out;
    for (int column = 1; column <= 12; ++column) out.push_back(from_table(data::illuminants_fl(), column));
    return out;
  }();
  return fl[static_cast<std::size_t>(number - 1)];
}

StandardIlluminant parse_standard_illuminant(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (lower == "d65") return StandardIlluminant::d65;
  if (lower == "d50") return StandardIlluminant::d50;
  if (lower == "a") return StandardIlluminant::a;
  if (lower == "e") return StandardIlluminant::e;
  throw UsageError("unknown illuminant '" + std::string(name) + "' (known: d65, d50, a, e)");
}

Vec3d illuminant_white_xyz(StandardIlluminant illuminant) {
  const Vec3d xyz = spectrum_to_xyz(standard_illuminant(illuminant), 360, 830);
  return xyz / xyz.y;
}

DenseSpectrum illuminant_with_chromaticity(Chromaticity white) {
  const DenseSpectrum& d65 = standard_illuminant(StandardIlluminant::d65);
  auto tilted = [&](double a, double b) {
    return DenseSpectrum::sampled([&](double nm) {
      const double t = (nm - 560.0) / 100.0;
      return d65(nm) * std::exp(a * t + b * t * t);
    });
  };
  auto residual = [&](double a, double b) {
    const Chromaticity c = XYZ_to_xy(spectrum_to_xyz(tilted(a, b)));
    return Vec2<double>{c.x - white.x, c.y - white.y};
  };
  double a = 0.0, b = 0.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Vec2<double> r = residual(a, b);
    if (std::hypot(r.x, r.y) < 1e-12) return tilted(a, b);
    // Jacobian by central differences; the map is smooth and nearly linear near D65.
    constexpr double h = 1e-5;
    const Vec2<double> ra = residual(a + h, b), rb = residual(a, b + h);
    const Vec2<double> ra_ = residual(a - h, b), rb_ = residual(a, b - h);
    const double j00 = (ra.x - ra_.x) / (2 * h), j10 = (ra.y - ra_.y) / (2 * h);
    const double j01 = (rb.x - rb_.x) / (2 * h), j11 = (rb.y - rb_.y) / (2 * h);
    const double det = j00 * j11 - j01 * j10;
    if (!(std::abs(det) > 0.0)) break;
    a -= (j11 * r.x - j01 * r.y) / det;
    b -= (-j10 * r.x + j00 * r.y) / det;
  }
  throw UsageError("no smooth D65-derived illuminant reaches white (" + std::to_string(white.x) +
                   ", " + std::to_string(white.y) + ")");
}

DenseSpectrum illuminant_for_white(Chromaticity white) {
  auto near = [&](Chromaticity c) { return std::abs(c.x - white.x) < 1e-4 && std::abs(c.y - white.y) < 1e-4; };
  if (near(kWhiteD65)) return standard_illuminant(StandardIlluminant::d65);
  if (near(kWhiteD50)) return standard_illuminant(StandardIlluminant::d50);
  if (near(kWhiteE)) return standard_illuminant(StandardIlluminant::e);
  return illuminant_with_chromaticity(white);
}

}  // namespace prism::color
