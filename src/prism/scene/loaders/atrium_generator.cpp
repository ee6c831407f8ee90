#include "prism/scene/loaders/atrium_generator.h"

#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/atrium_textures.h"
#include "prism/scene/loaders/sphere_mesh.h"

namespace prism::loaders {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Courtyard layout (metres): columns stand on two long sides (x = ±kHalfWidth) and two
// short sides (z = ±kHalfLength); each storey is kStorey high.
constexpr float kHalfWidth = 7.0f, kHalfLength = 14.0f, kStorey = 6.0f, kWallGap = 3.0f;
constexpr int kColumnsLong = 9, kColumnsShort = 5, kStoreys = 2;
constexpr float kColumnRadius = 0.35f, kArchThickness = 0.4f;

enum Materials : std::uint32_t { kStone, kFloor, kWall, kGold, kGlass, kLight, kLeaves, kMaterialCount };
enum Textures : int { kFloorTexture, kWallTexture, kLeafTexture };

// Planters in the courtyard (centres, metres) and the foliage cards standing in them.
constexpr float kPlanterHalf = 0.6f, kPlanterHeight = 0.6f, kCardWidth = 1.4f, kCardHeight = 1.6f;
constexpr float kPlanters[4][2] = {{-4.5f, -9.0f}, {4.5f, -9.0f}, {-4.5f, 9.0f}, {4.5f, 9.0f}};

void add_quad(TriangleMesh& m, Vec3f a, Vec3f b, Vec3f c, Vec3f d) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// An axis-aligned box, faces outward.
void add_box(TriangleMesh& m, Vec3f lo, Vec3f hi) {
  const Vec3f p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                      {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  add_quad(m, p[0], p[3], p[2], p[1]);  // −z
  add_quad(m, p[4], p[5], p[6], p[7]);  // +z
  add_quad(m, p[0], p[4], p[7], p[3]);  // −x
  add_quad(m, p[1], p[2], p[6], p[5]);  // +x
  add_quad(m, p[0], p[1], p[5], p[4]);  // −y
  add_quad(m, p[3], p[7], p[6], p[2]);  // +y
}

// A column: an open cylinder of `segments` around and `rings` bands up, with normals
// (smooth shaft), standing on a square plinth.
TriangleMesh make_column(Vec3f base, float height, int segments, int rings) {
  TriangleMesh m;
  for (int r = 0; r <= rings; ++r) {
    const float y = base.y + 0.3f + (height - 0.3f) * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
      // Gentle fluting: the radius ripples with 16 flutes.
      const float radius = kColumnRadius * (1.0f + 0.04f * std::cos(16.0f * phi));
      m.positions.emplace_back(base.x + radius * std::cos(phi), y, base.z - radius * std::sin(phi));
      m.normals.emplace_back(std::cos(phi), 0.0f, -std::sin(phi));
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto a = static_cast<std::uint32_t>(r * segments + s);
      const auto b = static_cast<std::uint32_t>(r * segments + (s + 1) % segments);
      const auto c = b + static_cast<std::uint32_t>(segments), d = a + static_cast<std::uint32_t>(segments);
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  const std::size_t shaft_vertices = m.positions.size();
  TriangleMesh plinth;
  add_box(plinth, base + Vec3f(-0.5f, 0.0f, -0.5f), base + Vec3f(0.5f, 0.3f, 0.5f));
  for (std::uint32_t i : plinth.indices) m.indices.push_back(static_cast<std::uint32_t>(shaft_vertices) + i);
  m.positions.insert(m.positions.end(), plinth.positions.begin(), plinth.positions.end());
  m.normals.clear();  // the plinth is flat-shaded, so the mesh has none
  return m;
}

// A semicircular arch band from `a` to `b` (column centres at the springing height),
// `segments` pieces along the arc, a square cross-section kArchThickness wide.
void add_arch(TriangleMesh& m, Vec3f a, Vec3f b, int segments) {
  const Vec3f centre = 0.5f * (a + b), along = 0.5f * (b - a);
  const float radius = length(along);
  const Vec3f u = along / radius, up(0.0f, 1.0f, 0.0f), side = cross(u, up) * (0.5f * kArchThickness);
  const auto point = [&](int i, float r) {
    const float t = kPi * static_cast<float>(i) / static_cast<float>(segments);
    return centre - u * (r * std::cos(t)) + up * (r * std::sin(t));
  };
  const float inner = radius - 0.5f * kArchThickness, outer = radius + 0.5f * kArchThickness;
  for (int i = 0; i < segments; ++i) {
    const Vec3f i0 = point(i, inner), i1 = point(i + 1, inner), o0 = point(i, outer), o1 = point(i + 1, outer);
    add_quad(m, i0 - side, i1 - side, i1 + side, i0 + side);  // intrados (faces down/in)
    add_quad(m, o0 + side, o1 + side, o1 - side, o0 - side);  // extrados
    add_quad(m, i0 + side, i1 + side, o1 + side, o0 + side);  // the two faces
    add_quad(m, o0 - side, o1 - side, i1 - side, i0 - side);
  }
}

// A quad with per-vertex uvs.
void add_quad_uv(TriangleMesh& m, const std::array<Vec3f, 4>& p, const std::array<Vec2f, 4>& uv) {
  add_quad(m, p[0], p[1], p[2], p[3]);
  m.uvs.insert(m.uvs.end(), uv.begin(), uv.end());
}

// A wall quad from `a` to `b` along the floor, `height` high, facing the side a
// counter-clockwise winding seen from inside gives; u runs along the wall, v down it.
void add_wall(TriangleMesh& m, Vec3f a, Vec3f b, float height) {
  const float along = length(b - a) / kWallTextureMeters, top = 0.0f, bottom = height / kWallTextureMeters;
  const float u0 = (a.x + a.z) / kWallTextureMeters;  // continuous enough at the corners
  add_quad_uv(m, {a, b, b + Vec3f(0, height, 0), a + Vec3f(0, height, 0)},
              {Vec2f(u0, bottom), Vec2f(u0 + along, bottom), Vec2f(u0 + along, top), Vec2f(u0, top)});
}

// A plant: three vertical cards crossed at 60°, standing on `foot`, the leaf texture's
// top edge (v = 0) at the top of each card.
void add_plant(TriangleMesh& m, Vec3f foot, float turn_radians) {
  for (int k = 0; k < 3; ++k) {
    const float theta = turn_radians + static_cast<float>(k) * kPi / 3.0f;
    const Vec3f half = Vec3f(std::cos(theta), 0.0f, std::sin(theta)) * (0.5f * kCardWidth), up(0.0f, kCardHeight, 0.0f);
    add_quad_uv(m, {foot - half, foot + half, foot + half + up, foot - half + up},
                {Vec2f(0, 1), Vec2f(1, 1), Vec2f(1, 0), Vec2f(0, 0)});
  }
}

Material diffuse(const char* name, Vec3f color, int texture = -1) {
  Material m;
  m.name = name;
  m.base_color = color;
  m.base_color_texture = texture;
  return m;
}

}  // namespace

Scene generate_atrium(std::size_t target) {
  if (target < kAtriumMinTriangles || target > kAtriumMaxTriangles)
    throw UsageError(fmt::format("atrium: --triangles must be between {} and {}", kAtriumMinTriangles, kAtriumMaxTriangles));
  Scene scene;
  scene.name = "atrium";
  scene.textures = {make_floor_tile_texture(), make_wall_block_texture(), make_leaf_texture()};
  scene.materials = {diffuse("stone", {0.55f, 0.5f, 0.42f}), diffuse("floor-tiles", Vec3f(1.0f), kFloorTexture),
                     diffuse("wall-blocks", Vec3f(1.0f), kWallTexture)};
  Material gold;
  gold.name = "gold";
  gold.type = MaterialType::conductor;
  gold.conductor_fresnel = ConductorFresnel::complex_ior;
  gold.conductor_name = "Au";
  gold.base_color = Vec3f(1.0f);
  gold.roughness = 0.3f;
  Material glass;
  glass.name = "glass";
  glass.type = MaterialType::dielectric;
  glass.base_color = Vec3f(1.0f);
  glass.ior = 1.5f;
  glass.roughness = 0.0f;
  Material light = diffuse("skylight", Vec3f(0.0f));
  light.emission.color = Vec3f(1.0f, 0.95f, 0.85f);
  light.emission.luminance_nits = 40.0f;  // scaled for the default exposure (EV100 0)
  scene.materials.push_back(gold);
  scene.materials.push_back(glass);
  scene.materials.push_back(light);
  // Foliage: the leaf texture's alpha cuts the cards out (glTF alphaMode MASK, cutoff 0.5).
  Material leaves = diffuse("leaves", Vec3f(1.0f), kLeafTexture);
  leaves.alpha_mode = AlphaMode::mask;
  leaves.alpha_cutoff = 0.5f;
  scene.materials.push_back(leaves);

  const int columns = kStoreys * 2 * (kColumnsLong + kColumnsShort);
  const int arches = kStoreys * 2 * (kColumnsLong - 1 + kColumnsShort - 1);
  // Triangles: columns 2·s·r + 12 (plinth), arches 8·(s/2) each, the sphere about s²;
  // with r = s the total is (2·columns + 1)·s² + 4·arches·s + fixed. Solve for s.
  const double fixed = 1500.0;
  const double qa = 2.0 * columns + 1.0, qb = 4.0 * arches, qc = fixed - static_cast<double>(target);
  const int s = std::max(8, static_cast<int>(std::lround((-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa))));

  // Floor: one quad per 1 m tile, uvs from the position so the tile texture (4 × 4 tiles
  // of 1 m) lines up with the quads.
  TriangleMesh floor;
  floor.name = "floor-tiles";
  floor.material = kFloor;
  const int nx = static_cast<int>(2.0f * (kHalfWidth + kWallGap)), nz = static_cast<int>(2.0f * (kHalfLength + kWallGap));
  const auto floor_uv = [](const Vec3f& p) { return Vec2f(p.x / kFloorTextureMeters, p.z / kFloorTextureMeters); };
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) {
      const float x0 = -(kHalfWidth + kWallGap) + static_cast<float>(i), z0 = -(kHalfLength + kWallGap) + static_cast<float>(k);
      const Vec3f a(x0, 0, z0), b(x0, 0, z0 + 1), c(x0 + 1, 0, z0 + 1), d(x0 + 1, 0, z0);
      add_quad_uv(floor, {a, b, c, d}, {floor_uv(a), floor_uv(b), floor_uv(c), floor_uv(d)});
    }
  scene.meshes.push_back(std::move(floor));

  // Outer walls (inward-facing), open to the sky.
  TriangleMesh walls;
  walls.name = "walls";
  walls.material = kWall;
  const float wx = kHalfWidth + kWallGap, wz = kHalfLength + kWallGap, wh = kStorey * kStoreys + 1.0f;
  add_wall(walls, {-wx, 0, -wz}, {wx, 0, -wz}, wh);
  add_wall(walls, {wx, 0, wz}, {-wx, 0, wz}, wh);
  add_wall(walls, {-wx, 0, wz}, {-wx, 0, -wz}, wh);
  add_wall(walls, {wx, 0, -wz}, {wx, 0, wz}, wh);
  scene.meshes.push_back(std::move(walls));

  // Gallery floor between the storeys: a slab ring around the courtyard.
  TriangleMesh gallery;
  gallery.name = "gallery";
  gallery.material = kStone;
  const float gy0 = kStorey + 0.9f, gy1 = kStorey + 1.2f, in = 0.6f;
  add_box(gallery, {-wx, gy0, -wz}, {-kHalfWidth + in, gy1, wz});
  add_box(gallery, {kHalfWidth - in, gy0, -wz}, {wx, gy1, wz});
  add_box(gallery, {-kHalfWidth + in, gy0, -wz}, {kHalfWidth - in, gy1, -kHalfLength + in});
  add_box(gallery, {-kHalfWidth + in, gy0, kHalfLength - in}, {kHalfWidth - in, gy1, wz});
  scene.meshes.push_back(std::move(gallery));

  // Columns and arches, storey by storey, side by side.
  TriangleMesh arch_mesh;
  arch_mesh.name = "arches";
  arch_mesh.material = kStone;
  const float column_height = kStorey - 2.0f;
  for (int storey = 0; storey < kStoreys; ++storey) {
    const float y = storey == 0 ? 0.0f : gy1;
    std::vector<std::pair<Vec3f, Vec3f>> rows;  // first and last column of each side
    rows.push_back({{-kHalfWidth, y, -kHalfLength}, {-kHalfWidth, y, kHalfLength}});
    rows.push_back({{kHalfWidth, y, -kHalfLength}, {kHalfWidth, y, kHalfLength}});
    rows.push_back({{-kHalfWidth, y, -kHalfLength}, {kHalfWidth, y, -kHalfLength}});
    rows.push_back({{-kHalfWidth, y, kHalfLength}, {kHalfWidth, y, kHalfLength}});
    for (int side = 0; side < 4; ++side) {
      const int n = side < 2 ? kColumnsLong : kColumnsShort;
      const auto [first, last] = rows[side];
      for (int c = 0; c < n; ++c) {
        const Vec3f p = first + (last - first) * (static_cast<float>(c) / static_cast<float>(n - 1));
        TriangleMesh column = make_column(p, column_height, s, s);
        column.name = fmt::format("column-{}-{}-{}", storey, side, c);
        column.material = kStone;
        scene.meshes.push_back(std::move(column));
        if (c + 1 < n) {
          const Vec3f q = first + (last - first) * (static_cast<float>(c + 1) / static_cast<float>(n - 1));
          add_arch(arch_mesh, p + Vec3f(0, column_height, 0), q + Vec3f(0, column_height, 0), std::max(4, s / 2));
        }
      }
    }
  }
  scene.meshes.push_back(std::move(arch_mesh));

  // The two showpieces in the courtyard: a rough gold sphere and a glass block.
  TriangleMesh sphere = make_uv_sphere(Vec3f(-2.0f, 1.0f, 2.0f), 1.0f, std::clamp(s / 2, 16, 256));
  sphere.name = "gold-sphere";
  sphere.material = kGold;
  scene.meshes.push_back(std::move(sphere));
  TriangleMesh block;
  block.name = "glass-block";
  block.material = kGlass;
  add_box(block, {1.0f, 0.0f, -3.0f}, {3.0f, 1.5f, -1.0f});
  scene.meshes.push_back(std::move(block));

  // Planters with foliage cards: two plants in each, turned differently.
  TriangleMesh planters, foliage;
  planters.name = "planters";
  planters.material = kStone;
  foliage.name = "foliage";
  foliage.material = kLeaves;
  for (int i = 0; i < 4; ++i) {
    const Vec3f centre(kPlanters[i][0], 0.0f, kPlanters[i][1]);
    add_box(planters, centre - Vec3f(kPlanterHalf, 0.0f, kPlanterHalf), centre + Vec3f(kPlanterHalf, kPlanterHeight, kPlanterHalf));
    for (int plant = 0; plant < 2; ++plant) {
      const Vec3f foot = centre + Vec3f(plant == 0 ? -0.25f : 0.25f, kPlanterHeight, plant == 0 ? 0.2f : -0.2f);
      add_plant(foliage, foot, 0.4f * static_cast<float>(i) + 0.9f * static_cast<float>(plant));
    }
  }
  scene.meshes.push_back(std::move(planters));
  scene.meshes.push_back(std::move(foliage));

  // A skylight over the courtyard, emitting downwards, and a sky environment.
  TriangleMesh sky;
  sky.name = "skylight";
  sky.material = kLight;
  const float ly = kStorey * kStoreys + 4.0f;
  add_quad(sky, {-3, ly, -6}, {3, ly, -6}, {3, ly, 6}, {-3, ly, 6});
  scene.meshes.push_back(std::move(sky));
  Light environment;
  environment.name = "sky";
  environment.type = LightType::environment;
  environment.color = Vec3f(0.55f, 0.7f, 1.0f);
  environment.intensity = 4.0f;
  scene.lights.push_back(environment);

  scene.camera.name = "courtyard";
  scene.camera.eye = Vec3f(1.75f, 1.7f, kHalfLength + 1.5f);  // between two columns
  scene.camera.target = Vec3f(0.0f, 3.5f, 0.0f);
  scene.camera.fov_degrees = 60.0f;
  scene.cameras = {scene.camera};
  scene.default_width = 1280;
  scene.default_height = 720;
  return scene;
}

}  // namespace prism::loaders
