#include "rtl/cosim/fp_units.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <sstream>

#include "Vfp32_add.h"
#include "Vfp32_cmp.h"
#include "Vfp32_minmax.h"
#include "Vfp32_mul.h"
#include "firmware/common/intersect.h"
#include "firmware/common/float_bits.h"
#include "verilated.h"

namespace strata::rtl {
namespace {

bool is_nan_bits(uint32_t u) { return (u & 0x7F800000u) == 0x7F800000u && (u & 0x007FFFFFu) != 0; }

std::string hex(uint32_t u) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", u);
  return buf;
}

constexpr size_t kKeptMismatches = 10;

void record(FpCompareResult& r, const OperandPair& p, const std::string& what) {
  ++r.mismatches;
  if (r.first.size() < kKeptMismatches) r.first.push_back({p.first, p.second, what});
}

// Clock a model with pipeline depth `stages`: the pair presented before posedge k is on the
// outputs after posedge k + stages - 1. check(index, model) compares one result.
template <class Model, class Drive, class Check>
void run_pipelined(Model& m, size_t n, unsigned stages, Drive drive, Check check) {
  m.en = 1;
  m.clk = 0;
  m.eval();
  for (size_t cycle = 0; cycle < n + stages - 1; ++cycle) {
    if (cycle < n) drive(cycle);
    m.clk = 1;
    m.eval();
    if (cycle + 1 >= stages) check(cycle + 1 - stages);
    m.clk = 0;
    m.eval();
  }
}

}  // namespace

bool fp_results_agree(uint32_t rtl, uint32_t host) { return is_nan_bits(host) ? is_nan_bits(rtl) : rtl == host; }

const char* fp_op_name(FpOp op) {
  switch (op) {
    case FpOp::kMul: return "mul";
    case FpOp::kAdd: return "add";
    case FpOp::kSub: return "sub";
    case FpOp::kCmp: return "cmp";
    case FpOp::kMinMax: return "minmax";
  }
  return "?";
}

std::vector<FpOp> all_fp_ops() { return {FpOp::kMul, FpOp::kAdd, FpOp::kSub, FpOp::kCmp, FpOp::kMinMax}; }

FpCompareResult compare_fp_unit(FpOp op, const std::vector<OperandPair>& pairs) {
  FpCompareResult r;
  auto context = std::make_unique<VerilatedContext>();
  const size_t n = pairs.size();
  switch (op) {
    case FpOp::kMul: {
      Vfp32_mul m{context.get()};
      run_pipelined(
          m, n, 2, [&](size_t i) { m.a = pairs[i].first; m.b = pairs[i].second; },
          [&](size_t i) {
            const uint32_t host = float_bits(bits_float(pairs[i].first) * bits_float(pairs[i].second));
            if (!fp_results_agree(m.y, host)) record(r, pairs[i], "rtl " + hex(m.y) + " host " + hex(host));
          });
      m.final();
      break;
    }
    case FpOp::kAdd:
    case FpOp::kSub: {
      const bool sub = op == FpOp::kSub;
      Vfp32_add m{context.get()};
      m.sub = sub;
      run_pipelined(
          m, n, 2, [&](size_t i) { m.a = pairs[i].first; m.b = pairs[i].second; },
          [&](size_t i) {
            const float a = bits_float(pairs[i].first), b = bits_float(pairs[i].second);
            const uint32_t host = float_bits(sub ? a - b : a + b);
            if (!fp_results_agree(m.y, host)) record(r, pairs[i], "rtl " + hex(m.y) + " host " + hex(host));
          });
      m.final();
      break;
    }
    case FpOp::kCmp: {
      Vfp32_cmp m{context.get()};
      run_pipelined(
          m, n, 1, [&](size_t i) { m.a = pairs[i].first; m.b = pairs[i].second; },
          [&](size_t i) {
            const float a = bits_float(pairs[i].first), b = bits_float(pairs[i].second);
            const bool lt = a < b, le = a <= b, eq = a == b;
            if (bool(m.lt) != lt || bool(m.le) != le || bool(m.eq) != eq)
              record(r, pairs[i],
                     "rtl lt/le/eq " + std::to_string(m.lt) + std::to_string(m.le) + std::to_string(m.eq) +
                         " host " + std::to_string(lt) + std::to_string(le) + std::to_string(eq));
          });
      m.final();
      break;
    }
    case FpOp::kMinMax: {
      // Each pair twice: max in one cycle, min in the next. Results are operands, so they are
      // compared bit for bit, NaN payloads included.
      Vfp32_minmax m{context.get()};
      run_pipelined(
          m, 2 * n, 1,
          [&](size_t i) {
            m.m = pairs[i / 2].first;
            m.x = pairs[i / 2].second;
            m.max = (i % 2) == 0;
          },
          [&](size_t i) {
            const float a = bits_float(pairs[i / 2].first), b = bits_float(pairs[i / 2].second);
            const bool is_max = (i % 2) == 0;
            const uint32_t host = float_bits(is_max ? max_ignore_nan(a, b) : min_ignore_nan(a, b));
            if (m.y != host) record(r, pairs[i / 2], std::string(is_max ? "max" : "min") + " rtl " + hex(m.y) + " host " + hex(host));
          });
      m.final();
      break;
    }
  }
  r.vectors = n;
  return r;
}

