#include "prism/accel/embree_accel.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/sample_stream.h"
#include "prism/scene/surface_alpha.h"

namespace prism {
namespace {

void throw_on_device_error(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE) throw Error(fmt::format("embree: {} failed (error {})", what, static_cast<int>(code)));
}

void fill_ray(const Ray& ray, RTCRay& r) {
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = ray.t_min;
  r.tfar = ray.t_max;
  r.time = 0.0f;
  r.mask = std::numeric_limits<unsigned>::max();
  r.id = 0;
  r.flags = 0;
}

// What an alpha-tested mesh's filter needs (geometry user data).
struct AlphaGeometry {
  const Scene* scene;
  const TriangleMesh* mesh;
  std::uint32_t mesh_index;
};

// A uniform number in [0, 1) from the ray and the primitive only (stochastic coverage must
// not depend on threads or on how often Embree calls the filter for the same hit).
float coverage_number(RTCRayN* ray, unsigned n, unsigned i, std::uint32_t mesh, std::uint32_t prim) {
  std::uint64_t h = mix64((std::uint64_t{mesh} << 32) | prim);
  for (float f : {RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i),
                  RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)}) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    h = mix64(h ^ bits);
  }
  return static_cast<float>(h >> 40) * 0x1p-24f;
}

// Intersection and occlusion filter of meshes with alpha coverage (surface_alpha.h):
// rejecting a candidate hit lets the ray continue through the cut-out.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* g = static_cast<const AlphaGeometry*>(args->geometryUserPtr);
  const Material& material = g->scene->materials[g->mesh->material];
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const std::uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    const float alpha = surface_alpha(*g->scene, *g->mesh, prim, RTCHitN_u(args->hit, args->N, i),
                                      RTCHitN_v(args->hit, args->N, i));
    const float u = material.alpha_mode == AlphaMode::blend
                        ? coverage_number(args->ray, args->N, i, g->mesh_index, prim) : 0.0f;
    if (!surface_alpha_accepts(material, alpha, u)) args->valid[i] = 0;
  }
}

// Rays per rtcIntersect1M / rtcOccluded1M call: large enough that the per-call cost
// vanishes, small enough that the stream stays in L1 (64 × 80 B).
constexpr std::size_t kStreamRays = 64;

RTCIntersectContext incoherent_context() {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  return context;
}

}  // namespace

struct EmbreeAccel::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<AlphaGeometry> alpha_geometry;  // stable: reserved before any pointer is taken
};

EmbreeAccel::EmbreeAccel(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw Error("embree: cannot create a device (unsupported CPU?)");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  impl_->alpha_geometry.reserve(scene.meshes.size());

  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangle_count()));
    throw_on_device_error(impl_->device, "allocating geometry buffers");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices[3 * i + 0] = mesh.positions[i].x;
      vertices[3 * i + 1] = mesh.positions[i].y;
      vertices[3 * i + 2] = mesh.positions[i].z;
    }
    std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    if (mesh.material < scene.materials.size() && has_alpha_coverage(scene.materials[mesh.material])) {
      impl_->alpha_geometry.push_back({&scene, &mesh, static_cast<std::uint32_t>(m)});
      rtcSetGeometryUserData(geom, &impl_->alpha_geometry.back());
      rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
      rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(impl_->scene, geom, static_cast<unsigned>(m));
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(impl_->scene);
  throw_on_device_error(impl_->device, "building the BVH");
}

EmbreeAccel::~EmbreeAccel() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

bool EmbreeAccel::intersect(const Ray& ray, Hit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  fill_ray(ray, rh.ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = rh.ray.tfar;
  hit.mesh = rh.hit.geomID;
  hit.triangle = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return true;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  fill_ray(ray, r);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

void EmbreeAccel::intersect_slots(const Ray* rays, const std::uint32_t* slots, std::size_t count, Hit* hits,
                                  std::uint8_t* found, RayCoherence coherence) const {
  RTCIntersectContext context = incoherent_context();
  if (coherence == RayCoherence::coherent) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) RTCRayHit stream[kStreamRays];
  for (std::size_t first = 0; first < count; first += kStreamRays) {
    const std::size_t n = std::min(kStreamRays, count - first);
    for (std::size_t i = 0; i < n; ++i) {
      fill_ray(rays[slots[first + i]], stream[i].ray);
      stream[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      stream[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect1M(impl_->scene, &context, stream, static_cast<unsigned>(n), sizeof(RTCRayHit));
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t s = slots[first + i];
      const RTCRayHit& rh = stream[i];
      found[s] = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      hits[s] = Hit{rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v};
    }
  }
}

void EmbreeAccel::intersect_packet(const Ray* rays, unsigned lanes, Hit* hits, std::uint8_t* found) const {
  static_assert(kPacketRays == 8, "rtcIntersect8");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(32) RTCRayHit8 packet;
  alignas(32) int valid[kPacketRays];
  for (std::size_t i = 0; i < kPacketRays; ++i) {
    const Ray& ray = rays[i];
    valid[i] = (lanes >> i) & 1u ? -1 : 0;
    packet.ray.org_x[i] = ray.origin.x;
    packet.ray.org_y[i] = ray.origin.y;
    packet.ray.org_z[i] = ray.origin.z;
    packet.ray.dir_x[i] = ray.direction.x;
    packet.ray.dir_y[i] = ray.direction.y;
    packet.ray.dir_z[i] = ray.direction.z;
    packet.ray.tnear[i] = ray.t_min;
    packet.ray.tfar[i] = ray.t_max;
    packet.ray.time[i] = 0.0f;
    packet.ray.mask[i] = std::numeric_limits<unsigned>::max();
    packet.ray.id[i] = 0;
    packet.ray.flags[i] = 0;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, impl_->scene, &context, &packet);
  for (std::size_t i = 0; i < kPacketRays; ++i) {
    found[i] = packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    hits[i] = Hit{packet.ray.tfar[i], packet.hit.geomID[i], packet.hit.primID[i], packet.hit.u[i], packet.hit.v[i]};
  }
}

void EmbreeAccel::occluded_slots(const Ray* rays, const std::uint32_t* slots, std::size_t count,
                                 const std::uint8_t* pending, std::uint8_t* blocked) const {
  RTCIntersectContext context = incoherent_context();
  alignas(64) RTCRay stream[kStreamRays];
  std::uint32_t stream_slots[kStreamRays];
  std::size_t next = 0;
  while (next < count) {
    std::size_t n = 0;
    // Every slot's ray is written, and counted in where it is pending: no branch on
    // whether a path cast a shadow ray, a coin flip to the predictor.
    for (; next < count && n < kStreamRays; ++next) {
      const std::uint32_t s = slots[next];
      fill_ray(rays[s], stream[n]);
      stream_slots[n] = s;
      n += pending[s] != 0;
    }
    if (n == 0) break;
    rtcOccluded1M(impl_->scene, &context, stream, static_cast<unsigned>(n), sizeof(RTCRay));
    for (std::size_t i = 0; i < n; ++i) blocked[stream_slots[i]] = stream[i].tfar < 0.0f;  // -inf on a hit
  }
}

}  // namespace prism
