#pragma once
// Internal to the JSON scene loader: the state shared by the readers of each section
// (json_scene_*.cpp), one reader per concept.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "prism/scene/load_options.h"
#include "prism/scene/loaders/json_value.h"
#include "prism/scene/loaders/texture_cache.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

enum class SpectrumUse { emission, reflectance };

struct JsonSceneReader {
  JsonSceneReader(Scene& scene_, JsonDocument& document_, const std::filesystem::path& scene_dir_,
                  const LoadOptions& options_)
      : scene(scene_), document(document_), scene_dir(scene_dir_), options(options_), textures(scene_, options_) {}

  Scene& scene;
  JsonDocument& document;
  std::filesystem::path scene_dir;
  LoadOptions options;
  TextureCache textures;
  std::map<std::string, std::uint32_t, std::less<>> material_indices;
  std::map<std::string, std::vector<std::uint32_t>, std::less<>> mesh_indices;  // a file may give several
  std::vector<bool> mesh_is_prototype;
  std::map<std::uint32_t, float> emission_power_lm;  // material → luminous flux to convert to nits
  float meters_per_unit = 1.0f;

  std::filesystem::path resolve(const JsonValue& file_name) const;
  // A texture reference: "file.png" or {"file", "encoding", "wrap", "wrap_u", "wrap_v"}.
  // `default_encoding` says what the key reads: sRGB for colours, linear for data, which an
  // "encoding" given in the file does not change (TextureContent); a colour is read as
  // `colour_content` (a wide-gamut material's base colour asks for its space, an
  // environment map keeps its own gamut: an OpenEXR's texels are read into that space).
  // `check` runs on the image once it is decoded (at the end of the load).
  int read_texture(const JsonValue& value, TextureEncoding default_encoding, TextureCache::ImageCheck check = {},
                   TextureContent colour_content = TextureContent::color);
  // A spectrum given as data (json_scene_spectra.cpp): a name, a black body, points or a CSV
  // column; reflectances must lie in [0, 1], emission must be visible.
  color::PiecewiseLinearSpectrum read_spectrum(const JsonValue& value, SpectrumUse use) const;
  std::uint32_t material_index(const JsonValue& name) const;

  void read_material(const JsonValue& value);
  void read_attenuation(Material& m, const JsonValue& value) const;
  void read_clearcoat(Material& m, const JsonValue& value);
  void read_sheen(Material& m, const JsonValue& value);
  void read_iridescence(Material& m, const JsonValue& value);
  void read_light(const JsonValue& value);
  void read_environment(const JsonValue& value);
  // A light's `color` (≥ 0) and `color_space`, or its `spectrum` instead.
  void read_light_color(const JsonValue& value, Light& light) const;
  void read_camera(const JsonValue& value);
  void read_mesh(const JsonValue& value);
  void read_instance(const JsonValue& value);
  void finish_emission_power();  // needs the geometry and instances
};

// "srgb", "acescg" or "rec2020": the primaries a colour is given with.
ColorPickerSpace read_color_picker_space(const JsonValue& value);

// {"translate", "rotate": {"axis", "angle_degrees"}, "rotate_degrees": [x, y, z],
//  "scale": s | [x, y, z], "matrix": 12 or 16 numbers, row-major}: M then S, R, T.
Transform read_transform(const JsonValue& value);

}  // namespace prism::loaders
