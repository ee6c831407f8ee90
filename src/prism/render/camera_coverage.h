#pragma once
// Which pixels see something: for each pixel, the fraction of a grid of camera rays through
// it that hit a surface of the prepared scene (escaped rays see the environment or the void).
// Exposure metering (display/exposure_metering.h) leaves out what sees nothing, so that the
// black void around a Cornell box or a sky behind a model does not set the exposure. One
// ray per grid point, traced apart from the render and independent of its samples: a
// 512² film at 1 ray a pixel costs about as much as one sample per pixel of camera rays.
#include <vector>

#include "prism/render/prepared_scene.h"

namespace prism {

// Row-major from the top-left pixel, width × height values in [0, 1]; `rays_per_axis`² rays
// on a regular grid inside each pixel through the lens centre (at least 1).
std::vector<float> camera_ray_coverage(const PreparedScene& scene, int width, int height, int rays_per_axis = 1);

}  // namespace prism
