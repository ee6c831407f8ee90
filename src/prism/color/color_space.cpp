// Deriving RGB↔XYZ matrices from primaries and white (Lindbloom, "RGB/XYZ Matrices";
// SMPTE RP 177-1993 §3.3), validating user primaries, and parsing "xy:" specs.
#include "prism/color/color_space.h"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include <fmt/format.h>

namespace prism::color {
namespace {

// Twice the signed area of the primaries' triangle in the xy plane is the determinant of
// the matrix whose columns are (x, y, 1 − x − y). Chromaticities are O(1), so an absolute
// threshold is meaningful; 1e-10 is far below any real gamut (sRGB's is ~0.224) and far
// above the rounding noise of the determinant (~1e-16).
constexpr double kMinTwiceArea = 1e-10;
constexpr double kMinBarycentric = 1e-9;

// fmt rather than string concatenation: GCC 12's -Wrestrict misfires on
// "literal" + std::string&& (GCC bug 105329).
std::string describe(Chromaticity c) { return fmt::format("({}, {})", c.x, c.y); }

bool finite(Chromaticity c) { return std::isfinite(c.x) && std::isfinite(c.y); }

Mat3 chromaticity_columns(Chromaticity r, Chromaticity g, Chromaticity b) {
  auto column = [](Chromaticity c) { return Vec3d{c.x, c.y, 1.0 - c.x - c.y}; };
  return Mat3::from_columns(column(r), column(g), column(b));
}

void validate_triangle(Chromaticity r, Chromaticity g, Chromaticity b) {
  if (!finite(r) || !finite(g) || !finite(b))
    throw UsageError("primaries must be finite numbers");
  const double twice_area = determinant(chromaticity_columns(r, g, b));
  if (std::abs(twice_area) < kMinTwiceArea)
    throw UsageError("primaries " + describe(r) + " " + describe(g) + " " + describe(b) +
                     " are collinear: they span no gamut");
}

}  // namespace

Mat3 rgb_to_xyz_matrix(Chromaticity r, Chromaticity g, Chromaticity b, const Vec3d& white_XYZ) {
  validate_triangle(r, g, b);
  if (!is_finite(white_XYZ) || !(white_XYZ.y > 0.0))
    throw UsageError("white must be finite with positive luminance Y");
  // Lindbloom writes each primary as XYZ at Y = 1, (x/y, 1, (1−x−y)/y), and solves for the
  // scales S with [primaries]·S = W. Using (x, y, 1−x−y) instead only rescales each column
  // by y, which S absorbs; it also admits a primary with y = 0 (a point on the alychne).
  const Mat3 columns = chromaticity_columns(r, g, b);
  const Vec3d scale = inverse(columns) * white_XYZ;
  // Each primary's column sums to 1, so scale_i / (X+Y+Z of white) are the barycentric
  // coordinates of the white in the triangle. A white on an edge (or within rounding of
  // it) would make RGB white lack a primary altogether: require each coordinate to be
  // at least kMinBarycentric, far above rounding (~1e-16) and far below any real space
  // (sRGB's smallest is ~0.18).
  const double white_sum = white_XYZ.x + white_XYZ.y + white_XYZ.z;
  const Vec3d barycentric = scale / white_sum;
  if (!(white_sum > 0.0) || !(barycentric.x > kMinBarycentric && barycentric.y > kMinBarycentric &&
                              barycentric.z > kMinBarycentric)) {
    const Chromaticity w = white_sum > 0.0 ? XYZ_to_xy(white_XYZ) : Chromaticity{NAN, NAN};
    throw UsageError("white " + describe(w) + " is not inside the triangle of primaries " +
                     describe(r) + " " + describe(g) + " " + describe(b));
  }
  return columns * Mat3::diagonal(scale);
}

void validate_primaries(const Primaries& p) {
  if (!finite(p.white) || !(p.white.y > 0.0))
    throw UsageError("white " + describe(p.white) + " must have y > 0");
  (void)rgb_to_xyz_matrix(p.red, p.green, p.blue, xy_to_XYZ(p.white));
}

ColorSpace make_color_space(std::string name, Chromaticity r, Chromaticity g, Chromaticity b,
                            Chromaticity white) {
  if (!finite(white) || !(white.y > 0.0))
    throw UsageError("white " + describe(white) + " must have y > 0");
  const Mat3 to_xyz = rgb_to_xyz_matrix(r, g, b, xy_to_XYZ(white));
  return ColorSpace{std::move(name), r, g, b, white, to_xyz, inverse(to_xyz)};
}

ColorSpace make_color_space(std::string name, const Primaries& p) {
  return make_color_space(std::move(name), p.red, p.green, p.blue, p.white);
}

ColorSpace parse_color_space(std::string_view spec) {
  constexpr std::string_view prefix = "xy:";
  if (spec.substr(0, prefix.size()) != prefix) {
    try {
      return color_space(spec);
    } catch (const UsageError& e) {
      throw UsageError(std::string(e.what()) + "; or a user space xy:rx,ry,gx,gy,bx,by,wx,wy");
    }
  }

  double numbers[8];
  std::string_view rest = spec.substr(prefix.size());
  for (int i = 0; i < 8; ++i) {
    const std::size_t comma = rest.find(',');
    const std::string_view field = rest.substr(0, comma);
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, numbers[i]);
    if (ec != std::errc() || ptr != end || field.empty() || (i < 7) == (comma == std::string_view::npos))
      throw UsageError("malformed colour space '" + std::string(spec) +
                       "': expected xy:rx,ry,gx,gy,bx,by,wx,wy (eight numbers)");
    rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
  }
  const Primaries p{{numbers[0], numbers[1]}, {numbers[2], numbers[3]},
                    {numbers[4], numbers[5]}, {numbers[6], numbers[7]}};
  return make_color_space(std::string(spec), p);
}

}  // namespace prism::color
