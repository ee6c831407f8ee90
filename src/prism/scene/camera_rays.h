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
  Ray generate_ray(float film_x, float film_y, Vec2f u_lens = Vec2f(0.5f, 0.5f)) const;
  // Angle subtended by one pixel at the image centre: the ray cone's spread (texture LOD).
  float pixel_spread_angle() const { return 2.0f * scale_y_ * inv_height_; }
  bool has_lens() const { return aperture_radius_ > 0.0f; }  // generate_ray reads u_lens

 private:
  Transform camera_to_world_;
  float scale_x_ = 1.0f, scale_y_ = 1.0f;  // tangent of the half-angles
  float inv_width_ = 1.0f, inv_height_ = 1.0f;
  float aperture_radius_ = 0.0f, focus_distance_ = 1.0f;
};

}  // namespace prism
