#pragma once
// RGB → spectrum by Jakob & Hanika 2019: coefficient tables for srgb, acescg and rec2020,
// fitted at build time by our own optimiser (jakob_hanika_fit.h, tools/
// generate_jakob_hanika_tables.cpp) and embedded in the library. A lookup trilinearly
// interpolates the coefficients of the 8 surrounding grid points (paper §5).
//
// The tables describe reflectances in [0, 1]³: the spectrum s(λ), seen under the flat
// spectrum (illuminant E, the neutral of a spectral render) and adapted from E to the
// space's white by Bradford as the film does, reproduces the RGB (see
// jakob_hanika_target_xyz_matrix for why not under the space's own white).
#include <cstdint>
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

  // The interval [node i, node i + 1] a value falls in along the chroma (x, y) or the
  // scale (z) axis: the last node at or below the value (compared in float), kept within
  // [0, resolution − 2]; what lookup interpolates between. v must not be NaN.
  int chroma_cell(double v) const { return cell(chroma_, chroma_guide_, v); }
  int scale_cell(double v) const { return cell(scale_, scale_guide_, v); }
  const std::vector<float>& chroma_nodes() const { return chroma_; }
  const std::vector<float>& scale_nodes() const { return scale_; }

  const std::string& space() const { return space_; }
  int resolution() const { return resolution_; }

 private:
  JakobHanikaTable(std::string space, std::span<const unsigned char> bytes, int resolution);
  float coefficient(int l, int k, int j, int i, int c) const;
  // Per axis, the last node at or below each of kNodeGuideCells equal steps of [0, 1]: a
  // lookup starts there and walks forward, which at 4096 steps for 64 nodes is almost
  // never a step, except past the densest nodes at the ends (smoothstep spacing).
  static constexpr int kNodeGuideCells = 4096;
  static std::vector<std::uint8_t> node_guide(const std::vector<float>& nodes);
  static int cell(const std::vector<float>& nodes, const std::vector<std::uint8_t>& guide, double v);

  std::string space_;
  int resolution_ = 0;
  std::vector<float> scale_;   // z of each slice (stored in the table)
  std::vector<float> chroma_;  // x, y of each node (jakob_hanika_chroma_node)
  std::vector<float> coefficients_;
  std::vector<std::uint8_t> chroma_guide_, scale_guide_;
};

namespace detail {
// Defined in the generated jakob_hanika_table_data.cpp (spectral_tables.cmake).
int jakob_hanika_embedded_resolution();
std::span<const unsigned char> jakob_hanika_embedded_table(std::string_view canonical_space);
}  // namespace detail

}  // namespace prism::color
