#pragma once
// The viewer's Dear ImGui panels. Each edits plain controls and says whether it changed
// them, so the caller decides what to restart: render controls restart accumulation,
// display controls only re-run the display pipeline on the current film.
#include <string>
#include <vector>

#include "prism/viewer/display_worker.h"
#include "prism/viewer/memory_monitor.h"
#include "prism/viewer/render_session.h"
#include "prism/viewer/viewer_state.h"

namespace prism::viewer {

// A combo box over names; true when the selection changed.
bool combo(const char* label, int& index, const std::vector<std::string>& names);

// Transport (spectral/RGB, working space, wavelengths, strategy, upsampling), estimator,
// max depth, samples per pass, resolution scale.
bool render_settings_panel(RenderControls& controls);

// Scene cameras, reset and field of view. `scene_cameras` are the scene's own cameras.
bool camera_panel(RenderControls& controls, const std::vector<Camera>& scene_cameras, const Camera& initial);

// Non-geometric lights and emissive materials: intensity in physical units, colour and
// its colour-picker space.
bool lights_panel(RenderControls& controls);

// Exposure, bloom, blue correction, ODT and encoding, display primaries, debug views,
// HDR10 metadata (with the measured MaxCLL/MaxFALL of `shown`).
bool display_panel(DisplayControls& controls, const DisplayFrame* shown);

struct SaveRequest {
  std::string image_path, film_path, camera_path;
  bool save_image = false, save_film = false, save_camera = false;
};
void save_panel(SaveRequest& request, const std::string& last_message);

struct UiTimings {
  double frame_ms_mean = 0, frame_ms_max = 0, fps = 0;
};

// The stats overlay: spp, samples/s, pass time, time to the current spp, UI frame times,
// the process' memory.
void stats_overlay(const FilmFrame* film, const DisplayFrame* shown, const UiTimings& ui, const MemoryFigures& memory,
                   const std::string& status);

}  // namespace prism::viewer
