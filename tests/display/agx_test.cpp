// AgX (display/agx.h) against OpenColorIO 2.5.2 running Troy Sobotka's sobotka/AgX
// configuration (tests/data/oracles/agx_ocio.csv; origin in tests/data/oracles/README.md):
// linear Rec.709 in, code values of the config's "AgX" view on its sRGB, BT.1886 and
// Display P3 displays out. Prism runs the same inputs through the whole display pipeline
// (--rendering agx with the srgb-100nit, rec709-100nit and p3d65-100nit targets, each with
// its default encoding), so the test covers the curve, the matrices and the encodings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/display/agx.h"
#include "prism/display/display_pipeline.h"

namespace prism::display {
namespace {

struct AgxOracleRow {
  Vec3d in, out;
};

std::map<std::string, std::vector<AgxOracleRow>> read_agx_oracle() {
  std::ifstream file(std::string(PRISM_SOURCE_DIR) + "/tests/data/oracles/agx_ocio.csv");
  std::map<std::string, std::vector<AgxOracleRow>> rows;
  std::string line;
  std::getline(file, line);  // header
  while (std::getline(file, line)) {
    std::stringstream ss(line);
    std::string transform, field;
    std::getline(ss, transform, ',');
    std::getline(ss, field, ',');  // id
    AgxOracleRow r;
    for (int k = 0; k < 3; ++k) std::getline(ss, field, ','), r.in[k] = std::stod(field);
    for (int k = 0; k < 3; ++k) std::getline(ss, field, ','), r.out[k] = std::stod(field);
    rows[transform].push_back(r);
  }
  return rows;
}

// Max |Δcode| of the pipeline against one display of the oracle. The oracle is not clamped
// (OCIO's P3 conversion gives 1.00006 for a white); a display cannot show code above 1, so
// both sides are compared clamped to [0, 1].
double max_code_error(const std::vector<AgxOracleRow>& rows, OdtId target) {
  ImageRgbF film{static_cast<int>(rows.size()), 1, {}};
  for (const AgxOracleRow& r : rows)
    for (int k = 0; k < 3; ++k) film.rgb.push_back(static_cast<float>(r.in[k]));
  DisplaySettings s;
  s.rendering = Rendering::agx;
  s.odt = target;
  const DisplayImage shown = apply_display_pipeline(film, color::color_space("srgb"), s);
  double worst = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      // The film is float: compare against the oracle's output for the float input, which
      // the CSV's 9 significant digits reproduce exactly.
      const double expected = std::clamp(rows[i].out[k], 0.0, 1.0);
      worst = std::max(worst, std::abs(static_cast<double>(shown.code[3 * i + k]) - expected));
    }
  return worst;
}

// Bound: OCIO evaluates the base curve through the configuration's 4096-entry LUT, linear
// between entries; the curve's |f''| < 10 bounds that interpolation error by
// 10/(8·4095²) ≈ 7.5e-8 of code, and OCIO's float32 log2/pow chain adds a few 1e-7. 1e-5
// leaves room for both and for the float32 film and output, and is 200× tighter than the
// issue's 2e-3 acceptance: a wrong constant moves code by ≥ 1e-4 (measured on these
// inputs: the inset matrix rederived from sRGB's primaries instead of the config's literal
// gives 2.9e-4; the log floor moved by 0.004 stops, 2.2e-4).
constexpr double kCodeTolerance = 1e-5;

TEST(AgxOracle, SrgbDisplayMatchesOcio) {
  const auto rows = read_agx_oracle();
  ASSERT_EQ(rows.at("agx__sRGB__AgX").size(), 40u);
  EXPECT_LT(max_code_error(rows.at("agx__sRGB__AgX"), OdtId::srgb_100nit), kCodeTolerance);
}

TEST(AgxOracle, Bt1886DisplayMatchesOcio) {
  const auto rows = read_agx_oracle();
  EXPECT_LT(max_code_error(rows.at("agx__BT.1886__AgX"), OdtId::rec709_100nit), kCodeTolerance);
}

// Display P3: the configuration converts BT.709 to P3 through its own XYZ matrices, which
// send white (1, 1, 1) to (1.00006, 0.99998, 0.99998) — the oracle's row for a grey of 50 —
// so they differ from the exact conversion (rows summing to 1) by up to 6e-5 of light, about
// as much in γ-2.2 code near white. Bound 1e-4 (measured 7.0e-5).
TEST(AgxOracle, DisplayP3MatchesOcio) {
  const auto rows = read_agx_oracle();
  EXPECT_LT(max_code_error(rows.at("agx__Display P3__AgX"), OdtId::p3d65_100nit), 1e-4);
}

// The generator's curve passes its pivot and end points: middle grey's log position 10/16.5
// maps to 0.5, and 0 and 1 to themselves; and it rises monotonically.
TEST(AgxCurve, PivotEndPointsAndMonotone) {
  EXPECT_NEAR(agx_base_curve(10.0 / 16.5), 0.5, 1e-12);
  EXPECT_NEAR(agx_base_curve(0.0), 0.0, 1e-12);
  EXPECT_NEAR(agx_base_curve(1.0), 1.0, 1e-12);
  double previous = -1.0;
  for (int i = 0; i <= 4096; ++i) {
    const double y = agx_base_curve(i / 4096.0);
    EXPECT_GT(y, previous) << i;
    previous = y;
  }
}

TEST(AgxCurve, NegativeAndNonFiniteInputsShowBlack) {
  const Vec3d out = agx_display_linear({-1.0, std::nan(""), -0.0});
  for (int k = 0; k < 3; ++k) EXPECT_EQ(out[k], 0.0);
}

}  // namespace
}  // namespace prism::display
