#include "prism/core/lane_slots.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "prism/accel/embree_accel.h"
#include "prism/core/ray.h"

namespace prism {
namespace {

// A callee that fills a row of T through a pointer, as EmbreeAccel::intersect_packet does.
void fill_hits(Hit* hits, int count) {
  for (int k = 0; k < count; ++k)
    hits[k] = Hit{0.5f * static_cast<float>(k), 7u, static_cast<std::uint32_t>(k), 0.25f, 0.75f};
}

TEST(LaneSlots, HoldsExactlyNSlotsInARowAlignedForTheirType) {
  // data() is handed to callees that write N values in a row: no padding, no header.
  static_assert(sizeof(LaneSlots<Ray, 8>) == 8 * sizeof(Ray));
  static_assert(sizeof(LaneSlots<Hit, 8>) == 8 * sizeof(Hit));
  static_assert(alignof(LaneSlots<Ray, 8>) == alignof(Ray));
  static_assert(LaneSlots<Hit, 8>::size() == 8);
  LaneSlots<Ray, 8> rays;
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(rays.data()) % alignof(Ray), 0u);
}

TEST(LaneSlots, ReadsBackWhatSetWroteOverTheTypesDefaults) {
  LaneSlots<Ray, 4> rays;
  for (int k = 0; k < 4; ++k) {
    Ray r;
    r.origin = Vec3f(static_cast<float>(k), 1.0f, 2.0f);
    r.direction = Vec3f(0.0f, 0.0f, 1.0f);
    r.t_min = 0.125f * static_cast<float>(k);
    r.t_max = 10.0f + static_cast<float>(k);
    rays.set(static_cast<std::size_t>(k), r);
  }
  for (int k = 0; k < 4; ++k) {
    const Ray& r = rays[static_cast<std::size_t>(k)];
    EXPECT_EQ(r.origin.x, static_cast<float>(k));
    EXPECT_EQ(r.t_min, 0.125f * static_cast<float>(k));
    EXPECT_EQ(r.t_max, 10.0f + static_cast<float>(k));
  }
  // A slot written again holds the new value.
  Ray again;
  again.t_max = 3.0f;
  rays.set(2, again);
  EXPECT_EQ(rays[2].t_max, 3.0f);
  EXPECT_EQ(rays[2].origin.x, 0.0f);
  EXPECT_EQ(rays[3].t_max, 13.0f);
}

TEST(LaneSlots, ShowsWhatACalleeWroteThroughData) {
  LaneSlots<Hit, 8> hits;
  fill_hits(hits.data(), 8);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(hits[k].t, 0.5f * static_cast<float>(k));
    EXPECT_EQ(hits[k].mesh, 7u);
    EXPECT_EQ(hits[k].triangle, k);
    EXPECT_EQ(hits[k].v, 0.75f);
  }
}

}  // namespace
}  // namespace prism
