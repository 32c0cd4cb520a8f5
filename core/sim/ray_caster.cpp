#include "sim/ray_caster.h"

#include <embree3/rtcore.h>
#include <limits>

#include "common/error.h"

namespace sonarcarve {

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
  rh.ray.tnear = 1e-4f;
  rh.ray.tfar = max_distance;
  rh.ray.mask = std::numeric_limits<unsigned>::max();
  rh.ray.time = 0.0f;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    return false;
  }
  const auto& tri = scene_.triangles[rh.hit.primID];
  const float u = rh.hit.u;
  const float v = rh.hit.v;
  hit.distance = rh.ray.tfar;
  hit.normal = ((1.0f - u - v) * scene_.normals[tri[0]] + u * scene_.normals[tri[1]] +
                v * scene_.normals[tri[2]])
                   .normalized();
  hit.triangle = rh.hit.primID;
  return true;
}

}  // namespace sonarcarve
