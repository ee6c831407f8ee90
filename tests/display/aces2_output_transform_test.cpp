// The ACES 2.0 Output Transform against an independent implementation: OpenColorIO 2.5.2's
// built-in "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - <preset>_2.0" transforms, alone
// (display XYZ) and followed by its display encodings (code values), on ACES2065-1 inputs
// from black to far above the tonescale's roof, neutral and saturated, inside and outside
// AP1 (tests/data/oracles/aces2_ocio.csv; origin in tests/data/oracles/README.md).
//
// Tolerances:
//  - Code values: 1e-3, a quarter of an 8-bit step and about one 10-bit step. A wrong
//    constant, table or stage order moves saturated colours by 1e-2 and more; OCIO
//    computes in float32 and builds its tables by bisection to fixed tolerances, which
//    leaves differences of order 1e-5 (measured ≤ 1e-4 of code value).
//    One exception: a channel with no light at all (a colour on the limiting gamut's
//    surface). OCIO passes the result through XYZ in float32 (limiting RGB → XYZ → display
//    RGB), leaving that channel at ±1e-7 of the pixel's brightest one; gamma 2.4/2.6 and PQ
//    have an infinite slope at 0, so that noise alone is up to 1.6e-3 of code (PQ of −1e-4
//    cd/m² beside 2000 cd/m²). There the light itself is compared: within 1e-6 of the
//    pixel's brightest channel (measured ≤ 1.3e-7), which no real error fits into.
//  - Display XYZ: 1e-4 of the colour's largest component (1.0 = 100 cd/m², floor 0.01):
//    the same float32 and bisection noise, measured ≤ 4e-5 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/aces2_output_transform.h"
#include "prism/display/display_encoding.h"