namespace {

uint32_t make_float(uint32_t sign, uint32_t exponent, uint32_t mantissa) {
  return (sign << 31) | ((exponent & 0xFFu) << 23) | (mantissa & 0x7FFFFFu);
}

const std::vector<uint32_t>& special_values() {
  static const std::vector<uint32_t> v = [] {
    const uint32_t magnitudes[] = {
        0x00000000u,  // zero
        0x00000001u,  // smallest subnormal
        0x00000002u, 0x00000003u,
        0x00400000u,  // subnormal 2^-127
        0x007FFFFFu,  // largest subnormal
        0x00800000u,  // smallest normal
        0x00800001u, 0x00FFFFFFu,
        0x01000000u,
        0x0C000000u,  // 2^-103
        0x1F800000u,  // 2^-64
        0x33000000u, 0x33800000u, 0x34000000u,  // 2^-25, 2^-24, 2^-23
        0x3EAAAAABu,  // 1/3
        0x3F000000u,  // 0.5
        0x3F7FFFFFu, 0x3F800000u, 0x3F800001u,  // 1 and its neighbours
        0x3FC00000u, 0x3FFFFFFFu, 0x40000000u,
        0x4B000000u, 0x4B800000u,  // 2^23, 2^24
        0x5F800000u,  // 2^64
        0x7E800000u, 0x7F000000u,  // 2^126, 2^127
        0x7F7FFFFEu, 0x7F7FFFFFu,  // largest finite
        0x7F800000u,  // inf
        0x7FC00000u, 0x7FFFFFFFu,  // quiet NaNs
        0x7F800001u, 0x7FBFFFFFu,  // signalling NaNs
    };
    std::vector<uint32_t> out;
    for (uint32_t m : magnitudes) {
      out.push_back(m);
      out.push_back(m | 0x80000000u);
    }
    return out;
  }();
  return v;
}

}  // namespace

std::vector<OperandPair> random_operands(FpOp op, uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(op) + 1);
  auto bits = [&](unsigned n) { return static_cast<uint32_t>(rng() & ((n >= 32) ? 0xFFFFFFFFull : ((1ull << n) - 1))); };
  auto uniform = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1)); };
  auto clamp_exp = [](int e) { return static_cast<uint32_t>(e < 0 ? 0 : (e > 255 ? 255 : e)); };
  const std::vector<uint32_t>& specials = special_values();
  std::vector<OperandPair> out;
  out.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    uint32_t a = 0, b = 0;
    switch (rng() % 8) {
      case 0:  // uniform bit patterns
        a = bits(32);
        b = bits(32);
        break;
      case 1: {  // nearby exponents: alignment, cancellation (add), ordinary products
        const int ea = uniform(1, 254);
        a = make_float(bits(1), static_cast<uint32_t>(ea), bits(23));
        b = make_float(bits(1), clamp_exp(ea + uniform(-30, 30)), bits(23));
        break;
      }
      case 2: {  // short significands: exact results and exact ties
        const int ea = uniform(1, 254);
        a = make_float(bits(1), static_cast<uint32_t>(ea), bits(23) & ~((1u << uniform(0, 22)) - 1));
        const int eb = op == FpOp::kMul ? uniform(1, 254) : ea + uniform(-26, 26);
        b = make_float(bits(1), clamp_exp(eb), bits(23) & ~((1u << uniform(0, 22)) - 1));
        break;
      }
      case 3: {  // exponent sums at the thresholds (products) / huge and tiny sums (add)
        const int ea = uniform(1, 254);
        int eb;
        if (op == FpOp::kMul)
          eb = (rng() % 2) ? (127 - 126 - ea) + uniform(-26, 3) + 127 : (254 - ea + 127) + uniform(-2, 2);
        else
          eb = (rng() % 2) ? uniform(250, 254) : uniform(0, 3);
        if (op != FpOp::kMul && eb >= 250) a = make_float(bits(1), static_cast<uint32_t>(uniform(250, 254)), bits(23));
        else a = make_float(bits(1), static_cast<uint32_t>(ea), bits(23));
        b = make_float(bits(1), clamp_exp(eb), bits(23));
        break;
      }
      case 4:  // subnormals against anything small or ordinary
        a = make_float(bits(1), 0, bits(23));
        b = (rng() % 2) ? make_float(bits(1), 0, bits(23)) : make_float(bits(1), static_cast<uint32_t>(uniform(1, 200)), bits(23));
        if (rng() % 2) std::swap(a, b);
        break;
      case 5: {  // equal or neighbouring values, either sign
        a = make_float(bits(1), static_cast<uint32_t>(uniform(0, 254)), bits(23));
        const int delta = uniform(-3, 3);
        b = (a & 0x80000000u) | ((a & 0x7FFFFFFFu) + static_cast<uint32_t>(delta));
        if ((b & 0x7F800000u) == 0x7F800000u) b = a;
        if (rng() % 2) b ^= 0x80000000u;
        break;
      }
      case 6:  // one special value against a random one
        a = specials[rng() % specials.size()];
        b = (rng() % 2) ? bits(32) : make_float(bits(1), static_cast<uint32_t>(uniform(100, 154)), bits(23));
        if (rng() % 2) std::swap(a, b);
        break;
      default: {  // ordinary magnitudes
        a = make_float(bits(1), static_cast<uint32_t>(uniform(100, 154)), bits(23));
        b = make_float(bits(1), static_cast<uint32_t>(uniform(100, 154)), bits(23));
        break;
      }
    }
    out.push_back({a, b});
  }
  return out;
}

