#include "sim/ray_caster.h"

#include <embree3/rtcore.h>
#include <algorithm>
#include <limits>

#include "common/error.h"

namespace sonarcarve {
namespace {
// Hits nearer than this along a ray are ignored (a ray leaving a surface does not meet it).
constexpr float kNearest = 1e-4f;
}  // namespace

struct RayCaster::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Embree() {
    if (scene != nullptr) {
      rtcReleaseScene(scene);
    }
    if (device != nullptr) {
      rtcReleaseDevice(device);
    }
  }
};

RayCaster::RayCaster(const Scene& scene) : scene_(scene), embree_(std::make_unique<Embree>()) {
  if (scene.triangles.empty()) {
    throw Error("scene", scene.name, "no triangles to ray-cast");
  }
  embree_->device = rtcNewDevice("verbose=0");
  if (embree_->device == nullptr) {
    throw Error("Embree", "", "cannot create a ray-casting device");
  }
  embree_->scene = rtcNewScene(embree_->device);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               scene.vertices.size()));
  for (std::size_t i = 0; i < scene.vertices.size(); ++i) {
    vertices[3 * i + 0] = scene.vertices[i].x();
    vertices[3 * i + 1] = scene.vertices[i].y();
    vertices[3 * i + 2] = scene.vertices[i].z();
  }
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), scene.triangles.size()));
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      indices[3 * i + static_cast<std::size_t>(k)] =
          scene.triangles[i][static_cast<std::size_t>(k)];
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(embree_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(embree_->scene);
  if (rtcGetDeviceError(embree_->device) != RTC_ERROR_NONE) {
    throw Error("Embree", scene.name, "building the ray-casting structure failed");
  }
}

RayCaster::~RayCaster() = default;

bool RayCaster::intersect(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                          float max_distance, RayHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = origin.x();
  rh.ray.org_y = origin.y();
  rh.ray.org_z = origin.z();
  rh.ray.dir_x = direction.x();
  rh.ray.dir_y = direction.y();
  rh.ray.dir_z = direction.z();
  rh.ray.tnear = kNearest;
  rh.ray.tfar = max_distance;
  rh.ray.mask = std::numeric_limits<unsigned>::max();
  rh.ray.time = 0.0f;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &rh);
  hit.found = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  if (hit.found) {
    fillHit(rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar, hit);
  }
  return hit.found;
}

void RayCaster::intersectFan(const Eigen::Vector3f& origin,
                             std::span<const Eigen::Vector3f> directions, float max_distance,
                             std::span<RayHit> hits) const {
  if (hits.size() != directions.size()) {
    throw Error("ray caster", scene_.name, "expected one hit slot per ray of the fan");
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  constexpr std::size_t kPacket = 16;
  alignas(64) int valid[kPacket];
  RTCRayHit16 packet;
  // What Embree leaves as it was, set once.
  for (std::size_t i = 0; i < kPacket; ++i) {
    packet.ray.org_x[i] = origin.x();
    packet.ray.org_y[i] = origin.y();
    packet.ray.org_z[i] = origin.z();
    packet.ray.tnear[i] = kNearest;
    packet.ray.mask[i] = std::numeric_limits<unsigned>::max();
    packet.ray.time[i] = 0.0f;
    packet.ray.flags[i] = 0;
  }
  for (std::size_t first = 0; first < directions.size(); first += kPacket) {
    const std::size_t count = std::min(kPacket, directions.size() - first);
    for (std::size_t i = 0; i < kPacket; ++i) {
      valid[i] = i < count ? -1 : 0;
      // Lanes past the end repeat the last ray (inactive, but kept finite).
      const Eigen::Vector3f& direction = directions[first + std::min(i, count - 1)];
      packet.ray.dir_x[i] = direction.x();
      packet.ray.dir_y[i] = direction.y();
      packet.ray.dir_z[i] = direction.z();
      packet.ray.tfar[i] = max_distance;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, embree_->scene, &context, &packet);
    for (std::size_t i = 0; i < count; ++i) {
      RayHit& hit = hits[first + i];
      hit.found = packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
      if (hit.found) {
        fillHit(packet.hit.primID[i], packet.hit.u[i], packet.hit.v[i], packet.ray.tfar[i], hit);
      }
    }
  }
}

void RayCaster::fillHit(unsigned triangle, float u, float v, float distance, RayHit& hit) const {
  const auto& tri = scene_.triangles[triangle];
  hit.distance = distance;
  hit.normal = ((1.0f - u - v) * scene_.normals[tri[0]] + u * scene_.normals[tri[1]] +
                v * scene_.normals[tri[2]])
                   .normalized();
  hit.triangle = triangle;
}

}  // namespace sonarcarve
