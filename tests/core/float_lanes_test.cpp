// core/float_lanes.h: every lane operation against the scalar operation it stands for,
// bit for bit, on values that tell them apart (signed zeros, NaNs, infinities, subnormals),
// in both widths (AVX2 where the processor has it).
#include "prism/core/float_lanes.h"
#include "prism/core/target_region.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "prism/core/vec.h"
#include "support/same_bits.h"

namespace prism {
namespace {

struct LaneResults {
  std::vector<float> max, min, select, abs, copysign, sqrt, dot, length;
  std::vector<bool> is_inf;
  std::vector<Vec3f> cross;
};

namespace sse2_lanes {
namespace ops = lanes::sse2;
#include "float_lanes_test_body.inc"
}  // namespace sse2_lanes

#if PRISM_FLOAT_LANES_AVX2
PRISM_TARGET_REGION_BEGIN("avx2")
namespace avx2_lanes {
namespace ops = lanes::avx2;
#include "float_lanes_test_body.inc"
}  // namespace avx2_lanes
PRISM_TARGET_REGION_END
#endif

using test::same_bits;  // support/same_bits.h

void expect_scalar_bits(const LaneResults& r, const std::vector<float>& xs, const std::vector<float>& ys,
                        const char* width) {
  ASSERT_EQ(r.max.size(), xs.size()) << width;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const float x = xs[i], y = ys[i];
    const Vec3f a(x, y, x * y), b(y, x - y, x);
    const Vec3f c = cross(a, b);
    EXPECT_TRUE(same_bits(r.max[i], std::max(x, y))) << width << " max " << x << " " << y;
    EXPECT_TRUE(same_bits(r.min[i], std::min(x, y))) << width << " min " << x << " " << y;
    EXPECT_TRUE(same_bits(r.select[i], x < y ? x : y)) << width << " select " << x << " " << y;
    EXPECT_TRUE(same_bits(r.abs[i], std::abs(x))) << width << " abs " << x;
    EXPECT_TRUE(same_bits(r.copysign[i], std::copysign(1.0f, x))) << width << " copysign " << x;
    EXPECT_TRUE(same_bits(r.sqrt[i], std::sqrt(x)) || (std::isnan(r.sqrt[i]) && std::isnan(std::sqrt(x))))
        << width << " sqrt " << x;
    EXPECT_EQ(r.is_inf[i], std::isinf(x)) << width << " is_inf " << x;
    const auto same_or_both_nan = [](float p, float q) { return same_bits(p, q) || (std::isnan(p) && std::isnan(q)); };
    EXPECT_TRUE(same_or_both_nan(r.dot[i], dot(a, b))) << width << " dot " << x << " " << y;
    EXPECT_TRUE(same_or_both_nan(r.length[i], length(a))) << width << " length " << x << " " << y;
    EXPECT_TRUE(same_or_both_nan(r.cross[i].x, c.x) && same_or_both_nan(r.cross[i].y, c.y) &&
                same_or_both_nan(r.cross[i].z, c.z))
        << width << " cross " << x << " " << y;
  }
}

TEST(FloatLanes, EveryOperationIsTheScalarOneBitForBit) {
  const float values[] = {-1.5f,
                          -0.0f,
                          0.0f,
                          0.1f,
                          3.0f,
                          1e30f,
                          -2.5e-3f,
                          std::numeric_limits<float>::denorm_min(),
                          -std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN()};
  std::vector<float> xs, ys;
  for (const float x : values)
    for (const float y : values) {
      xs.push_back(x);
      ys.push_back(y);
    }
  while (xs.size() % 8 != 0) {  // whole vectors in both widths
    xs.push_back(0.75f);
    ys.push_back(-0.0f);
  }
  expect_scalar_bits(sse2_lanes::lane_results(xs, ys), xs, ys, "sse2");
#if PRISM_FLOAT_LANES_AVX2
  if (lanes::avx2_supported()) expect_scalar_bits(avx2_lanes::lane_results(xs, ys), xs, ys, "avx2");
#endif
}

}  // namespace
}  // namespace prism
