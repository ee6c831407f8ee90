// Build-time generator of the Jakob–Hanika 2019 coefficient tables embedded in the prism
// library (see src/prism/color/spectral_tables.cmake). Usage:
//   prism_generate_jakob_hanika_tables --resolution R --output-dir DIR SPACE...
// writes DIR/jakob_hanika_SPACE_R.bin: float scale[R], then float coefficients
// [3][R][R][R][3] (native byte order), and prints fit statistics and timing.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/color/jakob_hanika_fit.h"

int main(int argc, char** argv) {
  int resolution = 64;
  std::string output_dir = ".";
  std::vector<std::string> spaces;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--resolution" && a + 1 < argc) resolution = std::atoi(argv[++a]);
    else if (arg == "--output-dir" && a + 1 < argc) output_dir = argv[++a];
    else spaces.push_back(arg);
  }
  if (resolution < 2 || spaces.empty()) {
    std::fprintf(stderr, "usage: %s --resolution R --output-dir DIR SPACE...\n", argv[0]);
    return 2;
  }
  for (const std::string& name : spaces) {
    const auto start = std::chrono::steady_clock::now();
    const prism::color::ColorSpace& space = prism::color::color_space(name);
    prism::color::JakobHanikaTableStats stats;
    const prism::color::JakobHanikaTableData table = prism::color::generate_jakob_hanika_table(space, resolution, &stats);
    const std::string path = output_dir + "/jakob_hanika_" + name + "_" + std::to_string(resolution) + ".bin";
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(table.scale.data()),
              static_cast<std::streamsize>(table.scale.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(table.coefficients.data()),
              static_cast<std::streamsize>(table.coefficients.size() * sizeof(float)));
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", path.c_str());
      return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %ld fits, %ld not converged to 1e-6, max residual %.3g dE76, %.1f s\n", name.c_str(),
                stats.fits, stats.not_converged, stats.max_delta_e, seconds);
  }
  return 0;
}
