#include "prism/accel/embree_accel.h"

#include <cstring>
#include <limits>
#include <string>

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include "prism/core/error.h"

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

}  // namespace

struct EmbreeAccel::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

EmbreeAccel::EmbreeAccel(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw Error("embree: cannot create a device (unsupported CPU?)");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);

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

}  // namespace prism
