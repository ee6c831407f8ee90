#include "prism/render/prepared_scene.h"

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/material_textures.h"

namespace prism {

PreparedScene::PreparedScene(const Scene& scene) {
  validate_scene(scene);
  scene_ = std::make_unique<Scene>(flatten_instances(scene));
  build();
}

PreparedScene::PreparedScene(Scene&& scene) {
  validate_scene(scene);
  scene_ = std::make_unique<Scene>(flatten_instances(std::move(scene)));
  build();
}

void PreparedScene::build() {
  accel_ = std::make_unique<EmbreeAccel>(*scene_);
  mip_pyramids_.clear();
  for (const TextureImage& t : scene_->textures) mip_pyramids_.push_back(base_level_pyramid(t));
  build_material_pyramids();
}

void PreparedScene::build_material_pyramids() {
  // Textures in parallel (a glTF model has a few of 2048² or more); each pyramid borrows its
  // level 0 from scene_, whose address is stable. Environment maps keep level 0 alone (a
  // third of their memory), unless a material uses one as well.
  const std::vector<bool> used = textures_used_by_materials(*scene_);
  parallel_for(scene_->textures.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      const TextureImage& image = scene_->textures[t];
      const bool filtered = mip_pyramids_[t].levels.size() > 1 || (image.width == 1 && image.height == 1);
      if (used[t] && !filtered) mip_pyramids_[t] = build_mip_pyramid(image);
    }
  });
}

PreparedScene::~PreparedScene() = default;

std::shared_ptr<const LightSampler> PreparedScene::light_sampler(const LightSamplerOptions& options) const {
  const std::lock_guard<std::mutex> lock(light_sampler_mutex_);
  if (!light_sampler_ || !(light_sampler_options_ == options)) {
    light_sampler_ = std::make_shared<const LightSampler>(*scene_, scene_bounds(*scene_), options);
    light_sampler_options_ = options;
  }
  return light_sampler_;
}

void PreparedScene::set_camera(const Camera& camera) { scene_->camera = camera; }

void PreparedScene::set_materials(std::vector<Material> materials) {
  if (materials.size() != scene_->materials.size())
    throw SceneError(fmt::format("the scene has {} materials, not {}: meshes refer to materials by index",
                                 scene_->materials.size(), materials.size()));
  for (const Material& m : materials) validate_material(m);
  bool same_emission = true;
  for (std::size_t i = 0; i < materials.size(); ++i)
    same_emission = same_emission && materials[i].emission == scene_->materials[i].emission;
  scene_->materials = std::move(materials);
  build_material_pyramids();  // a texture a material now uses for the first time
  if (!same_emission) {
    const std::lock_guard<std::mutex> lock(light_sampler_mutex_);
    light_sampler_.reset();
  }
}

void PreparedScene::set_lights(std::vector<Light> lights) {
  if (lights == scene_->lights) return;
  scene_->lights = std::move(lights);
  const std::lock_guard<std::mutex> lock(light_sampler_mutex_);
  light_sampler_.reset();
}

}  // namespace prism
