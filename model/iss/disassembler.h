// A small disassembler for traces and error messages (ABI register names).
#pragma once

#include "model/iss/decoder.h"

#include <cstdint>
#include <string>

namespace strata::iss {

const char* int_reg_name(unsigned index);
const char* fp_reg_name(unsigned index);

std::string disassemble(uint32_t word, uint32_t pc);
std::string disassemble(const Decoded& d, uint32_t word, uint32_t pc);

}  // namespace strata::iss