namespace prism::display {
namespace {

struct OracleRow {
  std::string transform;
  Vec3d in, out;
};

std::vector<OracleRow> read_oracle() {
  std::ifstream file(std::string(PRISM_SOURCE_DIR) + "/tests/data/oracles/aces2_ocio.csv");
  std::vector<OracleRow> rows;
  std::string line;
  std::getline(file, line);  // header
  while (std::getline(file, line)) {
    std::stringstream ss(line);
    std::string transform, field;
    std::getline(ss, transform, ',');
    std::vector<double> v;
    while (std::getline(ss, field, ',')) v.push_back(std::stod(field));
    if (v.size() != 7) continue;
    rows.push_back({transform, {v[1], v[2], v[3]}, {v[4], v[5], v[6]}});
  }
  return rows;
}

struct Preset {
  double peak_nits;
  std::string limiting;
};

// OCIO's preset names → peak and limiting primaries (prism::color names).
Preset preset(const std::string& name) {
  static const std::map<std::string, Preset> presets = {
      {"SDR-100nit-REC709_2.0", {100, "rec709"}},     {"SDR-100nit-P3-D65_2.0", {100, "p3-d65"}},
      {"HDR-500nit-REC2020_2.0", {500, "rec2020"}},   {"HDR-1000nit-REC2020_2.0", {1000, "rec2020"}},
      {"HDR-2000nit-REC2020_2.0", {2000, "rec2020"}}, {"HDR-4000nit-REC2020_2.0", {4000, "rec2020"}},
      {"HDR-1000nit-P3-D65_2.0", {1000, "p3-d65"}}};
  return presets.at(name);
}

// OCIO's display encodings: the container primaries and display light (cd/m²) → code.
struct Encoding {
  std::string primaries;
  double (*encode)(double nits);
  double (*decode)(double code);
};

Encoding encoding(const std::string& name) {
  // Decoding mirrors negative codes (OCIO keeps the sign of a slightly negative channel).
  static const std::map<std::string, Encoding> encodings = {
      {"sRGB",
       {"rec709", [](double n) { return encode_display_nits(DisplayEncoding::srgb, n, 100.0); },
        [](double c) { return std::copysign(decode_display_nits(DisplayEncoding::srgb, std::abs(c), 100.0), c); }}},
      {"REC.1886-REC.709",
       {"rec709", [](double n) { return encode_display_nits(DisplayEncoding::bt1886, n, 100.0); },
        [](double c) { return std::copysign(decode_display_nits(DisplayEncoding::bt1886, std::abs(c), 100.0), c); }}},
      // Gamma 2.6 (the P3-D65 SDR cinema/mastering EOTF): a pure power on relative light.
      {"G2.6-P3-D65",
       {"p3-d65", [](double n) { return std::pow(std::max(n / 100.0, 0.0), 1.0 / 2.6); },
        [](double c) { return std::copysign(100.0 * std::pow(std::abs(c), 2.6), c); }}},
      {"REC.2100-PQ",
       {"rec2020", [](double n) { return encode_display_nits(DisplayEncoding::pq, n, 100.0); },
        [](double c) { return std::copysign(decode_display_nits(DisplayEncoding::pq, std::abs(c), 100.0), c); }}},
      {"ST2084-P3-D65",
       {"p3-d65", [](double n) { return encode_display_nits(DisplayEncoding::pq, n, 100.0); },
        [](double c) { return std::copysign(decode_display_nits(DisplayEncoding::pq, std::abs(c), 100.0), c); }}}};
  return encodings.at(name);
}

const Aces2OutputTransform& transform_for(const std::string& preset_name, const std::string& encoding_primaries) {
  static std::map<std::string, std::unique_ptr<Aces2OutputTransform>> cache;
  const std::string key = preset_name + "|" + encoding_primaries;
  auto& slot = cache[key];
  if (!slot) {
    const Preset p = preset(preset_name);
    slot = std::make_unique<Aces2OutputTransform>(
        Aces2Parameters{p.peak_nits, p.limiting, encoding_primaries});
  }
  return *slot;
}

double max_abs_difference(const Vec3d& a, const Vec3d& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

TEST(Aces2OutputTransform, MatchesOcioDisplayXyzOnEveryPreset) {
  const std::vector<OracleRow> rows = read_oracle();
  std::map<std::string, double> worst;
  int checked = 0;
  for (const OracleRow& row : rows) {
    if (row.transform.rfind("xyz__", 0) != 0) continue;
    const std::string name = row.transform.substr(5);
    const Aces2OutputTransform& t = transform_for(name, preset(name).limiting);
    const Vec3d xyz = color::color_space(preset(name).limiting).rgb_to_xyz * (t.display_nits(row.in) / 100.0);
    const double error = max_abs_difference(xyz, row.out) / std::max(max_component(row.out), 0.01);
    worst[name] = std::max(worst[name], error);
    EXPECT_LE(error, 1e-4) << name << " input " << row.in.x << " " << row.in.y << " " << row.in.z << ": "
                           << xyz.x << " " << xyz.y << " " << xyz.z << " vs OCIO " << row.out.x << " "
                           << row.out.y << " " << row.out.z;
    ++checked;
  }
  EXPECT_EQ(checked, 7 * 60);
  for (const auto& [name, e] : worst) std::printf("  xyz %-26s max relative error %.2e\n", name.c_str(), e);
}

TEST(Aces2OutputTransform, EncodingPrimariesOnlyChangeTheContainer) {
  // The rendering depends on the limiting gamut alone: the same preset in a Rec.2020
  // container emits the same light (OCIO's presets all go through XYZ the same way).
  for (const OracleRow& row : read_oracle()) {
    if (row.transform.rfind("xyz__", 0) != 0) continue;
    const std::string name = row.transform.substr(5);
    const Vec3d xyz =
        color::color_space("rec2020").rgb_to_xyz * (transform_for(name, "rec2020").display_nits(row.in) / 100.0);
    EXPECT_LE(max_abs_difference(xyz, row.out) / std::max(max_component(row.out), 0.01), 1e-4) << name;
  }
}

TEST(Aces2OutputTransform, MatchesOcioCodeValuesOnEveryPresetAndEncoding) {
  const std::vector<OracleRow> rows = read_oracle();
  std::map<std::string, double> worst;
  int checked = 0;
  for (const OracleRow& row : rows) {
    if (row.transform.rfind("bi__", 0) != 0) continue;
    const std::string rest = row.transform.substr(4);
    const std::size_t split = rest.find("__");
    const std::string name = rest.substr(0, split);
    const Encoding enc = encoding(rest.substr(split + 2));
    const Vec3d nits = transform_for(name, enc.primaries).display_nits(row.in);
    const Vec3d oracle_nits{enc.decode(row.out.x), enc.decode(row.out.y), enc.decode(row.out.z)};
    const double brightest = max_component(Vec3d(std::abs(oracle_nits.x), std::abs(oracle_nits.y), std::abs(oracle_nits.z)));
    for (int c = 0; c < 3; ++c) {
      const double error = std::abs(enc.encode(nits[c]) - row.out[c]);
      const bool unlit = std::abs(oracle_nits[c]) <= 1e-6 * brightest && std::abs(nits[c]) <= 1e-6 * brightest;
      if (!unlit) worst[row.transform] = std::max(worst[row.transform], error);
      EXPECT_TRUE(error <= 1e-3 || unlit)
          << row.transform << " input " << row.in.x << " " << row.in.y << " " << row.in.z << " channel " << c
          << ": code " << enc.encode(nits[c]) << " vs OCIO " << row.out[c] << " (" << nits[c] << " vs "
          << oracle_nits[c] << " cd/m²)";
    }
    ++checked;
  }
  EXPECT_EQ(checked, 7 * 60);
  for (const auto& [name, e] : worst)
    std::printf("  %-50s max code error %.2e (lit channels)\n", name.c_str(), e);
}

// Display light inside the display's cube (5 % … 95 % of peak per channel) → ACES → display
// comes back: the inverse undoes the clamp-free part of the forward transform. The gamut
// compressor's inverse is approximate above its analytical threshold (CTL
// gamut_compress_inv iterates once), which shows as ≤ 3e-6 of peak here and up to ~2 % on the
// cube's faces themselves; 1e-4 of peak is far below a visible or 10-bit difference.
TEST(Aces2OutputTransform, InverseRoundTripsInsideTheDisplayGamut) {
  const Aces2Parameters cases[] = {
      {100, "rec709", "rec709"}, {100, "p3-d65", "p3-d65"}, {1000, "rec2020", "rec2020"}, {4000, "p3-d65", "p3-d65"}};
  for (const Aces2Parameters& p : cases) {
    const Aces2OutputTransform t(p);
    const int n = 6;
    for (int r = 0; r <= n; ++r)
      for (int g = 0; g <= n; ++g)
        for (int b = 0; b <= n; ++b) {
          const Vec3d display = (Vec3d(0.05) + Vec3d(r, g, b) * (0.9 / n)) * p.peak_luminance_nits;
          const Vec3d aces = t.aces_from_display_nits(display);
          const Vec3d again = t.display_nits(aces);
          EXPECT_LE(max_abs_difference(again, display), 1e-4 * p.peak_luminance_nits)
              << p.limiting_primaries << " " << p.peak_luminance_nits << ": " << display.x << " " << display.y
              << " " << display.z << " → " << again.x << " " << again.y << " " << again.z;
          // And ACES → display → ACES for those scene colours (relative to their largest AP0 value).
          const Vec3d aces_again = t.aces_from_display_nits(again);
          EXPECT_LE(max_abs_difference(aces_again, aces), 1e-3 * std::max(max_component(aces), 1e-3));
        }
  }
}

TEST(Aces2OutputTransform, GreysComeOutNeutralIncreasingAndSaturateAtPeak) {
  // The CAM adapts to each space's own white, so AP0 greys (ACES white) render as display
  // greys (D65); the tonescale increases monotonically and reaches the peak at the roof.
  for (const double peak : {100.0, 1000.0, 4000.0}) {
    const Aces2OutputTransform t({peak, "rec2020", "rec2020"});
    double previous = 0.0;
    for (double scene = 1e-4; scene < 2e4; scene *= 1.5) {
      const Vec3d nits = t.display_nits(Vec3d(scene));
      EXPECT_NEAR(nits.x, nits.y, 1e-9 * nits.y);
      EXPECT_NEAR(nits.z, nits.y, 1e-9 * nits.y);
      EXPECT_GE(nits.y, previous);
      EXPECT_LE(nits.y, peak * (1.0 + 1e-12));
      previous = nits.y;
    }
    EXPECT_GE(previous, 0.999 * peak);
  }
}

TEST(Aces2OutputTransform, RejectsPeaksOutside100To10000Nits) {
  EXPECT_THROW(Aces2OutputTransform({99.0, "rec709", "rec709"}), UsageError);
  EXPECT_THROW(Aces2OutputTransform({10001.0, "rec2020", "rec2020"}), UsageError);
  EXPECT_THROW(Aces2OutputTransform({std::nan(""), "rec2020", "rec2020"}), UsageError);
  EXPECT_NO_THROW(Aces2OutputTransform({10000.0, "rec2020", "rec2020"}));
}

TEST(Aces2OutputTransform, RejectsUnknownSpacesAndMismatchedWhites) {
  EXPECT_THROW(Aces2OutputTransform({100.0, "no-such-space", "rec709"}), UsageError);
  // DCI-P3's white is not D65: simulating another white (white scaling) is not implemented.
  EXPECT_THROW(Aces2OutputTransform({100.0, "dci-p3", "rec2020"}), UsageError);
}

}  // namespace
}  // namespace prism::display
