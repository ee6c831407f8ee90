#include "prism/render/merge_partial_renders.h"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace {

// Σ w_p x_p / Σ w_p per value, in double.
std::vector<float> weighted_mean(const std::vector<PartialRender>& parts, const std::vector<float> AovImages::*channel) {
  const std::size_t size = (parts.front().aovs.*channel).size();
  std::vector<double> sum(size, 0.0);
  double total = 0.0;
  for (const auto& p : parts) {
    const double weight = p.sample_end - p.sample_begin;
    const std::vector<float>& v = p.aovs.*channel;
    for (std::size_t i = 0; i < size; ++i) sum[i] += weight * v[i];
    total += weight;
  }
  std::vector<float> out(size);
  for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<float>(sum[i] / total);
  return out;
}

ImageRgbF weighted_mean(const std::vector<PartialRender>& parts, ImageRgbF AovImages::*layer) {
  const ImageRgbF& first = parts.front().aovs.*layer;
  std::vector<double> sum(first.rgb.size(), 0.0);
  double total = 0.0;
  for (const auto& p : parts) {
    const double weight = p.sample_end - p.sample_begin;
    const ImageRgbF& v = p.aovs.*layer;
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += weight * v.rgb[i];
    total += weight;
  }
  ImageRgbF out{first.width, first.height, std::vector<float>(sum.size())};
  for (std::size_t i = 0; i < sum.size(); ++i) out.rgb[i] = static_cast<float>(sum[i] / total);
  return out;
}

// Depth is the mean over the samples that hit: each part counts with samples × coverage
// (its number of hits); a pixel no part hit stays +inf.
std::vector<float> merged_depth(const std::vector<PartialRender>& parts) {
  const std::size_t size = parts.front().aovs.depth.size();
  std::vector<double> sum(size, 0.0), hits(size, 0.0);
  for (const auto& p : parts) {
    const double samples = p.sample_end - p.sample_begin;
    for (std::size_t i = 0; i < size; ++i) {
      const double h = samples * p.aovs.depth_coverage[i];
      if (h > 0.0) {
        sum[i] += h * p.aovs.depth[i];
        hits[i] += h;
      }
    }
  }
  std::vector<float> out(size);
  for (std::size_t i = 0; i < size; ++i)
    out[i] = hits[i] > 0.0 ? static_cast<float>(sum[i] / hits[i]) : std::numeric_limits<float>::infinity();
  return out;
}

// Variance of the merged pixel mean, per channel, from each part's sample count n, mean m
// and variance of the mean v: its sum of squared deviations is M2 = n (n − 1) v, and the
// parts combine by Chan, Golub & LeVeque (1979): M2 = Σ M2_i + Σ n_i (m_i − m)², m the
// merged mean. Every term is non-negative, so no cancellation (unlike Σx² − n m²) in the
// float values the files hold. A one-sample part has M2 = 0, exactly.
ImageRgbF merged_variance(const std::vector<PartialRender>& parts, const ImageRgbF& merged_mean, double samples) {
  ImageRgbF out{merged_mean.width, merged_mean.height, std::vector<float>(merged_mean.rgb.size())};
  for (std::size_t i = 0; i < out.rgb.size(); ++i) {
    double m2 = 0.0;
    for (const auto& p : parts) {
      const double n = p.sample_end - p.sample_begin;
      const double d = double(p.image.rgb[i]) - merged_mean.rgb[i];
      m2 += n * (n - 1.0) * p.aovs.variance.rgb[i] + n * d * d;
    }
    out.rgb[i] = samples >= 2.0 ? static_cast<float>(m2 / (samples - 1.0) / samples) : 0.0f;
  }
  return out;
}

void check_aov_sizes(const PartialRender& p) {
  const std::size_t pixels = static_cast<std::size_t>(p.image.width) * static_cast<std::size_t>(p.image.height);
  const AovImages& a = p.aovs;
  const bool ok = (!a.set.albedo || a.albedo.rgb.size() == 3 * pixels) && (!a.set.normal || a.normal.rgb.size() == 3 * pixels) &&
                  (!a.set.depth || (a.depth.size() == pixels && a.depth_coverage.size() == pixels)) &&
                  (!a.set.variance || a.variance.rgb.size() == 3 * pixels) &&
                  (!a.set.sample_count || a.sample_count.size() == pixels);
  if (!ok) throw UsageError(fmt::format("'{}' has AOV layers of the wrong size", p.name));
}

}  // namespace

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
    if (p.aovs.set != first.aovs.set)
      throw UsageError(fmt::format("'{}' holds the AOVs '{}' but '{}' holds '{}'", p.name, format_aov_list(p.aovs.set),
                                   first.name, format_aov_list(first.aovs.set)));
    check_aov_sizes(p);
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
  merged.aovs.set = first.aovs.set;
  if (first.aovs.set.albedo) merged.aovs.albedo = weighted_mean(parts, &AovImages::albedo);
  if (first.aovs.set.normal) merged.aovs.normal = weighted_mean(parts, &AovImages::normal);
  if (first.aovs.set.depth) {
    merged.aovs.depth = merged_depth(parts);
    merged.aovs.depth_coverage = weighted_mean(parts, &AovImages::depth_coverage);
  }
  if (first.aovs.set.variance) merged.aovs.variance = merged_variance(parts, merged.image, merged.samples);
  if (first.aovs.set.sample_count) {  // the parts' samples add up (float: exact below 2^24)
    merged.aovs.sample_count.assign(first.aovs.sample_count.size(), 0.0f);
    for (const auto& p : parts)
      for (std::size_t i = 0; i < p.aovs.sample_count.size(); ++i) merged.aovs.sample_count[i] += p.aovs.sample_count[i];
  }
  return merged;
}

}  // namespace prism
