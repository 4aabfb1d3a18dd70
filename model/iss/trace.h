// Per-instruction trace lines: hart, pc, encoding, disassembly and the registers written.
#pragma once

#include "model/iss/decoder.h"

#include <cstdint>
#include <cstdio>

namespace strata::iss {

void trace_retired(std::FILE* out, uint32_t hart, uint32_t pc, uint32_t word, const Decoded& d,
                   const uint32_t* x, const uint32_t* f);
void trace_trap(std::FILE* out, uint32_t hart, uint32_t pc, uint32_t cause, uint32_t tval, bool handled);

}  // namespace strata::iss
