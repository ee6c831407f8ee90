#include "prism/scene/loaders/scene_writers.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/bsdf/ior.h"
#include "prism/color/chromatic_adaptation.h"
#include "prism/bsdf/microfacet.h"
#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/texture_png.h"
#include "prism/scene/surface_alpha.h"
#include "prism/scene/type_names.h"

namespace prism::loaders {
namespace {

// Buffered output through fmt, flushed to the stream in large pieces.
class Writer {
 public:
  explicit Writer(const std::filesystem::path& path) : file_(path), out_(file_.temporary_path(), std::ios::binary) {
    if (!out_) throw IoError(fmt::format("cannot write '{}'", path.string()));
  }
  template <typename... Args>
  void operator()(fmt::format_string<Args...> f, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), f, std::forward<Args>(args)...);
    if (buffer_.size() > (1u << 20)) flush();
  }
  void finish(const std::filesystem::path& path) {
    flush();
    out_.close();
    if (!out_) throw IoError(fmt::format("cannot write '{}'", path.string()));
    file_.commit();
  }

 private:
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
  AtomicFile file_;
  std::ofstream out_;
  fmt::memory_buffer buffer_;
};

void check_writable(const Scene& scene) {
  if (!scene.instances.empty()) throw UsageError("scene writer: instances are not supported");
  for (const Light& l : scene.lights) {
    if (l.type != LightType::environment || l.environment_texture >= 0)
      throw UsageError("scene writer: only a constant environment light is supported");
    if (l.spectrum)
      throw UsageError(fmt::format("scene writer: light '{}' has a spectrum; only RGB colours are written", l.name));
  }
  for (const Material& m : scene.materials)
    if (m.base_color_spectrum || m.emission.spectrum)
      throw UsageError(fmt::format("scene writer: material '{}' has a spectrum; only RGB colours are written", m.name));
}

std::string vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

std::string_view wrap_name(TextureWrap w) { return enum_name(kTextureWrapNames, w); }

// A prism-scene/1 texture reference: the PNG's name, with wrap modes when not repeat.
std::string json_texture(const Scene& scene, const std::vector<std::string>& files, int index) {
  const TextureImage& t = scene.textures[static_cast<std::size_t>(index)];
  if (t.offset_u != 0.0f || t.offset_v != 0.0f || t.scale_u != 1.0f || t.scale_v != 1.0f || t.rotation_radians != 0.0f)
    throw UsageError(fmt::format("JSON writer: texture '{}' has a uv transform, which prism-scene/1 cannot hold", t.name));
  const std::string& file = files[static_cast<std::size_t>(index)];
  if (t.wrap_u == TextureWrap::repeat && t.wrap_v == TextureWrap::repeat) return fmt::format("\"{}\"", file);
  return fmt::format("{{\"file\": \"{}\", \"wrap_u\": \"{}\", \"wrap_v\": \"{}\"}}", file, wrap_name(t.wrap_u),
                     wrap_name(t.wrap_v));
}

std::string_view alpha_mode_name(AlphaMode a) { return enum_name(kAlphaModeNames, a); }

std::string_view type_name(MaterialType t) { return enum_name(kMaterialTypeNames, t); }

// A colour as pbrt-v4 says it: the name of its space (pbrt's ColorSpace directive) and its
// components there. pbrt-v4 has no ACEScg: an ACEScg colour is written in ACES2065-1 (AP0,
// the same white), which the pbrt loader takes back to ACEScg.
struct PbrtRgb {
  const char* space;
  Vec3f rgb;
};

PbrtRgb pbrt_rgb(const Vec3f& color, ColorPickerSpace space) {
  switch (space) {
    case ColorPickerSpace::acescg: {
      const Mat3 to_ap0 = color::conversion_matrix(color::color_space("acescg"), color::color_space("aces2065-1"));
      return {"aces2065-1", Vec3f(to_ap0 * Vec3d(color))};
    }
    case ColorPickerSpace::rec2020: return {"rec2020", color};
    case ColorPickerSpace::srgb: break;
  }
  return {"srgb", color};
}

// An RGB radiance whose luminance is `nits`, for pbrt's "rgb L" (in the colour's space).
PbrtRgb radiance_rgb(const Vec3f& color, ColorPickerSpace space, float nits) {
  const double y = relative_luminance(color, space);
  return pbrt_rgb(y > 0.0 ? color * static_cast<float>(nits / y) : Vec3f(0.0f), space);
}

