// The named colour spaces: primaries and whites as their defining standards print them,
// matrices derived at first use (see color_space.h for the white-point convention).
#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "prism/color/color_space.h"

namespace prism::color {
namespace {

std::vector<ColorSpace> build_named_spaces() {
  // ITU-R BT.709-6 Table 1 item 1.3 (also IEC 61966-2-1 sRGB).
  constexpr Chromaticity r709{0.64, 0.33}, g709{0.30, 0.60}, b709{0.15, 0.06};
  // SMPTE RP 431-2 / EG 432-1 P3 primaries.
  constexpr Chromaticity rP3{0.680, 0.320}, gP3{0.265, 0.690}, bP3{0.150, 0.060};
  // Adobe RGB (1998) Color Image Encoding v2005-05 §4.3.1.1: BT.709 red and blue.
  constexpr Chromaticity gAdobe{0.21, 0.71};
  // ITU-R BT.2020-2 Table 3 item 3.3.
  constexpr Chromaticity r2020{0.708, 0.292}, g2020{0.170, 0.797}, b2020{0.131, 0.046};
  // SMPTE ST 2065-1:2012 §4.1 (AP0) and Academy S-2014-004 §4.1 (AP1).
  constexpr Chromaticity rAp0{0.7347, 0.2653}, gAp0{0.0, 1.0}, bAp0{0.0001, -0.0770};
  constexpr Chromaticity rAp1{0.713, 0.293}, gAp1{0.165, 0.830}, bAp1{0.128, 0.044};

  std::vector<ColorSpace> spaces;
  spaces.push_back(make_color_space("srgb", r709, g709, b709, kWhiteD65));
  spaces.push_back(make_color_space("display-p3", rP3, gP3, bP3, kWhiteD65));
  spaces.push_back(make_color_space("dci-p3", rP3, gP3, bP3, kWhiteDci));
  spaces.push_back(make_color_space("adobe-rgb", r709, gAdobe, b709, kWhiteD65));
  spaces.push_back(make_color_space("rec2020", r2020, g2020, b2020, kWhiteD65));
  spaces.push_back(make_color_space("aces2065-1", rAp0, gAp0, bAp0, kWhiteAces));
  spaces.push_back(make_color_space("acescg", rAp1, gAp1, bAp1, kWhiteAces));
  spaces.push_back(xyz_space("xyz", kWhiteD65));
  spaces.push_back(xyz_space("xyz-d50", kWhiteD50));
  return spaces;
}

const std::vector<ColorSpace>& named_spaces() {
  static const std::vector<ColorSpace> spaces = build_named_spaces();
  return spaces;
}

// Alias → canonical name. Keys are already normalised (lower case, '_' and ' ' as '-').
constexpr std::pair<std::string_view, std::string_view> kAliases[] = {
    {"rec709", "srgb"},         {"rec.709", "srgb"},       {"bt709", "srgb"},
    {"bt.709", "srgb"},         {"linear-srgb", "srgb"},   {"lin-srgb", "srgb"},
    {"p3", "display-p3"},       {"p3-d65", "display-p3"},  {"displayp3", "display-p3"},
    {"p3-dci", "dci-p3"},       {"dcip3", "dci-p3"},       {"adobergb", "adobe-rgb"},
    {"adobe-rgb-1998", "adobe-rgb"}, {"adobe-1998", "adobe-rgb"},
    {"rec.2020", "rec2020"},    {"bt2020", "rec2020"},     {"bt.2020", "rec2020"},
    {"ap0", "aces2065-1"},      {"aces", "aces2065-1"},    {"aces-ap0", "aces2065-1"},
    {"ap1", "acescg"},          {"aces-ap1", "acescg"},    {"ciexyz", "xyz"},
    {"cie-xyz", "xyz"},         {"xyz-d65", "xyz"},        {"ciexyz-d50", "xyz-d50"},
};

std::string normalise(std::string_view name) {
  std::string out(name);
  for (char& c : out) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c == '_' || c == ' ') c = '-';
  }
  return out;
}

}  // namespace

ColorSpace xyz_space(std::string name, Chromaticity white) {
  return ColorSpace{std::move(name), {1.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}, white,
                    Mat3::identity(), Mat3::identity()};
}

const ColorSpace& color_space(std::string_view name) {
  std::string key = normalise(name);
  for (const auto& [alias, canonical] : kAliases)
    if (key == alias) key = canonical;
  for (const ColorSpace& space : named_spaces())
    if (space.name == key) return space;

  std::string valid;
  for (const std::string& n : color_space_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw UsageError("unknown colour space '" + std::string(name) + "' (valid: " + valid +
                   ")");
}

std::vector<std::string> color_space_names() {
  std::vector<std::string> names;
  for (const ColorSpace& space : named_spaces()) names.push_back(space.name);
  return names;
}

}  // namespace prism::color
