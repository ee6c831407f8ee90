#pragma once
// `--environment`: light a scene with an environment of the user's choosing instead of (or,
// for scenes without any, in place of) the scene's own — the usual way to look at glTF
// models, which carry no lights of their own. The map is an equirectangular image in
// linear radiance (.hdr, .exr) or sRGB-encoded (.png, .jpg), or `uniform` for a constant
// white sky (a furnace). `luminance_nits` scales it as the JSON scene's environment does
// (docs/scene-formats.md): a texel value of 1 (or the uniform sky) has that luminance.
// `rotation_degrees` turns the map about the world's +y axis (right-handed, so +90° carries
// the map's +x direction to −z).
#include <optional>
#include <string>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"

namespace prism {

struct EnvironmentOverride {
  std::string source;  // "uniform" or an image file; empty: keep the scene's lights
  float luminance_nits = 1.0f;  // texel values are nits; matches the default exposure (scale 1)
  float rotation_degrees = 0.0f;
};

// Replaces the scene's environment light (if any) with the override; other lights and
// emitters stay. Throws UsageError for bad numbers and IoError for an unreadable image;
// `options` limits the image's size and memory as for scene textures.
void apply_environment_override(Scene& scene, const EnvironmentOverride& override_options,
                                const LoadOptions& options = {});

// Whether anything in the scene emits light: a non-geometric light or a material with
// emission that some mesh uses.
bool scene_has_emitters(const Scene& scene);

// The one-line warning `prism render` and `prism view` print for a scene without emitters
// (it would render black), naming the way out; nothing when the scene emits.
std::optional<std::string> no_emitters_warning(const Scene& scene);

}  // namespace prism
