// The padded Sobol' sampler's AVX2 lanes and the integrator's bounce blocks drawn ahead of
// shading (sampling/padded_sobol_lanes.h, render/wavefront_integrator.h) change no pixel:
// the same render with PRISM_SAMPLER_SCALAR=1, which takes the scalar sampler and draws
// each vertex's numbers inside shade(), is bitwise the same image. The switch is read once
// per process, so the two renders are two runs of `prism`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "prism/io/exr.h"
#include "prism/sampling/padded_sobol_lanes.h"
#include "support/cli_test.h"

namespace prism {
namespace {

class SamplerLanesCli : public test::CliTest {};

TEST_F(SamplerLanesCli, ScalarAndLaneRendersAreBitwiseTheSame) {
  if (!padded_sobol_lanes_available()) GTEST_SKIP() << "this processor (or PRISM_SAMPLER_SCALAR) runs no AVX2 lanes";
  for (const char* mode : {"spectral", "rgb"}) {
    const std::string args = std::string("render cornell-box --width 24 --height 24 --spp 4 --threads 2 --mode ") + mode;
    ASSERT_EQ(run(args + " -o " + path("lanes.exr")), 0) << log();
    ASSERT_EQ(setenv("PRISM_SAMPLER_SCALAR", "1", 1), 0);
    const int scalar = run(args + " -o " + path("scalar.exr"));
    unsetenv("PRISM_SAMPLER_SCALAR");
    ASSERT_EQ(scalar, 0) << log();
    const ExrFile a = read_exr(path("lanes.exr")), b = read_exr(path("scalar.exr"));
    ASSERT_EQ(a.image.rgb.size(), b.image.rgb.size());
    EXPECT_TRUE(a.image.rgb == b.image.rgb) << mode;
  }
}

}  // namespace
}  // namespace prism
