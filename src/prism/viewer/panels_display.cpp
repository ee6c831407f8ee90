// Display-side panels: exposure, bloom, LMT, ODT/encoding, primaries, debug views, HDR10
// metadata (panels.h). Nothing here re-renders the film.
#include <algorithm>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "prism/display/display_primaries.h"
#include "prism/viewer/panels.h"

namespace prism::viewer {
namespace {

bool slider(const char* label, double& value, double lo, double hi, const char* format = "%.3f") {
  float v = static_cast<float>(value);
  if (!ImGui::SliderFloat(label, &v, static_cast<float>(lo), static_cast<float>(hi), format)) return false;
  value = v;
  return true;
}

bool exposure_section(DisplayControls& c, const DisplayFrame* shown) {
  bool changed = ImGui::Checkbox("auto exposure", &c.auto_exposure);
  if (c.auto_exposure) {
    changed |= slider("key", c.auto_exposure_key, 0.02, 0.8);
    changed |= slider("centre weight", c.metering.centre_weight, 0.0, 1.0, "%.2f");
    changed |= slider("adaptation (1/s)", c.adaptation_speed, 0.1, 20.0, "%.1f");
    if (shown && shown->metered_ev100)
      ImGui::Text("EV100 %.2f (metered %.2f)", shown->ev100, *shown->metered_ev100);
  } else {
    // Switching auto exposure off keeps the EV it showed, so the picture does not jump.
    if (shown && shown->metered_ev100 && changed) c.ev100 = shown->ev100;
    changed |= slider("EV100", c.ev100, -10.0, 20.0, "%.2f");
  }
  return changed;
}

bool bloom_section(display::DisplaySettings& s) {
  bool changed = slider("bloom", s.bloom.strength, 0.0, 1.0);
  if (s.bloom.strength > 0) {
    changed |= slider("bloom threshold", s.bloom.threshold, 0.1, 4.0);
    int space = s.bloom.threshold_space == display::BloomThresholdSpace::hsv ? 0 : 1;
    if (combo("threshold space", space, {"hsv", "rgb"})) {
      s.bloom.threshold_space = space == 0 ? display::BloomThresholdSpace::hsv : display::BloomThresholdSpace::rgb;
      changed = true;
    }
  }
  return changed;
}

bool odt_section(display::DisplaySettings& s) {
  bool changed = false;
  // The rendering first: it decides which targets there are (rendering.h).
  const std::vector<std::string> renderings = display::rendering_names();
  int rendering = 0;
  for (std::size_t i = 0; i < renderings.size(); ++i)
    if (display::parse_rendering(renderings[i]) == s.rendering) rendering = static_cast<int>(i);
  if (combo("rendering", rendering, renderings)) {
    s.rendering = display::parse_rendering(renderings[static_cast<std::size_t>(rendering)]);
    if (!display::rendering_supports_target(s.rendering, s.odt)) s.odt = display::OdtId::srgb_100nit;
    s.encoding.reset();
    s.peak_nits.reset();
    changed = true;
  }
  const std::vector<std::string> odts = display::rendering_target_names(s.rendering);
  int odt = 0;
  for (std::size_t i = 0; i < odts.size(); ++i)
    if (display::parse_odt(odts[i]) == s.odt) odt = static_cast<int>(i);
  if (combo("ODT", odt, odts)) {
    s.odt = display::parse_odt(odts[static_cast<std::size_t>(odt)]);
    s.encoding.reset();  // follow the new ODT's own encoding
    changed = true;
  }
  std::vector<std::string> encodings{"ODT default"};
  for (const std::string& e : display::display_encoding_names()) encodings.push_back(e);
  int enc = 0;
  for (std::size_t i = 1; i < encodings.size(); ++i)
    if (s.encoding && display::parse_display_encoding(encodings[i]) == *s.encoding) enc = static_cast<int>(i);
  if (combo("encoding", enc, encodings)) {
    s.encoding = enc == 0 ? std::nullopt
                          : std::optional(display::parse_display_encoding(encodings[static_cast<std::size_t>(enc)]));
    changed = true;
  }
  return changed;
}

// The named spaces a display can have (primaries and white inside the spectral locus).
const std::vector<std::string>& display_primaries_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"ODT's own"};
    for (const std::string& n : color::color_space_names()) {
      try {
        display::parse_display_primaries(n);
        out.push_back(n);
      } catch (const std::exception&) {
      }
    }
    return out;
  }();
  return names;
}

