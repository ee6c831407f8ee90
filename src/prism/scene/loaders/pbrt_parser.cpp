// pbrt-v4 scene format: the directive loop, transforms, attribute and object structure,
// camera, film and sampler settings, Include/Import.
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/path_safety.h"
#include "prism/scene/loaders/pbrt_builder.h"
#include "prism/scene/loaders/pbrt_scene.h"

namespace prism::loaders {
namespace {

constexpr int kMaxIncludeDepth = 16;
constexpr std::size_t kMaxAttributeDepth = 100000;
constexpr std::size_t kMaxInstances = 50'000'000;  // placements of object meshes


std::string expect_string(PbrtTokenizer& tokens, std::string_view directive) {
  const PbrtToken t = tokens.next();
  if (t.kind != PbrtTokenKind::string) tokens.fail(t.line, fmt::format("{} expects a quoted string", directive));
  return std::string(t.text);
}

// n numbers, optionally inside brackets (Transform and ConcatTransform use them).
std::vector<double> expect_numbers(PbrtTokenizer& tokens, std::size_t n, std::string_view directive) {
  const bool bracket = tokens.peek().kind == PbrtTokenKind::open_bracket;
  const int line = tokens.peek().line;
  if (bracket) tokens.next();
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    const PbrtToken t = tokens.next();
    if (t.kind != PbrtTokenKind::word) tokens.fail(t.line, fmt::format("{} expects {} numbers", directive, n));
    v.push_back(parse_pbrt_number(tokens, t));
  }
  if (bracket && tokens.next().kind != PbrtTokenKind::close_bracket)
    tokens.fail(line, fmt::format("{} expects {} numbers in brackets", directive, n));
  return v;
}

PbrtMatrix from_pbrt_order(const std::vector<double>& v) {
  // pbrt lists the matrix column by column (the translation is elements 12..14).
  PbrtMatrix r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = v[j * 4 + i];
  return r;
}

}  // namespace

PbrtBuilder::PbrtBuilder(const std::filesystem::path& scene_dir, const LoadOptions& options)
    : scene_dir_(scene_dir), options_(options), textures_(std::make_unique<TextureCache>(scene_, options)) {
  // pbrt-v4's defaults: a 1280×720 film, 16 samples per pixel, path depth 5, fov 90°.
  scene_.default_width = 1280;
  scene_.default_height = 720;
  scene_.default_spp = 16;
  scene_.default_max_depth = 5;
  scene_.camera.fov_degrees = 90.0f;
}

void PbrtBuilder::parse(std::string_view text, const std::string& source, int include_depth) {
  PbrtTokenizer tokens(text, source);
  while (tokens.peek().kind != PbrtTokenKind::end) {
    const PbrtToken name = tokens.next();
    if (name.kind != PbrtTokenKind::word)
      tokens.fail(name.line, fmt::format("expected a directive, found '{}'", name.text));
    directive(tokens, name, include_depth);
  }
}

void PbrtBuilder::ignore(std::string_view what, const PbrtParams& params) {
  ignored_[std::string(what)].push_back(params.line);
}

void PbrtBuilder::note_unused(std::string_view directive, const PbrtParams& params) {
  for (const auto& p : params.unused()) ignored_[fmt::format("{} parameter {}", directive, p)];
}

std::filesystem::path PbrtBuilder::resolve(const PbrtParams& params, std::string_view param,
                                           const std::string& file) const {
  return resolve_scene_reference(scene_dir_, file, options_.allow_external_paths,
                                 fmt::format("{}:{}: {}", params.source, params.line, param));
}

