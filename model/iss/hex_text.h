// A guest address or size as error text: "0x" and at least 8 hex digits. One definition for the
// messages of the ISS's memory and program loader and the chip's guest layout.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace strata::iss {

inline std::string hex_text(uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%08llx", static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace strata::iss
