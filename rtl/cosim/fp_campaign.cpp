// strata-rtl-fp-campaign [N] [SEED]: N random operand pairs (default 4,000,000) plus every
// edge case through each verilated FP unit, compared bit for bit with the host. Prints the
// vectors compared and the mismatches per unit; exits 1 on any mismatch.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rtl/cosim/fp_units.h"

int main(int argc, char** argv) {
  uint64_t n = 4000000, seed = 1;
  try {
    if (argc > 1) n = std::stoull(argv[1]);
    if (argc > 2) seed = std::stoull(argv[2]);
  } catch (const std::exception&) {
    std::fprintf(stderr, "usage: strata-rtl-fp-campaign [N] [SEED]\n");
    return 2;
  }
  uint64_t total_mismatches = 0;
  std::printf("%-8s %12s %12s %12s\n", "unit", "random", "edge", "mismatches");
  for (strata::rtl::FpOp op : strata::rtl::all_fp_ops()) {
    uint64_t vectors_random = 0, mismatches = 0;
    // In chunks, so memory stays small at any N.
    const uint64_t chunk = 1000000;
    for (uint64_t done = 0, part = 0; done < n; done += chunk, ++part) {
      const uint64_t count = (n - done < chunk) ? n - done : chunk;
      const auto r = strata::rtl::compare_fp_unit(op, strata::rtl::random_operands(op, count, seed * 1000003 + part));
      vectors_random += r.vectors;
      mismatches += r.mismatches;
      if (r.mismatches) std::printf("%s\n", strata::rtl::describe(r, op).c_str());
    }
    const auto e = strata::rtl::compare_fp_unit(op, strata::rtl::edge_operands(op));
    mismatches += e.mismatches;
    if (e.mismatches) std::printf("%s\n", strata::rtl::describe(e, op).c_str());
    std::printf("%-8s %12llu %12llu %12llu\n", strata::rtl::fp_op_name(op),
                static_cast<unsigned long long>(vectors_random), static_cast<unsigned long long>(e.vectors),
                static_cast<unsigned long long>(mismatches));
    std::fflush(stdout);
    total_mismatches += mismatches;
  }
  std::printf("%s\n", total_mismatches ? "FAIL: mismatches" : "OK: every vector bit-identical to the host");
  return total_mismatches ? 1 : 0;
}
