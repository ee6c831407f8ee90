#pragma once
// The presentation backend: puts the display thread's 8-bit image on the window's default
// framebuffer (OpenGL 3.3 blit, letterboxed) and reads the window back for screenshots and
// for the HDR UI composite. It is the one part that knows how pixels reach the screen, so
// an HDR swap chain (10-bit PQ or scRGB FP16) can replace it without touching the rest.
#include <cstdint>
#include <vector>

#include "prism/io/image.h"

namespace prism::viewer {

struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;  // framebuffer pixels, y from the bottom
};

class Presenter {
 public:
  Presenter();
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // Replaces the shown image (rows top first, RGBA8).
  void upload(int width, int height, const std::vector<std::uint8_t>& rgba);
  // Clears the default framebuffer and draws the image centred, aspect kept.
  void draw(int framebuffer_width, int framebuffer_height);
  Viewport last_viewport() const { return viewport_; }

  // The default framebuffer's back buffer as RGB8, rows top first (call before swapping).
  static EncodedImage read_framebuffer(int width, int height);

 private:
  unsigned texture_ = 0, read_fbo_ = 0;
  int width_ = 0, height_ = 0;
  Viewport viewport_;
};

}  // namespace prism::viewer
