// Parsing of "WxH" resolution arguments.
#pragma once

#include <cstdint>
#include <string>

namespace strata::sim {

// Throws std::invalid_argument naming the value when it is not WxH with positive integers.
void parse_resolution(const std::string& text, uint32_t* width, uint32_t* height);

}  // namespace strata::sim
