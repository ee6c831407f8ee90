#include "prism/viewer/camera_controller.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace prism::viewer {
namespace {

Camera looking_down_z() {
  Camera c;
  c.eye = {0, 0, -10};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fov_degrees = 40;
  return c;
}

TEST(CameraController, OrbitKeepsTheDistanceToTheTarget) {
  const Camera c = orbit(looking_down_z(), std::numbers::pi / 2, 0.0);
  EXPECT_NEAR(view_distance(c), 10.0, 1e-4);
  EXPECT_NEAR(std::fabs(c.eye.x), 10.0, 1e-4);  // a quarter turn about +y
  EXPECT_NEAR(c.eye.z, 0.0, 1e-4);
  EXPECT_EQ(c.target.x, 0.0f);
}

TEST(CameraController, OrbitPitchStopsShortOfThePole) {
  const Camera c = orbit(looking_down_z(), 0.0, 10.0);
  EXPECT_NEAR(view_distance(c), 10.0, 1e-4);
  const double elevation = std::asin(std::fabs(c.eye.y) / 10.0);
  EXPECT_LT(elevation, std::numbers::pi / 2 - 0.5 * std::numbers::pi / 180);
  EXPECT_GT(elevation, std::numbers::pi / 2 - 2.0 * std::numbers::pi / 180);
}

TEST(CameraController, PanMovesEyeAndTargetTogether) {
  const Camera c = pan(looking_down_z(), 2.0, 1.0);
  EXPECT_NEAR(c.target.y - c.eye.y, 0.0, 1e-5);
  EXPECT_NEAR(std::fabs(c.eye.x), 2.0, 1e-5);
  EXPECT_NEAR(c.eye.y, 1.0, 1e-5);
  EXPECT_NEAR(view_distance(c), 10.0, 1e-4);
}

TEST(CameraController, DollyScalesTheDistance) {
  EXPECT_NEAR(view_distance(dolly(looking_down_z(), 0.5)), 5.0, 1e-4);
  EXPECT_GT(view_distance(dolly(looking_down_z(), 0.0)), 0.0);  // never onto the target
}

TEST(CameraController, FlyAndLook) {
  const Camera f = fly(looking_down_z(), 1.0, 0.0, 2.0);
  EXPECT_NEAR(f.eye.z, -9.0, 1e-5);
  EXPECT_NEAR(f.eye.y, 2.0, 1e-5);
  EXPECT_NEAR(view_distance(f), 10.0, 1e-4);
  const Camera l = look(looking_down_z(), std::numbers::pi, 0.0);
  EXPECT_EQ(l.eye.z, -10.0f);
  EXPECT_NEAR(l.target.z, -20.0, 1e-3);  // turned around
}

TEST(CameraController, PixelFootprintSpansTheFieldOfView) {
  const Camera c = looking_down_z();
  const double extent = 2.0 * 10.0 * std::tan(20.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(pixel_footprint(c, 100) * 100, extent, 1e-6);
}

}  // namespace
}  // namespace prism::viewer