// pbrt-v4's ColorSpace is graphics state: written only where the next colour's space
// differs from the one in effect.
class PbrtColorSpaceState {
 public:
  void use(Writer& w, const char* space, std::string_view indent = "") {
    if (current_ == space) return;
    w("{}ColorSpace \"{}\"\n", indent, space);
    current_ = space;
  }
  std::string_view current() const { return current_; }

 private:
  std::string_view current_ = "srgb";
};

}  // namespace

void write_scene_json(const Scene& scene, const std::filesystem::path& path) {
  check_writable(scene);
  // Textures first, so the scene file never names a PNG that is not there yet.
  const std::vector<std::string> files = write_scene_textures(scene, path);
  Writer w(path);
  const Camera& c = scene.camera;
  w("{{\n \"format\": \"prism-scene/1\",\n \"name\": \"{}\",\n \"meters_per_unit\": 1.0,\n", scene.name);
  w(" \"render\": {{\"width\": {}, \"height\": {}}},\n", scene.default_width, scene.default_height);
  w(" \"camera\": {{\"name\": \"{}\", \"eye\": {}, \"target\": {}, \"up\": {}, \"fov_degrees\": {}}},\n",
    c.name.empty() ? "default" : c.name, vec(c.eye), vec(c.target), vec(c.up), c.fov_degrees);
  w(" \"materials\": [\n");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    w("  {{\"name\": \"{}\", \"type\": \"{}\", \"base_color\": {}, \"roughness\": {}", m.name, type_name(m.type),
      vec(m.base_color), m.roughness);
    if (m.base_color_space != ColorPickerSpace::srgb)
      w(", \"base_color_space\": \"{}\"", picker_space_name(m.base_color_space));
    if (m.type == MaterialType::conductor && m.conductor_fresnel == ConductorFresnel::complex_ior)
      w(", \"conductor\": \"{}\"", m.conductor_name);
    if (m.type == MaterialType::dielectric) {
      // A dispersive glass by its model's coefficients (the reader derives n_d from them).
      const auto& d = m.dispersion_coefficients;
      if (m.dispersion == DispersionModel::cauchy)
        w(", \"dispersion\": {{\"model\": \"cauchy\", \"coefficients\": [{}, {}]}}", d[0], d[1]);
      else if (m.dispersion == DispersionModel::sellmeier)
        w(", \"dispersion\": {{\"model\": \"sellmeier\", \"coefficients\": [{}]}}", fmt::join(d, ", "));
      else
        w(", \"ior\": {}", m.ior);
      if (m.thin_walled) w(", \"thin_walled\": true");
    }
    if (m.absorbs_inside())
      w(", \"attenuation_color\": {}, \"attenuation_distance\": {}", vec(m.attenuation_color), m.attenuation_distance);
    if (m.type == MaterialType::metallic_roughness) {
      w(", \"metallic\": {}", m.metallic);
      if (m.ior != 1.5f) w(", \"ior\": {}", m.ior);
      if (m.specular != 1.0f) w(", \"specular\": {}", m.specular);
      if (m.specular_color != Vec3f(1.0f)) w(", \"specular_color\": {}", vec(m.specular_color));
      if (m.specular_texture >= 0) w(", \"specular_texture\": {}", json_texture(scene, files, m.specular_texture));
      if (m.specular_color_texture >= 0)
        w(", \"specular_color_texture\": {}", json_texture(scene, files, m.specular_color_texture));
    }
    if (m.has_clearcoat()) {
      w(", \"clearcoat\": {}, \"clearcoat_roughness\": {}", m.clearcoat, m.clearcoat_roughness);
      if (m.clearcoat_texture >= 0) w(", \"clearcoat_texture\": {}", json_texture(scene, files, m.clearcoat_texture));
      if (m.clearcoat_roughness_texture >= 0)
        w(", \"clearcoat_roughness_texture\": {}", json_texture(scene, files, m.clearcoat_roughness_texture));
      if (m.clearcoat_normal_texture >= 0)
        w(", \"clearcoat_normal_texture\": {}, \"clearcoat_normal_scale\": {}",
          json_texture(scene, files, m.clearcoat_normal_texture), m.clearcoat_normal_scale);
    }
    if (m.has_iridescence()) {
      w(", \"iridescence\": {}, \"iridescence_ior\": {}, \"iridescence_thickness_min_nm\": {}, "
        "\"iridescence_thickness_max_nm\": {}",
        m.iridescence, m.iridescence_ior, m.iridescence_thickness_min_nm, m.iridescence_thickness_max_nm);
      if (m.iridescence_texture >= 0)
        w(", \"iridescence_texture\": {}", json_texture(scene, files, m.iridescence_texture));
      if (m.iridescence_thickness_texture >= 0)
        w(", \"iridescence_thickness_texture\": {}", json_texture(scene, files, m.iridescence_thickness_texture));
    }
    if (m.anisotropy > 0.0f) {
      w(", \"anisotropy\": {}, \"anisotropy_rotation_degrees\": {}", m.anisotropy,
        m.anisotropy_rotation_rad * 180.0 / std::numbers::pi);
      if (m.anisotropy_texture >= 0) w(", \"anisotropy_texture\": {}", json_texture(scene, files, m.anisotropy_texture));
    }
    if (m.has_sheen()) {
      w(", \"sheen_color\": {}, \"sheen_roughness\": {}", vec(m.sheen_color), m.sheen_roughness);
      if (m.sheen_color_texture >= 0) w(", \"sheen_color_texture\": {}", json_texture(scene, files, m.sheen_color_texture));
      if (m.sheen_roughness_texture >= 0)
        w(", \"sheen_roughness_texture\": {}", json_texture(scene, files, m.sheen_roughness_texture));
    }
    if (m.base_color_texture >= 0) w(", \"base_color_texture\": {}", json_texture(scene, files, m.base_color_texture));
    if (m.metallic_roughness_texture >= 0)
      w(", \"metallic_roughness_texture\": {}", json_texture(scene, files, m.metallic_roughness_texture));
    if (m.normal_texture >= 0)
      w(", \"normal_texture\": {}, \"normal_scale\": {}", json_texture(scene, files, m.normal_texture), m.normal_scale);
    if (m.bump_texture >= 0)
      w(", \"bump_texture\": {}, \"bump_scale\": {}", json_texture(scene, files, m.bump_texture), m.bump_scale);
    if (m.alpha_mode != AlphaMode::opaque) w(", \"alpha_mode\": \"{}\", \"alpha_cutoff\": {}", alpha_mode_name(m.alpha_mode), m.alpha_cutoff);
    if (m.opacity != 1.0f) w(", \"opacity\": {}", m.opacity);
    if (m.is_emissive()) {
      w(", \"emission\": {{\"color\": {}, \"luminance_nits\": {}, \"two_sided\": {}", vec(m.emission.color),
        m.emission.luminance_nits, m.emission.two_sided);
      if (m.emission.color_space != ColorPickerSpace::srgb)
        w(", \"color_space\": \"{}\"", picker_space_name(m.emission.color_space));
      if (m.emission.texture >= 0) w(", \"texture\": {}", json_texture(scene, files, m.emission.texture));
      w("}}");
    }
    w("}}{}\n", i + 1 < scene.materials.size() ? "," : "");
  }
  w(" ],\n \"meshes\": [\n");
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const TriangleMesh& mesh = scene.meshes[i];
    w("  {{\"name\": \"{}\", \"material\": \"{}\",\n   \"positions\": [", mesh.name, scene.materials[mesh.material].name);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      w("{}{}, {}, {}", v ? ", " : "", mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z);
    if (!mesh.normals.empty()) {
      w("],\n   \"normals\": [");
      for (std::size_t v = 0; v < mesh.normals.size(); ++v)
        w("{}{}, {}, {}", v ? ", " : "", mesh.normals[v].x, mesh.normals[v].y, mesh.normals[v].z);
    }
    if (!mesh.uvs.empty()) {
      w("],\n   \"uvs\": [");
      for (std::size_t v = 0; v < mesh.uvs.size(); ++v) w("{}{}, {}", v ? ", " : "", mesh.uvs[v].x, mesh.uvs[v].y);
    }
    w("],\n   \"indices\": [");
    for (std::size_t k = 0; k < mesh.indices.size(); ++k) w("{}{}", k ? ", " : "", mesh.indices[k]);
    w("]}}{}\n", i + 1 < scene.meshes.size() ? "," : "");
  }
  w(" ]");
  for (const Light& l : scene.lights) {
    w(",\n \"environment\": {{\"name\": \"{}\", \"color\": {}, \"luminance_nits\": {}", l.name, vec(l.color), l.intensity);
    if (l.color_space != ColorPickerSpace::srgb) w(", \"color_space\": \"{}\"", picker_space_name(l.color_space));
    w("}}");
  }
  w("\n}}\n");
  w.finish(path);
}

