// The padded Sobol' sampler's AVX2 lanes and the integrator's bounce blocks drawn ahead of
// shading (sampling/padded_sobol_lanes.h, render/wavefront_integrator.h) change no pixel:
// the same render with `--simd scalar`, which takes the scalar sampler and draws each
// vertex's numbers inside shade(), is bitwise the same image; so is every level this
// processor runs, and a level it does not run is refused with exit 2.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "prism/io/exr.h"
#include "prism/render/simd_level.h"
#include "prism/sampling/padded_sobol_lanes.h"
#include "support/cli_test.h"

namespace prism {
namespace {

class SamplerLanesCli : public test::CliTest {};

TEST_F(SamplerLanesCli, ScalarAndLaneRendersAreBitwiseTheSame) {
  if (!padded_sobol_lanes_available()) GTEST_SKIP() << "this processor runs no AVX2 lanes";
  for (const char* mode : {"spectral", "rgb"}) {
    const std::string args = std::string("render cornell-box --width 24 --height 24 --spp 4 --threads 2 --mode ") + mode;
    ASSERT_EQ(run(args + " -o " + path("auto.exr")), 0) << log();
    const ExrFile reference = read_exr(path("auto.exr"));
    for (const std::string& level : simd_level_names()) {
      const std::string out = path(level + ".exr");
      const int status = run(args + " --simd " + level + " -o " + out);
      if (!simd_level_supported(parse_simd_level(level))) {
        EXPECT_EQ(status, 2) << level << ": " << log();
        continue;
      }
      ASSERT_EQ(status, 0) << level << ": " << log();
      const ExrFile b = read_exr(out);
      ASSERT_EQ(reference.image.rgb.size(), b.image.rgb.size());
      EXPECT_TRUE(reference.image.rgb == b.image.rgb) << mode << ", --simd " << level;
    }
  }
}

}  // namespace
}  // namespace prism
