#include "suites.h"

namespace prism::bench {

const std::vector<SuiteEntry>& all_suites() {
  static const std::vector<SuiteEntry> suites{
      {"limit", "raw Embree incoherent rays/s vs the renderer's rays/s (efficiency), Cornell box", run_limit_suite},
      {"throughput", "samples/s and Mrays/s, Cornell box 512^2 spectral and RGB, median of --repeat", run_throughput_suite},
      {"steadiness", "pass-time spread with path regeneration on vs off", run_steadiness_suite},
      {"convergence", "relMSE vs time/spp and chromaticity error vs spp per wavelength strategy", run_convergence_suite},
      {"efficiency", "1/(time x relMSE) on the 512^2 Cornell box as a ratio to pbrt-v4's figure quoted in issue 8",
       run_efficiency_suite},
      {"sampler", "RMSE vs a 4096-spp reference per --sampler (independent, sobol, zsobol) at equal spp and equal time",
       run_sampler_suite},
      {"display", "4K exposure+ACES SDR and 1000-nit PQ, Mpixels/s vs OpenColorIO's CPU processor", run_display_suite},
      {"scaling", "samples/s with 1 and 2 threads (parallel efficiency)", run_scaling_suite},
      {"startup", "scene build + BVH build time and peak RSS for a generated large mesh", run_startup_suite},
      {"denoise", "AOV-guided denoiser: 1280x720 frame time on 2 threads; 16 spp denoised vs 256 spp raw relMSE",
       run_denoise_suite},
      {"adaptive", "--noise-threshold vs uniform sampling: efficiency 1/(time x relMSE), plain and glossy/glass Cornell box",
       run_adaptive_suite},
  };
  return suites;
}

}  // namespace prism::bench
