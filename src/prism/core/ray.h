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

}  // namespace prism
