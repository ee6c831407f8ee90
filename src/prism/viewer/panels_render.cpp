// Render-side panels: transport, path settings, camera, lights (panels.h).
#include <algorithm>
#include <array>

#include <fmt/format.h>
#include <imgui.h>

#include "prism/color/color_space.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/viewer/panels.h"

namespace prism::viewer {
namespace {

int index_of(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? 0 : static_cast<int>(it - names.begin());
}

// The spaces RGB transport supports (transport_mode.h: spaces with reflectance conversion).
const std::vector<std::string>& working_spaces() {
  static const std::vector<std::string> names{"srgb", "acescg", "rec2020"};
  return names;
}

const std::vector<std::string>& picker_spaces() {
  static const std::vector<std::string> names{"sRGB", "ACEScg", "Rec.2020"};
  return names;
}

bool light_colour(const char* id, Vec3f& colour, ColorPickerSpace& space) {
  ImGui::PushID(id);
  bool changed = ImGui::ColorEdit3("colour", &colour.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
  int s = static_cast<int>(space);
  if (combo("picker space", s, picker_spaces())) {
    space = static_cast<ColorPickerSpace>(s);
    changed = true;
  }
  ImGui::PopID();
  return changed;
}

const char* intensity_unit(LightType type) {
  switch (type) {
    case LightType::point: return "intensity (cd)";
    case LightType::spot: return "axis intensity (cd)";
    case LightType::directional: return "illuminance (lux)";
    case LightType::environment: return "luminance scale (nits)";
  }
  return "intensity";
}

}  // namespace

bool combo(const char* label, int& index, const std::vector<std::string>& names) {
  bool changed = false;
  if (ImGui::BeginCombo(label, names.at(static_cast<std::size_t>(index)).c_str())) {
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
      if (ImGui::Selectable(names[static_cast<std::size_t>(i)].c_str(), i == index) && i != index) {
        index = i;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool render_settings_panel(RenderControls& c) {
  if (!ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) return false;
  TransportSettings& t = c.settings.transport;
  bool changed = false;
  int kind = t.kind == TransportKind::spectral ? 0 : 1;
  if (combo("transport", kind, {"spectral", "rgb"})) {
    t.kind = kind == 0 ? TransportKind::spectral : TransportKind::rgb;
    changed = true;
  }
  int space = index_of(working_spaces(), t.working_space);
  if (combo("working space", space, working_spaces())) {
    t.working_space = working_spaces()[static_cast<std::size_t>(space)];
    changed = true;
  }
  if (t.kind == TransportKind::spectral) {
    static const std::vector<std::string> counts{"3", "4", "8"};
    int n = t.wavelengths == 3 ? 0 : (t.wavelengths == 4 ? 1 : 2);
    if (combo("wavelengths", n, counts)) {
      t.wavelengths = std::array{3, 4, 8}[static_cast<std::size_t>(n)];
      changed = true;
    }
    const std::vector<std::string> strategies = color::wavelength_strategy_names();
    int strategy = index_of(strategies, std::string(color::wavelength_strategy_name(t.wavelength_strategy)));
    if (combo("wavelength sampling", strategy, strategies)) {
      t.wavelength_strategy = color::parse_wavelength_strategy(strategies[static_cast<std::size_t>(strategy)]);
      changed = true;
    }
    int up = t.upsampling == Upsampling::jakob_hanika ? 0 : 1;
    if (combo("upsampling", up, {"jakob-hanika", "mallett-yuksel"})) {
      t.upsampling = up == 0 ? Upsampling::jakob_hanika : Upsampling::mallett_yuksel;
      changed = true;
    }
  }
  int estimator = static_cast<int>(c.settings.path.estimator);  // LightEstimator's order
  if (combo("estimator", estimator,
            {std::string(light_estimator_name(LightEstimator::mis)),
             std::string(light_estimator_name(LightEstimator::nee_only)),
             std::string(light_estimator_name(LightEstimator::bsdf_only))})) {
    c.settings.path.estimator = static_cast<LightEstimator>(estimator);
    changed = true;
  }
  int sampler = static_cast<int>(c.settings.path.sampler);  // SamplerKind's order
  if (combo("sampler", sampler, {"independent", "sobol", "zsobol"})) {
    c.settings.path.sampler = static_cast<SamplerKind>(sampler);
    changed = true;
  }
  int normal_mapping = static_cast<int>(c.settings.path.normal_mapping);  // NormalMapping's order
  if (combo("normal maps", normal_mapping,
            {std::string(normal_mapping_name(NormalMapping::classic)),
             std::string(normal_mapping_name(NormalMapping::microfacet))})) {
    c.settings.path.normal_mapping = static_cast<NormalMapping>(normal_mapping);
    changed = true;
  }
  changed |= ImGui::SliderInt("max depth", &c.settings.path.max_depth, 0, 64);  // 0: emitted light only
  // The integrator's pass is a group of whole samples per pixel; bounces per pass (the
  // seed's #Bounce/Frame) also shows the film every N bounces inside a pass (0: off).
  changed |= ImGui::SliderInt("samples per pass", &c.settings.samples_per_pass, 1, 64);
  changed |= ImGui::SliderInt("bounces per pass", &c.settings.bounces_per_pass, 0, 16);
  float scale = static_cast<float>(c.resolution_scale);
  if (ImGui::SliderFloat("resolution scale", &scale, 0.125f, 1.0f, "%.3f")) {
    c.resolution_scale = std::clamp(static_cast<double>(scale), 0.125, 1.0);
    changed = true;
  }
  return changed;
}

bool camera_panel(RenderControls& c, const std::vector<Camera>& scene_cameras, const Camera& initial) {
  if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return false;
  bool changed = false;
  for (std::size_t i = 0; i < scene_cameras.size(); ++i) {
    const std::string label = scene_cameras[i].name.empty() ? "camera " + std::to_string(i) : scene_cameras[i].name;
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Button(label.c_str())) {
      c.camera = scene_cameras[i];
      changed = true;
    }
    ImGui::PopID();
    ImGui::SameLine();
  }
  if (ImGui::Button("reset (R)")) {
    c.camera = initial;
    changed = true;
  }
  changed |= ImGui::SliderFloat("fov (deg)", &c.camera.fov_degrees, 5.0f, 120.0f, "%.1f");
  ImGui::Text("eye    %.3g %.3g %.3g", c.camera.eye.x, c.camera.eye.y, c.camera.eye.z);
  ImGui::Text("target %.3g %.3g %.3g", c.camera.target.x, c.camera.target.y, c.camera.target.z);
  return changed;
}

bool lights_panel(RenderControls& c) {
  if (!ImGui::CollapsingHeader("Lights")) return false;
  bool changed = false;
  for (std::size_t i = 0; i < c.materials.size(); ++i) {
    Emission& e = c.materials[i].emission;
    if (!(e.luminance_nits > 0.0f)) continue;
    const std::string id = fmt::format("m{}", i);
    if (ImGui::TreeNode(id.c_str(), "emitter: %s", c.materials[i].name.c_str())) {
      changed |= ImGui::DragFloat("luminance (nits)", &e.luminance_nits, e.luminance_nits * 0.01f + 0.01f, 0.0f, 1e9f,
                                  "%.4g", ImGuiSliderFlags_Logarithmic);
      if (e.spectrum)
        ImGui::TextUnformatted("colour: the scene's spectrum");
      else
        changed |= light_colour(id.c_str(), e.color, e.color_space);
      ImGui::TreePop();
    }
  }
  for (std::size_t i = 0; i < c.lights.size(); ++i) {
    Light& l = c.lights[i];
    const std::string id = fmt::format("l{}", i);
    if (ImGui::TreeNode(id.c_str(), "light: %s", l.name.empty() ? id.c_str() : l.name.c_str())) {
      changed |= ImGui::DragFloat(intensity_unit(l.type), &l.intensity, l.intensity * 0.01f + 0.01f, 0.0f, 1e9f,
                                  "%.4g", ImGuiSliderFlags_Logarithmic);
      if (l.spectrum)
        ImGui::TextUnformatted("colour: the scene's spectrum");
      else if (l.type == LightType::environment && l.environment_texture >= 0)
        ImGui::TextUnformatted("colour: the map's texels");
      else
        changed |= light_colour(id.c_str(), l.color, l.color_space);
      ImGui::TreePop();
    }
  }
  c.settings.path.max_depth = std::max(c.settings.path.max_depth, 0);
  c.settings.bounces_per_pass = std::max(c.settings.bounces_per_pass, 0);
  return changed;
}

}  // namespace prism::viewer
