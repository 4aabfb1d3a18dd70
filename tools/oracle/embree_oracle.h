// An independent closest-hit oracle for tests and tools: Intel Embree 3 in robust mode
// (RTC_SCENE_FLAG_ROBUST: watertight triangle test, conservative traversal). Never used by
// the model or the firmware; test/numerics compares trace_closest against it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace strata::oracle {

struct OracleHit {
  bool hit = false;
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // Embree's barycentrics: weights of v1 and v2
  uint32_t primitive = 0;    // index into the triangle list given to the constructor
};

// One Embree device (single worker thread) and one static scene of the given triangles,
// with primitive id = index in `triangles`. Throws std::runtime_error on an Embree error.
class EmbreeScene {
 public:
  explicit EmbreeScene(const std::vector<scenes::Triangle>& triangles);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // rtcIntersect1 on the ray origin + t * dir, t in [tnear, tfar].
  OracleHit intersect(const float origin[3], const float dir[3], float tnear, float tfar) const;

  static std::string version();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata::oracle
