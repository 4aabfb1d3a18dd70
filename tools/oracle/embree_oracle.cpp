#include "tools/oracle/embree_oracle.h"

#include <embree3/rtcore.h>

#include <limits>
#include <stdexcept>

namespace strata::oracle {

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

namespace {
void check(RTCDevice device, const char* what) {
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " + std::to_string(int(err)) + ")");
}
}  // namespace

EmbreeScene::EmbreeScene(const std::vector<scenes::Triangle>& triangles) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice("threads=1,set_affinity=0");
  if (!impl_->device) throw std::runtime_error("embree: rtcNewDevice failed");
  RTCDevice dev = impl_->device;
  impl_->scene = rtcNewScene(dev);
  check(dev, "rtcNewScene");
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  check(dev, "rtcNewGeometry");
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  const size_t n = triangles.size();
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
  check(dev, "rtcSetNewGeometryBuffer");
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3* v[3] = {&triangles[i].v0, &triangles[i].v1, &triangles[i].v2};
    for (size_t k = 0; k < 3; ++k) {
      vertices[9 * i + 3 * k + 0] = v[k]->x;
      vertices[9 * i + 3 * k + 1] = v[k]->y;
      vertices[9 * i + 3 * k + 2] = v[k]->z;
      indices[3 * i + k] = unsigned(3 * i + k);
    }
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(impl_->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(impl_->scene);
  check(dev, "rtcCommitScene");
}

EmbreeScene::~EmbreeScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

OracleHit EmbreeScene::intersect(const float origin[3], const float dir[3], float tnear, float tfar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin[0];
  rh.ray.org_y = origin[1];
  rh.ray.org_z = origin[2];
  rh.ray.dir_x = dir[0];
  rh.ray.dir_y = dir[1];
  rh.ray.dir_z = dir[2];
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = std::numeric_limits<unsigned>::max();
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  OracleHit out;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
  out.hit = true;
  out.t = rh.ray.tfar;
  out.u = rh.hit.u;
  out.v = rh.hit.v;
  out.primitive = rh.hit.primID;
  return out;
}

std::string EmbreeScene::version() {
  return std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) + "." +
         std::to_string(RTC_VERSION_PATCH);
}

}  // namespace strata::oracle
