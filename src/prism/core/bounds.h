#pragma once
#include <limits>

#include "prism/core/vec.h"

namespace prism {

struct Bounds3f {
  Vec3f lower{std::numeric_limits<float>::infinity()};
  Vec3f upper{-std::numeric_limits<float>::infinity()};

  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  void extend(const Vec3f& p) {
    lower = min(lower, p);
    upper = max(upper, p);
  }
  void extend(const Bounds3f& b) {
    lower = min(lower, b.lower);
    upper = max(upper, b.upper);
  }
  Vec3f diagonal() const { return upper - lower; }
  Vec3f center() const { return (lower + upper) * 0.5f; }
  bool contains(const Vec3f& p) const {
    return p.x >= lower.x && p.y >= lower.y && p.z >= lower.z && p.x <= upper.x &&
           p.y <= upper.y && p.z <= upper.z;
  }
};

}  // namespace prism
