#include "model/memory/energy_table.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace strata::memory {

namespace {
struct Point {
  uint64_t bytes;
  double nj;
};
constexpr uint64_t kKiB = 1024;
constexpr Point kTable[] = {{512 * kKiB, 0.524}, {1024 * kKiB, 0.579}, {2048 * kKiB, 0.686},
                            {4096 * kKiB, 0.901}, {8192 * kKiB, 1.17},  {16384 * kKiB, 1.61}};
}  // namespace

double sram_access_energy_nj(uint64_t bytes) {
  constexpr std::size_t n = sizeof kTable / sizeof kTable[0];
  if (bytes < kTable[0].bytes || bytes > kTable[n - 1].bytes)
    throw std::invalid_argument("no CACTI energy for an SRAM of " + std::to_string(bytes) +
                                " bytes (table covers 512 KB..16 MB); give access_energy_nj");
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Point& a = kTable[i];
    const Point& b = kTable[i + 1];
    if (bytes == a.bytes) return a.nj;
    if (bytes < b.bytes) {
      const double f = std::log(static_cast<double>(bytes) / static_cast<double>(a.bytes)) /
                       std::log(static_cast<double>(b.bytes) / static_cast<double>(a.bytes));
      return std::exp(std::log(a.nj) + f * (std::log(b.nj) - std::log(a.nj)));
    }
  }
  return kTable[n - 1].nj;
}

}  // namespace strata::memory
