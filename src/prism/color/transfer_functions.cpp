// Transfer functions, each written from its defining document (cited per function).
#include "prism/color/transfer_functions.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "prism/core/error.h"

namespace prism::color {
namespace {

// --- sRGB, IEC 61966-2-1:1999 ---------------------------------------------------------
// The standard's decode break 0.04045 and encode break 0.0031308 are rounded versions of
// each other (0.04045 / 12.92 = 0.00313080495...), and its two segments miss each other by
// ~3e-8 at the join. We keep the decode exactly as printed and make the encode its exact
// inverse: the encode break is 0.04045 / 12.92, and linear values in the ~2e-9 wide gap
// that decode never produces encode to the break itself, keeping encode monotonic.
constexpr double kSrgbCodeBreak = 0.04045;
constexpr double kSrgbSlope = 12.92;
constexpr double kSrgbLinearBreak = kSrgbCodeBreak / kSrgbSlope;
constexpr double kSrgbOffset = 0.055;
constexpr double kSrgbGamma = 2.4;

double srgb_encode_positive(double l) {
  if (l <= kSrgbLinearBreak) return kSrgbSlope * l;
  const double code = (1.0 + kSrgbOffset) * std::pow(l, 1.0 / kSrgbGamma) - kSrgbOffset;
  return std::max(code, kSrgbCodeBreak);
}

double srgb_decode_positive(double v) {
  if (v <= kSrgbCodeBreak) return v / kSrgbSlope;
  return std::pow((v + kSrgbOffset) / (1.0 + kSrgbOffset), kSrgbGamma);
}

// --- BT.1886 Annex 1 -------------------------------------------------------------------
constexpr double kBt1886Gamma = 2.4;

struct Bt1886Display {
  double a, b;  // L = a · max(V + b, 0)^γ
};

Bt1886Display bt1886_display(double white_nits, double black_nits) {
  if (!(black_nits >= 0.0) || !(white_nits > black_nits) || !std::isfinite(white_nits))
    throw UsageError("BT.1886 needs 0 <= black luminance < white luminance (nits)");
  const double w = std::pow(white_nits, 1.0 / kBt1886Gamma);
  const double k = std::pow(black_nits, 1.0 / kBt1886Gamma);
  return {std::pow(w - k, kBt1886Gamma), k / (w - k)};
}

// --- SMPTE ST 2084:2014 §5.3 constants, exact rationals as the standard defines them ----
constexpr double kPqM1 = 2610.0 / 16384.0;
constexpr double kPqM2 = 2523.0 / 4096.0 * 128.0;
constexpr double kPqC1 = 3424.0 / 4096.0;
constexpr double kPqC2 = 2413.0 / 4096.0 * 32.0;
constexpr double kPqC3 = 2392.0 / 4096.0 * 32.0;

// --- BT.2100-2 Table 5 HLG: b and c follow from a (b = 1 − 4a, c = 0.5 − a·ln(4a)) -------
constexpr double kHlgA = 0.17883277;
constexpr double kHlgB = 1.0 - 4.0 * kHlgA;
// std::log is not constexpr, and a namespace-scope dynamic initialiser could run after a
// static initialiser in another file that calls us: compute on first use instead.
double hlg_c() {
  static const double c = 0.5 - kHlgA * std::log(4.0 * kHlgA);
  return c;
}

// --- ACEScc / ACEScct: log2 encoding of S-2014-003 and S-2016-001 ------------------------
constexpr double kAcesLogOffset = 9.72;
constexpr double kAcesLogScale = 17.52;
constexpr double kHalfMax = 65504.0;  // largest finite IEEE half: the decoders' ceiling
// ACEScct: a straight-line toe below X_BRK that meets the log curve with equal value and
// slope (S-2016-001 §4.4 prints A = 10.5402377416545, B = 0.0729055341958355).
constexpr double kAcescctLinearBreak = 0.0078125;
double aces_log2_encode(double linear) { return (std::log2(linear) + kAcesLogOffset) / kAcesLogScale; }
double aces_log2_decode(double code) { return std::exp2(code * kAcesLogScale - kAcesLogOffset); }

double aces_code_ceiling() {
  static const double ceiling = aces_log2_encode(kHalfMax);
  return ceiling;
}

struct AcescctToe {
  double code_break, slope, offset;
};

const AcescctToe& acescct_toe() {
  static const AcescctToe toe = [] {
    const double code_break = aces_log2_encode(kAcescctLinearBreak);
    const double slope = 1.0 / (kAcescctLinearBreak * std::log(2.0) * kAcesLogScale);  // d/dx of the log segment
    return AcescctToe{code_break, slope, code_break - slope * kAcescctLinearBreak};
  }();
  return toe;
}

struct TransferEntry {
  TransferFunction tf;
  std::string_view name;
};
constexpr TransferEntry kTransfers[] = {
    {TransferFunction::srgb, "srgb"},     {TransferFunction::bt1886, "bt1886"},
    {TransferFunction::pq, "pq"},         {TransferFunction::hlg, "hlg"},
    {TransferFunction::scrgb, "scrgb"},   {TransferFunction::acescc, "acescc"},
    {TransferFunction::acescct, "acescct"},
};

}  // namespace

double srgb_encode(double linear) { return std::copysign(srgb_encode_positive(std::abs(linear)), linear); }
double srgb_decode(double code) { return std::copysign(srgb_decode_positive(std::abs(code)), code); }

double bt1886_encode(double linear) { return std::pow(std::max(linear, 0.0), 1.0 / kBt1886Gamma); }
double bt1886_decode(double code) { return std::pow(std::max(code, 0.0), kBt1886Gamma); }

double bt1886_encode_nits(double luminance_nits, double white_nits, double black_nits) {
  const Bt1886Display d = bt1886_display(white_nits, black_nits);
  return std::pow(std::max(luminance_nits, 0.0) / d.a, 1.0 / kBt1886Gamma) - d.b;
}

double bt1886_decode_nits(double code, double white_nits, double black_nits) {
  const Bt1886Display d = bt1886_display(white_nits, black_nits);
  return d.a * std::pow(std::max(code + d.b, 0.0), kBt1886Gamma);
}

// ST 2084 eq. 5.2 (inverse EOTF), luminance clamped to the standard's 0..10000 nits.
double pq_encode_nits(double luminance_nits) {
  const double y = std::clamp(luminance_nits / kPqPeakNits, 0.0, 1.0);
  const double ym = std::pow(y, kPqM1);
  return std::pow((kPqC1 + kPqC2 * ym) / (1.0 + kPqC3 * ym), kPqM2);
}

// ST 2084 eq. 5.1 (EOTF), code clamped to [0, 1].
double pq_decode_nits(double code) {
  const double np = std::pow(std::clamp(code, 0.0, 1.0), 1.0 / kPqM2);
  const double y = std::pow(std::max(np - kPqC1, 0.0) / (kPqC2 - kPqC3 * np), 1.0 / kPqM1);
  return kPqPeakNits * y;
}

double hlg_encode(double scene_linear) {
  const double e = std::max(scene_linear, 0.0);
  if (e <= 1.0 / 12.0) return std::sqrt(3.0 * e);
  return kHlgA * std::log(12.0 * e - kHlgB) + hlg_c();
}

double hlg_decode(double code) {
  const double v = std::max(code, 0.0);
  if (v <= 0.5) return v * v / 3.0;
  return (std::exp((v - hlg_c()) / kHlgA) + kHlgB) / 12.0;
}

double scrgb_from_nits(double luminance_nits) { return luminance_nits / kScrgbWhiteNits; }
double scrgb_to_nits(double scrgb) { return scrgb * kScrgbWhiteNits; }

// S-2014-003 §4.4: a half-slope toe below 2^-15 keeps small and zero values finite.
double acescc_encode(double linear) {
  if (linear <= 0.0) return aces_log2_encode(std::exp2(-16.0));
  if (linear < std::exp2(-15.0)) return aces_log2_encode(std::exp2(-16.0) + linear * 0.5);
  return aces_log2_encode(linear);
}

// S-2014-003 §4.5.
double acescc_decode(double code) {
  if (code < (kAcesLogOffset - 15.0) / kAcesLogScale) return (aces_log2_decode(code) - std::exp2(-16.0)) * 2.0;
  if (code < aces_code_ceiling()) return aces_log2_decode(code);
  return kHalfMax;
}

double acescct_encode(double linear) {
  const AcescctToe& toe = acescct_toe();
  if (linear <= kAcescctLinearBreak) return toe.slope * linear + toe.offset;
  return aces_log2_encode(linear);
}

double acescct_decode(double code) {
  const AcescctToe& toe = acescct_toe();
  if (code <= toe.code_break) return (code - toe.offset) / toe.slope;
  if (code < aces_code_ceiling()) return aces_log2_decode(code);
  return kHalfMax;
}

TransferFunction parse_transfer_function(std::string_view name) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (key == "st2084" || key == "smpte2084") key = "pq";
  if (key == "bt.1886") key = "bt1886";
  for (const TransferEntry& e : kTransfers)
    if (e.name == key) return e.tf;
  std::string valid;
  for (const TransferEntry& e : kTransfers) valid += std::string(valid.empty() ? "" : ", ") + std::string(e.name);
  throw UsageError("unknown transfer function '" + std::string(name) + "' (valid: " + valid + ")");
}

