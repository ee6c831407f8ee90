#pragma once
// ACES 1.x Output Transforms (RRT + ODT) by name, from ACES2065-1 to display-linear light
// in absolute nits in the display's RGB primaries. Encoding to code values is a separate
// stage (display_encoding.h), so every encoding of one ODT shows the same light.
//
//   srgb-100nit         RRT + ODT.Academy.RGBmonitor_100nits_dim (Rec.709 primaries, sRGB)
//   rec709-100nit       RRT + ODT.Academy.Rec709_100nits_dim (BT.1886)
//   p3d65-100nit        the same SDR video rendering on P3-D65 primaries (Display P3, sRGB curve)
//   rec2020-100nit      RRT + ODT.Academy.Rec2020_100nits_dim (BT.1886)
//   rec2020-pq-1000nit  RRTODT.Academy.Rec2020_1000nits_15nits_ST2084 (SSTS)
//   rec2020-pq-2000nit  RRTODT.Academy.Rec2020_2000nits_15nits_ST2084
//   rec2020-pq-4000nit  RRTODT.Academy.Rec2020_4000nits_15nits_ST2084
//   p3d65-pq-1000nit    RRTODT.Academy.P3D65_1000nits_15nits_ST2084
//   none                no tone mapping: ACES → Rec.709 (Bradford), 1.0 = 80 nits
#include <string>
#include <string_view>
#include <vector>

#include "prism/core/mat3.h"
#include "prism/core/vec.h"
#include "prism/display/display_encoding.h"
#include "prism/display/ssts.h"

namespace prism::display {

enum class OdtId {
  none, srgb_100nit, rec709_100nit, p3d65_100nit, rec2020_100nit,
  rec2020_pq_1000nit, rec2020_pq_2000nit, rec2020_pq_4000nit, p3d65_pq_1000nit,
};

struct OdtDescription {
  OdtId id;
  std::string_view name;
  std::string_view display_space;  // prism::color name of the display primaries
  DisplayEncoding default_encoding;
  bool hdr;                 // SSTS Output Transform (else SDR C5+C9 path, or none)
  double y_min_nits;        // HDR: Y_MIN; SDR: 0 (display black)
  double y_mid_nits;        // HDR: Y_MID
  double white_nits;        // peak: HDR Y_MAX, SDR 100, none 80
};

const OdtDescription& odt_description(OdtId id);
// Case-insensitive; '_' accepted for '-'. Unknown: UsageError listing the names.
OdtId parse_odt(std::string_view name);
std::vector<std::string> odt_names();

class AcesOutputTransform {
 public:
  // stretch_black (HDR only, the CTL's STRETCH_BLACK): map linear code 0 to 0 nits rather
  // than Y_MIN. The Academy's ST 2084 transforms ship with it on.
  explicit AcesOutputTransform(OdtId id, bool stretch_black = true);

  // ACES2065-1 → display-linear RGB (display primaries), nits. Equal to
  // display_nits_from_normalized(normalized_ap1(aces), peak).
  Vec3d display_nits(const Vec3d& aces) const;

  // The two halves of display_nits, split at the ODT's normalised linear code in AP1 (SDR:
  // after the C9 tone scale, dim-surround gamma and desaturation, 1.0 = display white; HDR:
  // (SSTS − Y_MIN)/(Y_MAX − Y_MIN); none: ACES in AP1, 1.0 = 80 nits). Overlays and the
  // render-scale upscale work at this step.
  Vec3d normalized_ap1(const Vec3d& aces) const;
  // Limit/clamp in the display primaries, to display RGB, × peak_nits (the ODT's peak, or a
  // per-pixel peak moved toward the UI luminance by an overlay).
  Vec3d display_nits_from_normalized(const Vec3d& cv_ap1, double peak_nits) const;
  const OdtDescription& description() const { return *desc_; }

  // The pieces of normalized_ap1 / display_nits_from_normalized that the float block kernel
  // (aces_output_kernel.h) tabulates or folds, so that both paths draw on one definition.
  //
  // The per-channel tone curve from AP1 rendering-space RGB (the sweeteners' output) to the
  // normalised linear code: SDR (C9(C5(x)) − 0.02)/(48 − 0.02), HDR (SSTS(x) − Y_MIN)/
  // (Y_MAX − Y_MIN), none: x.
  double normalized_tone_curve(double x) const;
  // Where that curve leaves 0 (its black floor, zero slope in log–log): SDR 0.18·2^-6.5,
  // whose C5 value is the C9 curve's low knee (ODT_48nits); HDR the SSTS's min.x; none 0.
  double normalized_tone_curve_floor_end() const;
  bool stretch_black() const { return stretch_black_; }
  const Mat3& xyz_to_display() const { return xyz_to_display_; }
  const Mat3& limit_xyz_to_rgb() const { return limit_xyz_to_rgb_; }
  const Mat3& limit_rgb_to_xyz() const { return limit_rgb_to_xyz_; }
  const Mat3& ap1_to_display() const { return ap1_to_display_; }

 private:

  const OdtDescription* desc_;
  bool stretch_black_;
  Mat3 xyz_to_display_;      // XYZ (D65) → display RGB
  Mat3 limit_xyz_to_rgb_, limit_rgb_to_xyz_;  // limiting primaries (= display primaries)
  Mat3 ap1_to_display_;      // for `none`: Bradford ACES white → display white
  TsParams ts_{};
};

// SDR ODT darkSurround_to_dimSurround (ODT_Common.ctl): the luminance Y (AP1 → XYZ, relative
// to the ACES white) raised to the dim-surround gamma 0.9811, with the CTL's clamp to
// [0, HALF_MAX]. The transform keeps xy, so the whole pixel scales by this ÷ Y.
double dim_surround_luminance(double y);
// The SDR ODT's desaturation by 0.93 about AP1 luminance (ODT_SAT_FACTOR).
const Mat3& sdr_odt_desaturation();

}  // namespace prism::display
