#include "denoise_exr.h"

#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"

namespace prism::cli {
namespace {

using Names = std::vector<std::string>;

// The first of `candidates` whose channels are all in the file.
std::optional<std::vector<float>> read_first(const std::filesystem::path& path, const std::vector<Names>& candidates) {
  for (const Names& names : candidates)
    if (auto values = read_exr_channels(path, names)) return values;
  return std::nullopt;
}

std::vector<float> distances(const std::vector<float>& positions) {
  std::vector<float> d(positions.size() / 3);
  for (std::size_t i = 0; i < d.size(); ++i)
    d[i] = std::hypot(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
  return d;
}

// pbrt-v4's Variance.* is the samples' variance s²; the denoiser needs that of the mean.
std::vector<float> sample_variance_to_mean(std::vector<float> v, const ExrFile& file, const std::filesystem::path& path) {
  const auto spp = file.metadata.ints.find("samplesPerPixel");
  if (spp == file.metadata.ints.end() || spp->second < 1)
    throw IoError(fmt::format("'{}': Variance.R/G/B needs the samplesPerPixel attribute (pbrt-v4 writes it)",
                              path.string()));
  for (float& x : v) x /= static_cast<float>(spp->second);
  return v;
}

}  // namespace

DenoiseExrInput read_denoise_exr(const std::filesystem::path& path) {
  DenoiseExrInput in;
  in.file = read_exr(path);
  auto albedo = read_first(path, {{"albedo.R", "albedo.G", "albedo.B"}, {"Albedo.R", "Albedo.G", "Albedo.B"}});
  auto normal = read_first(path, {{"N.x", "N.y", "N.z"}, {"Ns.X", "Ns.Y", "Ns.Z"}, {"N.X", "N.Y", "N.Z"},
                                  {"Nsx", "Nsy", "Nsz"}});
  auto depth = read_exr_channels(path, {"Z"});
  if (!depth)
    if (auto p = read_first(path, {{"P.X", "P.Y", "P.Z"}, {"Px", "Py", "Pz"}})) depth = distances(*p);
  auto variance = read_exr_channels(path, {"variance.R", "variance.G", "variance.B"});
  if (!variance)
    if (auto v = read_exr_channels(path, {"Variance.R", "Variance.G", "Variance.B"}))
      variance = sample_variance_to_mean(std::move(*v), in.file, path);
  std::vector<std::string> missing;
  if (!albedo) missing.emplace_back("albedo (albedo.R/G/B or Albedo.R/G/B)");
  if (!normal) missing.emplace_back("normal (N.x/y/z, Ns.X/Y/Z or N.X/Y/Z)");
  if (!depth) missing.emplace_back("depth (Z or P.X/Y/Z)");
  if (!variance) missing.emplace_back("variance (variance.R/G/B or Variance.R/G/B)");
  if (!missing.empty())
    throw IoError(fmt::format("'{}' lacks the layers the denoiser needs: {}", path.string(), fmt::join(missing, "; ")));
  auto& b = in.buffers;
  b.width = in.file.image.width;
  b.height = in.file.image.height;
  b.color = in.file.image.rgb;
  b.albedo = std::move(*albedo);
  b.normal = std::move(*normal);
  b.depth = std::move(*depth);
  b.variance = std::move(*variance);
  denoise::check_denoise_buffers(b);
  return in;
}

ExrChannelGroup noisy_beauty_channels(const std::vector<float>& noisy_rgb) {
  return {{"noisy.R", "noisy.G", "noisy.B"}, noisy_rgb};
}

std::vector<ExrChannelGroup> denoise_guide_channels(const denoise::DenoiseBuffers& b) {
  return {{{"albedo.R", "albedo.G", "albedo.B"}, b.albedo},
          {{"N.x", "N.y", "N.z"}, b.normal},
          {{"Z"}, b.depth},
          {{"variance.R", "variance.G", "variance.B"}, b.variance}};
}

}  // namespace prism::cli
