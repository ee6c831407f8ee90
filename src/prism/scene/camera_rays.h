#pragma once
// Primary rays of the pinhole or thin-lens camera for a film of a given size.
#include "prism/core/ray.h"
#include "prism/core/transform.h"
#include "prism/scene/scene.h"

namespace prism {

class PinholeCamera {
 public:
  PinholeCamera(const Camera& camera, int width, int height);
  // Ray through film position (x, y) in pixels, (0, 0) the top-left corner of the image.
  // u_lens picks the point on the lens (thin-lens cameras; ignored by pinholes).
  // Inlined: a Ray returned from a call comes back through memory, written as 8-byte and
  // smaller stores, and the caller reads it in 16-byte loads, which the store buffer
  // cannot forward (a stall on every camera ray; docs/performance-design.md "Store-forwarding stalls").
  [[gnu::always_inline]] Ray generate_ray(float film_x, float film_y, Vec2f u_lens = Vec2f(0.5f, 0.5f)) const {
    const float ndc_x = 2.0f * film_x * inv_width_ - 1.0f;   // -1 left, +1 right
    const float ndc_y = 1.0f - 2.0f * film_y * inv_height_;  // +1 top, -1 bottom
    // Camera space: +z forward, +y up, +x to the image's left (see Transform::look_at).
    const Vec3f local(-ndc_x * scale_x_, ndc_y * scale_y_, 1.0f);
    if (aperture_radius_ <= 0.0f)
      return Ray{camera_to_world_.translation, normalize(camera_to_world_.apply_vector(local))};
    return thin_lens_ray(local, u_lens);
  }
  // Angle subtended by one pixel at the image centre: the ray cone's spread (texture LOD).
  float pixel_spread_angle() const { return 2.0f * scale_y_ * inv_height_; }
  bool has_lens() const { return aperture_radius_ > 0.0f; }  // generate_ray reads u_lens

 private:
  // generate_ray's ray through the lens point u_lens, for the pinhole ray's `local` direction.
  Ray thin_lens_ray(const Vec3f& local, Vec2f u_lens) const;

  Transform camera_to_world_;
  float scale_x_ = 1.0f, scale_y_ = 1.0f;  // tangent of the half-angles
  float inv_width_ = 1.0f, inv_height_ = 1.0f;
  float aperture_radius_ = 0.0f, focus_distance_ = 1.0f;
};

}  // namespace prism
