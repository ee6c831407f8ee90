#pragma once
// Shared by the suites that time `prism::render`: settings for the benchmark renders and
// the figures derived from a RenderResult. Render time is the sum of pass times, so scene
// flattening and the BVH build (measured by the startup suite) are not counted.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/render/renderer.h"

namespace prism::bench {

struct RenderMeasurement {
  double render_seconds = 0;      // sum of pass times
  double total_seconds = 0;       // the whole render() call, setup included
  double samples_per_second = 0;  // pixel samples
  double rays_per_second = 0;     // closest-hit + shadow rays
  double rays_per_sample = 0;
  double camera_packet_rays_per_sample = 0;  // traced in camera packets (RenderResult::camera_packet_rays)
  std::uint64_t rays = 0, shadow_rays = 0;
};

RenderMeasurement measure(const RenderResult& result);

// Cornell box settings: square image, fixed spp, the default path settings (max depth 8,
// MIS) and the requested transport (spectral: 4 wavelengths, cosh unless changed).
RenderSettings cornell_settings(int size, int spp, TransportKind kind, int threads);

// "spectral" / "rgb" for tables.
std::string transport_label(const RenderSettings& settings);

double median(std::vector<double> values);
double mean(const std::vector<double>& values);
// Sample standard deviation / mean; 0 for fewer than two values.
double coefficient_of_variation(const std::vector<double>& values);

}  // namespace prism::bench