std::string_view transfer_function_name(TransferFunction tf) {
  for (const TransferEntry& e : kTransfers)
    if (e.tf == tf) return e.name;
  return "unknown";
}

std::vector<std::string> transfer_function_names() {
  std::vector<std::string> names;
  for (const TransferEntry& e : kTransfers) names.emplace_back(e.name);
  return names;
}

double transfer_encode(TransferFunction tf, double linear) {
  switch (tf) {
    case TransferFunction::srgb: return srgb_encode(linear);
    case TransferFunction::bt1886: return bt1886_encode(linear);
    case TransferFunction::pq: return pq_encode_nits(linear * kPqPeakNits);
    case TransferFunction::hlg: return hlg_encode(linear);
    case TransferFunction::scrgb: return linear;
    case TransferFunction::acescc: return acescc_encode(linear);
    case TransferFunction::acescct: return acescct_encode(linear);
  }
  throw UsageError("unknown transfer function");
}

double transfer_decode(TransferFunction tf, double code) {
  switch (tf) {
    case TransferFunction::srgb: return srgb_decode(code);
    case TransferFunction::bt1886: return bt1886_decode(code);
    case TransferFunction::pq: return pq_decode_nits(code) / kPqPeakNits;
    case TransferFunction::hlg: return hlg_decode(code);
    case TransferFunction::scrgb: return code;
    case TransferFunction::acescc: return acescc_decode(code);
    case TransferFunction::acescct: return acescct_decode(code);
  }
  throw UsageError("unknown transfer function");
}

}  // namespace prism::color
