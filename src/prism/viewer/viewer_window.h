#pragma once
// The window: GLFW with an OpenGL 3.3 core context, Dear ImGui on it, the UI scaled by the
// monitor's content scale (HiDPI). Creating it without a display throws NoDisplayError.
#include <string>

#include "prism/core/error.h"

struct GLFWwindow;

namespace prism::viewer {

class NoDisplayError : public Error {
 public:
  NoDisplayError() : Error("no display; use prism render or run under Xvfb") {}
};

class ViewerWindow {
 public:
  ViewerWindow(int width, int height, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  // Waits for input at most `timeout_s` (0: only polls).
  void wait_events(double timeout_s);
  void framebuffer_size(int& width, int& height) const;
  void begin_ui_frame();  // ImGui new frame (re-applies the content scale when it changes)
  void render_ui();       // draws the current ImGui draw data into the bound framebuffer
  void swap();

 private:
  void apply_content_scale();

  GLFWwindow* window_ = nullptr;
  float content_scale_ = 0.0f;
};

}  // namespace prism::viewer
