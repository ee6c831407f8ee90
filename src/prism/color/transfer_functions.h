#pragma once
// Transfer functions between linear light and non-linear code values. All take and return
// double; "encode" goes linear → code value, "decode" goes code value → linear.
//
// Out-of-domain inputs: sRGB is extended by odd symmetry (as scRGB-nl / sYCC do), so
// negatives survive a round trip; BT.1886, PQ and HLG clamp negative input to 0; scRGB is
// linear and passes negatives through; ACEScc/ACEScct follow their specs (ACEScc maps
// linear <= 0 to its floor, both decoders clamp at the half-float maximum 65504).
#include <string>
#include <string_view>
#include <vector>

namespace prism::color {

// IEC 61966-2-1:1999 §5.2 / §5.3 (sRGB), relative linear light in [0, 1].
double srgb_encode(double linear);
double srgb_decode(double code);

// ITU-R BT.1886 Annex 1 EOTF with the reference γ = 2.4. The relative form maps code V to
// V^2.4 (Lw = 1, Lb = 0); the display form maps V to luminance in nits for a display with
// white luminance white_nits and black luminance black_nits.
double bt1886_encode(double linear);
double bt1886_decode(double code);
double bt1886_encode_nits(double luminance_nits, double white_nits = 100.0, double black_nits = 0.0);
double bt1886_decode_nits(double code, double white_nits = 100.0, double black_nits = 0.0);

// SMPTE ST 2084:2014 (PQ) EOTF⁻¹ and EOTF in absolute luminance, 0 to 10000 nits.
inline constexpr double kPqPeakNits = 10000.0;
double pq_encode_nits(double luminance_nits);
double pq_decode_nits(double code);

// ITU-R BT.2100-2 Table 5 HLG OETF (scene linear E in [0, 1] → E') and its inverse.
double hlg_encode(double scene_linear);
double hlg_decode(double code);

// scRGB (IEC 61966-2-2): linear BT.709 where 1.0 is the 80 nit sRGB reference white;
// values below 0 and above 1 are legal.
inline constexpr double kScrgbWhiteNits = 80.0;
double scrgb_from_nits(double luminance_nits);
double scrgb_to_nits(double scrgb);

// ACEScc (Academy S-2014-003 §4.4, §4.5) and ACEScct (S-2016-001 §4.4, §4.5), on ACES
// linear values (AP1). ACEScct's toe constants are derived in the .cpp, not pasted.
double acescc_encode(double linear);
double acescc_decode(double code);
double acescct_encode(double linear);
double acescct_decode(double code);

// The transfer functions by name, for command lines and configuration files.
enum class TransferFunction { srgb, bt1886, pq, hlg, scrgb, acescc, acescct };

// "srgb", "bt1886", "pq" (alias "st2084"), "hlg", "scrgb", "acescc", "acescct";
// case-insensitive. Unknown name: UsageError listing the valid ones.
TransferFunction parse_transfer_function(std::string_view name);
std::string_view transfer_function_name(TransferFunction tf);
std::vector<std::string> transfer_function_names();

// Encode/decode on each function's own linear scale: relative [0, 1] for srgb and bt1886,
// 1.0 = 10000 nits for pq, scene-linear for hlg, 1.0 = 80 nits for scrgb, ACES linear
// for acescc/acescct.
double transfer_encode(TransferFunction tf, double linear);
double transfer_decode(TransferFunction tf, double code);

}  // namespace prism::color
