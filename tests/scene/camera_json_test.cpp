#include "prism/scene/camera_json.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "prism/core/error.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

TEST(CameraJson, RoundTripsThroughText) {
  Camera c;
  c.eye = {1.5f, 2.0f, -3.25f};
  c.target = {0.0f, 1.0f, 0.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  c.fov_degrees = 35.5f;
  const Camera back = camera_from_json(camera_to_json(c));
  EXPECT_EQ(back.eye.x, c.eye.x);
  EXPECT_EQ(back.eye.z, c.eye.z);
  EXPECT_EQ(back.target.y, c.target.y);
  EXPECT_EQ(back.fov_degrees, c.fov_degrees);
  EXPECT_EQ(back.aperture_radius, 0.0f);
}

TEST(CameraJson, ReadsTheDocumentedSnippetOntoABase) {
  Camera base;
  base.aperture_radius = 0.1f;
  base.focus_distance = 4.0f;
  const Camera c = camera_from_json(R"({"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_degrees":50})", base);
  EXPECT_EQ(c.eye.z, 5.0f);
  EXPECT_EQ(c.fov_degrees, 50.0f);
  EXPECT_EQ(c.aperture_radius, 0.1f);  // absent fields keep the base's values
  EXPECT_EQ(c.focus_distance, 4.0f);
}

TEST(CameraJson, RejectsBadInput) {
  EXPECT_THROW(camera_from_json("{"), SceneError);
  EXPECT_THROW(camera_from_json("[1, 2]"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"eye":[0,0]})"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"eye":["a",0,0]})"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"eye":[0,0,0],"target":[0,0,0]})"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"eye":[0,0,1],"target":[0,0,0],"up":[0,0,2]})"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"fov_degrees":180})"), SceneError);
  EXPECT_THROW(camera_from_json(R"({"fov_degrees":"wide"})"), SceneError);
}

TEST(CameraJson, FileRoundTripAndMissingFile) {
  const test::ScratchFolder scratch;
  const auto path = scratch / "camera.json";
  Camera c;
  c.eye = {3, 4, 5};
  write_camera_json(path, c);
  EXPECT_EQ(read_camera_json(path).eye.y, 4.0f);
  std::filesystem::remove(path);
  EXPECT_THROW(read_camera_json(path), IoError);
}

}  // namespace
}  // namespace prism
