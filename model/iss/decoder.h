// The predecoder: each instruction word becomes a compact Decoded record once, so the
// executor dispatches on an enum with unpacked fields instead of re-parsing bits.
#pragma once

#include "model/iss/ops.h"

#include <cstdint>

namespace strata::iss {

// Register-file access slots: reads and writes per instruction, x0 excluded (it is not
// stored). slot = int_reads + 3 * (int_writes + 2 * (fp_reads + 4 * fp_writes)).
constexpr unsigned kRfSlotCount = 3 * 2 * 4 * 4;

struct RfAccesses {
  unsigned int_reads, int_writes, fp_reads, fp_writes;
};

constexpr RfAccesses rf_slot_accesses(unsigned slot) {
  return {slot % 3, (slot / 3) % 2, (slot / 6) % 4, slot / 24};
}

struct Decoded {
  Op op = Op::kIllegal;
  uint8_t rd = 0, rs1 = 0, rs2 = 0, rs3 = 0;
  uint8_t rm = 0;  // FP rounding-mode field (7 = dynamic); zimm for csr*i lives in rs1
  uint8_t rf = 0;  // register-file access slot
  uint8_t reserved = 0;
  int32_t imm = 0;  // immediate; the CSR number for CSR ops
};
static_assert(sizeof(Decoded) == 12, "Decoded must stay compact: it is read every instruction");

// Never fails: anything unknown or malformed decodes to Op::kIllegal.
Decoded decode(uint32_t word);

}  // namespace strata::iss
