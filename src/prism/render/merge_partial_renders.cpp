#include "prism/render/merge_partial_renders.h"

#include <algorithm>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {

MergedRender merge_partial_renders(const std::vector<PartialRender>& parts) {
  if (parts.empty()) throw UsageError("nothing to merge");
  const PartialRender& first = parts.front();
  std::vector<std::pair<int, int>> ranges;
  for (const auto& p : parts) {
    if (p.image.width != first.image.width || p.image.height != first.image.height)
      throw UsageError(fmt::format("'{}' is {}x{} but '{}' is {}x{}", p.name, p.image.width, p.image.height,
                                   first.name, first.image.width, first.image.height));
    if (p.fingerprint != first.fingerprint)
      throw UsageError(fmt::format("'{}' was rendered from a different scene or settings than '{}'", p.name, first.name));
    if (p.sample_end <= p.sample_begin)
      throw UsageError(fmt::format("'{}' holds no samples (range {}:{})", p.name, p.sample_begin, p.sample_end));
    ranges.emplace_back(p.sample_begin, p.sample_end);
  }
  std::sort(ranges.begin(), ranges.end());
  MergedRender merged;
  for (const auto& r : ranges) {
    if (!merged.ranges.empty() && r.first < merged.ranges.back().second)
      throw UsageError(fmt::format("sample ranges overlap at sample {}: each sample may be merged once", r.first));
    if (!merged.ranges.empty() && r.first == merged.ranges.back().second)
      merged.ranges.back().second = r.second;
    else
      merged.ranges.push_back(r);
    merged.samples += r.second - r.first;
  }

  std::vector<double> sum(first.image.rgb.size(), 0.0);
  for (const auto& p : parts) {
    const double weight = p.sample_end - p.sample_begin;
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += weight * p.image.rgb[i];
  }
  merged.image = ImageRgbF{first.image.width, first.image.height, std::vector<float>(sum.size())};
  for (std::size_t i = 0; i < sum.size(); ++i) merged.image.rgb[i] = static_cast<float>(sum[i] / merged.samples);
  return merged;
}

}  // namespace prism
