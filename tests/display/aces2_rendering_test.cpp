// `--rendering aces2` through the display pipeline (rendering_pipeline.h): for each display
// target, the code values of OpenColorIO 2.5.2's ACES 2.0 preset and display encoding that
// tests/data/oracles/aces2_targets.csv names (tests/data/oracles/aces2_ocio.csv; origin in
// tests/data/oracles/README.md). The transform itself is tested in
// aces2_output_transform_test.cpp; this test holds the wiring: preset per target, peak,
// primaries and the target's encoding. Also the inverse round trip and rec2020-100nit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/rendering_pipeline.h"

namespace prism::display {
namespace {

std::string oracle_path(const std::string& name) { return std::string(PRISM_SOURCE_DIR) + "/tests/data/oracles/" + name; }

// transform → rows of (AP0 input, code output).
std::map<std::string, std::vector<std::pair<Vec3d, Vec3d>>> read_aces2_oracle() {
  std::ifstream file(oracle_path("aces2_ocio.csv"));
  std::map<std::string, std::vector<std::pair<Vec3d, Vec3d>>> rows;
  std::string line;
  std::getline(file, line);
  while (std::getline(file, line)) {
    std::stringstream ss(line);
    std::string transform, field;
    std::getline(ss, transform, ',');
    std::getline(ss, field, ',');
    Vec3d in, out;
    for (int k = 0; k < 3; ++k) std::getline(ss, field, ','), in[k] = std::stod(field);
    for (int k = 0; k < 3; ++k) std::getline(ss, field, ','), out[k] = std::stod(field);
    rows[transform].emplace_back(in, out);
  }
  return rows;
}

std::map<std::string, std::string> read_targets() {
  std::ifstream file(oracle_path("aces2_targets.csv"));
  std::map<std::string, std::string> targets;
  std::string line;
  std::getline(file, line);
  while (std::getline(file, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the CSV has CRLF line ends
    const auto comma = line.find(',');
    targets[line.substr(0, comma)] = line.substr(comma + 1);
  }
  return targets;
}

DisplayImage run(const std::vector<std::pair<Vec3d, Vec3d>>& rows, OdtId target) {
  ImageRgbF film{static_cast<int>(rows.size()), 1, {}};
  for (const auto& r : rows)
    for (int k = 0; k < 3; ++k) film.rgb.push_back(static_cast<float>(r.first[k]));
  DisplaySettings s;
  s.rendering = Rendering::aces2;
  s.odt = target;
  return apply_display_pipeline(film, color::color_space("aces2065-1"), s);
}

// The acceptance bound, 1e-3 of code: a quarter of an 8-bit step, about one 10-bit
// step. The OCIO outputs are not clamped (a P3-limited colour can encode slightly below 0 in
// a Rec.2020 container); a file cannot hold that, so both sides are compared in [0, 1].
TEST(Aces2Rendering, EveryTargetMatchesItsAcademyPreset) {
  const auto oracle = read_aces2_oracle();
  const auto targets = read_targets();
  ASSERT_EQ(targets.size(), 7u);
  for (const auto& [target, transform] : targets) {
    const auto& rows = oracle.at(transform);
    const DisplayImage shown = run(rows, parse_odt(target));
    double worst = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(shown.code[3 * i + k] - std::clamp(rows[i].second[k], 0.0, 1.0)));
    EXPECT_LT(worst, 1e-3) << target << " vs " << transform;
    RecordProperty(target, std::to_string(worst));
  }
}

// rec2020-100nit has no Academy preset: the SDR Rec.709-limited rendering, its light
// converted to Rec.2020 primaries, BT.1886-encoded.
TEST(Aces2Rendering, Rec2020SdrIsTheRec709RenderingInARec2020Container) {
  const auto rows = read_aces2_oracle().at("bi__SDR-100nit-REC709_2.0__sRGB");
  const DisplayImage rec709 = run(rows, OdtId::rec709_100nit), rec2020 = run(rows, OdtId::rec2020_100nit);
  EXPECT_EQ(rec2020.encoding, DisplayEncoding::bt1886);
  const Mat3 m = color::conversion_matrix(color::color_space("srgb"), color::color_space("rec2020"));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Vec3d light = m * Vec3d{rec709.nits[3 * i], rec709.nits[3 * i + 1], rec709.nits[3 * i + 2]};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(rec2020.nits[3 * i + k], light[k], 1e-4 * 100.0);  // float32 light
  }
}

// Forward → inverse → forward gives the same code values (ACES 2.0 is built to invert): the
// inverse of a displayed colour is a scene colour the forward maps back onto it.
TEST(Aces2Rendering, InverseRoundTrip) {
  const auto rows = read_aces2_oracle().at("bi__HDR-1000nit-REC2020_2.0__REC.2100-PQ");
  for (OdtId target : {OdtId::srgb_100nit, OdtId::rec2020_pq_1000nit, OdtId::p3d65_100nit}) {
    const DisplayImage first = run(rows, target);
    DisplaySettings s;
    s.rendering = Rendering::aces2;
    s.odt = target;
    const ImageRgbF scene = aces2_inverse(ImageRgbF{first.width, 1, first.code}, first.encoding, s);
    const DisplayImage second = apply_display_pipeline(scene, color::color_space("aces2065-1"), s);
    for (std::size_t i = 0; i < first.code.size(); ++i)
      // The forward's light is exactly invertible, but its code is not always: the encoding
      // clips light below 0 (a colour on the limiting gamut's edge, converted to the
      // container), and the inverse then starts from a colour just outside the forward's
      // range. The 1e-3 of code (measured 3.2e-4, at such colours).
      EXPECT_NEAR(second.code[i], first.code[i], 1e-3) << odt_description(target).name << " " << i;
  }
}

TEST(Aces2Rendering, PeakNits) {
  ImageRgbF film{1, 1, {100.0f, 100.0f, 100.0f}};
  DisplaySettings s;
  s.rendering = Rendering::aces2;
  s.odt = OdtId::rec2020_pq_1000nit;
  s.peak_nits = 600.0;
  const DisplayImage shown = apply_display_pipeline(film, color::color_space("aces2065-1"), s);
  EXPECT_EQ(shown.y_max_nits, 600.0);
  EXPECT_LE(shown.nits[1], 600.0 + 1e-3);
  EXPECT_GT(shown.nits[1], 300.0);  // a bright grey reaches toward the peak
  s.peak_nits = 50.0;
  EXPECT_THROW(apply_display_pipeline(film, color::color_space("aces2065-1"), s), UsageError);
  s.peak_nits = 20000.0;
  EXPECT_THROW(apply_display_pipeline(film, color::color_space("aces2065-1"), s), UsageError);
}

}  // namespace
}  // namespace prism::display
