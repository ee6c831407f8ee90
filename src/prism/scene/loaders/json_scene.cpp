#include "prism/scene/loaders/json_scene.h"

#include <algorithm>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/json_tree.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/loaders/json_scene_reader.h"
#include "prism/scene/loaders/scene_camera.h"

namespace prism::loaders {
namespace {

void read_render_settings(Scene& scene, const JsonValue& render) {
  render.expect_keys({"width", "height", "spp", "max_depth", "normal_mapping"});
  if (auto v = render.find("width")) scene.default_width = static_cast<int>(v->as_integer(1, 65536));
  if (auto v = render.find("height")) scene.default_height = static_cast<int>(v->as_integer(1, 65536));
  if (auto v = render.find("spp")) scene.default_spp = static_cast<int>(v->as_integer(1, 1 << 24));
  if (auto v = render.find("max_depth")) scene.default_max_depth = static_cast<int>(v->as_integer(0, 1024));
  if (auto v = render.find("normal_mapping"))
    scene.default_normal_mapping = v->as_enum<NormalMapping>(
        {{normal_mapping_name(NormalMapping::classic), NormalMapping::classic},
         {normal_mapping_name(NormalMapping::microfacet), NormalMapping::microfacet}});
}

void warn_unknown_keys(Scene& scene, const JsonDocument& document) {
  if (document.unknown_keys.empty()) return;
  constexpr std::size_t kListed = 20;
  std::vector<std::string> listed(document.unknown_keys.begin(),
                                  document.unknown_keys.begin() +
                                      static_cast<std::ptrdiff_t>(std::min(kListed, document.unknown_keys.size())));
  std::string more = document.unknown_keys.size() > kListed
                         ? fmt::format(" and {} more", document.unknown_keys.size() - kListed)
                         : std::string();
  scene.warnings.push_back(fmt::format("{}: unknown keys ignored: {}{}", document.source, fmt::join(listed, ", "), more));
}

void read_document(JsonSceneReader& reader, const JsonValue& root) {
  root.expect_keys({"format", "name", "description", "meters_per_unit", "render", "camera", "cameras", "materials",
                    "lights", "environment", "meshes", "instances"});
  const std::string format = root["format"].as_string();
  if (format != kJsonSceneFormat)
    root["format"].fail(fmt::format("unsupported format '{}' (this version reads '{}')", format, kJsonSceneFormat));
  Scene& scene = reader.scene;
  scene.name = root.get_string("name", scene.name);
  if (auto d = root.find("description")) d->as_string();
  reader.meters_per_unit = root.get_float("meters_per_unit", 1.0f, 1e-9f, 1e9f);
  if (auto r = root.find("render")) read_render_settings(scene, *r);
  if (auto ms = root.find("materials"))
    for (const JsonValue& m : ms->elements()) reader.read_material(m);
  if (auto ms = root.find("meshes"))
    for (const JsonValue& m : ms->elements()) reader.read_mesh(m);
  if (auto is = root.find("instances"))
    for (const JsonValue& i : is->elements()) reader.read_instance(i);
  // With instances or prototypes, every mesh that is not a prototype is placed once where it
  // is, and prototypes only through instances (no instances at all: every mesh once).
  const auto& prototypes = reader.mesh_is_prototype;
  const bool has_prototype = std::find(prototypes.begin(), prototypes.end(), true) != prototypes.end();
  if (!scene.instances.empty() || has_prototype) {
    for (std::uint32_t m = 0; m < scene.meshes.size(); ++m)
      if (!prototypes[m]) scene.instances.push_back({m, Transform{}});
    if (scene.instances.empty())
      root["meshes"].fail("every mesh is a prototype and no instance places one: the scene would be empty");
  }
  if (auto ls = root.find("lights"))
    for (const JsonValue& l : ls->elements()) reader.read_light(l);
  if (auto e = root.find("environment")) reader.read_environment(*e);
  if (root.has("camera") && root.has("cameras")) root.fail("give either 'camera' or 'cameras', not both");
  if (auto c = root.find("camera")) reader.read_camera(*c);
  if (auto cs = root.find("cameras")) {
    const auto cameras = cs->elements();
    if (cameras.empty()) cs->fail("expected at least one camera");
    for (const JsonValue& c : cameras) reader.read_camera(c);
  }
  reader.finish_emission_power();
  if (scene.cameras.empty()) {
    scene.camera = frame_scene_camera(scene);
    scene.cameras.push_back(scene.camera);
  } else {
    scene.camera = scene.cameras.front();
  }
}

}  // namespace

TextPosition text_position(std::string_view text, std::size_t offset) {
  TextPosition p;
  offset = std::min(offset, text.size());
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

Scene parse_json_scene(std::string_view text, std::string_view source, const std::filesystem::path& scene_dir,
                       std::string_view default_name, const LoadOptions& options) {
  std::optional<JsonTree> tree;
  try {
    tree.emplace(text);
  } catch (const JsonSyntaxError& e) {
    const TextPosition p = text_position(text, e.offset());
    throw SceneError(fmt::format("{}:{}:{}: malformed JSON: {}", source, p.line, p.column, e.what()));
  }
  Scene scene;
  scene.name = std::string(default_name);
  JsonDocument document{std::string(source), {}, {}};
  JsonSceneReader reader(scene, document, scene_dir, options);
  try {
    read_document(reader, JsonValue(*tree, document));
    reader.textures.finish();  // the images, decoded together (texture_cache.h)
  } catch (...) {
    reader.textures.rethrow_first_error(std::current_exception());
  }
  warn_unknown_keys(scene, document);
  validate_scene(scene);
  return scene;
}

Scene load_json_scene(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string text = read_file_text(path, "scene");
  std::filesystem::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  return parse_json_scene(text, path.string(), dir, path.stem().string(), options);
}

}  // namespace prism::loaders
