#include "prism/display/display_encoding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"

namespace prism::display {

DisplayEncoding parse_display_encoding(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n == "srgb") return DisplayEncoding::srgb;
  if (n == "bt1886" || n == "rec709" || n == "bt.1886") return DisplayEncoding::bt1886;
  if (n == "pq" || n == "st2084") return DisplayEncoding::pq;
  if (n == "scrgb") return DisplayEncoding::scrgb;
  if (n == "gamma22" || n == "gamma2.2") return DisplayEncoding::gamma22;
  if (n == "gamma26" || n == "gamma2.6") return DisplayEncoding::gamma26;
  throw UsageError("unknown encoding '" + std::string(name) + "' (valid: srgb, bt1886, pq, scrgb, gamma22, gamma26)");
}

std::string_view display_encoding_name(DisplayEncoding e) {
  switch (e) {
    case DisplayEncoding::srgb: return "srgb";
    case DisplayEncoding::bt1886: return "bt1886";
    case DisplayEncoding::pq: return "pq";
    case DisplayEncoding::scrgb: return "scrgb";
    case DisplayEncoding::gamma22: return "gamma22";
    case DisplayEncoding::gamma26: return "gamma26";
  }
  return "?";
}

std::vector<std::string> display_encoding_names() { return {"srgb", "bt1886", "pq", "scrgb", "gamma22", "gamma26"}; }

bool is_float_encoding(DisplayEncoding e) { return e == DisplayEncoding::scrgb; }

color::IccToneCurve icc_tone_curve(DisplayEncoding e) {
  switch (e) {
    case DisplayEncoding::srgb: return color::IccToneCurve::srgb;
    case DisplayEncoding::bt1886: return color::IccToneCurve::gamma_2_4;
    case DisplayEncoding::gamma22: return color::IccToneCurve::gamma_2_2;
    case DisplayEncoding::gamma26: return color::IccToneCurve::gamma_2_6;
    default: break;
  }
  throw UsageError(fmt::format("the {} encoding has no ICC tone curve (it is not a relative SDR curve)",
                               display_encoding_name(e)));
}

double encode_display_nits(DisplayEncoding e, double nits, double white_nits) {
  switch (e) {
    case DisplayEncoding::srgb: return color::srgb_encode(std::clamp(nits / white_nits, 0.0, 1.0));
    case DisplayEncoding::bt1886: return color::bt1886_encode(std::clamp(nits / white_nits, 0.0, 1.0));
    case DisplayEncoding::pq: return color::pq_encode_nits(std::clamp(nits, 0.0, color::kPqPeakNits));
    case DisplayEncoding::scrgb: return color::scrgb_from_nits(nits);
    case DisplayEncoding::gamma22: return std::pow(std::clamp(nits / white_nits, 0.0, 1.0), 1.0 / 2.2);
    case DisplayEncoding::gamma26: return std::pow(std::clamp(nits / white_nits, 0.0, 1.0), 1.0 / 2.6);
  }
  return 0.0;
}

double decode_display_nits(DisplayEncoding e, double code, double white_nits) {
  switch (e) {
    case DisplayEncoding::srgb: return color::srgb_decode(code) * white_nits;
    case DisplayEncoding::bt1886: return color::bt1886_decode(code) * white_nits;
    case DisplayEncoding::pq: return color::pq_decode_nits(code);
    case DisplayEncoding::scrgb: return color::scrgb_to_nits(code);
    case DisplayEncoding::gamma22: return std::pow(std::max(code, 0.0), 2.2) * white_nits;
    case DisplayEncoding::gamma26: return std::pow(std::max(code, 0.0), 2.6) * white_nits;
  }
  return 0.0;
}

}  // namespace prism::display