namespace {

// A dielectric's η for pbrt-v4: a number, pbrt's own "glass-BK7" for Prism's N-BK7, or
// (λ, η) pairs every 20 nm across the visible for any other dispersive glass (the pbrt-v4
// reader fits them with a Cauchy glass: exact for a Cauchy one).
std::string pbrt_eta(const Material& m) {
  if (m.dispersion == DispersionModel::none) return fmt::format("\"float eta\" [ {} ]", m.ior);
  const bsdf::SellmeierIor bk7 = bsdf::sellmeier_bk7();
  const auto& d = m.dispersion_coefficients;
  bool is_bk7 = m.dispersion == DispersionModel::sellmeier;
  for (int i = 0; i < 3; ++i)
    is_bk7 = is_bk7 && d[static_cast<std::size_t>(i)] == static_cast<float>(bk7.b[i]) &&
             d[static_cast<std::size_t>(3 + i)] == static_cast<float>(bk7.c_um2[i]);
  if (is_bk7) return "\"spectrum eta\" \"glass-BK7\"";
  std::string pairs;
  for (int nm = 380; nm <= 780; nm += 20) pairs += fmt::format("{} {} ", nm, dielectric_ior(m, nm));
  return fmt::format("\"spectrum eta\" [ {}]", pairs);
}

// A conductor's or rough glass's roughness for pbrt-v4, as α = r² of Prism's perceptual
// roughness r (written with remaproughness false):
// "roughness", or where the material is anisotropic uroughness along dP/du and vroughness
// across it (render/anisotropy.h), which holds a direction of rotation 0 or π/2 (mod π) and
// no texture; any other is refused.
std::string pbrt_roughness(const Material& m, const std::string& prefix) {
  const float alpha = m.roughness * m.roughness;
  if (!m.has_anisotropy()) return fmt::format("\"float {}roughness\" [ {} ]", prefix, alpha);
  const double turns = m.anisotropy_rotation_rad / std::numbers::pi;  // in half turns
  const double rest = turns - std::round(turns);                          // 0: along u; ±½: along v
  const bool along_u = std::abs(rest) < 1e-6, along_v = std::abs(std::abs(rest) - 0.5) < 1e-6;
  if (m.anisotropy_texture >= 0 || !(along_u || along_v))
    throw UsageError(fmt::format("pbrt writer: material '{}': anisotropy {}, which pbrt-v4's uroughness and "
                                 "vroughness cannot say",
                                 m.name, m.anisotropy_texture >= 0 ? "from a texture" : "at an angle to the uv axes"));
  const float across = std::max(alpha, bsdf::kMinAnisotropicAlpha);
  const float along = bsdf::anisotropic_alpha_along(across, m.anisotropy);
  return fmt::format("\"float {0}uroughness\" [ {1} ] \"float {0}vroughness\" [ {2} ]", prefix,
                     along_u ? along : across, along_u ? across : along);
}

// pbrt-v4 texture names of what a material needs: its reflectance image and, for
// alpha-tested materials, a float alpha image (pbrt puts alpha on the Shape).
struct PbrtMaterialTextures {
  std::string reflectance;  // empty: none
  std::string alpha;        // empty: none
  std::string displacement;  // the bump map's float texture; empty: none
  std::optional<float> constant_alpha;
};

// pbrt-v4's image t axis points up (it looks up 1 − v), Prism's down: v_pbrt = 1 − v,
// and a texture's v transform becomes vscale = s, vdelta = 1 − s − offset.
std::string pbrt_image_params(const TextureImage& t, const std::string& file, const char* encoding) {
  if (t.rotation_radians != 0.0f) throw UsageError(fmt::format("pbrt writer: texture '{}' is rotated", t.name));
  if (t.wrap_u != t.wrap_v || t.wrap_u == TextureWrap::mirror)
    throw UsageError(fmt::format("pbrt writer: texture '{}' wraps in a way pbrt-v4 cannot say", t.name));
  std::string out = fmt::format(" \"string filename\" \"{}\" \"string encoding\" \"{}\" \"string wrap\" \"{}\"", file,
                                encoding, t.wrap_u == TextureWrap::repeat ? "repeat" : "clamp");
  if (t.offset_u != 0.0f || t.offset_v != 0.0f || t.scale_u != 1.0f || t.scale_v != 1.0f)
    out += fmt::format(" \"float uscale\" [ {} ] \"float vscale\" [ {} ] \"float udelta\" [ {} ] \"float vdelta\" [ {} ]",
                       t.scale_u, t.scale_v, t.offset_u, 1.0f - t.scale_v - t.offset_v);
  return out;
}

// Writes the Texture directives of material `index` (and its alpha PNG next to the scene).
PbrtMaterialTextures write_pbrt_textures(Writer& w, const Scene& scene, std::size_t index, const std::vector<std::string>& files,
                                         const std::filesystem::path& path) {
  const Material& m = scene.materials[index];
  PbrtMaterialTextures out;
  if (m.base_color_texture >= 0) {
    if (m.type != MaterialType::diffuse && m.type != MaterialType::metallic_roughness)
      throw UsageError(fmt::format("pbrt writer: material '{}': only diffuse reflectance can be textured", m.name));
    if (m.base_color.x != m.base_color.y || m.base_color.x != m.base_color.z)
      throw UsageError(fmt::format("pbrt writer: material '{}': a texture tinted other than grey", m.name));
    const auto t = static_cast<std::size_t>(m.base_color_texture);
    out.reflectance = fmt::format("{}-reflectance", m.name);
    w("Texture \"{}\" \"spectrum\" \"imagemap\"{} \"float scale\" [ {} ]\n", out.reflectance,
      pbrt_image_params(scene.textures[t], files[t], "sRGB"), m.base_color.x);
  }
  if (m.bump_texture >= 0) {
    // pbrt-v4's "displacement" float texture: the image's first channel times "scale".
    const auto t = static_cast<std::size_t>(m.bump_texture);
    out.displacement = fmt::format("{}-bump", m.name);
    w("Texture \"{}\" \"float\" \"imagemap\"{} \"float scale\" [ {} ]\n", out.displacement,
      pbrt_image_params(scene.textures[t], files[t], "linear"), m.bump_scale);
  }
  if (!has_alpha_coverage(m)) return out;
  const int t = m.base_color_texture;
  const TextureImage* image = t >= 0 ? &scene.textures[static_cast<std::size_t>(t)] : nullptr;
  if (!image || (image->channels != 2 && image->channels != 4)) {
    // Constant coverage: pbrt keeps a hit with probability alpha (MASK: all or nothing).
    const float alpha = m.alpha_mode == AlphaMode::mask ? (m.opacity >= m.alpha_cutoff ? 1.0f : 0.0f) : m.opacity;
    if (alpha < 1.0f) out.constant_alpha = alpha;
    return out;
  }
  // pbrt-v4 keeps a hit with probability alpha; MASK becomes a 0/1 image so that it cuts
  // exactly where Prism's cutoff does at the texels.
  TextureImage alpha = *image;
  alpha.channels = 1;
  alpha.codes.clear();  // a float image of the one channel
  alpha.texels.resize(static_cast<std::size_t>(image->width) * image->height);
  for (std::size_t i = 0; i < alpha.texels.size(); ++i) {
    const float a = m.opacity * image->value(i * image->channels + image->channels - 1);
    alpha.texels[i] = m.alpha_mode == AlphaMode::mask ? (a >= m.alpha_cutoff ? 1.0f : 0.0f) : a;
  }
  const std::string file = texture_file_name(path, *image, static_cast<std::size_t>(t), fmt::format("-alpha-{}", index));
  write_file_atomically(path.parent_path() / file, encode_texture_channel_png(alpha, 0));
  out.alpha = fmt::format("{}-alpha", m.name);
  w("Texture \"{}\" \"float\" \"imagemap\"{}\n", out.alpha, pbrt_image_params(alpha, file, "linear"));
  return out;
}

}  // namespace

