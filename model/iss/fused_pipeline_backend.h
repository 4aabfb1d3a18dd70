// Where the fused box and triangle tests are computed when not by the C++ reference
// (pipeline_reference.h). An embedder sets one on a FunctionalStrataHook, which then sends
// every strata.boxtest and strata.tritest to it (one virtual call per fused test, nothing per
// ordinary instruction); strata.tridiv stays the reference's triangle_divide, as the divide is a
// separate operation in the model too. The chip uses it to run the verilated RTL pipelines
// inside a frame (tm.pipeline_impl=rtl, docs/rtl-cosim.md); the model itself never sees what
// is behind the interface (model/ includes nothing from rtl/ or sim/).
//
// A backend must answer exactly as the reference does (same hit decisions, same bits), and
// without advancing simulated time: the chip times the op on its XU crossbar from the TM
// config, the backend supplies only the values.
#pragma once

#include <cstdint>

#include "model/iss/pipeline_reference.h"

namespace strata::iss {

// What a backend counts, for the statistics (every number is a count of operations or of the
// backend's own clock cycles).
struct FusedBackendCounts {
  uint64_t box_tests = 0, triangle_tests = 0;
  // Operations whose latency, as the backend observed it, differs from what the TM config
  // charges (tm.pipelines.box.latency, tm.pipelines.triangle.latency), the documented slow
  // path below excepted.
  uint64_t box_latency_mismatches = 0, triangle_latency_mismatches = 0;
  // Triangle tests that took the exact-fallback path, documented as its latency plus 2 cycles
  // (docs/rtl-cosim.md, "Slow path"): the model charges them the ordinary latency.
  uint64_t triangle_slow_path_tests = 0;
  // Cycles of the backend's own clock spent on the operations (reset excluded).
  uint64_t box_cycles = 0, triangle_cycles = 0;
};

class FusedPipelineBackend {
 public:
  virtual ~FusedPipelineBackend() = default;
  // As iss::box_test and iss::triangle_test (same arguments, same results).
  virtual BoxTestResult box_test(const strata_pipe_ray& ray, const strata_pipe_box& box) = 0;
  virtual TriangleTestResult triangle_test(const strata_pipe_ray& ray, const strata_pipe_triangle& tri,
                                           const TrianglePartial& previous) = 0;
  virtual FusedBackendCounts counts() const = 0;
};

}  // namespace strata::iss
