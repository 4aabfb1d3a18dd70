// The shared memory levels as the chip sees them: what it wires, clocks, traces and reports on,
// and nothing of how a level works inside. A new model of a level (another DRAM, an L2 with
// another policy) implements one of these interfaces, registers the statistics of its level's
// contract, and gets a case in the factory (memory_level_factory.h) under its config's name;
// the chip, the report and the tests do not change. The pattern is iss::FusedPipelineBackend's.
//
// The contracts list what the chip reads by path from each level's statistics group (the
// summary, energy totals, fidelity sentinels, sampling targets); the factory checks them when
// it makes a level (stats/stat_contract.h).
#pragma once

#include <cstdint>
#include <vector>

#include <systemc>
#include <tlm>

#include "model/memory/stream_occupancy.h"
#include "model/memory/stream_sram.h"
#include "model/memory/window_trace.h"
#include "model/stats/stat_contract.h"
#include "model/stats/stat_group.h"
#include "tlm/clock.h"

namespace strata::memory {

class MemoryLevel {
 public:
  virtual ~MemoryLevel() = default;
  // Where requests from above arrive (TLM-2.0 blocking transport, the payload extension of
  // tlm/memory_extension.h).
  virtual tlm::tlm_target_socket<>& target_socket() = 0;
  // The chip's clock, before sc_start: every level counts in the TMs' cycles.
  virtual void set_clock(const transport::Clock& clock) = 0;
  virtual void trace(sc_core::sc_trace_file* file, const TraceWindow& window) = 0;
  virtual const stats::Group& stats() const = 0;
};

// Off-chip memory behind the L2 (memory.dram.model).
class DramLevel : public MemoryLevel {
 public:
  static const std::vector<stats::Requirement>& contract();
};

// The L2 shared by the TMs; misses and write-backs go to the DRAM level below.
class L2Level : public MemoryLevel {
 public:
  virtual tlm::tlm_initiator_socket<>& downstream_socket() = 0;
  static const std::vector<stats::Requirement>& contract();
};

// The ray stream memory: treelet buffers of rays, and the treelet assignment.
class StreamLevel : public MemoryLevel {
 public:
  virtual uint32_t capacity() const = 0;  // rays it can hold
  virtual uint32_t stored() const = 0;    // rays it holds now
  // Rays in flight over the frame, and the layout of its SRAM (for the treelet statistics).
  virtual const StreamOccupancy& occupancy() const = 0;
  virtual const StreamLayout& layout() const = 0;
  static const std::vector<stats::Requirement>& contract();
};

}  // namespace strata::memory
