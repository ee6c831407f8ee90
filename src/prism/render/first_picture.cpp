#include "prism/render/first_picture.h"

#include "prism/display/exposure.h"
#include "prism/render/camera_coverage.h"

namespace prism {

FirstPicture first_picture_defaults(const Scene& scene) {
  FirstPicture p;
  p.camera = scene.camera;
  p.width = scene.default_width;
  p.height = scene.default_height;
  if (scene.default_max_depth) p.path.max_depth = *scene.default_max_depth;
  if (scene.default_normal_mapping) p.path.normal_mapping = *scene.default_normal_mapping;
  const Camera& c = scene.camera;
  if (c.f_number > 0.0f && c.shutter_seconds > 0.0f && c.iso > 0.0f)
    p.camera_ev100 = display::ev100_from_camera(c.f_number, c.shutter_seconds, c.iso);
  return p;
}

display::MeteredExposure meter_rendered_film(const PreparedScene& scene, const Film& film,
                                             const color::ColorSpace& film_space,
                                             const display::MeteringSettings& metering) {
  const ImageRgbF means{film.width(), film.height(), film.mean_rgb()};
  const std::vector<float> coverage = camera_ray_coverage(scene, film.width(), film.height());
  return display::meter_exposure(means, film_space.rgb_to_xyz.row(1), coverage, metering);
}

}  // namespace prism
