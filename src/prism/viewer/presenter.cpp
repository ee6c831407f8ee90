// OpenGL 3.3 core presentation (presenter.h). Functions above OpenGL 1.1 come from the
// system libGL (GLVND exports the whole core profile).
#define GL_GLEXT_PROTOTYPES 1
#include "prism/viewer/presenter.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>

namespace prism::viewer {
namespace {

EncodedImage read_pixels(int width, int height, int channels) {
  EncodedImage out{width, height, channels, 8, {}};
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * height * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, channels == 4 ? GL_RGBA : GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
  out.samples.resize(bytes.size());
  const std::size_t row = static_cast<std::size_t>(width) * channels;
  for (int y = 0; y < height; ++y)  // OpenGL rows start at the bottom
    std::copy_n(bytes.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row), row,
                out.samples.begin() + static_cast<std::ptrdiff_t>(y * row));
  return out;
}

}  // namespace

Presenter::Presenter() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glGenFramebuffers(1, &read_fbo_);
}

Presenter::~Presenter() {
  glDeleteFramebuffers(1, &read_fbo_);
  glDeleteTextures(1, &texture_);
}

void Presenter::upload(int width, int height, const std::vector<std::uint8_t>& rgba) {
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (width != width_ || height != height_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    width_ = width;
    height_ = height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  }
}

void Presenter::draw(int fb_width, int fb_height) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_width, fb_height);
  glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (width_ == 0 || height_ == 0) return;
  const double scale = std::min(static_cast<double>(fb_width) / width_, static_cast<double>(fb_height) / height_);
  viewport_.width = static_cast<int>(std::lround(width_ * scale));
  viewport_.height = static_cast<int>(std::lround(height_ * scale));
  viewport_.x = (fb_width - viewport_.width) / 2;
  viewport_.y = (fb_height - viewport_.height) / 2;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo_);
  // Texture row 0 is the image's top: blit it upside down onto the window.
  glBlitFramebuffer(0, 0, width_, height_, viewport_.x, viewport_.y + viewport_.height,
                    viewport_.x + viewport_.width, viewport_.y,
                    GL_COLOR_BUFFER_BIT, scale == 1.0 ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

EncodedImage Presenter::read_framebuffer(int width, int height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  return read_pixels(width, height, 3);
}

}  // namespace prism::viewer
