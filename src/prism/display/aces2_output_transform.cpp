#include "prism/display/aces2_output_transform.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/aces_common.h"

namespace prism::display {
namespace {

constexpr double kReferenceLuminance = 100.0;  // cd/m² of display-referred RGB 1.0

const Aces2Parameters& checked(const Aces2Parameters& p) {
  if (!(p.peak_luminance_nits >= 100.0 && p.peak_luminance_nits <= 10000.0))
    throw UsageError("ACES 2.0 peak luminance " + std::to_string(p.peak_luminance_nits) +
                     " cd/m² is outside 100 … 10000");
  const color::ColorSpace& limiting = color::color_space(p.limiting_primaries);
  const color::ColorSpace& encoding = color::color_space(p.encoding_primaries);
  if (std::abs(limiting.white.x - encoding.white.x) > 1e-9 || std::abs(limiting.white.y - encoding.white.y) > 1e-9)
    throw UsageError("ACES 2.0 limiting primaries '" + p.limiting_primaries + "' and encoding primaries '" +
                     p.encoding_primaries + "' have different whites (white scaling is not supported)");
  return p;
}

Vec3d clamp(const Vec3d& v, double lo, double hi) {
  return {std::clamp(v.x, lo, hi), std::clamp(v.y, lo, hi), std::clamp(v.z, lo, hi)};
}

// cos h and sin h of a colour's hue, from its opponent pair (h = 0 where M = 0, as the
// CAM's atan2 gives).
std::pair<double, double> hue_direction(const Vec3d& aab, const Vec3d& jmh) {
  if (!(jmh.y > 0.0)) return {1.0, 0.0};
  return {aab.y / jmh.y, aab.z / jmh.y};
}

Aces2GamutGeometry make_geometry(const HellwigCam& input, const Aces2Tonescale& ts) {
  Aces2GamutGeometry g;
  g.limit_j_max = input.y_to_j(ts.peak_nits);
  g.mid_j = input.y_to_j(ts.grey_display * kReferenceLuminance);
  g.focus_distance = 1.35 + 1.35 * 1.75 * ts.log_peak;
  g.lower_hull_gamma_inv = 1.0 / (1.14 + 0.07 * ts.log_peak);
  return g;
}

}  // namespace

Aces2OutputTransform::Aces2OutputTransform(const Aces2Parameters& parameters)
    : parameters_(checked(parameters)),
      input_cam_(color::color_space("aces2065-1").rgb_to_xyz),
      limit_cam_(color::color_space(parameters.limiting_primaries).rgb_to_xyz),
      tonescale_(parameters.peak_luminance_nits),
      chroma_(parameters.peak_luminance_nits),
      geometry_(make_geometry(input_cam_, tonescale_)) {
  const HellwigCam reach_cam(color::color_space("acescg").rgb_to_xyz);
  reach_ = make_aces2_reach_table(reach_cam, geometry_.limit_j_max);
  cusps_ = make_aces2_cusp_table(reach_cam, limit_cam_, tonescale_.peak_nits, tonescale_.forward_limit, geometry_);
  ap0_to_ap1_ = aces_matrices().ap0_to_ap1;
  ap1_to_ap0_ = aces_matrices().ap1_to_ap0;
  const color::ColorSpace& limiting = color::color_space(parameters.limiting_primaries);
  const color::ColorSpace& encoding = color::color_space(parameters.encoding_primaries);
  limiting_to_encoding_ = encoding.xyz_to_rgb * limiting.rgb_to_xyz;
  encoding_to_limiting_ = inverse(limiting_to_encoding_);
}

Vec3d Aces2OutputTransform::limiting_rgb(const Vec3d& aces2065_1) const {
  // Scene values outside AP1 or above 8 r_hit are clamped first (CTL clamp_AP0_to_AP1).
  const Vec3d aces = ap1_to_ap0_ * clamp(ap0_to_ap1_ * aces2065_1, 0.0, tonescale_.forward_limit);
  const Vec3d aab = input_cam_.rgb_to_aab(aces);
  const Vec3d jmh = input_cam_.aab_to_jmh(aab);
  const auto [cos_h, sin_h] = hue_direction(aab, jmh);

  // Tonescale on the achromatic response's luminance.
  const double j_ts =
      std::copysign(input_cam_.y_to_j(tonescale_.forward(input_cam_.achromatic_to_y(aab.x))), aab.x);
  const Aces2ChromaCompression::Context context{geometry_.limit_j_max, reach_.at(jmh.z),
                                                chroma_.normaliser(cos_h, sin_h)};
  const double m_ts = chroma_.forward(jmh.x, jmh.y, j_ts, context);
  const Vec2<double> jm = aces2_gamut_compress_forward(j_ts, m_ts, context.reach_max_m,
                                                       cusps_.shape(jmh.z, geometry_), geometry_);
  return limit_cam_.aab_to_rgb(limit_cam_.jmh_to_aab(jm.x, jm.y, cos_h, sin_h));
}

Vec3d Aces2OutputTransform::display_nits(const Vec3d& aces2065_1) const {
  const Vec3d rgb = clamp(limiting_rgb(aces2065_1), 0.0, tonescale_.peak_nits / kReferenceLuminance);
  return limiting_to_encoding_ * rgb * kReferenceLuminance;
}

Vec3d Aces2OutputTransform::aces_from_limiting_rgb(const Vec3d& rgb) const {
  const Vec3d aab = limit_cam_.rgb_to_aab(rgb);
  const Vec3d jmh = limit_cam_.aab_to_jmh(aab);
  const auto [cos_h, sin_h] = hue_direction(aab, jmh);
  const Aces2ChromaCompression::Context context{geometry_.limit_j_max, reach_.at(jmh.z),
                                                chroma_.normaliser(cos_h, sin_h)};
  const Vec2<double> jm_ts = aces2_gamut_compress_inverse(jmh.x, jmh.y, context.reach_max_m,
                                                          cusps_.shape(jmh.z, geometry_), geometry_);
  const double j = std::copysign(
      input_cam_.y_to_j(tonescale_.inverse(input_cam_.j_to_y(std::abs(jm_ts.x)))), jm_ts.x);
  const double m = chroma_.inverse(j, jm_ts.y, jm_ts.x, context);
  const Vec3d aces = input_cam_.aab_to_rgb(input_cam_.jmh_to_aab(j, m, cos_h, sin_h));
  return ap1_to_ap0_ * clamp(ap0_to_ap1_ * aces, 0.0, tonescale_.forward_limit);
}

Vec3d Aces2OutputTransform::aces_from_display_nits(const Vec3d& display_rgb_nits) const {
  const Vec3d rgb = clamp(encoding_to_limiting_ * (display_rgb_nits / kReferenceLuminance), 0.0,
                          tonescale_.peak_nits / kReferenceLuminance);
  return aces_from_limiting_rgb(rgb);
}

}  // namespace prism::display
