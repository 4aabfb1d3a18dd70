// How each ISS operation is timed on a TP: which resource it goes to and how long its
// result takes. Derived once per TM config from the ISS's op table (model/iss/ops.h), so
// a TP looks up one small record per instruction instead of branching on the op.
#pragma once

#include "model/iss/ops.h"
#include "model/tm/tm_config.h"
#include "model/tm/xu_class.h"

#include <array>
#include <cstdint>

namespace strata::tm {

enum class Route : uint8_t {
  kLocal,             // the TP's own ALU or register moves: fixed latency, no shared unit
  kXu,                // a general shared XU
  kFusedMultiplyAdd,  // an FP multiplier, then an FP adder
  kMemory,            // the caller times it against the memory system (loads, stores,
                      // atomics, global registers, stream memory, pipeline input loads)
  kConfigure,         // strata.pipe.*: reconfigures the crossbar
  kBoxTest,
  kTriangleTest,
  kTriangleDivide,
};

// Pipeline state an op reads or writes besides registers, one bit per group.
enum PipeState : uint8_t {
  kPipeRay = 1,       // ray input registers (strata.ldray, strata.settmax)
  kPipeBox = 2,       // box input registers (strata.ldbox)
  kPipeTriangle = 4,  // triangle input registers (strata.ldtri)
  kPipePartial = 8,   // the triangle test's latched partial result (read by strata.tridiv)
};
constexpr unsigned kPipeStateCount = 4;

struct OpTiming {
  Route route = Route::kLocal;
  XuClass xu = XuClass::kCount;            // kXu only
  PipelineMode mode = PipelineMode::kGeneral;  // kConfigure only
  uint8_t reads_pipe = 0;                  // PipeState bits that must be ready before issue
  uint8_t writes_pipe = 0;                 // PipeState bits set ready with the result
  uint32_t latency = 0;                    // issue to result; 0 for kMemory (the caller says)
  // The op's register operands, by slot (bit i: rd, rs1, rs2, rs3), taken from its roles once
  // here so the TP's scoreboard does not switch on roles per instruction.
  uint8_t int_operands = 0;  // int sources and destinations (waited for; x0 is skipped)
  uint8_t fp_operands = 0;   // FP sources and destinations
  uint8_t int_results = 0;   // int destinations
  uint8_t fp_results = 0;    // FP destinations
};

class OpTimingTable {
 public:
  explicit OpTimingTable(const TmConfig& config);
  const OpTiming& operator[](iss::Op op) const { return table_[static_cast<unsigned>(op)]; }

 private:
  std::array<OpTiming, iss::kOpCount> table_{};
};

}  // namespace strata::tm