std::vector<OperandPair> edge_operands(FpOp op) {
  std::vector<OperandPair> out;
  const std::vector<uint32_t>& specials = special_values();
  for (uint32_t a : specials)
    for (uint32_t b : specials) out.push_back({a, b});
  std::mt19937_64 rng(0xED6Eull + static_cast<uint64_t>(op));
  auto bits = [&](unsigned n) { return static_cast<uint32_t>(rng() & ((1ull << n) - 1)); };
  for (int k = 0; k < 4000; ++k) {
    const uint32_t s = bits(1), t = bits(1);
    const uint32_t ea = 1 + static_cast<uint32_t>(rng() % 254);
    // Rounding ties. Products: a 12-bit and a 13-bit significand give at most 25 bits, so the
    // product is exact or an exact tie. Sums: b = half an ulp of a (or 1.5, 2.5 ... ulps).
    out.push_back({make_float(s, ea, bits(11) << 12), make_float(t, 1 + static_cast<uint32_t>(rng() % 254), bits(12) << 11)});
    if (ea > 24) out.push_back({make_float(s, ea, bits(23)), make_float(t, ea - 24, (k % 2) ? 0 : bits(23) & ~0xFFFFu)});
    // Products rounding at the subnormal boundary and into subnormals (exact ties there too).
    const int eb_under = 127 - static_cast<int>(ea) - 126 + 127 - static_cast<int>(rng() % 26);
    if (eb_under >= 1 && eb_under <= 254)
      out.push_back({make_float(s, ea, bits(11) << 12), make_float(t, static_cast<uint32_t>(eb_under), bits(12) << 11)});
    // Overflow: exponent sums just above the largest finite; sums of two huge values.
    const int eb_over = 254 - static_cast<int>(ea) + 127 + static_cast<int>(rng() % 3) - 1;
    if (eb_over >= 1 && eb_over <= 254) out.push_back({make_float(s, ea, bits(23)), make_float(t, static_cast<uint32_t>(eb_over), bits(23))});
    out.push_back({make_float(s, 254, bits(23)), make_float(s, 254 - static_cast<uint32_t>(rng() % 2), bits(23))});
    out.push_back({make_float(s, 254, 0x7FFFFFu), make_float(s, 230 + static_cast<uint32_t>(rng() % 4), bits(23))});
    // Cancellation: a - a', a' within a few ulps or one exponent apart, and the exact zero.
    const uint32_t a = make_float(s, ea, bits(23));
    out.push_back({a, a ^ 0x80000000u});
    out.push_back({a, (a + static_cast<uint32_t>(rng() % 8)) ^ ((op == FpOp::kSub) ? 0u : 0x80000000u)});
    if (ea > 1) out.push_back({a, make_float(s ^ (op == FpOp::kSub ? 0u : 1u), ea - 1, bits(23))});
    // Subnormal results of sums and subnormal operands.
    out.push_back({make_float(s, 0, bits(23)), make_float(t, 0, bits(23))});
    out.push_back({make_float(s, 1, bits(23)), make_float(s ^ (op == FpOp::kSub ? 0u : 1u), 1, bits(23))});
    out.push_back({make_float(s, 0, bits(23)), make_float(t, 1 + static_cast<uint32_t>(rng() % 60), bits(23))});
  }
  return out;
}

std::string describe(const FpCompareResult& r, FpOp op) {
  std::ostringstream s;
  s << fp_op_name(op) << ": " << r.vectors << " vectors, " << r.mismatches << " mismatches";
  for (const FpMismatch& m : r.first) s << "\n  a=" << hex(m.a) << " b=" << hex(m.b) << ": " << m.what;
  return s.str();
}

}  // namespace strata::rtl
