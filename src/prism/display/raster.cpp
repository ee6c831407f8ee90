#include "prism/display/raster.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

namespace prism::display {
namespace {

struct Glyph {
  char c;
  std::array<const char*, 5> rows;  // '#' = ink, three columns each
};

// Prism's own 3×5 glyphs.
constexpr Glyph kGlyphs[] = {
    {'0', {"###", "#.#", "#.#", "#.#", "###"}}, {'1', {".#.", "##.", ".#.", ".#.", "###"}},
    {'2', {"###", "..#", "###", "#..", "###"}}, {'3', {"###", "..#", ".##", "..#", "###"}},
    {'4', {"#.#", "#.#", "###", "..#", "..#"}}, {'5', {"###", "#..", "###", "..#", "###"}},
    {'6', {"###", "#..", "###", "#.#", "###"}}, {'7', {"###", "..#", "..#", ".#.", ".#."}},
    {'8', {"###", "#.#", "###", "#.#", "###"}}, {'9', {"###", "#.#", "###", "..#", "###"}},
    {'.', {"...", "...", "...", "...", ".#."}}, {'-', {"...", "...", "###", "...", "..."}},
    {'+', {"...", ".#.", "###", ".#.", "..."}}, {'/', {"..#", "..#", ".#.", "#..", "#.."}},
    {' ', {"...", "...", "...", "...", "..."}}, {'A', {".#.", "#.#", "###", "#.#", "#.#"}},
    {'B', {"##.", "#.#", "##.", "#.#", "##."}}, {'C', {".##", "#..", "#..", "#..", ".##"}},
    {'D', {"##.", "#.#", "#.#", "#.#", "##."}}, {'E', {"###", "#..", "##.", "#..", "###"}},
    {'F', {"###", "#..", "##.", "#..", "#.."}}, {'G', {".##", "#..", "#.#", "#.#", ".##"}},
    {'H', {"#.#", "#.#", "###", "#.#", "#.#"}}, {'I', {"###", ".#.", ".#.", ".#.", "###"}},
    {'K', {"#.#", "#.#", "##.", "#.#", "#.#"}}, {'L', {"#..", "#..", "#..", "#..", "###"}},
    {'M', {"#.#", "###", "###", "#.#", "#.#"}}, {'N', {"##.", "#.#", "#.#", "#.#", "#.#"}},
    {'O', {".#.", "#.#", "#.#", "#.#", ".#."}}, {'P', {"##.", "#.#", "##.", "#..", "#.."}},
    {'R', {"##.", "#.#", "##.", "#.#", "#.#"}}, {'S', {".##", "#..", ".#.", "..#", "##."}},
    {'T', {"###", ".#.", ".#.", ".#.", ".#."}}, {'U', {"#.#", "#.#", "#.#", "#.#", "###"}},
    {'W', {"#.#", "#.#", "#.#", "###", "#.#"}}, {'X', {"#.#", "#.#", ".#.", "#.#", "#.#"}},
    {'Y', {"#.#", "#.#", ".#.", ".#.", ".#."}},
};

const Glyph* find_glyph(char c) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kGlyphs)
    if (g.c == u) return &g;
  return nullptr;  // unknown characters draw as a space
}

}  // namespace

Canvas::Canvas(int width, int height, Vec3d bg) : image{width, height, {}} {
  image.rgb.resize(3u * width * height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    for (int c = 0; c < 3; ++c) image.rgb[i + c] = static_cast<float>(bg[c]);
}

void Canvas::set(int x, int y, Vec3d v) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  for (int c = 0; c < 3; ++c) image.rgb[3 * (std::size_t(y) * image.width + x) + c] = static_cast<float>(v[c]);
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Vec3d v) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) set(x, y, v);
}

void Canvas::draw_line(double x0, double y0, double x1, double y1, Vec3d v) {
  // DDA with one sample per pixel along the longer axis.
  const int steps = std::max(1, static_cast<int>(std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0)))));
  for (int i = 0; i <= steps; ++i) {
    const double t = double(i) / steps;
    set(static_cast<int>(std::lround(x0 + t * (x1 - x0))), static_cast<int>(std::lround(y0 + t * (y1 - y0))), v);
  }
}

int Canvas::draw_text(int x, int y, std::string_view text, Vec3d v, int scale) {
  int pen = x;
  for (char ch : text) {
    if (const Glyph* g = find_glyph(ch))
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (g->rows[row][col] == '#') fill_rect(pen + col * scale, y + row * scale, pen + (col + 1) * scale, y + (row + 1) * scale, v);
    pen += 4 * scale;
  }
  return text_width_px(text, scale);
}

int text_width_px(std::string_view text, int scale) {
  return text.empty() ? 0 : (4 * static_cast<int>(text.size()) - 1) * scale;
}

EncodedImage canvas_to_srgb8(const Canvas& canvas) {
  EncodedImage out;
  out.width = canvas.image.width;
  out.height = canvas.image.height;
  out.channels = 3;
  out.bit_depth = 8;
  out.samples.reserve(canvas.image.rgb.size());
  for (float v : canvas.image.rgb) out.samples.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)));
  return out;
}

}  // namespace prism::display
