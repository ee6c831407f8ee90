#pragma once
#include <limits>

#include "prism/core/vec.h"

namespace prism {

struct Ray {
  Vec3f origin;
  Vec3f direction;  // unit length
  float t_min = 0.0f;
  float t_max = std::numeric_limits<float>::infinity();
};

// `to = ray`, one float at a time. Assigned whole, a Ray made just before (an inlined
// camera ray) is built on the stack with overlapping 16-byte and 4-byte stores, then
// copied in 16-byte loads the store buffer cannot forward: a stall of a dozen cycles or
// more (docs/performance-design.md "Store-forwarding stalls").
inline void store_ray(Ray& to, const Ray& ray) {
  to.origin.x = ray.origin.x;
  to.origin.y = ray.origin.y;
  to.origin.z = ray.origin.z;
  to.direction.x = ray.direction.x;
  to.direction.y = ray.direction.y;
  to.direction.z = ray.direction.z;
  to.t_min = ray.t_min;
  to.t_max = ray.t_max;
}

}  // namespace prism
