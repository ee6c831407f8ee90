#include "prism/scene/camera_selection.h"

#include <gtest/gtest.h>

#include "prism/core/error.h"

namespace prism {
namespace {

Scene three_cameras() {
  Scene s;
  s.name = "test";
  for (const char* name : {"main", "7", "detail"}) {
    Camera c;
    c.name = name;
    c.fov_degrees = static_cast<float>(s.cameras.size() + 30);
    s.cameras.push_back(c);
  }
  s.camera = s.cameras[0];
  return s;
}

TEST(CameraSelection, ByNameAndByIndex) {
  Scene s = three_cameras();
  select_camera(s, "detail");
  EXPECT_EQ(s.camera.name, "detail");
  select_camera(s, "1");
  EXPECT_EQ(s.camera.name, "7");
  select_camera(s, "0");
  EXPECT_EQ(s.camera.name, "main");
  // A camera named with digits wins over the index of the same digits.
  select_camera(s, "7");
  EXPECT_EQ(s.camera.name, "7");
  EXPECT_FLOAT_EQ(s.camera.fov_degrees, 31.0f);
}

TEST(CameraSelection, UnknownNamesAndIndicesListTheCameras) {
  Scene s = three_cameras();
  for (const char* spec : {"3", "wide", "-1", "99999999999999999999999", ""}) {
    try {
      select_camera(s, spec);
      ADD_FAILURE() << "'" << spec << "' was accepted";
    } catch (const UsageError& e) {
      if (*spec) {
        EXPECT_NE(std::string(e.what()).find("0 'main' 1 '7' 2 'detail'"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_EQ(s.camera.name, "main");  // unchanged by the failures
}

}  // namespace
}  // namespace prism
