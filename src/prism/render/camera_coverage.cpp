#include "prism/render/camera_coverage.h"

#include <algorithm>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/scene/camera_rays.h"

namespace prism {

std::vector<float> camera_ray_coverage(const PreparedScene& scene, int width, int height, int rays_per_axis) {
  if (width <= 0 || height <= 0 || rays_per_axis < 1) throw UsageError("camera coverage needs a positive size");
  const PinholeCamera camera(scene.scene().camera, width, height);
  const EmbreeAccel& accel = scene.accel();
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  std::vector<float> coverage(pixels);
  const int m = rays_per_axis;
  const float step = 1.0f / static_cast<float>(m);
  parallel_for(pixels, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const float x = static_cast<float>(i % static_cast<std::size_t>(width));
      const float y = static_cast<float>(i / static_cast<std::size_t>(width));
      int hits = 0;
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b) {
          Hit hit;
          hits += accel.intersect(camera.generate_ray(x + (b + 0.5f) * step, y + (a + 0.5f) * step), hit) ? 1 : 0;
        }
      coverage[i] = static_cast<float>(hits) / static_cast<float>(m * m);
    }
  });
  return coverage;
}

}  // namespace prism
