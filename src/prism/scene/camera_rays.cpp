#include "prism/scene/camera_rays.h"

#include <cmath>
#include <numbers>

#include "prism/sampling/warps.h"

namespace prism {

PinholeCamera::PinholeCamera(const Camera& camera, int width, int height)
    : camera_to_world_(Transform::look_at(camera.eye, camera.target, camera.up)),
      inv_width_(1.0f / static_cast<float>(width)),
      inv_height_(1.0f / static_cast<float>(height)),
      aperture_radius_(camera.aperture_radius),
      focus_distance_(camera.focus_distance) {
  const float tan_half = std::tan(0.5f * camera.fov_degrees * std::numbers::pi_v<float> / 180.0f);
  // The field of view spans the smaller axis; the other axis extends by the aspect ratio.
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  scale_x_ = aspect >= 1.0f ? tan_half * aspect : tan_half;
  scale_y_ = aspect >= 1.0f ? tan_half : tan_half / aspect;
}

Ray PinholeCamera::thin_lens_ray(const Vec3f& local, Vec2f u_lens) const {
  // Thin lens (Kolb et al. 1995; pbrt §5.2.3): every ray through the lens point reaches
  // the pinhole ray's point on the plane of focus z = focus_distance.
  const Vec2f disk = sample_concentric_disk(u_lens);
  const Vec3f lens(aperture_radius_ * disk.x, aperture_radius_ * disk.y, 0.0f);
  const Vec3f focus = local * focus_distance_;
  return Ray{camera_to_world_.apply_point(lens), normalize(camera_to_world_.apply_vector(focus - lens))};
}

}  // namespace prism
