// Camera JSON snippets (viewer "save camera", `prism render --camera-json`).
#include "prism/scene/camera_json.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"

namespace prism {
namespace {

using nlohmann::json;

Vec3f read_vec3(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 3) throw SceneError(fmt::format("camera JSON: \"{}\" must be [x, y, z]", key));
  Vec3f out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_number()) throw SceneError(fmt::format("camera JSON: \"{}\" must hold numbers", key));
    out[i] = v[i].get<float>();
    if (!std::isfinite(out[i])) throw SceneError(fmt::format("camera JSON: \"{}\" is not finite", key));
  }
  return out;
}

float read_number(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw SceneError(fmt::format("camera JSON: \"{}\" must be a finite number", key));
  return v.get<float>();
}

json vec3_json(const Vec3f& v) { return json::array({v.x, v.y, v.z}); }

void check_camera(const Camera& c) {
  const Vec3f view = c.target - c.eye;
  if (length(view) <= 0.0f) throw SceneError("camera JSON: eye and target coincide");
  if (length(cross(view, c.up)) <= 1e-6f * length(view) * length(c.up))
    throw SceneError("camera JSON: \"up\" is zero or parallel to the viewing direction");
  if (!(c.fov_degrees > 0.0f && c.fov_degrees < 180.0f))
    throw SceneError(fmt::format("camera JSON: fov_degrees {} is outside (0, 180)", c.fov_degrees));
  if (c.aperture_radius < 0.0f || c.focus_distance <= 0.0f)
    throw SceneError("camera JSON: aperture_radius must be >= 0 and focus_distance > 0");
}

}  // namespace

std::string camera_to_json(const Camera& camera) {
  json j;
  j["eye"] = vec3_json(camera.eye);
  j["target"] = vec3_json(camera.target);
  j["up"] = vec3_json(camera.up);
  j["fov_degrees"] = camera.fov_degrees;
  if (camera.aperture_radius > 0.0f) {
    j["aperture_radius"] = camera.aperture_radius;
    j["focus_distance"] = camera.focus_distance;
  }
  return j.dump(2) + "\n";
}

Camera camera_from_json(const std::string& text, const Camera& base) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw SceneError(fmt::format("camera JSON: malformed at byte {}", e.byte));
  }
  if (!j.is_object()) throw SceneError("camera JSON: expected an object");
  Camera c = base;
  if (j.contains("eye")) c.eye = read_vec3(j, "eye");
  if (j.contains("target")) c.target = read_vec3(j, "target");
  if (j.contains("up")) c.up = read_vec3(j, "up");
  if (j.contains("fov_degrees")) c.fov_degrees = read_number(j, "fov_degrees");
  if (j.contains("aperture_radius")) c.aperture_radius = read_number(j, "aperture_radius");
  if (j.contains("focus_distance")) c.focus_distance = read_number(j, "focus_distance");
  check_camera(c);
  return c;
}

Camera read_camera_json(const std::filesystem::path& path, const Camera& base) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("cannot open camera file '{}'", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return camera_from_json(text.str(), base);
  } catch (const SceneError& e) {
    throw SceneError(fmt::format("{}: {}", path.string(), e.what()));
  }
}

void write_camera_json(const std::filesystem::path& path, const Camera& camera) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary);
    out << camera_to_json(camera);
    if (!out) throw IoError(fmt::format("cannot write camera file '{}'", path.string()));
  }
  file.commit();
}

}  // namespace prism
