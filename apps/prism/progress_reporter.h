#pragma once
// Progress display for long renders: on a terminal a single updating line with the pass,
// samples per second and an ETA; otherwise nothing until the final summary.
#include <cstdio>

#include "prism/render/renderer.h"

namespace prism::cli {

class ProgressReporter {
 public:
  explicit ProgressReporter(std::FILE* stream);
  void on_pass(const RenderProgress& progress);
  // Ends the updating line (if one was drawn) so the next output starts on a fresh line.
  void finish();

 private:
  std::FILE* stream_;
  bool interactive_;
  bool drew_ = false;
};

}  // namespace prism::cli
