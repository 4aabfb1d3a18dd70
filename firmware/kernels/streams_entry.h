// The RISC-V entry shared by the four streaming kernels (streams or streams + pipelines, with
// the compact or the record-per-path state): the boot block the platform fills in, and main's
// body. Each *_main.cpp names its two policies and nothing else.
#pragma once

#include "firmware/kernels/riscv_machine.h"
#include "firmware/kernels/streams_compact_paths.h"
#include "firmware/kernels/streams_record_paths.h"

namespace strata::kernels {

// Runs PathsOf's kernel with Pipeline's tests on this thread, from the boot block.
template <template <class> class PathsOf, class Pipeline>
inline int streams_entry(const BootBlock& boot) {
  RiscvMachine machine;
  Pipeline pipeline;
  const KernelContext ctx = kernel_context(boot, strata_thread_id());
  if constexpr (sizeof(typename PathsOf<RiscvMachine>::Ray) == sizeof(CompactRay))
    run_streams_kernel<PathsOf>(machine, pipeline, ctx, SampleSlots{reinterpret_cast<Pixel*>(boot.sample_slots)});
  else
    run_streams_kernel<PathsOf>(machine, pipeline, ctx,
                                PathTable{reinterpret_cast<PathRecord*>(boot.path_table), boot.path_slots});
  return 0;
}

}  // namespace strata::kernels
