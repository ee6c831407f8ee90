// Input mapping of the viewer's camera (camera_input.h).
#include "prism/viewer/camera_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "prism/viewer/camera_controller.h"

namespace prism::viewer {
namespace {

constexpr double kRadiansPerPixel = 0.005;

}  // namespace

CameraInputResult CameraInput::update(GLFWwindow* window, Camera& camera, int image_height_px, double dt) {
  CameraInputResult r;
  const ImGuiIO& io = ImGui::GetIO();
  const auto set = [&](const Camera& next, const char* what) {
    camera = next;
    r.changed = true;
    if (r.what.empty()) r.what = what;
  };
  if (!io.WantCaptureMouse) {
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    const bool moved = (dx != 0 || dy != 0) && std::isfinite(dx) && std::isfinite(dy);
    if (moved && ImGui::IsMouseDown(ImGuiMouseButton_Left))
      set(orbit(camera, -dx * kRadiansPerPixel, -dy * kRadiansPerPixel), "orbit");
    if (moved && ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
      const double px = pixel_footprint(camera, image_height_px);
      set(pan(camera, -dx * px, dy * px), "pan");
    }
    if (moved && ImGui::IsMouseDown(ImGuiMouseButton_Right))
      set(look(camera, -dx * kRadiansPerPixel, -dy * kRadiansPerPixel), "look");
    if (io.MouseWheel != 0) set(dolly(camera, std::pow(0.9, io.MouseWheel)), "dolly");
  }
  // Keys are read once per frame: with sticky keys (set by the window) a press and release
  // between two frames (a quick tap, or synthetic input) still reads as pressed once.
  const auto down = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS; };
  const bool ctrl = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL);
  const bool shift = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
  const bool w = down(GLFW_KEY_W), a = down(GLFW_KEY_A), s = down(GLFW_KEY_S), d = down(GLFW_KEY_D);
  const bool q = down(GLFW_KEY_Q), e = down(GLFW_KEY_E), reset = down(GLFW_KEY_R);
  r.quit = ctrl && q;
  if (!io.WantCaptureKeyboard && !ctrl) {
    const double speed = 0.25 * scene_size_ * dt * (shift ? 4.0 : 1.0);
    const double forward = (w ? 1 : 0) - (s ? 1 : 0);
    const double right = (d ? 1 : 0) - (a ? 1 : 0);
    const double up = (e ? 1 : 0) - (q ? 1 : 0);
    if (forward != 0 || right != 0 || up != 0) set(fly(camera, forward * speed, right * speed, up * speed), "fly");
    if (reset && !r_was_down_) set(initial_, "reset");
  }
  r_was_down_ = reset;
  return r;
}

}  // namespace prism::viewer
