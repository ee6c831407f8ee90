#include "aov_exr.h"

#include <string>

namespace prism::cli {
namespace {

const std::vector<std::string> kAlbedo{"albedo.R", "albedo.G", "albedo.B"};
const std::vector<std::string> kNormal{"N.x", "N.y", "N.z"};
const std::vector<std::string> kDepth{"Z"};
const std::vector<std::string> kCoverage{"Z.coverage"};
const std::vector<std::string> kVariance{"variance.R", "variance.G", "variance.B"};
const std::vector<std::string> kSampleCount{"sampleCount"};

}  // namespace

std::vector<ExrChannelGroup> aov_exr_channels(const AovImages& aovs) {
  std::vector<ExrChannelGroup> groups;
  if (aovs.set.albedo) groups.push_back({kAlbedo, aovs.albedo.rgb});
  if (aovs.set.normal) groups.push_back({kNormal, aovs.normal.rgb});
  if (aovs.set.depth) {
    groups.push_back({kDepth, aovs.depth});
    groups.push_back({kCoverage, aovs.depth_coverage});
  }
  if (aovs.set.variance) groups.push_back({kVariance, aovs.variance.rgb});
  if (aovs.set.sample_count) groups.push_back({kSampleCount, aovs.sample_count});
  return groups;
}

AovImages read_aov_exr_channels(const std::filesystem::path& path, int width, int height) {
  AovImages aovs;
  if (auto albedo = read_exr_channels(path, kAlbedo)) {
    aovs.set.albedo = true;
    aovs.albedo = ImageRgbF{width, height, std::move(*albedo)};
  }
  if (auto normal = read_exr_channels(path, kNormal)) {
    aovs.set.normal = true;
    aovs.normal = ImageRgbF{width, height, std::move(*normal)};
  }
  auto depth = read_exr_channels(path, kDepth);
  auto coverage = read_exr_channels(path, kCoverage);
  if (depth && coverage) {
    aovs.set.depth = true;
    aovs.depth = std::move(*depth);
    aovs.depth_coverage = std::move(*coverage);
  }
  if (auto variance = read_exr_channels(path, kVariance)) {
    aovs.set.variance = true;
    aovs.variance = ImageRgbF{width, height, std::move(*variance)};
  }
  if (auto count = read_exr_channels(path, kSampleCount)) {
    aovs.set.sample_count = true;
    aovs.sample_count = std::move(*count);
  }
  return aovs;
}

}  // namespace prism::cli
