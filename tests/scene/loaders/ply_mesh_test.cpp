#include "prism/scene/loaders/ply_mesh.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <limits>
#include <string>

#include "loader_test_files.h"
#include "prism/core/error.h"

namespace prism::loaders {
namespace {

std::span<const unsigned char> bytes_of(const std::string& s) {
  return {reinterpret_cast<const unsigned char*>(s.data()), s.size()};
}

template <typename T>
void put(std::string& out, T value, bool big_endian) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

// A unit quad (one face of four vertices) with normals, in binary.
std::string binary_quad(bool big_endian) {
  std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment test\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float p[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& v : p) {
    for (float c : {v[0], v[1], 0.0f, 0.0f, 0.0f, 1.0f}) put(s, c, big_endian);
    put<unsigned char>(s, 255, big_endian);
  }
  put<unsigned char>(s, 4, big_endian);
  for (int i : {0, 1, 2, 3}) put<std::int32_t>(s, i, big_endian);
  return s;
}

TEST(PlyMesh, ReadsAsciiWithUvsAndFansPolygons) {
  const std::string ply =
      "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "property float u\r\nproperty float v\r\nelement face 1\r\nproperty list uchar uint vertex_indices\r\n"
      "end_header\r\n0 0 0 0 0\r\n1 0 0 1 0\r\n1 1 0 1 1\r\n0 1 0 0 1\r\n4 0 1 2 3\r\n";
  const PlyMesh m = parse_ply_mesh(bytes_of(ply), "quad.ply");
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.uvs.size(), 4u);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.uvs[2].x, 1.0f);
  EXPECT_EQ(m.uvs[2].y, 1.0f);
}

TEST(PlyMesh, ReadsBinaryLittleAndBigEndian) {
  for (bool big : {false, true}) {
    const std::string ply = binary_quad(big);
    const PlyMesh m = parse_ply_mesh(bytes_of(ply), "quad.ply");
    ASSERT_EQ(m.positions.size(), 4u) << big;
    EXPECT_EQ(m.positions[2], Vec3f(1.0f, 1.0f, 0.0f)) << big;
    EXPECT_EQ(m.normals[3], Vec3f(0.0f, 0.0f, 1.0f)) << big;
    EXPECT_EQ(m.indices.size(), 6u) << big;
  }
}

TEST(PlyMesh, BadInputIsAOneLineError) {
  const std::string good = binary_quad(false);
  const auto error = [](const std::string& text) {
    return test::error_of<SceneError>([&] { parse_ply_mesh(bytes_of(text), "bad.ply"); });
  };
  EXPECT_NE(error("plx\n").find("bad.ply:1: not a PLY file"), std::string::npos);
  EXPECT_NE(error("ply\nformat ascii 1.0\nelement vertex 1\n").find("no end_header"), std::string::npos);
  EXPECT_NE(error("ply\nformat foo 1.0\nend_header\n").find("bad.ply:2: unknown format"), std::string::npos);
  EXPECT_NE(error("ply\nformat ascii 1.0\nproperty float x\nend_header\n").find("before any element"), std::string::npos);
  // Truncated data, at every length past the header.
  for (std::size_t n = good.find("end_header") + 11; n < good.size(); n += 3)
    EXPECT_NE(error(good.substr(0, n)).find("bad.ply: "), std::string::npos) << n;
  // A count that cannot fit in the file is refused before allocating.
  std::string huge = good;
  huge.replace(huge.find("vertex 4"), 8, "vertex 4000000000000");
  EXPECT_NE(error(huge).find("more than the file holds"), std::string::npos);
  // An index past the vertices.
  std::string bad_index = good;
  bad_index[bad_index.size() - 4] = 9;
  EXPECT_NE(error(bad_index).find("out of range"), std::string::npos);
  EXPECT_NE(error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                  "end_header\n0 nan? 0\n")
                .find("not a number"),
            std::string::npos);
  EXPECT_NE(error("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n")
                .find("out of range"),
            std::string::npos);
  EXPECT_NE(error("ply\nformat ascii 1.0\nelement blob 99999999999\nend_header\n").find("no vertex element"),
            std::string::npos);
}

TEST(PlyMesh, NonIntegerCountsIndicesAndHugeDoublesAreErrorsNotUndefinedConversions) {
  // Float- and double-typed lists and coordinates reach integer and float conversions that
  // are undefined for NaN or out-of-range values (UBSan float-cast-overflow under the asan
  // preset); each must be a one-line error instead.
  const auto error = [](const std::string& text) {
    return test::error_of<SceneError>([&] { parse_ply_mesh(bytes_of(text), "bad.ply"); });
  };
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list float float vertex_indices\nend_header\n";
  const auto body = [](double big, float count, float index) {
    std::string s;
    for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, big}) put(s, c, false);
    put(s, count, false);
    for (float i : {0.0f, 1.0f, index}) put(s, i, false);
    return s;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(parse_ply_mesh(bytes_of(header + body(0.0, 3.0f, 2.0f)), "ok.ply").indices.size(), 3u);
  EXPECT_NE(error(header + body(0.0, nan, 2.0f)).find("a list length is out of range"), std::string::npos);
  EXPECT_NE(error(header + body(0.0, 3.0f, nan)).find("vertex index nan is out of range"), std::string::npos);
  EXPECT_NE(error(header + body(1e300, 3.0f, 2.0f)).find("vertex 2: 1e+300 is beyond the range of a float"),
            std::string::npos);
}

TEST(PlyMesh, MissingFileIsAnIoError) {
  EXPECT_THROW(read_ply_mesh("/nonexistent/prism/x.ply"), IoError);
}

}  // namespace
}  // namespace prism::loaders
