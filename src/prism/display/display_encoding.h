#pragma once
// Display encodings: display-linear light in nits → signal code values, on the colour
// functions of prism::color (IEC 61966-2-1 sRGB, ITU-R BT.1886, SMPTE ST 2084 PQ,
// IEC 61966-2-2 scRGB) and a pure 2.2 power (the sRGB reference display's EOTF, which the
// AgX configuration takes as its sRGB and Display P3 displays).
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/icc_profile.h"

namespace prism::display {

enum class DisplayEncoding {
  srgb,    // relative: nits / display white, sRGB piecewise curve
  bt1886,  // relative: nits / display white, γ 2.4 (black 0)
  pq,      // absolute: ST 2084, 1.0 = 10000 nits
  scrgb,   // linear Rec.709, 1.0 = 80 nits, negatives and values above 1 kept
  gamma22, // relative: nits / display white, pure power 1/2.2 (black 0)
  gamma26, // relative: nits / display white, pure power 1/2.6 (black 0): ACES 2.0's P3-D65 SDR
};

// "srgb", "bt1886" (alias "rec709"), "pq" (alias "st2084"), "scrgb", "gamma22", "gamma26";
// case-insensitive.
// Unknown: UsageError listing the names.
DisplayEncoding parse_display_encoding(std::string_view name);
std::string_view display_encoding_name(DisplayEncoding e);
std::vector<std::string> display_encoding_names();

// Integer-codable encodings (everything but scrgb) take values in [0, 1].
bool is_float_encoding(DisplayEncoding e);
// The ICC tone curve of a relative (SDR) encoding: srgb → IEC 61966-2-1, bt1886 → γ 2.4
// (zero black), gamma22 → γ 563/256 (the ICC curve closest to 2.2 that prism::color writes:
// decoded light within 0.25 % of γ 2.2 down to code 0.04, below an 8-bit step), gamma26 → γ 2.6. PQ and scRGB have none: UsageError.
color::IccToneCurve icc_tone_curve(DisplayEncoding e);

// Display light (nits) → code value; relative encodings divide by white_nits first and
// clamp to [0, 1]; pq clamps to [0, 10000] nits.
double encode_display_nits(DisplayEncoding e, double luminance_nits, double white_nits);
// Code value → display light (nits), the inverse of encode_display_nits.
double decode_display_nits(DisplayEncoding e, double code, double white_nits);

}  // namespace prism::display
