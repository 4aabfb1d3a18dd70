// What the fused pipelines compute, from the ISA's input registers. The arithmetic itself is
// firmware/common/intersect.h, the one definition of the box and triangle tests shared with
// the firmware and the native twin, so a pipelined run makes bit-identical decisions.
#pragma once

#include "firmware/common/intersect.h"
#include "firmware/abi/strata_isa.h"

namespace strata::iss {

struct BoxTestResult {
  bool hit;
  float t_entry;  // +inf on a miss
};

// strata.boxtest: intersect_box with the ray's origin, inverse direction, tmin and tmax.
BoxTestResult box_test(const strata_pipe_ray& ray, const strata_pipe_box& box);

struct TriangleTestResult {
  bool hit;
  TrianglePartial partial;  // what strata.tridiv divides; kept from the last hit
};

// strata.tritest: triangle_hit_test with the ray's origin and direction. It decides the hit
// without a division and does not look at tmin/tmax: firmware compares the t it gets from
// strata.tridiv, as traverse.h does.
TriangleTestResult triangle_test(const strata_pipe_ray& ray, const strata_pipe_triangle& tri,
                                 const TrianglePartial& previous);

// strata.tridiv: triangle_finish (t, and the barycentric weights of v1 and v2).
TriangleHit triangle_divide(const TrianglePartial& partial);

}  // namespace strata::iss
