#pragma once
// Drawing primitives for the debug views: an RGB canvas of sRGB code values in [0, 1]
// (the views are written as 8-bit sRGB PNGs), lines, rectangles and a tiny bitmap font.
//
// The font is Prism's own 3×5 pixel glyph set (digits, upper-case letters, ". - + /" and
// space; lower case is drawn as upper case), drawn at an integer scale. It exists so that
// legends can carry numbers in nits without a font dependency.
#include <string_view>

#include "prism/core/vec.h"
#include "prism/io/image.h"

namespace prism::display {

struct Canvas {
  ImageRgbF image;  // sRGB code values
  Canvas(int width, int height, Vec3d background);
  void set(int x, int y, Vec3d srgb_code);  // ignores points outside
  void fill_rect(int x0, int y0, int x1, int y1, Vec3d srgb_code);  // [x0, x1) × [y0, y1)
  void draw_line(double x0, double y0, double x1, double y1, Vec3d srgb_code);
  // Text with its top-left corner at (x, y); returns the width drawn in pixels.
  int draw_text(int x, int y, std::string_view text, Vec3d srgb_code, int scale);
};

// Width in pixels of `text` at `scale` (4 columns per glyph: 3 + 1 spacing, minus the last).
int text_width_px(std::string_view text, int scale);
inline constexpr int kGlyphHeightPx = 5;

// 8-bit sRGB samples (rounded) of a canvas.
EncodedImage canvas_to_srgb8(const Canvas& canvas);

}  // namespace prism::display
