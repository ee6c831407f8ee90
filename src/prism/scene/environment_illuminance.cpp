#include "prism/scene/environment_illuminance.h"

#include "prism/color/color_space.h"
#include "prism/scene/emission.h"
#include "prism/scene/environment_mapping.h"

namespace prism {

double environment_illuminance_lux(const TextureImage& map, EnvironmentMapping mapping, const Vec3f& normal) {
  if (map.width <= 0 || map.height <= 0 || map.channels <= 0) return 0.0;
  const Vec3d y_row = picker_color_space(map.texel_space).rgb_to_xyz.row(1);  // the texels' space's luminance weights
  const double texels = double(map.width) * double(map.height);
  double lux = 0.0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const Vec2f uv((x + 0.5f) / map.width, (y + 0.5f) / map.height);
      const double cosine = dot(environment_uv_to_direction(mapping, uv), normal);
      if (!(cosine > 0.0)) continue;
      const double luminance = dot(y_row, Vec3d(texel_rgb(map, x, y)));
      lux += luminance * cosine * (environment_solid_angle_per_uv_area(mapping, uv) / texels);
    }
  return lux;
}

}  // namespace prism
