// CameraPacketCache's bookkeeping: which packet a block holds for a sample, when its room
// is free again, and which packet makes room when every one still waits for lanes. The
// integrator's images never depend on it (a packet traced again is the same packet); how
// many packets it traces does (render/path_tracer_test.cpp, CameraPackets).
#include <gtest/gtest.h>

#include "prism/render/camera_packet_cache.h"

namespace prism {
namespace {

TEST(CameraPacketCache, HoldsEachBlocksPacketsApart) {
  CameraPacketCache cache(20, 3);  // blocks of 8: two whole, one of four slots
  EXPECT_EQ(cache.blocks(), 3u);
  EXPECT_EQ(cache.find(0, 5), -1);
  const std::size_t a = cache.claim(0, 5, 0b0110);
  const std::size_t b = cache.claim(1, 5, 0b0001);
  EXPECT_NE(a, b);
  EXPECT_EQ(cache.find(0, 5), static_cast<std::ptrdiff_t>(a));
  EXPECT_EQ(cache.find(1, 5), static_cast<std::ptrdiff_t>(b));
  EXPECT_EQ(cache.find(2, 5), -1);
  EXPECT_EQ(cache.find(0, 6), -1);
  cache.packet(a).lanes[1].wavelength = 0.25;
  EXPECT_EQ(cache.packet(static_cast<std::size_t>(cache.find(0, 5))).lanes[1].wavelength, 0.25);
}

TEST(CameraPacketCache, APacketIsHeldUntilEveryWaitingLaneTookIt) {
  CameraPacketCache cache(8, 2);
  const std::size_t at = cache.claim(0, 3, 0b1010);
  cache.take(at, 1);
  EXPECT_EQ(cache.find(0, 3), static_cast<std::ptrdiff_t>(at));
  EXPECT_EQ(cache.waiting(at), 0b1000);
  cache.take(at, 3);
  EXPECT_EQ(cache.find(0, 3), -1) << "every lane taken: the room is free";
  // A packet nobody else waits for (the one lane that needs it takes it at once) is not held.
  cache.claim(0, 4, 0);
  EXPECT_EQ(cache.find(0, 4), -1);
}

TEST(CameraPacketCache, FreeRoomFirstThenTheHighestSampleMakesRoom) {
  CameraPacketCache cache(8, 3);
  const std::size_t s2 = cache.claim(0, 2, 0b01);
  const std::size_t s9 = cache.claim(0, 9, 0b01);
  const std::size_t s4 = cache.claim(0, 4, 0b01);
  EXPECT_TRUE(s2 != s9 && s9 != s4 && s2 != s4) << "free rooms are used before any packet is dropped";
  // Full, every packet waiting: sample 9's lanes are needed last, so it goes.
  const std::size_t s5 = cache.claim(0, 5, 0b11);
  EXPECT_EQ(s5, s9);
  EXPECT_EQ(cache.find(0, 9), -1);
  EXPECT_EQ(cache.find(0, 2), static_cast<std::ptrdiff_t>(s2));
  EXPECT_EQ(cache.find(0, 4), static_cast<std::ptrdiff_t>(s4));
  EXPECT_EQ(cache.find(0, 5), static_cast<std::ptrdiff_t>(s5));
  // Once sample 2's packet is taken, its room is the one reused.
  cache.take(s2, 0);
  EXPECT_EQ(cache.claim(0, 7, 0b10), s2);
  cache.clear();
  for (std::uint32_t sample : {4u, 5u, 7u}) EXPECT_EQ(cache.find(0, sample), -1);
}

}  // namespace
}  // namespace prism
