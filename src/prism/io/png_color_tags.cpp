#include "prism/io/png_color_tags.h"

#include <cmath>

namespace prism {

std::uint8_t cicp_color_primaries(const color::ColorSpace& space) {
  const auto same = [&](const char* name) {
    const color::ColorSpace& k = color::color_space(name);
    const auto eq = [](color::Chromaticity a, color::Chromaticity b) {
      return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) < 1e-4;
    };
    return eq(k.red, space.red) && eq(k.green, space.green) && eq(k.blue, space.blue) && eq(k.white, space.white);
  };
  if (same("srgb")) return 1;
  if (same("rec2020")) return 9;
  if (same("display-p3")) return 12;
  return 0;
}

PngColorMetadata sdr_png_color_metadata(const color::ColorSpace& primaries, color::IccToneCurve curve) {
  PngColorMetadata meta;
  const std::uint8_t cp = cicp_color_primaries(primaries);
  if (cp == 1 && curve == color::IccToneCurve::srgb) {
    meta.srgb_chunk = true;
    return meta;
  }
  // H.273 TransferCharacteristics: 13 = IEC 61966-2-1, 1 = BT.709/BT.1886 (decoded as γ 2.4
  // by displays); pure 2.2 and 2.6 powers are left to the ICC profile.
  if (cp != 0 && (curve == color::IccToneCurve::srgb || curve == color::IccToneCurve::gamma_2_4))
    meta.cicp = CicpInfo{cp, std::uint8_t(curve == color::IccToneCurve::srgb ? 13 : 1), 0, 1};
  const char* curve_name = curve == color::IccToneCurve::srgb ? "sRGB curve"
                           : curve == color::IccToneCurve::gamma_2_4 ? "gamma 2.4"
                           : curve == color::IccToneCurve::gamma_2_6 ? "gamma 2.6" : "gamma 2.2";
  const std::string name = primaries.name.empty() ? std::string("custom primaries") : primaries.name;
  meta.icc_profile = color::make_icc_display_profile(primaries, curve, "Prism " + name + ", " + curve_name);
  meta.icc_profile_name = "Prism " + name;
  if (meta.icc_profile_name.size() > 79) meta.icc_profile_name.resize(79);
  return meta;
}

}  // namespace prism
