// A functional implementation of the STRaTA extension for a standalone hart: fixed ids,
// an array of global registers, the reference pipelines, and a stream memory of LIFO
// per-treelet buffers with a ray capacity. No timing, one TM. The buffers hold rays of either
// entry width (48 B, or 64 B with push64/pop64): a pop must name the width of the ray it takes.
#pragma once

#include "model/iss/fused_pipeline_backend.h"
#include "model/iss/pipeline_reference.h"
#include "model/iss/strata_hook.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace strata::iss {

class FunctionalStrataHook : public StrataHook {
 public:
  struct Config {
    uint32_t tp_id = 0;
    uint32_t tm_id = 0;
    uint32_t tps_per_tm = 1;
    uint32_t tm_count = 1;
    uint32_t stream_capacity = 4096;  // rays
  };

  FunctionalStrataHook() : FunctionalStrataHook(Config{}) {}
  explicit FunctionalStrataHook(const Config& config);

  HookResult execute(const HookCall& call) override;

  uint32_t global(unsigned index) const { return globals_.at(index); }
  void set_global(unsigned index, uint32_t value) { globals_.at(index) = value; }
  std::size_t rays_queued() const { return rays_queued_; }
  // Where strata.boxtest and strata.tritest are computed: null (the default) is the C++
  // reference (pipeline_reference.h). The backend is not owned and must outlive the hook.
  void set_backend(FusedPipelineBackend* backend) { backend_ = backend; }

 private:
  enum class Mode { kGeneral, kBox, kTriangle };
  struct StreamRay {
    std::array<uint32_t, STRATA_STREAM_RAY64_WORDS> words;
    unsigned bytes;
  };

  HookResult pipeline(const HookCall& call);
  HookResult stream(const HookCall& call);

  Config config_;
  std::array<uint32_t, STRATA_GLOBAL_REGISTERS> globals_{};
  Mode mode_ = Mode::kGeneral;
  strata_pipe_ray ray_{};
  strata_pipe_box box_{};
  strata_pipe_triangle triangle_{};
  TriangleTestResult last_triangle_{};
  FusedPipelineBackend* backend_ = nullptr;
  std::map<uint32_t, std::vector<StreamRay>> buffers_;  // treelet -> LIFO
  std::size_t rays_queued_ = 0;
  uint32_t current_treelet_ = STRATA_NO_TREELET;
};

}  // namespace strata::iss
