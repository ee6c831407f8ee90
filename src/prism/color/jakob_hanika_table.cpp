// Lookup and trilinear interpolation in the embedded Jakob–Hanika coefficient tables.
#include "prism/color/jakob_hanika_table.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

#include "prism/color/color_space.h"
#include "prism/color/jakob_hanika_fit.h"
#include "prism/core/error.h"
#include "prism/core/guide_table.h"

namespace prism::color {

std::vector<std::string> JakobHanikaTable::space_names() { return {"srgb", "acescg", "rec2020"}; }

const JakobHanikaTable& JakobHanikaTable::get(std::string_view space_name) {
  const std::string canonical = color_space(space_name).name;
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<JakobHanikaTable>> tables;
  std::lock_guard lock(mutex);
  auto found = tables.find(canonical);
  if (found != tables.end()) return *found->second;
  const std::span<const unsigned char> bytes = detail::jakob_hanika_embedded_table(canonical);
  if (bytes.empty())
    throw UsageError("no Jakob-Hanika table for colour space '" + canonical +
                     "' (available: srgb, acescg, rec2020)");
  auto table = std::unique_ptr<JakobHanikaTable>(
      new JakobHanikaTable(canonical, bytes, detail::jakob_hanika_embedded_resolution()));
  return *tables.emplace(canonical, std::move(table)).first->second;
}

JakobHanikaTable::JakobHanikaTable(std::string space, std::span<const unsigned char> bytes, int resolution)
    : space_(std::move(space)), resolution_(resolution) {
  const std::size_t res = static_cast<std::size_t>(resolution);
  scale_.resize(res);
  coefficients_.resize(3 * res * res * res * 3);
  if (bytes.size() != (scale_.size() + coefficients_.size()) * sizeof(float))
    throw Error("embedded Jakob-Hanika table for '" + space_ + "' has the wrong size");
  std::memcpy(scale_.data(), bytes.data(), scale_.size() * sizeof(float));
  std::memcpy(coefficients_.data(), bytes.data() + scale_.size() * sizeof(float),
              coefficients_.size() * sizeof(float));
  for (int i = 0; i < resolution; ++i) chroma_.push_back(static_cast<float>(jakob_hanika_chroma_node(i, resolution)));
  if (resolution < 2 || resolution > 256) throw Error("Jakob-Hanika tables need 2 to 256 nodes per axis");
  for (std::size_t k = 0; k + 1 < scale_.size(); ++k)
    if (!(scale_[k] < scale_[k + 1]) || !(chroma_[k] < chroma_[k + 1]))
      throw Error("embedded Jakob-Hanika table for '" + space_ + "': nodes not increasing");
  chroma_guide_ = node_guide(chroma_);
  scale_guide_ = node_guide(scale_);
}

std::vector<std::uint8_t> JakobHanikaTable::node_guide(const std::vector<float>& nodes) {
  // Entry g: the last node at or below g / kNodeGuideCells, which is at or below every v
  // with ⌊v · kNodeGuideCells⌋ = g (a power of two: the product is exact in float), so the
  // walk forward from it finds std::upper_bound's node.
  std::vector<std::uint8_t> guide(kNodeGuideCells);
  fill_guide_table(std::span<const float>(nodes), std::span(guide));
  return guide;
}

// std::upper_bound's node, found from the axis' guide and a forward walk that rarely steps:
// a search's halving steps were coin-flip branches or, without branches, a chain of
// dependent loads, at every textured shading point and every environment-map radiance.
int JakobHanikaTable::cell(const std::vector<float>& nodes, const std::vector<std::uint8_t>& guide, double v) {
  const float fv = float(v);  // compared as std::upper_bound(nodes, float(v)) did
  const int n = static_cast<int>(nodes.size());
  const int g = fv > 0.0f ? (fv < 1.0f ? static_cast<int>(fv * kNodeGuideCells) : kNodeGuideCells - 1) : 0;
  int i = guide[static_cast<std::size_t>(g)];
  while (i + 1 < n && nodes[static_cast<std::size_t>(i) + 1] <= fv) ++i;
  return std::clamp(i, 0, n - 2);
}

float JakobHanikaTable::coefficient(int l, int k, int j, int i, int c) const {
  const std::size_t res = static_cast<std::size_t>(resolution_);
  return coefficients_[((((static_cast<std::size_t>(l) * res + k) * res + j) * res + i) * 3) + c];
}

SigmoidPolynomial JakobHanikaTable::lookup(Vec3d rgb) const {
  for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(std::isnan(rgb[c]) ? 0.0 : rgb[c], 0.0, 1.0);
  // Greys are exactly representable (c₀ = c₁ = 0): skip the table and its interpolation error.
  if (rgb.x == rgb.y && rgb.y == rgb.z) return SigmoidPolynomial::constant(rgb.x);

  const int l = rgb.x >= rgb.y ? (rgb.x >= rgb.z ? 0 : 2) : (rgb.y >= rgb.z ? 1 : 2);
  const double z = rgb[l];
  // The cell along each axis and the position in it, linear between the two nodes.
  auto locate = [](const std::vector<float>& nodes, int at, double v, double& t) {
    t = (v - nodes[at]) / (nodes[at + 1] - nodes[at]);
    return at;
  };
  double dx, dy, dz;
  const double x = rgb[(l + 1) % 3] / z, y = rgb[(l + 2) % 3] / z;
  const int xi = locate(chroma_, chroma_cell(x), x, dx), yi = locate(chroma_, chroma_cell(y), y, dy);
  const int zi = locate(scale_, scale_cell(z), z, dz);

  double c[3];
  for (int n = 0; n < 3; ++n) {
    auto at = [&](int dk, int dj, int di) { return double(coefficient(l, zi + dk, yi + dj, xi + di, n)); };
    auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
    c[n] = lerp(dz,
                lerp(dy, lerp(dx, at(0, 0, 0), at(0, 0, 1)), lerp(dx, at(0, 1, 0), at(0, 1, 1))),
                lerp(dy, lerp(dx, at(1, 0, 0), at(1, 0, 1)), lerp(dx, at(1, 1, 0), at(1, 1, 1))));
  }
  return {c[0], c[1], c[2]};
}

}  // namespace prism::color
