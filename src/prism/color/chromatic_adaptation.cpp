// Chromatic adaptation transforms. The cone matrices are the defining constants of each
// transform (they are not derivable from anything else), quoted from their sources.
#include "prism/color/chromatic_adaptation.h"

#include <cctype>
#include <string>

#include "prism/core/error.h"

namespace prism::color {
namespace {

Mat3 from_rows(const Vec3d& r0, const Vec3d& r1, const Vec3d& r2) {
  return transpose(Mat3::from_columns(r0, r1, r2));
}

struct CatEntry {
  Cat cat;
  std::string_view name;
};
constexpr CatEntry kCats[] = {
    {Cat::bradford, "bradford"},
    {Cat::cat02, "cat02"},
    {Cat::von_kries, "von-kries"},
    {Cat::xyz_scaling, "xyz-scaling"},
};

}  // namespace

Mat3 cat_cone_matrix(Cat cat) {
  switch (cat) {
    case Cat::bradford:  // ICC.1:2010 Annex E, eq. E.3; Lindbloom "Chromatic Adaptation"
      return from_rows({0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296});
    case Cat::cat02:  // CIE 159:2004 (CIECAM02) eq. 7
      return from_rows({0.7328, 0.4296, -0.1624}, {-0.7036, 1.6975, 0.0061}, {0.0030, 0.0136, 0.9834});
    case Cat::von_kries:  // Hunt–Pointer–Estévez, D65-normalised (as Lindbloom tabulates it)
      return from_rows({0.40024, 0.70760, -0.08081}, {-0.22630, 1.16532, 0.04570}, {0.0, 0.0, 0.91822});
    case Cat::xyz_scaling:
      return Mat3::identity();
  }
  throw UsageError("unknown chromatic adaptation transform");
}

Mat3 adaptation_matrix(const Vec3d& src_white_XYZ, const Vec3d& dst_white_XYZ, Cat cat) {
  const Mat3 cone = cat_cone_matrix(cat);
  const Vec3d src_cone = cone * src_white_XYZ;
  const Vec3d dst_cone = cone * dst_white_XYZ;
  if (!(src_cone.x > 0 && src_cone.y > 0 && src_cone.z > 0 && dst_cone.x > 0 && dst_cone.y > 0 &&
        dst_cone.z > 0) ||
      !is_finite(src_cone) || !is_finite(dst_cone))
    throw UsageError("white points must have positive cone responses to adapt between them");
  return inverse(cone) * Mat3::diagonal(dst_cone / src_cone) * cone;
}

Mat3 conversion_matrix(const ColorSpace& from, const ColorSpace& to, Cat cat) {
  const bool same_white = from.white.x == to.white.x && from.white.y == to.white.y;
  if (same_white) return to.xyz_to_rgb * from.rgb_to_xyz;
  return to.xyz_to_rgb * adaptation_matrix(white_XYZ(from), white_XYZ(to), cat) * from.rgb_to_xyz;
}

Cat parse_cat(std::string_view name) {
  std::string key(name);
  for (char& c : key) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c == '_') c = '-';
  }
  if (key == "hpe" || key == "vonkries") key = "von-kries";
  if (key == "scaling") key = "xyz-scaling";
  for (const CatEntry& e : kCats)
    if (e.name == key) return e.cat;
  std::string valid;
  for (const CatEntry& e : kCats) valid += std::string(valid.empty() ? "" : ", ") + std::string(e.name);
  throw UsageError("unknown chromatic adaptation transform '" + std::string(name) + "' (valid: " + valid + ")");
}

std::string_view cat_name(Cat cat) {
  for (const CatEntry& e : kCats)
    if (e.cat == cat) return e.name;
  return "unknown";
}

std::vector<std::string> cat_names() {
  std::vector<std::string> names;
  for (const CatEntry& e : kCats) names.emplace_back(e.name);
  return names;
}

}  // namespace prism::color
