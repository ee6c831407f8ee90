#include "prism/scene/environment_override.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/texture_file.h"

namespace prism {
namespace {

// Rotation by `degrees` about +y, right-handed: x → (cos θ, 0, −sin θ).
Transform rotation_about_y(float degrees) {
  const double theta = static_cast<double>(degrees) * std::numbers::pi / 180.0;
  const float c = static_cast<float>(std::cos(theta)), s = static_cast<float>(std::sin(theta));
  Transform t;
  t.m[0][0] = c;
  t.m[0][2] = s;
  t.m[2][0] = -s;
  t.m[2][2] = c;
  return t;
}

TextureEncoding encoding_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".hdr" || extension == ".exr" ? TextureEncoding::linear : TextureEncoding::srgb;
}

}  // namespace

void apply_environment_override(Scene& scene, const EnvironmentOverride& o, const LoadOptions& options) {
  if (o.source.empty()) return;
  if (!(o.luminance_nits >= 0.0f && std::isfinite(o.luminance_nits)))
    throw UsageError(fmt::format("--environment-nits must be a non-negative number (got {})", o.luminance_nits));
  if (!std::isfinite(o.rotation_degrees))
    throw UsageError("--environment-rotation must be a finite number of degrees");
  Light light;
  light.type = LightType::environment;
  light.intensity = o.luminance_nits;
  light.environment_to_world = rotation_about_y(o.rotation_degrees);
  if (o.source == "uniform") {
    light.name = "uniform environment (--environment)";
  } else {
    const std::filesystem::path path(o.source);
    light.name = path.filename().string();
    // Read before the scene changes, so a bad file leaves the scene as it was.
    TextureImage image =
        read_texture_file(path, encoding_of(path), TextureLimits(options.max_texture_dimension, options.memory_budget),
                          TextureContent::color_own_gamut);
    if (!image.primaries_note.empty()) scene.warnings.push_back(image.primaries_note);
    scene.textures.push_back(std::move(image));
    light.environment_texture = static_cast<int>(scene.textures.size() - 1);
  }
  std::erase_if(scene.lights, [](const Light& l) { return l.type == LightType::environment; });
  scene.lights.push_back(std::move(light));
}

bool scene_has_emitters(const Scene& scene) {
  if (!scene.lights.empty()) return true;
  return std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const TriangleMesh& mesh) {
    return mesh.material < scene.materials.size() && scene.materials[mesh.material].is_emissive() &&
           mesh.triangle_count() > 0;
  });
}

std::optional<std::string> no_emitters_warning(const Scene& scene) {
  if (scene_has_emitters(scene)) return std::nullopt;
  return fmt::format("{} has no lights or emissive surfaces, so the image will be black; light it with "
                     "--environment FILE.hdr or --environment uniform",
                     scene.name);
}

}  // namespace prism
