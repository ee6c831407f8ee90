// GLFW + OpenGL 3.3 core + Dear ImGui window of the viewer (viewer_window.h).
#include "prism/viewer/viewer_window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>

namespace prism::viewer {
namespace {

// GLFW reports "no display" through its error callback before glfwInit fails; the
// viewer turns the failure into one line of its own, so the callback stays quiet.
void quiet_glfw_error(int, const char*) {}

}  // namespace

ViewerWindow::ViewerWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(quiet_glfw_error);
  if (!glfwInit()) throw NoDisplayError();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw NoDisplayError();
  }
  glfwMakeContextCurrent(window_);
  glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
  glfwSwapInterval(0);  // frames are paced by wait_events, not by vsync
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // never write imgui.ini into the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  apply_content_scale();
}

ViewerWindow::~ViewerWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool ViewerWindow::should_close() const { return glfwWindowShouldClose(window_); }
void ViewerWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void ViewerWindow::wait_events(double timeout_s) {
  if (timeout_s > 0) glfwWaitEventsTimeout(timeout_s);
  else glfwPollEvents();
}

void ViewerWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

// Per-monitor DPI: the window's content scale changes when it moves to another monitor.
void ViewerWindow::apply_content_scale() {
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window_, &sx, &sy);
  const float scale = std::clamp(std::max(sx, sy), 0.5f, 4.0f);
  if (scale == content_scale_) return;
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale;
  content_scale_ = scale;
}

void ViewerWindow::begin_ui_frame() {
  apply_content_scale();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ViewerWindow::render_ui() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

void ViewerWindow::swap() { glfwSwapBuffers(window_); }

}  // namespace prism::viewer
