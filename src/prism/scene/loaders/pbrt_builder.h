#pragma once
// Internal state of the pbrt-v4 loader: the graphics state stack, named materials,
// textures and objects, and the Scene being filled. Directives are split by topic over
// pbrt_parser.cpp (structure, transforms, camera), pbrt_materials.cpp, pbrt_shapes.cpp
// and pbrt_lights.cpp.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "prism/scene/load_options.h"
#include "prism/scene/loaders/pbrt_matrix.h"
#include "prism/scene/loaders/pbrt_params.h"
#include "prism/scene/loaders/texture_cache.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

struct PbrtAreaLight {
  Vec3f color{0.0f};
  ColorPickerSpace color_space = ColorPickerSpace::srgb;
  float luminance_nits = 0.0f;
  std::optional<color::PiecewiseLinearSpectrum> spectrum;
  bool two_sided = false;
  std::optional<double> power;  // pbrt "power": emitted flux, applied per shape
};

struct PbrtGraphicsState {
  PbrtMatrix ctm;  // pbrt's current transformation matrix (render-from-object)
  int material = -1;  // index into scene.materials; -1: pbrt's default (diffuse 0.5)
  std::optional<PbrtAreaLight> area_light;
  bool reverse_orientation = false;
  std::string interior_medium;  // MediumInterface's first name ("": none)
  std::string color_space = "srgb";  // ColorSpace: the pbrt colour space of rgb parameters
};

// A MakeNamedMedium: what Prism renders of it, absorption inside glass (σ_a per scene unit,
// linear Rec.709), or why it renders none of it.
struct PbrtMedium {
  Vec3f sigma_a{0.0f};
  std::string unsupported;  // empty: an absorbing-only homogeneous medium
};

// A "reflectance"-like texture: an image (index into scene.textures) or a constant.
struct PbrtTexture {
  int image = -1;
  Vec3f value{1.0f};  // constant, or the image's tint (pbrt's "scale")
  ColorPickerSpace space = ColorPickerSpace::srgb;  // of a constant's value
};

class PbrtBuilder {
 public:
  PbrtBuilder(const std::filesystem::path& scene_dir, const LoadOptions& options);

  void parse(std::string_view text, const std::string& source, int include_depth);
  Scene finish();
  // After parse() or finish() threw `error`: the first failing image asked for before it,
  // if any, else `error` (images are decoded in batches; texture_cache.h).
  [[noreturn]] void rethrow_first_texture_error(std::exception_ptr error) { textures_->rethrow_first_error(error); }

 private:
  void directive(PbrtTokenizer& tokens, const PbrtToken& name, int include_depth);
  void camera(const std::string& type, const PbrtParams& params);
  void film(const std::string& type, const PbrtParams& params);
  void make_material(const std::string& type, const PbrtParams& params, const std::string& name);
  void texture(const std::string& name, const std::string& value_type, const std::string& klass,
               const PbrtParams& params);
  // `is_float`: a "float" texture (data), else a "spectrum" one (colour: an OpenEXR's
  // chromaticities apply, TextureContent).
  PbrtTexture imagemap(const std::string& name, const PbrtParams& params, bool is_float);
  void shape(const std::string& type, const PbrtParams& params);
  void light_source(const std::string& type, const PbrtParams& params);
  void area_light_source(const std::string& type, const PbrtParams& params);
  void make_medium(const std::string& name, const PbrtParams& params);
  void medium_interface(const std::string& interior, const std::string& exterior, const PbrtParams& params);
  std::uint32_t with_interior_medium(std::uint32_t material, const PbrtParams& shape_params);

  void add_mesh(TriangleMesh mesh, const PbrtParams& params, bool has_normals);
  std::uint32_t shape_material(const PbrtParams& params, double area);
  std::uint32_t alpha_material(std::uint32_t material, const PbrtParams& params);
  int texture_with_alpha(int base, int alpha);
  // A reflectance parameter: a colour (in the ColorSpace in effect) or a texture's.
  std::optional<PbrtColor> reflectance(const PbrtParams& params, std::string_view name, int& texture);
  std::filesystem::path resolve(const PbrtParams& params, std::string_view param, const std::string& file) const;
  void ignore(std::string_view what, const PbrtParams& params);
  void note_unused(std::string_view directive, const PbrtParams& params);

  std::filesystem::path scene_dir_;
  LoadOptions options_;
  Scene scene_;
  std::unique_ptr<TextureCache> textures_;
  std::vector<PbrtGraphicsState> stack_;
  PbrtGraphicsState state_;
  std::map<std::string, int> named_materials_;
  std::map<std::string, PbrtTexture> named_textures_;
  std::map<std::string, PbrtTexture> float_textures_;
  std::map<std::pair<std::uint32_t, std::string>, std::uint32_t> alpha_materials_;  // (material, alpha) → material
  std::map<std::string, PbrtMatrix> coordinate_systems_;
  std::map<std::string, std::vector<std::uint32_t>> objects_;
  std::optional<std::string> current_object_;
  std::vector<std::uint32_t> world_meshes_;
  std::vector<Instance> placements_;
  std::map<std::pair<int, int>, std::uint32_t> emissive_materials_;
  std::map<std::string, PbrtMedium> media_;
  std::map<std::pair<std::uint32_t, std::string>, std::uint32_t> absorbing_materials_;  // (material, medium) → material
  int area_light_id_ = 0;
  int default_material_ = -1;
  bool camera_seen_ = false, world_begun_ = false;
  std::map<std::string, std::vector<int>> ignored_;  // "what" → lines
  std::vector<std::string> approximations_;
};

}  // namespace prism::loaders
