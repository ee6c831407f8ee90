#include "progress_reporter.h"

#include <unistd.h>

#include <fmt/format.h>

namespace prism::cli {

ProgressReporter::ProgressReporter(std::FILE* stream)
    : stream_(stream), interactive_(::isatty(::fileno(stream)) != 0) {}

void ProgressReporter::on_pass(const RenderProgress& p) {
  if (!interactive_) return;
  const double fraction = p.passes_target > 0 ? static_cast<double>(p.passes_done) / p.passes_target : 1.0;
  const double eta = fraction > 0.0 ? p.elapsed_seconds * (1.0 / fraction - 1.0) : 0.0;
  constexpr int kBarWidth = 24;
  const int filled = static_cast<int>(fraction * kBarWidth);
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(kBarWidth - filled), '.');
  fmt::print(stream_, "\r[{}] pass {}/{}  {:.2f} M samples/s  elapsed {:.1f} s  ETA {:.1f} s \x1b[K", bar,
             p.passes_done, p.passes_target, p.samples_per_second * 1e-6, p.elapsed_seconds, eta);
  std::fflush(stream_);
  drew_ = true;
}

void ProgressReporter::finish() {
  if (drew_) fmt::print(stream_, "\n");
  drew_ = false;
}

}  // namespace prism::cli
