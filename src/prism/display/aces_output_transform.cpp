#include "prism/display/aces_output_transform.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/aces_common.h"
#include "prism/display/aces_rrt.h"
#include "prism/display/segmented_spline.h"

namespace prism::display {
namespace {

using E = DisplayEncoding;
constexpr double kSdrWhiteNits = 100.0;

const std::array<OdtDescription, 9> kOdts{{
    {OdtId::none, "none", "srgb", E::srgb, false, 0.0, 0.0, 80.0},
    {OdtId::srgb_100nit, "srgb-100nit", "srgb", E::srgb, false, 0.0, 0.0, kSdrWhiteNits},
    {OdtId::rec709_100nit, "rec709-100nit", "srgb", E::bt1886, false, 0.0, 0.0, kSdrWhiteNits},
    {OdtId::p3d65_100nit, "p3d65-100nit", "display-p3", E::srgb, false, 0.0, 0.0, kSdrWhiteNits},
    {OdtId::rec2020_100nit, "rec2020-100nit", "rec2020", E::bt1886, false, 0.0, 0.0, kSdrWhiteNits},
    // Y_MIN 0.0001, Y_MID 15 of the Academy's *_15nits_ST2084 transforms.
    {OdtId::rec2020_pq_1000nit, "rec2020-pq-1000nit", "rec2020", E::pq, true, 0.0001, 15.0, 1000.0},
    {OdtId::rec2020_pq_2000nit, "rec2020-pq-2000nit", "rec2020", E::pq, true, 0.0001, 15.0, 2000.0},
    {OdtId::rec2020_pq_4000nit, "rec2020-pq-4000nit", "rec2020", E::pq, true, 0.0001, 15.0, 4000.0},
    {OdtId::p3d65_pq_1000nit, "p3d65-pq-1000nit", "display-p3", E::pq, true, 0.0001, 15.0, 1000.0},
}};

// SDR ODT constants (ODT.Academy.*_100nits_dim.ctl, ACESlib.ODT_Common.ctl).
constexpr double kCinemaWhite = 48.0, kCinemaBlack = 0.02;
constexpr double kDimSurroundGamma = 0.9811;
constexpr double kOdtSatFactor = 0.93;

// darkSurround_to_dimSurround: raise Y to γ 0.9811 at constant xy.
Vec3d dark_to_dim_surround(const Vec3d& linear_cv) {
  const AcesMatrices& m = aces_matrices();
  const Vec3d XYZ = m.ap1_to_xyz * linear_cv;
  double divisor = XYZ.x + XYZ.y + XYZ.z;
  if (divisor == 0.0) divisor = 1e-10;
  const double x = XYZ.x / divisor, y = XYZ.y / divisor;
  const double Y = dim_surround_luminance(XYZ.y);
  const double yy = std::max(y, 1e-10);
  return m.xyz_to_ap1 * Vec3d{x * Y / yy, Y, (1.0 - x - y) * Y / yy};
}

}  // namespace

double dim_surround_luminance(double y) { return std::pow(std::clamp(y, 0.0, kHalfMax), kDimSurroundGamma); }

const Mat3& sdr_odt_desaturation() {
  static const Mat3 desat = saturation_matrix(kOdtSatFactor, aces_matrices().ap1_luminance);
  return desat;
}

const OdtDescription& odt_description(OdtId id) { return kOdts[static_cast<std::size_t>(id)]; }

OdtId parse_odt(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& d : kOdts)
    if (d.name == n) return d.id;
  std::string valid;
  for (const auto& d : kOdts) valid += (valid.empty() ? "" : ", ") + std::string(d.name);
  throw UsageError("unknown ODT '" + std::string(name) + "' (valid: " + valid + ")");
}

std::vector<std::string> odt_names() {
  std::vector<std::string> r;
  for (const auto& d : kOdts) r.emplace_back(d.name);
  return r;
}

AcesOutputTransform::AcesOutputTransform(OdtId id, bool stretch_black)
    : desc_(&odt_description(id)), stretch_black_(stretch_black) {
  const color::ColorSpace& display = color::color_space(desc_->display_space);
  xyz_to_display_ = display.xyz_to_rgb;
  limit_xyz_to_rgb_ = display.xyz_to_rgb;
  limit_rgb_to_xyz_ = display.rgb_to_xyz;
  ap1_to_display_ = color::conversion_matrix(color::color_space("acescg"), display, color::Cat::bradford);
  if (desc_->hdr) ts_ = make_output_ts_params(desc_->y_min_nits, desc_->y_mid_nits, desc_->white_nits);
}

