#pragma once
// Combining renders of disjoint sample ranges (render farms: `--sample-range`, then
// `prism merge`). The merged mean weights each part by its number of samples, which gives
// the image of one render over the union of the ranges (up to float rounding).
#include <cstdint>
#include <string>
#include <vector>

#include "prism/io/image.h"
#include "prism/render/aov_images.h"

namespace prism {

struct PartialRender {
  std::string name;        // for error messages (the file name)
  ImageRgbF image;         // per-pixel means
  int sample_begin = 0;    // sample indices [sample_begin, sample_end)
  int sample_end = 0;
  std::string fingerprint; // image_fingerprint as hex; parts must agree
  AovImages aovs;          // optional AOV layers; parts must keep the same set
};

struct MergedRender {
  ImageRgbF image;
  // Albedo and normal are weighted like the beauty; depth by samples × coverage (it is a
  // mean over the samples that hit), coverage by samples.
  AovImages aovs;
  int samples = 0;
  std::vector<std::pair<int, int>> ranges;  // sorted, adjacent ranges joined
};

// Throws UsageError when sizes, fingerprints or AOV sets differ, a range is empty, or
// ranges overlap.
MergedRender merge_partial_renders(const std::vector<PartialRender>& parts);

}  // namespace prism
