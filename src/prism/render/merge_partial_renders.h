#pragma once
// Combining renders of disjoint sample ranges (render farms: `--sample-range`, then
// `prism merge`). The merged mean weights each part by its number of samples, which gives
// the image of one render over the union of the ranges (up to float rounding).
#include <cstdint>
#include <string>
#include <vector>

#include "prism/io/image.h"

namespace prism {

struct PartialRender {
  std::string name;        // for error messages (the file name)
  ImageRgbF image;         // per-pixel means
  int sample_begin = 0;    // sample indices [sample_begin, sample_end)
  int sample_end = 0;
  std::string fingerprint; // image_fingerprint as hex; parts must agree
};

struct MergedRender {
  ImageRgbF image;
  int samples = 0;
  std::vector<std::pair<int, int>> ranges;  // sorted, adjacent ranges joined
};

// Throws UsageError when sizes or fingerprints differ, a range is empty, or ranges overlap.
MergedRender merge_partial_renders(const std::vector<PartialRender>& parts);

}  // namespace prism
