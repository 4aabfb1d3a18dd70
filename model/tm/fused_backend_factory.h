// How the program running the chip supplies the fused-pipeline backend of a TM whose config
// says tm.pipeline_impl=rtl (model/iss/fused_pipeline_backend.h): a factory in the frame's
// inputs, called once per such TM while the chip is elaborated. The model never names the
// implementation (sim/ fills the factory with the verilated RTL when it was built with it).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "model/iss/fused_pipeline_backend.h"

namespace strata::tm {

struct FusedBackendSetup {
  uint32_t tm = 0;
  // The chip cycle of the fused test being executed: the issuing TP's next issue cycle (for
  // a backend's own traces; the op's timing is the XU crossbar's). Valid during a test only.
  std::function<uint64_t()> cycle;
};

using FusedBackendFactory = std::function<std::unique_ptr<iss::FusedPipelineBackend>(const FusedBackendSetup&)>;

}  // namespace strata::tm
