// The fused pipelines as the streaming kernels' Pipeline policy (streams + pipelines design).
// A TP configures its TM for the kind of treelet it works on (box on node treelets, triangle
// on triangle treelets); shading runs on the XUs left general. RISC-V only: the intrinsics
// are the custom instructions.
#pragma once

#include "firmware/abi/strata_isa.h"
#include "firmware/common/traverse.h"

namespace strata::kernels {

// The fused pipelines as traverse.h's Tests policy. The pipelines compute intersect.h's
// functions, so the decisions are those of SoftwareTests, bit for bit.
struct FusedTests {
  void begin(const TraceRay& ray, float tmax) {
    const Vec3f inv = inverse_direction(ray.dir);
    const strata_pipe_ray r = {{ray.origin.x, ray.origin.y, ray.origin.z}, ray.tmin,
                               {ray.dir.x, ray.dir.y, ray.dir.z}, tmax,
                               {inv.x, inv.y, inv.z}, 0.0f};
    strata_load_ray(&r);
  }
  void set_tmax(float tmax) { strata_set_tmax(tmax); }
  bool box(const BvhNode& n, int side, float* t_entry) const {
    if (child_is_leaf(n.child[side]) && leaf_count(n.child[side]) == 0) return false;
    strata_load_box(reinterpret_cast<const strata_pipe_box*>(n.child_box[side]));
    return strata_box_test(t_entry) != 0;
  }
  bool triangle(const TriangleRecord& tri, const TraceRay&, TriangleHit* hit) const {
    strata_load_triangle(reinterpret_cast<const strata_pipe_triangle*>(tri.v0));
    if (!strata_triangle_test()) return false;
    strata_triangle_divide(&hit->t, &hit->b1, &hit->b2);
    return true;
  }
};

struct FusedPipelines {
  int mode = -1;  // 0 box, 1 triangle
  void enter_treelet(bool triangles) {
    const int wanted = triangles ? 1 : 0;
    if (wanted == mode) return;
    if (triangles) strata_pipe_triangle_mode(); else strata_pipe_box_mode();
    mode = wanted;
  }
  FusedTests tests() const { return FusedTests(); }
};


}  // namespace strata::kernels