Vec3d AcesOutputTransform::display_nits(const Vec3d& aces) const {
  return display_nits_from_normalized(normalized_ap1(aces), desc_->white_nits);
}

Vec3d AcesOutputTransform::normalized_ap1(const Vec3d& aces) const {
  const AcesMatrices& m = aces_matrices();
  if (desc_->id == OdtId::none) return m.ap0_to_ap1 * aces;
  Vec3d cv;
  if (desc_->hdr) {
    // ACESlib.OutputTransforms.ctl outputTransform(): RRT sweeteners, SSTS per channel,
    // Y_2_linCV.
    const double y_min = desc_->y_min_nits, y_max = desc_->white_nits;
    const Vec3d pre = rrt_sweeteners(aces);
    for (int c = 0; c < 3; ++c) cv[c] = (ssts(pre[c], ts_) - y_min) / (y_max - y_min);
    return cv;
  }
  // RRT, then the SDR video ODT: C9 tone scale to cinema luminance, normalised to linear
  // code, dim-surround gamma, desaturation 0.93.
  const Vec3d pre = m.ap0_to_ap1 * aces_rrt(aces);
  for (int c = 0; c < 3; ++c)
    cv[c] = (segmented_spline_c9_fwd(pre[c]) - kCinemaBlack) / (kCinemaWhite - kCinemaBlack);
  cv = dark_to_dim_surround(cv);
  return sdr_odt_desaturation() * cv;
}

double AcesOutputTransform::normalized_tone_curve_floor_end() const {
  if (desc_->id == OdtId::none) return 0.0;
  if (desc_->hdr) return ts_.min.x;
  return 0.18 * std::exp2(-6.5);  // ODT_48nits: minPoint = C5(0.18·2^-6.5)
}

double AcesOutputTransform::normalized_tone_curve(double x) const {
  if (desc_->id == OdtId::none) return x;
  if (desc_->hdr) return (ssts(x, ts_) - desc_->y_min_nits) / (desc_->white_nits - desc_->y_min_nits);
  return (segmented_spline_c9_fwd(segmented_spline_c5_fwd(x)) - kCinemaBlack) / (kCinemaWhite - kCinemaBlack);
}

Vec3d AcesOutputTransform::display_nits_from_normalized(const Vec3d& cv, double peak) const {
  const AcesMatrices& m = aces_matrices();
  if (desc_->id == OdtId::none) return (ap1_to_display_ * cv) * peak;
  // The clips below limit *light* to the display's peak: 1 at the ODT's own peak, larger
  // when an overlay lowers the pixel's normalisation peak toward the UI luminance.
  const double limit = desc_->white_nits / peak;
  if (!desc_->hdr) {
    // SDR: AP1 → XYZ, Bradford to D65, display primaries, clamp to [0, 1]; code 1 shows at
    // the peak, 0 at 0 nits.
    Vec3d rgb = xyz_to_display_ * (m.d60_to_d65 * (m.ap1_to_xyz * cv));
    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c], 0.0, limit) * peak;
    return rgb;
  }
  // HDR, no D60 simulation, full range, limiting primaries = display primaries:
  // limit_to_primaries clips to [0, 1] in the limiting primaries (applied, as in the CTL, to
  // XYZ that is still relative to the ACES white), then Bradford D60→D65.
  Vec3d limited = limit_xyz_to_rgb_ * (m.ap1_to_xyz * cv);
  for (int c = 0; c < 3; ++c) limited[c] = std::clamp(limited[c], 0.0, limit);
  Vec3d rgb = xyz_to_display_ * (m.d60_to_d65 * (limit_rgb_to_xyz_ * limited));
  const double y_min = desc_->y_min_nits;
  for (int c = 0; c < 3; ++c) {
    const double v = std::max(rgb[c], 0.0);
    // linCV_2_Y with Y_MIN = 0 (stretched black) or the display's Y_MIN.
    rgb[c] = stretch_black_ ? v * peak : v * (peak - y_min) + y_min;
  }
  return rgb;
}

}  // namespace prism::display
