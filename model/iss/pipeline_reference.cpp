#include "model/iss/pipeline_reference.h"

#include <limits>

namespace strata::iss {

BoxTestResult box_test(const strata_pipe_ray& ray, const strata_pipe_box& box) {
  const BoxRay box_ray = {load_vec3(ray.origin), load_vec3(ray.inv_direction), ray.tmin, ray.tmax};
  float t_entry = 0.0f;
  const bool hit = intersect_box(box.min, box.max, box_ray, &t_entry);
  return {hit, hit ? t_entry : std::numeric_limits<float>::infinity()};
}

TriangleTestResult triangle_test(const strata_pipe_ray& ray, const strata_pipe_triangle& tri,
                                 const TrianglePartial& previous) {
  TriangleTestResult r{false, previous};
  r.hit = triangle_hit_test(load_vec3(tri.v0), load_vec3(tri.v1), load_vec3(tri.v2), load_vec3(ray.origin),
                            load_vec3(ray.direction), &r.partial);
  return r;
}

TriangleHit triangle_divide(const TrianglePartial& partial) { return triangle_finish(partial); }

}  // namespace strata::iss