bool primaries_section(display::DisplaySettings& s) {
  const std::vector<std::string>& names = display_primaries_names();
  int index = 0;
  for (std::size_t i = 1; i < names.size(); ++i)
    if (s.display_primaries && s.display_primaries->name == names[i]) index = static_cast<int>(i);
  if (!combo("display primaries", index, names)) return false;
  s.display_primaries = index == 0 ? std::nullopt
                                   : std::optional(display::parse_display_primaries(names[static_cast<std::size_t>(index)]));
  return true;
}

bool view_section(DisplayControls& c) {
  std::vector<std::string> names{"none"};
  for (const std::string& n : display::debug_view_names()) names.push_back(n);
  int index = 0;
  for (std::size_t i = 1; i < names.size(); ++i)
    if (display::parse_debug_view(names[i]) == c.view) index = static_cast<int>(i);
  bool changed = false;
  if (combo("debug view", index, names)) {
    c.view = index == 0 ? display::DebugView::none : display::parse_debug_view(names[static_cast<std::size_t>(index)]);
    changed = true;
  }
  if (c.view == display::DebugView::sdr_hdr_split) changed |= slider("SDR white (nits)", c.sdr_white_nits, 80, 400, "%.0f");
  return changed;
}

bool hdr10_section(DisplayControls& c, const DisplayFrame* shown) {
  if (!ImGui::TreeNode("HDR10 metadata (PQ files)")) return false;
  bool changed = false;
  const auto field = [&](const char* label, double& v) {
    float f = static_cast<float>(v);
    if (ImGui::InputFloat(label, &f, 0, 0, "%.4g")) {
      v = std::max(0.0f, f);
      changed = true;
    }
  };
  field("mastering max (nits, 0=ODT)", c.mastering_max_nits);
  field("mastering min (nits, 0=ODT)", c.mastering_min_nits);
  field("MaxCLL (nits, 0=measured)", c.max_cll_nits);
  field("MaxFALL (nits, 0=measured)", c.max_fall_nits);
  if (shown) ImGui::Text("measured MaxCLL %.1f, MaxFALL %.1f nits", shown->content_light.max_cll_nits,
                         shown->content_light.max_fall_nits);
  ImGui::TreePop();
  return changed;
}

}  // namespace

bool display_panel(DisplayControls& c, const DisplayFrame* shown) {
  if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return false;
  bool changed = exposure_section(c, shown);
  changed |= bloom_section(c.settings);
  changed |= slider("blue correction", c.settings.blue_correction, 0.0, 1.0);
  changed |= odt_section(c.settings);
  changed |= primaries_section(c.settings);
  changed |= view_section(c);
  changed |= hdr10_section(c, shown);
  if (shown && !shown->error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", shown->error.c_str());
  return changed;
}

void save_panel(SaveRequest& r, const std::string& last_message) {
  if (!ImGui::CollapsingHeader("Save")) return;
  ImGui::InputText("image (.png/.avif)", &r.image_path);
  r.save_image = ImGui::Button("save display image");
  ImGui::InputText("film (.exr)", &r.film_path);
  r.save_film = ImGui::Button("save film EXR");
  ImGui::InputText("camera (.json)", &r.camera_path);
  r.save_camera = ImGui::Button("save camera JSON");
  if (!last_message.empty()) ImGui::TextWrapped("%s", last_message.c_str());
}

void stats_overlay(const FilmFrame* film, const DisplayFrame* shown, const UiTimings& ui, const MemoryFigures& memory,
                   const std::string& status) {
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  if (!ImGui::Begin("stats", nullptr, flags)) {
    ImGui::End();
    return;
  }
  if (film) {
    ImGui::Text("%d x %d  %d spp%s", film->film.width, film->film.height, film->spp, film->finished ? " (done)" : "");
    ImGui::Text("%.2f M samples/s", film->samples_per_second * 1e-6);
    ImGui::Text("pass %.0f ms, %.2f s to %d spp", film->last_pass_seconds * 1e3, film->elapsed_seconds, film->spp);
  } else {
    ImGui::Text("rendering first pass...");
  }
  if (shown) ImGui::Text("display %.0f ms, EV100 %.2f%s", shown->display_seconds * 1e3, shown->ev100,
                         shown->metered_ev100 ? " (metered)" : "");
  if (shown && !shown->preview_note.empty()) ImGui::TextColored(ImVec4(1, 0.85f, 0.3f, 1), "%s", shown->preview_note.c_str());
  ImGui::Text("UI %.1f fps (frame %.1f ms mean, %.1f ms max)", ui.fps, ui.frame_ms_mean, ui.frame_ms_max);
  if (memory.peak_mib > 0) ImGui::Text("memory %.0f MiB (peak %.0f MiB)", memory.resident_mib, memory.peak_mib);
  if (!status.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", status.c_str());
  ImGui::End();
}

}  // namespace prism::viewer
