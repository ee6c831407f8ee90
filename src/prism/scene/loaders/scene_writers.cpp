#include "prism/scene/loaders/scene_writers.h"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/scene/emission.h"

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
  if (!scene.textures.empty() || !scene.instances.empty())
    throw UsageError("scene writer: textures and instances are not supported");
  for (const Light& l : scene.lights)
    if (l.type != LightType::environment || l.environment_texture >= 0)
      throw UsageError("scene writer: only a constant environment light is supported");
}

std::string vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

const char* type_name(MaterialType t) {
  switch (t) {
    case MaterialType::diffuse: return "diffuse";
    case MaterialType::mirror: return "mirror";
    case MaterialType::conductor: return "conductor";
    case MaterialType::dielectric: return "dielectric";
    case MaterialType::metallic_roughness: return "metallic_roughness";
  }
  return "diffuse";
}

// An RGB radiance whose luminance is `nits`, for pbrt's "rgb L".
Vec3f radiance_rgb(const Vec3f& color, float nits) {
  const double y = relative_luminance(color, ColorPickerSpace::srgb);
  return y > 0.0 ? color * static_cast<float>(nits / y) : Vec3f(0.0f);
}

}  // namespace

void write_scene_json(const Scene& scene, const std::filesystem::path& path) {
  check_writable(scene);
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
    if (m.type == MaterialType::conductor && m.conductor_fresnel == ConductorFresnel::complex_ior)
      w(", \"conductor\": \"{}\"", m.conductor_name);
    if (m.type == MaterialType::dielectric) w(", \"ior\": {}", m.ior);
    if (m.type == MaterialType::metallic_roughness) w(", \"metallic\": {}", m.metallic);
    if (m.is_emissive())
      w(", \"emission\": {{\"color\": {}, \"luminance_nits\": {}, \"two_sided\": {}}}", vec(m.emission.color),
        m.emission.luminance_nits, m.emission.two_sided);
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
  for (const Light& l : scene.lights)
    w(",\n \"environment\": {{\"name\": \"{}\", \"color\": {}, \"luminance_nits\": {}}}", l.name, vec(l.color), l.intensity);
  w("\n}}\n");
  w.finish(path);
}

void write_scene_pbrt(const Scene& scene, const std::filesystem::path& path) {
  check_writable(scene);
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
  if (scene.default_max_depth > 0) w("Integrator \"volpath\" \"integer maxdepth\" [ {} ]\n", scene.default_max_depth);
  w("\nWorldBegin\n\n");
  for (const Light& l : scene.lights) {
    const Vec3f L = radiance_rgb(l.color, l.intensity);
    w("LightSource \"infinite\" \"rgb L\" [ {} {} {} ]\n\n", L.x, L.y, L.z);
  }
  for (const Material& m : scene.materials) {
    // Prism's perceptual roughness r has α = r²; written with remaproughness false.
    const float alpha = m.roughness * m.roughness;
    w("MakeNamedMaterial \"{}\"", m.name);
    switch (m.type) {
      case MaterialType::conductor:
      case MaterialType::mirror:
        if (m.type == MaterialType::conductor && m.conductor_fresnel == ConductorFresnel::complex_ior)
          w(" \"string type\" \"conductor\" \"spectrum eta\" \"metal-{0}-eta\" \"spectrum k\" \"metal-{0}-k\"", m.conductor_name);
        else
          w(" \"string type\" \"conductor\" \"rgb reflectance\" [ {} {} {} ]", m.base_color.x, m.base_color.y, m.base_color.z);
        w(" \"float roughness\" [ {} ] \"bool remaproughness\" false\n", m.type == MaterialType::mirror ? 0.0f : alpha);
        break;
      case MaterialType::dielectric:
        w(" \"string type\" \"dielectric\" \"float eta\" [ {} ] \"float roughness\" [ {} ] \"bool remaproughness\" false\n",
          m.ior, alpha);
        break;
      default:
        w(" \"string type\" \"diffuse\" \"rgb reflectance\" [ {} {} {} ]\n", m.base_color.x, m.base_color.y, m.base_color.z);
    }
  }
  for (const TriangleMesh& mesh : scene.meshes) {
    const Material& m = scene.materials[mesh.material];
    w("\n# {}\nAttributeBegin\n  NamedMaterial \"{}\"\n", mesh.name, m.name);
    if (m.is_emissive()) {
      const Vec3f L = radiance_rgb(m.emission.color, m.emission.luminance_nits);
      w("  AreaLightSource \"diffuse\" \"rgb L\" [ {} {} {} ]{}\n", L.x, L.y, L.z,
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
      for (const Vec2f& uv : mesh.uvs) w(" {} {}", uv.x, uv.y);
    }
    w(" ]\n    \"integer indices\" [");
    for (std::uint32_t i : mesh.indices) w(" {}", i);
    w(" ]\nAttributeEnd\n");
  }
  w.finish(path);
}

}  // namespace prism::loaders
