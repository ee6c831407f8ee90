#pragma once
// A small reader for PLY polygon meshes (ASCII, binary little- and big-endian), as pbrt-v4's
// "plymesh" shape refers to them. Reads the `vertex` element (x y z, optional nx ny nz and
// u v / s t / texture_u texture_v) and the `face` element's vertex index list (triangles;
// polygons are fanned). Other elements and properties are skipped.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "prism/core/vec.h"

namespace prism::loaders {

struct PlyMesh {
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;  // empty or one per position
  std::vector<Vec2f> uvs;      // empty or one per position
  std::vector<std::uint32_t> indices;  // three per triangle, each checked < positions.size()
};

// Every count is checked against the bytes that remain before anything is allocated, and
// every index against the vertex count. Throws SceneError "<source>: ..." naming the header
// line or the element and byte offset.
PlyMesh parse_ply_mesh(std::span<const unsigned char> bytes, std::string_view source);

// Throws IoError for a missing or unreadable file.
PlyMesh read_ply_mesh(const std::filesystem::path& path);

}  // namespace prism::loaders
