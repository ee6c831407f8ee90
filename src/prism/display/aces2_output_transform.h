#pragma once
// The Academy's ACES 2.0 Output Transform (ACES 2.0 "Output Transform technical details";
// aces-core lib/Lib.Academy.OutputTransform.ctl and Lib.Academy.DisplayEncoding.ctl),
// forward and inverse, for one peak luminance and limiting gamut:
//   ACES2065-1 → clamp to [0, 8 r_hit] in AP1 → Hellwig JMh (AP0 white) → tonescale on J
//   → chroma compression → gamut compression towards the limiting gamut → RGB in the
//   limiting primaries → clamp to [0, peak] → display-linear RGB in the encoding primaries.
// The result is light on the display in cd/m², before the EOTF's inverse. The creative
// white is the limiting gamut's own (no D60 simulation / white scaling): limiting and
// encoding primaries must share their white. Checked against OpenColorIO 2.5.2's built-in
// ACES 2.0 transforms (tests/display/aces2_output_transform_test.cpp).
#include <string>

#include "prism/core/mat3.h"
#include "prism/core/vec.h"
#include "prism/display/aces2_chroma_compression.h"
#include "prism/display/aces2_tables.h"
#include "prism/display/aces2_tonescale.h"
#include "prism/display/hellwig_cam.h"

namespace prism::display {

struct Aces2Parameters {
  double peak_luminance_nits = 100.0;         // 100 … 10000
  std::string limiting_primaries = "rec709";  // a prism::color space name ("rec709", "p3-d65", "rec2020", …)
  std::string encoding_primaries = "rec709";  // the display's primaries (container)
};

class Aces2OutputTransform {
 public:
  // Builds the tables (a few tens of milliseconds). UsageError for a peak outside
  // [100, 10000], an unknown space, or limiting and encoding whites that differ.
  explicit Aces2OutputTransform(const Aces2Parameters& parameters);

  // ACES2065-1 (linear AP0) → display-linear RGB in the encoding primaries, cd/m².
  Vec3d display_nits(const Vec3d& aces2065_1) const;
  // Display-linear RGB in the encoding primaries (cd/m²) → ACES2065-1. Exact inverse of
  // display_nits for colours the forward transform can produce (within the limiting gamut
  // and below the peak); anything else is clamped to that first.
  Vec3d aces_from_display_nits(const Vec3d& display_rgb_nits) const;

  const Aces2Parameters& parameters() const { return parameters_; }
  // The intermediate results, for tests: display-referred RGB in the limiting primaries
  // with 1.0 = 100 cd/m², before the clamp.
  Vec3d limiting_rgb(const Vec3d& aces2065_1) const;

 private:
  Vec3d aces_from_limiting_rgb(const Vec3d& rgb) const;

  Aces2Parameters parameters_;
  HellwigCam input_cam_, limit_cam_;
  Aces2Tonescale tonescale_;
  Aces2ChromaCompression chroma_;
  Aces2GamutGeometry geometry_;
  Aces2ReachTable reach_;
  Aces2CuspTable cusps_;
  Mat3 ap0_to_ap1_, ap1_to_ap0_;
  Mat3 limiting_to_encoding_, encoding_to_limiting_;
};

}  // namespace prism::display
