// What computes a chip run's fused tests when tm.pipeline_impl=rtl: the factory strata-sim puts
// in the frame's inputs (chip::FrameInputs::pipeline_backend), making one verilated-RTL backend
// per TM that uses it (rtl/cosim/rtl_fused_backend.h). Its only place in sim/, so the model
// never depends on the RTL.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "model/chip/chip_config.h"
#include "model/tm/fused_backend_factory.h"
#include "sim/output_file.h"

namespace strata::sim {

// The RTL VCDs of one run, as every output is written (sim/output_file.h): each TM's goes to a
// temporary beside its final name, and commit(), after the simulation, closes each and renames
// it only if all its writes succeeded. Uncommitted temporaries are removed with this object, so
// it must outlive the chip whose backends write them.
class RtlVcdSet {
 public:
  // A file being written to file->temporary(); `close` closes it and returns the errno of its
  // first failed write (0: none).
  void add(std::unique_ptr<PendingFile> file, std::function<int()> close);
  // Throws "<file>: cannot write RTL VCD: <reason>" for the first file that failed.
  void commit();
  bool empty() const { return files_.empty(); }

 private:
  struct Entry {
    std::unique_ptr<PendingFile> file;
    std::function<int()> close;
  };
  std::vector<Entry> files_;
};

// The RTL's own VCD, beside the chip's (--vcd): one file per TM, `<vcd_base>.rtl_tm<k>.vcd`,
// recording the fused tests issued in chip cycles [start, end].
struct RtlVcdOptions {
  std::string base;  // empty: no VCD
  uint64_t start = 0, end = ~uint64_t{0};
  std::shared_ptr<RtlVcdSet> files;  // where the files are registered; needed with a base
};

// The VCD file of TM `tm`'s RTL pipelines.
std::string rtl_vcd_path(const std::string& base, uint32_t tm);

// Throws chip::ConfigError naming tm.pipeline_impl when this strata-sim was built without the
// RTL (-DSTRATA_RTL=OFF).
tm::FusedBackendFactory rtl_pipeline_backend(const chip::ChipConfig& config, const RtlVcdOptions& vcd);

}  // namespace strata::sim
