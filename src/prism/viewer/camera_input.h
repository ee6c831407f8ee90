#pragma once
// Mouse and keyboard → camera motions (camera_controller.h), unless Dear ImGui owns the
// input: left drag orbits, middle drag pans, wheel dollies, right drag looks around,
// W/A/S/D/Q/E fly (Shift: 4× faster), R resets to the initial camera, Ctrl+Q quits.
#include <string>

#include "prism/scene/scene.h"

struct GLFWwindow;

namespace prism::viewer {

struct CameraInputResult {
  bool changed = false;
  bool quit = false;  // Ctrl+Q
  std::string what;  // "orbit", "pan", "dolly", "look", "fly", "reset" (for the event log)
};

class CameraInput {
 public:
  // `scene_size`: a length for fly speed (the scene's bounding-box diagonal).
  CameraInput(Camera initial, double scene_size) : initial_(std::move(initial)), scene_size_(scene_size) {}

  // Applies this frame's input to `camera`; `image_height_px` maps pixels to pan distance,
  // `dt` seconds to fly distance.
  CameraInputResult update(GLFWwindow* window, Camera& camera, int image_height_px, double dt);
  const Camera& initial() const { return initial_; }

 private:
  Camera initial_;
  double scene_size_;
  bool r_was_down_ = false;
};

}  // namespace prism::viewer