void PbrtBuilder::directive(PbrtTokenizer& tokens, const PbrtToken& name, int include_depth) {
  const std::string_view d = name.text;
  const auto params = [&] { return read_pbrt_params(tokens, name.line); };
  const auto ctm_mul = [&](const PbrtMatrix& m) { state_.ctm = state_.ctm * m; };
  if (d == "LookAt") {
    const auto v = expect_numbers(tokens, 9, d);
    const auto m = PbrtMatrix::look_at(&v[0], &v[3], &v[6]);
    if (!m) tokens.fail(name.line, "LookAt: the eye coincides with the target or the up vector is parallel to the view");
    ctm_mul(*m);
  } else if (d == "Translate") {
    const auto v = expect_numbers(tokens, 3, d);
    ctm_mul(PbrtMatrix::translate(v[0], v[1], v[2]));
  } else if (d == "Scale") {
    const auto v = expect_numbers(tokens, 3, d);
    ctm_mul(PbrtMatrix::scale(v[0], v[1], v[2]));
  } else if (d == "Rotate") {
    const auto v = expect_numbers(tokens, 4, d);
    ctm_mul(PbrtMatrix::rotate(v[0], v[1], v[2], v[3]));
  } else if (d == "Transform") {
    state_.ctm = from_pbrt_order(expect_numbers(tokens, 16, d));
  } else if (d == "ConcatTransform") {
    ctm_mul(from_pbrt_order(expect_numbers(tokens, 16, d)));
  } else if (d == "Identity") {
    state_.ctm = PbrtMatrix{};
  } else if (d == "CoordinateSystem") {
    coordinate_systems_[expect_string(tokens, d)] = state_.ctm;
  } else if (d == "CoordSysTransform") {
    const std::string n = expect_string(tokens, d);
    const auto it = coordinate_systems_.find(n);
    if (it == coordinate_systems_.end()) tokens.fail(name.line, fmt::format("unknown coordinate system '{}'", n));
    state_.ctm = it->second;
  } else if (d == "ReverseOrientation") {
    state_.reverse_orientation = !state_.reverse_orientation;
  } else if (d == "AttributeBegin" || d == "TransformBegin") {
    if (stack_.size() >= kMaxAttributeDepth) tokens.fail(name.line, "attributes nested too deeply");
    stack_.push_back(state_);
  } else if (d == "AttributeEnd" || d == "TransformEnd") {
    if (stack_.empty()) tokens.fail(name.line, fmt::format("{} without a matching begin", d));
    if (d == "TransformEnd") {
      state_.ctm = stack_.back().ctm;
    } else {
      state_ = stack_.back();
    }
    stack_.pop_back();
  } else if (d == "Camera") {
    const std::string type = expect_string(tokens, d);
    camera(type, params());
  } else if (d == "Film") {
    const std::string type = expect_string(tokens, d);
    film(type, params());
  } else if (d == "Sampler" || d == "Integrator") {
    const std::string type = expect_string(tokens, d);
    const PbrtParams p = params();
    if (d == "Sampler") {
      const int spp = p.get_int("pixelsamples", 16);
      if (spp < 1 || spp > 1 << 24) p.fail(*p.find("pixelsamples"), "must be between 1 and 16777216");
      scene_.default_spp = spp;
    } else {
      const int depth = p.get_int("maxdepth", 5);
      if (depth < 0 || depth > 100000) p.fail(*p.find("maxdepth"), "must be between 0 and 100000");
      scene_.default_max_depth = depth;  // 0: what the camera sees of emitters, as in pbrt-v4
      if (type != "path" && type != "volpath") ignore(fmt::format("Integrator \"{}\" (Prism's own path tracer is used)", type), p);
    }
    note_unused(d, p);
  } else if (d == "WorldBegin") {
    if (world_begun_) tokens.fail(name.line, "a second WorldBegin");
    world_begun_ = true;
    coordinate_systems_["world"] = PbrtMatrix{};
    state_.ctm = PbrtMatrix{};
  } else if (d == "WorldEnd") {
    // pbrt-v3 syntax; nothing to do.
  } else if (d == "ObjectBegin") {
    if (current_object_) tokens.fail(name.line, "ObjectBegin inside another object");
    const std::string n = expect_string(tokens, d);
    if (objects_.count(n)) tokens.fail(name.line, fmt::format("object '{}' is defined twice", n));
    if (stack_.size() >= kMaxAttributeDepth) tokens.fail(name.line, "attributes nested too deeply");
    stack_.push_back(state_);
    objects_[n];
    current_object_ = n;
  } else if (d == "ObjectEnd") {
    if (!current_object_ || stack_.empty()) tokens.fail(name.line, "ObjectEnd without ObjectBegin");
    current_object_.reset();
    state_ = stack_.back();
    stack_.pop_back();
  } else if (d == "ObjectInstance") {
    const std::string n = expect_string(tokens, d);
    const auto it = objects_.find(n);
    if (it == objects_.end()) tokens.fail(name.line, fmt::format("unknown object '{}'", n));
    if (current_object_) tokens.fail(name.line, "ObjectInstance inside an object definition");
    if (!state_.ctm.is_affine()) tokens.fail(name.line, "ObjectInstance: the transform is projective");
    if (placements_.size() + it->second.size() > kMaxInstances)
      tokens.fail(name.line, fmt::format("more than {} object instances", kMaxInstances));
    for (std::uint32_t mesh : it->second) placements_.push_back(Instance{mesh, state_.ctm.to_transform()});
  } else if (d == "Include" || d == "Import") {
    const std::string file = expect_string(tokens, d);
    if (include_depth >= kMaxIncludeDepth) tokens.fail(name.line, fmt::format("{} nested more than {} deep", d, kMaxIncludeDepth));
    PbrtParams where;
    where.source = tokens.source();
    where.line = name.line;
    const auto path = resolve(where, d, file);
    std::string text;
    try {
      text = read_file_text(path, "pbrt-v4 scene");
    } catch (const IoError& e) {
      throw IoError(fmt::format("{}:{}: {}: {}", tokens.source(), name.line, d, e.what()));
    }
    parse(text, path.filename().string(), include_depth + 1);
  } else if (d == "Material") {
    const std::string type = expect_string(tokens, d);
    make_material(type, params(), {});
  } else if (d == "MakeNamedMaterial") {
    const std::string n = expect_string(tokens, d);
    const PbrtParams p = params();
    const std::string type = p.get_string("type", "");
    if (type.empty()) tokens.fail(name.line, fmt::format("MakeNamedMaterial '{}' has no \"string type\"", n));
    make_material(type, p, n);
  } else if (d == "NamedMaterial") {
    const std::string n = expect_string(tokens, d);
    const auto it = named_materials_.find(n);
    if (it == named_materials_.end()) tokens.fail(name.line, fmt::format("unknown named material '{}'", n));
    state_.material = it->second;
  } else if (d == "Texture") {
    const std::string n = expect_string(tokens, d);
    const std::string value_type = expect_string(tokens, d);
    const std::string klass = expect_string(tokens, d);
    texture(n, value_type, klass, params());
  } else if (d == "Shape") {
    const std::string type = expect_string(tokens, d);
    shape(type, params());
  } else if (d == "LightSource") {
    const std::string type = expect_string(tokens, d);
    light_source(type, params());
  } else if (d == "AreaLightSource") {
    const std::string type = expect_string(tokens, d);
    area_light_source(type, params());
  } else if (d == "MakeNamedMedium") {
    const std::string n = expect_string(tokens, d);
    make_medium(n, params());
  } else if (d == "ColorSpace") {
    const std::string space = expect_string(tokens, d);
    if (!is_pbrt_color_space(space))
      tokens.fail(name.line, fmt::format("ColorSpace: unknown colour space '{}' (pbrt-v4 has srgb, rec2020, "
                                         "aces2065-1 and dci-p3)",
                                         space));
    state_.color_space = space;
  } else if (d == "Attribute") {
    expect_string(tokens, d);
    ignore(d, params());
  } else if (d == "MediumInterface") {
    // pbrt-v4: "interior" "exterior", or one name for both.
    const std::string interior = expect_string(tokens, d);
    std::string exterior = interior;
    if (tokens.peek().kind == PbrtTokenKind::string) exterior = std::string(tokens.next().text);
    medium_interface(interior, exterior, PbrtParams{{}, tokens.source(), name.line});
  } else if (d == "PixelFilter" || d == "Accelerator") {
    expect_string(tokens, d);
    ignore(d, params());
  } else if (d == "Option") {
    ignore(d, params());
  } else if (d == "TransformTimes") {
    expect_numbers(tokens, 2, d);
    ignore(d, PbrtParams{{}, tokens.source(), name.line});
  } else if (d == "ActiveTransform") {
    const PbrtToken t = tokens.next();
    if (t.kind != PbrtTokenKind::word) tokens.fail(t.line, "ActiveTransform expects StartTime, EndTime or All");
    ignore(d, PbrtParams{{}, tokens.source(), name.line});
  } else {
    tokens.fail(name.line, fmt::format("unknown directive '{}'", d));
  }
}

