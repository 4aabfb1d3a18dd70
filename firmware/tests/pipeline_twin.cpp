// The fused pipeline instructions against the same tests run in software on the thread
// processor (firmware/common/intersect.h compiled for RISC-V): hits, entry distances, t and
// barycentrics must agree bit for bit on thousands of random rays, boxes and triangles.
#include "strata_runtime.h"

#include "firmware/common/intersect.h"
#include "firmware/abi/strata_isa.h"

namespace {

uint32_t state = 0x12345678u;

float random_float(float lo, float hi) {
  state = state * 1664525u + 1013904223u;
  return lo + (hi - lo) * static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
}

// A ray from a random origin towards `target`, sometimes with one direction component
// zeroed (an infinite inverse) and sometimes with a finite tmax.
strata_pipe_ray ray_towards(const float target[3]) {
  strata_pipe_ray r;
  for (int i = 0; i < 3; ++i) {
    r.origin[i] = random_float(-4.0f, 4.0f);
    r.direction[i] = target[i] - r.origin[i];
  }
  if ((state & 0x700u) == 0) r.direction[state % 3] = 0.0f;
  const strata::Vec3f inv = strata::inverse_direction(strata::load_vec3(r.direction));
  r.inv_direction[0] = inv.x;
  r.inv_direction[1] = inv.y;
  r.inv_direction[2] = inv.z;
  r.tmin = 0.0f;
  r.tmax = (state & 0x800u) ? random_float(0.5f, 1.5f) : __builtin_inff();
  r.pad = 0.0f;
  return r;
}

}  // namespace

int main() {
  int box_hits = 0, triangle_hits = 0;
  for (int i = 0; i < 3000; ++i) {
    // Box and ray: aimed at a point in the box, or a little outside it.
    strata_pipe_box box;
    float target[3];
    for (int k = 0; k < 3; ++k) {
      const float a = random_float(-3.0f, 3.0f), b = random_float(-3.0f, 3.0f);
      box.min[k] = a < b ? a : b;
      box.max[k] = a < b ? b : a;
      target[k] = random_float(box.min[k] - 0.2f, box.max[k] + 0.2f);
    }
    const strata_pipe_ray ray = ray_towards(target);
    const strata::BoxRay box_ray = {strata::load_vec3(ray.origin), strata::load_vec3(ray.inv_direction), ray.tmin,
                                    ray.tmax};
    float t_soft = 0.0f, t_fused = 0.0f;
    const bool hit_soft = strata::intersect_box(box.min, box.max, box_ray, &t_soft);
    strata_pipe_box_mode();
    strata_load_ray(&ray);
    strata_load_box(&box);
    const bool hit_fused = strata_box_test(&t_fused) != 0;
    STRATA_CHECK(hit_soft == hit_fused);
    if (hit_soft) {
      STRATA_CHECK(strata_float_bits(t_soft) == strata_float_bits(t_fused));
      ++box_hits;
    }

    // Triangle and ray: aimed at barycentric weights that are sometimes slightly negative.
    strata_pipe_triangle tri;
    const float w1 = random_float(-0.1f, 0.7f), w2 = random_float(-0.1f, 0.7f);
    for (int k = 0; k < 3; ++k) {
      tri.v0[k] = random_float(-3.0f, 3.0f);
      tri.v1[k] = tri.v0[k] + random_float(-2.0f, 2.0f);
      tri.v2[k] = tri.v0[k] + random_float(-2.0f, 2.0f);
      target[k] = tri.v0[k] + w1 * (tri.v1[k] - tri.v0[k]) + w2 * (tri.v2[k] - tri.v0[k]);
    }
    const strata_pipe_ray tri_ray = ray_towards(target);
    strata::TrianglePartial partial;
    const bool tri_soft =
        strata::triangle_hit_test(strata::load_vec3(tri.v0), strata::load_vec3(tri.v1), strata::load_vec3(tri.v2),
                                  strata::load_vec3(tri_ray.origin), strata::load_vec3(tri_ray.direction), &partial);
    strata_pipe_triangle_mode();
    strata_load_ray(&tri_ray);
    strata_load_triangle(&tri);
    const bool tri_fused = strata_triangle_test() != 0;
    STRATA_CHECK(tri_soft == tri_fused);
    if (tri_soft) {
      const strata::TriangleHit h = strata::triangle_finish(partial);
      float t, u, v;
      strata_triangle_divide(&t, &u, &v);
      STRATA_CHECK(strata_float_bits(h.t) == strata_float_bits(t));
      STRATA_CHECK(strata_float_bits(h.b1) == strata_float_bits(u));
      STRATA_CHECK(strata_float_bits(h.b2) == strata_float_bits(v));
      ++triangle_hits;
    }
  }
  strata_pipe_general();
  STRATA_CHECK(box_hits > 1500);  // most rays are aimed to hit
  STRATA_CHECK(triangle_hits > 1500);
  return 0;
}
