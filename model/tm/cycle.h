// The TM timing core counts whole clock cycles. Same type as strata::transport::Cycle
// (tlm/clock.h, checked in xu_crossbar.cpp) without pulling SystemC into every header.
#pragma once

#include <cstdint>

namespace strata::tm {

using Cycle = uint64_t;

}  // namespace strata::tm