void PbrtBuilder::camera(const std::string& type, const PbrtParams& p) {
  if (camera_seen_) ignore("second Camera", p);
  camera_seen_ = true;
  if (type != "perspective") ignore(fmt::format("Camera \"{}\" (rendered as perspective)", type), p);
  const auto camera_to_world = state_.ctm.inverse();
  if (!camera_to_world || !state_.ctm.is_affine()) throw SceneError(fmt::format("{}:{}: Camera: the camera transform is singular or projective", p.source, p.line));
  coordinate_systems_["camera"] = *camera_to_world;
  // Prism's camera space has +x to the image's left where pbrt's has +x to the right, so
  // pbrt's image is reproduced exactly when its camera-to-world matrix mirrors x (as
  // files that begin with `Scale -1 1 1` do); otherwise the image is mirrored.
  if (camera_to_world->determinant3() > 0.0)
    approximations_.push_back(fmt::format(
        "Camera (line {}) has a right-handed transform: the image is mirrored left-right relative to pbrt-v4 "
        "(add `Scale -1 1 1` before LookAt to match)", p.line));
  const Transform c = camera_to_world->to_transform();
  Camera& cam = scene_.camera;
  cam.eye = c.apply_point(Vec3f(0.0f));
  cam.target = c.apply_point(Vec3f(0.0f, 0.0f, 1.0f));
  cam.up = normalize(c.apply_vector(Vec3f(0.0f, 1.0f, 0.0f)));
  const double fov = p.get_float("fov", 90.0);
  if (!(fov > 0.0 && fov < 180.0)) p.fail(*p.find("fov"), "must be between 0 and 180 degrees");
  cam.fov_degrees = static_cast<float>(fov);
  const double lens = p.get_float("lensradius", 0.0), focus = p.get_float("focaldistance", 1e6);
  if (lens < 0.0) p.fail(*p.find("lensradius"), "must not be negative");
  if (!(focus > 0.0)) p.fail(*p.find("focaldistance"), "must be positive");
  // pbrt measures the focal distance in camera space; Prism along the viewing direction
  // in scene units: the same when the camera transform has no scale.
  const double unit = length(c.apply_vector(Vec3f(0.0f, 0.0f, 1.0f)));
  cam.aperture_radius = static_cast<float>(lens * unit);
  cam.focus_distance = static_cast<float>(focus * unit);
  cam.name = "default";
  note_unused("Camera", p);
}

