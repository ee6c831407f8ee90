#pragma once
// A scene made ready for rendering once: validated, instances flattened into world-space
// meshes and its BVH built. Interactive use (the viewer) renders many times with a new
// camera, materials or lights but the same geometry; keeping the flattened copy, the BVH
// and the textures' mip pyramids across those renders turns a restart from O(triangles +
// texels) into O(pixels).
#include <memory>
#include <mutex>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_sampling.h"

namespace prism {

class PreparedScene {
 public:
  // Throws SceneError for invalid scenes (validate_scene). The first copies the scene; the
  // second takes it over (its meshes and texture texels are moved, not copied: a loaded
  // scene need not be held twice).
  explicit PreparedScene(const Scene& scene);
  explicit PreparedScene(Scene&& scene);
  ~PreparedScene();
  PreparedScene(const PreparedScene&) = delete;
  PreparedScene& operator=(const PreparedScene&) = delete;

  const Scene& scene() const { return *scene_; }
  const EmbreeAccel& accel() const { return *accel_; }
  // One per scene texture, level 0 borrowed from the prepared scene's own texels: the whole
  // pyramid for textures materials use, level 0 alone for the others (environment maps).
  const std::vector<MipPyramid>& mip_pyramids() const { return mip_pyramids_; }
  // The light sampler for `options`, built on first use and kept while the options and the
  // emitters (the materials' emission, the lights) stay as they are, so that a restart
  // after a camera move does not rebuild the distributions over an environment map or a
  // textured emitter (≈ 150 ms for DamagedHelmet's 2048² emission texture). Thread-safe;
  // the pointer stays valid after a later change replaces it.
  std::shared_ptr<const LightSampler> light_sampler(const LightSamplerOptions& options) const;

  // What may change between renders without rebuilding: the BVH only depends on meshes
  // and instances, which stay as prepared. Material indices must stay in range (the
  // material count is fixed) and light parameters finite; both throw SceneError otherwise.
  void set_camera(const Camera& camera);
  void set_materials(std::vector<Material> materials);
  void set_lights(std::vector<Light> lights);

 private:
  std::unique_ptr<Scene> scene_;  // stable address: the BVH's alpha filters read its meshes and textures
  std::unique_ptr<EmbreeAccel> accel_;
  std::vector<MipPyramid> mip_pyramids_;
  mutable std::mutex light_sampler_mutex_;
  mutable std::shared_ptr<const LightSampler> light_sampler_;  // null until asked for, or after a change
  mutable LightSamplerOptions light_sampler_options_;

  void build();  // the BVH and the mip pyramids of scene_
  void build_material_pyramids();  // the pyramids of textures materials use, where not built yet
};

}  // namespace prism
