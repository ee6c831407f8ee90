#pragma once
// Shared plumbing for the libpng readers and writers (io/ internal): libpng reports
// errors by longjmp, so the message is kept in an error state for the IoError thrown
// afterwards. Functions calling libpng under setjmp must keep only trivially
// destructible objects in their own frame.
#include <png.h>

#include <cstdio>
#include <vector>

#include "prism/io/png.h"

namespace prism::libpng {

struct ErrorState {
  char message[256] = "unknown libpng error";
};

inline void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message);
  png_longjmp(png, 1);
}

inline void on_warning(png_structp, png_const_charp) {}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// libpng's text records for png_set_text, pointing into `entries` (which must outlive the
// write). Throws IoError for a keyword outside 1–79 characters. In png.cpp.
std::vector<png_text> text_chunks(const std::vector<PngText>& entries);

}  // namespace prism::libpng
