#include "prism/render/simd_level.h"

#include <array>

#include "prism/core/enum_names.h"
#include "prism/core/error.h"
#include "prism/core/float_lanes.h"
#include "prism/sampling/padded_sobol_lanes.h"

namespace prism {
namespace {

constexpr std::array<EnumName<SimdLevel>, 5> kNames{{
    {SimdLevel::automatic, "auto"},
    {SimdLevel::avx512, "avx512"},
    {SimdLevel::avx2, "avx2"},
    {SimdLevel::sse2, "sse2"},
    {SimdLevel::scalar, "scalar"},
}};

bool avx2_shading_supported() {
#if PRISM_FLOAT_LANES_AVX2
  return lanes::avx2_supported();
#else
  return false;
#endif
}

}  // namespace

std::string_view simd_level_name(SimdLevel level) { return enum_name(kNames, level); }

SimdLevel parse_simd_level(std::string_view name) {
  if (const std::optional<SimdLevel> level = enum_value(kNames, name)) return *level;
  throw UsageError("unknown --simd level '" + std::string(name) + "' (expected one of: " + enum_name_list(kNames) +
                   ")");
}

std::vector<std::string> simd_level_names() { return enum_names(kNames); }

bool simd_level_supported(SimdLevel level) {
  switch (level) {
    case SimdLevel::avx512: return padded_sobol_lanes_supported(SobolLanes::avx512) && avx2_shading_supported();
    case SimdLevel::avx2: return padded_sobol_lanes_supported(SobolLanes::avx2) && avx2_shading_supported();
    case SimdLevel::automatic:
    case SimdLevel::sse2:
    case SimdLevel::scalar: return true;
  }
  return false;
}

void require_simd_level(SimdLevel level) {
  if (simd_level_supported(level)) return;
  const char* missing = level == SimdLevel::avx512 ? "AVX-512 F/DQ/VL/BW and GFNI" : "AVX2";
  throw UsageError("--simd " + std::string(simd_level_name(level)) + ": this processor (or build) lacks " + missing);
}

SobolLanes sampler_lanes(SimdLevel level) {
  switch (level) {
    case SimdLevel::automatic: return padded_sobol_lanes();
    case SimdLevel::avx512: return SobolLanes::avx512;
    case SimdLevel::avx2: return SobolLanes::avx2;
    case SimdLevel::sse2:
    case SimdLevel::scalar: return SobolLanes::none;
  }
  return SobolLanes::none;
}

int shading_lane_width(SimdLevel level) {
  switch (level) {
    case SimdLevel::automatic: return avx2_shading_supported() ? 8 : lanes::sse2::kWidth;
    case SimdLevel::avx512:
    case SimdLevel::avx2: return 8;
    case SimdLevel::sse2: return lanes::sse2::kWidth;
    case SimdLevel::scalar: return 0;
  }
  return 0;
}

}  // namespace prism
