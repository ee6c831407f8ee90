// prism-scene/1: cameras (pinhole and thin lens) with optional physical exposure.
#include <fmt/format.h>

#include "prism/scene/loaders/json_scene_reader.h"

namespace prism::loaders {

void JsonSceneReader::read_camera(const JsonValue& value) {
  value.expect_keys({"name", "type", "eye", "target", "up", "fov_degrees", "aperture_radius", "focus_distance", "exposure"});
  Camera c;
  c.name = value.get_string("name", fmt::format("camera{}", scene.cameras.size()));
  enum class Kind { pinhole, thin_lens };
  const Kind kind = value.has("type") ? value["type"].as_enum<Kind>({{"pinhole", Kind::pinhole}, {"thin_lens", Kind::thin_lens}})
                                      : Kind::pinhole;
  c.eye = value["eye"].as_vec3();
  c.target = value["target"].as_vec3();
  c.up = value.get_vec3("up", c.up);
  const Vec3f view = c.target - c.eye;
  if (!(length(view) > 0.0f)) value["target"].fail("the target coincides with the eye");
  if (!(length(cross(view, c.up)) > 0.0f)) value["up"].fail("'up' is parallel to the viewing direction");
  c.fov_degrees = value.get_float("fov_degrees", c.fov_degrees, 0.01f, 179.0f);
  if (kind == Kind::thin_lens) {
    c.aperture_radius = value["aperture_radius"].as_float(0.0f, 1e9f);
    c.focus_distance = value.get_float("focus_distance", length(view), 1e-9f, 1e12f);
  } else if (value.has("aperture_radius") || value.has("focus_distance")) {
    value.fail("'aperture_radius' and 'focus_distance' need \"type\": \"thin_lens\"");
  } else {
    c.focus_distance = length(view);
  }
  if (auto e = value.find("exposure")) {
    e->expect_keys({"f_number", "shutter_seconds", "iso"});
    c.f_number = (*e)["f_number"].as_float(0.5f, 1024.0f);
    c.shutter_seconds = (*e)["shutter_seconds"].as_float(1e-9f, 1e6f);
    c.iso = e->get_float("iso", c.iso, 1.0f, 1e7f);
  }
  scene.cameras.push_back(std::move(c));
}

}  // namespace prism::loaders
