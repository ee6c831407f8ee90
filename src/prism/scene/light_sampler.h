#pragma once
// Emissive triangles of a scene and how next-event estimation picks them: a triangle is
// chosen with probability proportional to its emitted power (area × mean radiance over
// the channels), then a point uniformly on it.
#include <cstdint>
#include <vector>

#include "prism/core/vec.h"
#include "prism/scene/scene.h"

namespace prism {

struct LightSample {
  Vec3f position;
  Vec3f normal;     // unit front-face normal of the emitter
  Vec3f radiance;   // emitted radiance towards the front side
  float pdf_area;   // selection probability × 1/area, per unit area
};

class LightSampler {
 public:
  explicit LightSampler(const Scene& scene);

  bool empty() const { return triangles_.empty(); }
  std::size_t light_count() const { return triangles_.size(); }

  // u_select chooses the triangle, u_point the point on it.
  LightSample sample(float u_select, Vec2f u_point) const;

  // Area density with which sample() produces a point on the given triangle, 0 if the
  // triangle is not emissive.
  float pdf_area(std::uint32_t mesh, std::uint32_t triangle) const;

 private:
  struct EmissiveTriangle {
    Vec3f p0, e1, e2;
    Vec3f normal;
    Vec3f radiance;
    float area;
  };
  std::vector<EmissiveTriangle> triangles_;
  std::vector<float> cdf_;                    // inclusive, normalised, size = triangles_
  std::vector<float> pmf_;
  std::vector<std::int64_t> first_light_of_mesh_;  // -1 for non-emissive meshes
};

}  // namespace prism