void PbrtBuilder::film(const std::string& type, const PbrtParams& p) {
  if (type != "rgb") ignore(fmt::format("Film \"{}\" (an RGB film is used)", type), p);
  const int w = p.get_int("xresolution", 1280), h = p.get_int("yresolution", 720);
  if (w < 1 || h < 1 || w > 65536 || h > 65536)
    throw SceneError(fmt::format("{}:{}: Film: resolution {}×{} is out of range", p.source, p.line, w, h));
  scene_.default_width = w;
  scene_.default_height = h;
  scene_.output_file = p.get_string("filename", "");  // prism render writes it unless -o is given
  note_unused("Film", p);
}

Scene PbrtBuilder::finish() {
  textures_->finish();  // the images, decoded together, before the checks of the whole file
  // pbrt-v4's image textures keep their file's colour space: an OpenEXR in wider primaries
  // than Rec.709 was read into Rec.2020 or ACEScg (TextureContent::color_own_gamut), and
  // the material's base colour is in that space (its factor, an imagemap's "scale", is grey
  // in every space).
  for (Material& m : scene_.materials)
    if (m.base_color_texture >= 0)
      m.base_color_space = scene_.textures[static_cast<std::size_t>(m.base_color_texture)].texel_space;
  if (!stack_.empty()) throw SceneError(fmt::format("{} AttributeBegin without AttributeEnd", stack_.size()));
  if (current_object_) throw SceneError(fmt::format("ObjectBegin '{}' without ObjectEnd", *current_object_));
  bool any_object_mesh = false;
  for (const auto& [n, meshes] : objects_) any_object_mesh |= !meshes.empty();
  if (any_object_mesh) {
    for (std::uint32_t m : world_meshes_) scene_.instances.push_back(Instance{m, Transform{}});
    scene_.instances.insert(scene_.instances.end(), placements_.begin(), placements_.end());
  }
  if (!ignored_.empty()) {
    std::vector<std::string> items;
    for (const auto& [what, lines] : ignored_)
      items.push_back(lines.empty() ? what : fmt::format("{} (line {})", what, fmt::join(lines, ", ")));
    scene_.warnings.push_back(fmt::format("pbrt-v4: ignored: {}", fmt::join(items, "; ")));
  }
  if (!approximations_.empty())
    scene_.warnings.push_back(fmt::format("pbrt-v4: approximated: {}", fmt::join(approximations_, "; ")));
  scene_.cameras = {scene_.camera};
  validate_scene(scene_);
  return std::move(scene_);
}

Scene parse_pbrt_scene(std::string_view text, std::string_view source, const std::filesystem::path& scene_dir,
                       const LoadOptions& options) {
  PbrtBuilder builder(scene_dir, options);
  Scene scene;
  try {
    builder.parse(text, std::string(source), 0);
    scene = builder.finish();
  } catch (...) {
    builder.rethrow_first_texture_error(std::current_exception());
  }
  if (scene.name.empty()) scene.name = std::filesystem::path(source).stem().string();
  return scene;
}

Scene load_pbrt_scene(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string text = read_file_text(path, "pbrt-v4 scene");
  std::error_code ec;
  const auto dir = std::filesystem::absolute(path, ec).parent_path();
  return parse_pbrt_scene(text, path.filename().string(), dir, options);
}

}  // namespace prism::loaders
