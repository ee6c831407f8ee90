#pragma once
// RGB → spectrum by Jakob & Hanika 2019: coefficient tables for srgb, acescg and rec2020,
// fitted at build time by our own optimiser (jakob_hanika_fit.h, tools/
// generate_jakob_hanika_tables.cpp) and embedded in the library. A lookup trilinearly
// interpolates the coefficients of the 8 surrounding grid points (paper §5).
//
// The tables describe reflectances in [0, 1]³: the spectrum s(λ), seen under the space's
// white illuminant (D65 for srgb and rec2020; for acescg an SPD with the ACES white, see
// illuminant_for_white), reproduces the RGB.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/sigmoid_polynomial.h"
#include "prism/core/vec.h"

namespace prism::color {

class JakobHanikaTable {
 public:
  // The table of a named space ("srgb", "acescg", "rec2020" and their aliases as
  // color_space() accepts them). Other spaces: UsageError.
  static const JakobHanikaTable& get(std::string_view space_name);
  static std::vector<std::string> space_names();

  // Coefficients for a reflectance; components are clamped to [0, 1].
  SigmoidPolynomial lookup(Vec3d rgb) const;

  const std::string& space() const { return space_; }
  int resolution() const { return resolution_; }

 private:
  JakobHanikaTable(std::string space, std::span<const unsigned char> bytes, int resolution);
  float coefficient(int l, int k, int j, int i, int c) const;

  std::string space_;
  int resolution_ = 0;
  std::vector<float> scale_;   // z of each slice (stored in the table)
  std::vector<float> chroma_;  // x, y of each node (jakob_hanika_chroma_node)
  std::vector<float> coefficients_;
};

namespace detail {
// Defined in the generated jakob_hanika_table_data.cpp (spectral_tables.cmake).
int jakob_hanika_embedded_resolution();
std::span<const unsigned char> jakob_hanika_embedded_table(std::string_view canonical_space);
}  // namespace detail

}  // namespace prism::color