void write_scene_pbrt(const Scene& scene, const std::filesystem::path& path) {
  check_writable(scene);
  // pbrt-v4 has no sheen, no thin film, no anisotropy off the uv axes and no coat normal
  // map: refused before any file is written, not dropped in silence.
  for (const Material& m : scene.materials) {
    if (m.has_sheen())
      throw UsageError(fmt::format("pbrt writer: material '{}' has a sheen, which pbrt-v4 cannot hold", m.name));
    if (m.has_iridescence())
      throw UsageError(fmt::format("pbrt writer: material '{}' has a thin film (iridescence), which pbrt-v4 cannot hold",
                                   m.name));
    pbrt_roughness(m, "");  // refuses an anisotropy direction pbrt-v4 cannot say
    if (m.has_clearcoat() && m.clearcoat_normal_texture >= 0)
      throw UsageError(fmt::format(
          "pbrt writer: material '{}' has a coat with its own normal map, which pbrt-v4 cannot hold", m.name));
  }
  const std::vector<std::string> files = write_scene_textures(scene, path);
  Writer w(path);
  const Camera& c = scene.camera;
  w("# {} — written by Prism (pbrt-v4 scene format)\n", scene.name);
  w("# `Scale -1 1 1` gives pbrt-v4's camera the same handedness as Prism's.\nScale -1 1 1\n");
  w("LookAt {} {} {}  {} {} {}  {} {} {}\n", c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z);
  w("Camera \"perspective\" \"float fov\" [ {} ]", c.fov_degrees);
  if (c.aperture_radius > 0.0f) w(" \"float lensradius\" [ {} ] \"float focaldistance\" [ {} ]", c.aperture_radius, c.focus_distance);
  w("\nFilm \"rgb\" \"integer xresolution\" [ {} ] \"integer yresolution\" [ {} ] \"string filename\" \"{}.exr\"\n",
    scene.default_width, scene.default_height, scene.name);
  if (scene.default_spp > 0) w("Sampler \"zsobol\" \"integer pixelsamples\" [ {} ]\n", scene.default_spp);
  if (scene.default_max_depth)
    w("Integrator \"volpath\" \"integer maxdepth\" [ {} ]\n", *scene.default_max_depth);
  w("\nWorldBegin\n\n");
  PbrtColorSpaceState world_space;
  for (const Light& l : scene.lights) {
    const PbrtRgb L = radiance_rgb(l.color, l.color_space, l.intensity);
    world_space.use(w, L.space);
    w("LightSource \"infinite\" \"rgb L\" [ {} {} {} ]\n\n", L.rgb.x, L.rgb.y, L.rgb.z);
  }
  std::vector<PbrtMaterialTextures> textures;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    textures.push_back(write_pbrt_textures(w, scene, i, files, path));
    if (m.absorbs_inside()) {
      // pbrt-v4 says absorbing glass with a medium inside the shape: homogeneous, σ_s = 0,
      // σ_a = −ln(c) / d per unit (render/volume_absorption.h); the shapes name it in their
      // MediumInterface below (pbrt_media.cpp reads it back).
      const Vec3f& c = m.attenuation_color;
      const auto sigma = [&](float v) { return -std::log(std::max(v, 1e-30f)) / m.attenuation_distance; };
      w("MakeNamedMedium \"{}-interior\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ {} {} {} ] "
        "\"rgb sigma_s\" [ 0 0 0 ]\n",
        m.name, sigma(c.x), sigma(c.y), sigma(c.z));
    }
    const PbrtRgb base_rgb = pbrt_rgb(m.base_color, m.base_color_space);
    world_space.use(w, base_rgb.space);  // pbrt-v4 reads a named material's colours in the space in effect
    w("MakeNamedMaterial \"{}\"", m.name);
    if (m.normal_texture >= 0) {
      // pbrt-v4's normalmap is a plain repeated image: no scale, no uv transform.
      const TextureImage& t = scene.textures[static_cast<std::size_t>(m.normal_texture)];
      const bool plain = m.normal_scale == 1.0f && t.wrap_u == TextureWrap::repeat && t.wrap_v == TextureWrap::repeat &&
                         t.offset_u == 0.0f && t.offset_v == 0.0f && t.scale_u == 1.0f && t.scale_v == 1.0f &&
                         t.rotation_radians == 0.0f;
      if (!plain)
        throw UsageError(
            fmt::format("pbrt writer: material '{}': a normal map with a scale, wrap or uv transform", m.name));
      w(" \"string normalmap\" \"{}\"", files[static_cast<std::size_t>(m.normal_texture)]);
    }
    if (!textures.back().displacement.empty()) w(" \"texture displacement\" \"{}\"", textures.back().displacement);
    // A clear coat becomes pbrt-v4's coated materials, whose interface has no weight: any
    // coat is written whole (docs/scene-formats.md).
    const bool coated = m.has_clearcoat();
    const float coat_alpha = m.clearcoat_roughness * m.clearcoat_roughness;
    switch (m.type) {
      case MaterialType::conductor:
      case MaterialType::mirror: {
        const std::string base = coated ? "conductor." : "";
        w(" \"string type\" \"{}\"", coated ? "coatedconductor" : "conductor");
        if (m.type == MaterialType::conductor && m.conductor_fresnel == ConductorFresnel::complex_ior)
          w(" \"spectrum {0}eta\" \"metal-{1}-eta\" \"spectrum {0}k\" \"metal-{1}-k\"", base, m.conductor_name);
        else
          w(" \"rgb reflectance\" [ {} {} {} ]", base_rgb.rgb.x, base_rgb.rgb.y, base_rgb.rgb.z);
        if (m.type == MaterialType::mirror)
          w(" \"float {}roughness\" [ 0 ]", base);
        else
          w(" {}", pbrt_roughness(m, base));
        if (coated) w(" \"float interface.roughness\" [ {} ]", coat_alpha);
        w(" \"bool remaproughness\" false\n");
        break;
      }
      case MaterialType::dielectric:
        if (m.thin_walled)  // pbrt-v4's thindielectric is smooth: it takes eta only
          w(" \"string type\" \"thindielectric\" {}\n", pbrt_eta(m));
        else
          w(" \"string type\" \"dielectric\" {} {} \"bool remaproughness\" false\n", pbrt_eta(m),
            pbrt_roughness(m, ""));
        break;
      default:
        w(" \"string type\" \"{}\"", coated ? "coateddiffuse" : "diffuse");
        if (!textures.back().reflectance.empty())
          w(" \"texture reflectance\" \"{}\"", textures.back().reflectance);
        else
          w(" \"rgb reflectance\" [ {} {} {} ]", base_rgb.rgb.x, base_rgb.rgb.y, base_rgb.rgb.z);
        if (coated) w(" \"float roughness\" [ {} ] \"bool remaproughness\" false", coat_alpha);
        w("\n");
    }
  }
  for (const TriangleMesh& mesh : scene.meshes) {
    const Material& m = scene.materials[mesh.material];
    w("\n# {}\nAttributeBegin\n  NamedMaterial \"{}\"\n", mesh.name, m.name);
    if (m.absorbs_inside()) w("  MediumInterface \"{}-interior\" \"\"\n", m.name);
    if (m.is_emissive()) {
      const PbrtRgb L = radiance_rgb(m.emission.color, m.emission.color_space, m.emission.luminance_nits);
      PbrtColorSpaceState block = world_space;  // AttributeEnd restores the world's
      block.use(w, L.space, "  ");
      w("  AreaLightSource \"diffuse\" \"rgb L\" [ {} {} {} ]{}\n", L.rgb.x, L.rgb.y, L.rgb.z,
        m.emission.two_sided ? " \"bool twosided\" true" : "");
    }
    w("  Shape \"trianglemesh\"\n    \"point3 P\" [");
    for (const Vec3f& p : mesh.positions) w(" {} {} {}", p.x, p.y, p.z);
    if (!mesh.normals.empty()) {
      w(" ]\n    \"normal N\" [");
      for (const Vec3f& n : mesh.normals) w(" {} {} {}", n.x, n.y, n.z);
    }
    if (!mesh.uvs.empty()) {
      w(" ]\n    \"point2 uv\" [");
      for (const Vec2f& uv : mesh.uvs) w(" {} {}", uv.x, 1.0f - uv.y);  // pbrt's v points up the image
    }
    w(" ]\n    \"integer indices\" [");
    for (std::uint32_t i : mesh.indices) w(" {}", i);
    w(" ]\n");
    const PbrtMaterialTextures& t = textures[mesh.material];
    if (!t.alpha.empty()) w("    \"texture alpha\" \"{}\"\n", t.alpha);
    else if (t.constant_alpha) w("    \"float alpha\" [ {} ]\n", *t.constant_alpha);
    w("AttributeEnd\n");
  }
  w.finish(path);
}

}  // namespace prism::loaders
