#include "sim/pipeline_backend.h"

#include <algorithm>
#include <cmath>
#include <memory>

#if STRATA_HAVE_RTL
#include "rtl/cosim/rtl_fused_backend.h"
#endif

namespace strata::sim {

std::string rtl_vcd_path(const std::string& base, uint32_t tm) {
  return base + ".rtl_tm" + std::to_string(tm) + ".vcd";
}

void RtlVcdSet::add(std::unique_ptr<PendingFile> file, std::function<int()> close) {
  files_.push_back({std::move(file), std::move(close)});
}

void RtlVcdSet::commit() {
  // Every file is closed before the first error is thrown: none is left open or half-flushed.
  std::vector<int> errors;
  for (Entry& e : files_) errors.push_back(e.close());
  for (size_t i = 0; i < files_.size(); ++i) files_[i].file->commit(errors[i]);
}

#if STRATA_HAVE_RTL

tm::FusedBackendFactory rtl_pipeline_backend(const chip::ChipConfig& config, const RtlVcdOptions& vcd) {
  rtl::RtlBackendConfig base;
  base.box_latency = config.tm.pipelines.box.latency;
  base.triangle_latency = config.tm.pipelines.triangle.latency;
  base.vcd_start = vcd.start;
  base.vcd_end = vcd.end;
  // The chip's VCD counts in ns; a chip cycle lasts 1 / clock_ghz of them.
  base.ps_per_cycle = std::max<uint64_t>(1, static_cast<uint64_t>(std::llround(1000.0 / config.clock_ghz)));
  const std::string vcd_base = vcd.base;
  const std::shared_ptr<RtlVcdSet> files = vcd.files;
  return [base, vcd_base, files](const tm::FusedBackendSetup& setup) -> std::unique_ptr<iss::FusedPipelineBackend> {
    rtl::RtlBackendConfig c = base;
    c.cycle = setup.cycle;
    if (vcd_base.empty()) return std::make_unique<rtl::RtlFusedBackend>("rtl_pipelines", std::move(c));
    // The backend writes the temporary; the set makes it final after the run. The backend
    // lives as long as the chip, which the caller keeps until the set is committed.
    auto file = std::make_unique<PendingFile>(rtl_vcd_path(vcd_base, setup.tm), "RTL VCD");
    c.vcd_path = file->temporary().string();
    auto backend = std::make_unique<rtl::RtlFusedBackend>("rtl_pipelines", std::move(c));
    rtl::RtlFusedBackend* writer = backend.get();
    files->add(std::move(file), [writer] { return writer->close_vcd(); });
    return backend;
  };
}

#else

tm::FusedBackendFactory rtl_pipeline_backend(const chip::ChipConfig&, const RtlVcdOptions&) {
  throw chip::ConfigError(
      "tm.pipeline_impl: rtl is not available: this strata-sim was built with -DSTRATA_RTL=OFF (no verilated "
      "pipelines); rebuild with -DSTRATA_RTL=ON (needs Verilator, scripts/install-deps) or use "
      "tm.pipeline_impl=model");
}

#endif

}  // namespace strata::sim
