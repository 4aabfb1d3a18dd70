/* Single-precision F extension: exact results, rounding modes, flags, NaN and signed-zero
 * rules. Operations under test go through inline asm so the compiler cannot fold them. */
#include "strata_runtime.h"

#define F(bits) strata_bits_float(bits)
#define B(x) strata_float_bits(x)

#define FOP2(insn, a, b)                                                          \
  __extension__({                                                                 \
    float r_;                                                                     \
    __asm__ volatile(insn " %0, %1, %2" : "=f"(r_) : "f"(a), "f"(b));             \
    r_;                                                                           \
  })
#define FOP2_RM(insn, rm, a, b)                                                   \
  __extension__({                                                                 \
    float r_;                                                                     \
    __asm__ volatile(insn " %0, %1, %2, " rm : "=f"(r_) : "f"(a), "f"(b));        \
    r_;                                                                           \
  })
#define FCVT_W(insn, rm, a)                                                       \
  __extension__({                                                                 \
    uint32_t r_;                                                                  \
    __asm__ volatile(insn " %0, %1, " rm : "=r"(r_) : "f"(a));                    \
    r_;                                                                           \
  })
#define FCMP(insn, a, b)                                                          \
  __extension__({                                                                 \
    uint32_t r_;                                                                  \
    __asm__ volatile(insn " %0, %1, %2" : "=r"(r_) : "f"(a), "f"(b));             \
    r_;                                                                           \
  })
#define FCLASS(a)                                                                 \
  __extension__({                                                                 \
    uint32_t r_;                                                                  \
    __asm__ volatile("fclass.s %0, %1" : "=r"(r_) : "f"(a));                      \
    r_;                                                                           \
  })

#define NV 16u
#define DZ 8u
#define OF 4u
#define UF 2u
#define NX 1u

static uint32_t take_flags(void) {
  const uint32_t f = STRATA_CSR_READ(fflags);
  STRATA_CSR_WRITE(fflags, 0);
  return f;
}

/* Sum of 1/k^2 and a Newton square root; the expected bits come from the same code built
 * natively with -ffp-contract=off (binary32, round to nearest even). */
__attribute__((noinline)) static float series(int n) {
  float s = 0.0f;
  for (int k = 1; k <= n; ++k) {
    const float fk = (float)k;
    s += 1.0f / (fk * fk);
  }
  return s;
}

__attribute__((noinline)) static float newton_sqrt(float x) {
  float g = x;
  for (int i = 0; i < 20; ++i) g = 0.5f * (g + x / g);
  return g;
}

int main(void) {
  volatile float one = 1.0f, two = 2.0f, three = 3.0f, zero = 0.0f;
  take_flags();

  STRATA_CHECK(B(__builtin_sqrtf(two)) == 0x3FB504F3u);
  STRATA_CHECK(take_flags() == NX);
  STRATA_CHECK(B(one / three) == 0x3EAAAAABu);
  STRATA_CHECK(take_flags() == NX);
  STRATA_CHECK(B(__builtin_sqrtf(F(0x40800000u))) == 0x40000000u); /* sqrt(4) = 2, exact */
  STRATA_CHECK(take_flags() == 0);

  /* Flags. */
  STRATA_CHECK(B(one / zero) == 0x7F800000u);
  STRATA_CHECK(take_flags() == DZ);
  STRATA_CHECK(B(__builtin_sqrtf(-one)) == 0x7FC00000u);
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(B(FOP2("fmul.s", F(0x7F000000u), two)) == 0x7F800000u);
  STRATA_CHECK(take_flags() == (OF | NX));
  STRATA_CHECK(B(FOP2("fmul.s", F(0x0DA24260u), F(0x2EDBE6FFu))) == 0x000116C2u); /* 1e-30 * 1e-10 */
  STRATA_CHECK(take_flags() == (UF | NX));
  STRATA_CHECK(B(FOP2("fmul.s", F(0x00800000u), F(0x3F000000u))) == 0x00400000u); /* exact subnormal */
  STRATA_CHECK(take_flags() == 0);
  STRATA_CHECK(B(FOP2("fsub.s", F(0x7F800000u), F(0x7F800000u))) == 0x7FC00000u); /* inf - inf */
  STRATA_CHECK(take_flags() == NV);

  /* Rounding modes on a tie: 1 + 2^-24 lies halfway between 1 and 1 + 2^-23. */
  const float tiny = F(0x33800000u); /* 2^-24 */
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rne", one, tiny)) == 0x3F800000u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rtz", one, tiny)) == 0x3F800000u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rdn", one, tiny)) == 0x3F800000u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rup", one, tiny)) == 0x3F800001u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rmm", one, tiny)) == 0x3F800001u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rdn", -one, -tiny)) == 0xBF800001u);
  STRATA_CHECK(B(FOP2_RM("fadd.s", "rup", -one, -tiny)) == 0xBF800000u);
  STRATA_CHECK(B(FOP2_RM("fsub.s", "rdn", one, one)) == 0x80000000u); /* exact zero: -0 when rounding down */
  STRATA_CHECK(B(FOP2_RM("fsub.s", "rne", one, one)) == 0x00000000u);

  /* Conversions to integer in every static mode, and through frm. */
  const float p25 = 2.5f, m25 = -2.5f;
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rne", p25) == 2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", p25) == 2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rdn", p25) == 2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rup", p25) == 3);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rmm", p25) == 3);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rne", m25) == (uint32_t)-2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", m25) == (uint32_t)-2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rdn", m25) == (uint32_t)-3);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rup", m25) == (uint32_t)-2);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rmm", m25) == (uint32_t)-3);
  STRATA_CHECK(take_flags() == NX);
  STRATA_CSR_WRITE(frm, 3); /* RUP */
  STRATA_CHECK(FCVT_W("fcvt.w.s", "dyn", F(0x3FC00000u)) == 2); /* 1.5 */
  STRATA_CSR_WRITE(frm, 2); /* RDN */
  STRATA_CHECK(FCVT_W("fcvt.w.s", "dyn", F(0x3FC00000u)) == 1);
  STRATA_CHECK(STRATA_CSR_READ(fcsr) == ((2u << 5) | NX));
  STRATA_CSR_WRITE(fcsr, 0);

  /* Saturation: NaN and too-large values give the largest integer, with NV only. */
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", F(0x7FC00000u)) == 0x7FFFFFFFu);
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", F(0x4F400000u)) == 0x7FFFFFFFu);  /* 3.2e9 */
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", F(0xCF400000u)) == 0x80000000u);  /* -3.2e9 */
  STRATA_CHECK(FCVT_W("fcvt.w.s", "rtz", F(0xCF000000u)) == 0x80000000u);  /* -2^31 exactly: valid */
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(FCVT_W("fcvt.wu.s", "rtz", -one) == 0);
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(FCVT_W("fcvt.wu.s", "rtz", F(0xBF000000u)) == 0); /* -0.5 truncates to 0: only inexact */
  STRATA_CHECK(take_flags() == NX);
  STRATA_CHECK(FCVT_W("fcvt.wu.s", "rtz", F(0x4F800000u)) == 0xFFFFFFFFu); /* 2^32 */
  STRATA_CHECK(take_flags() == NV);

  /* Conversions from integer. */
  volatile int32_t big = 16777217, maxi = 0x7FFFFFFF;
  volatile uint32_t maxu = 0xFFFFFFFFu;
  STRATA_CHECK(B((float)big) == 0x4B800000u);  /* ties to even */
  STRATA_CHECK(B((float)maxi) == 0x4F000000u);
  STRATA_CHECK(B((float)maxu) == 0x4F800000u);
  STRATA_CHECK(take_flags() == NX);
  STRATA_CHECK((int32_t)F(0xC0E00000u) == -7);  /* (int)-7.0f */
  STRATA_CHECK((int32_t)(float)(-2.7f) == -2);

  /* min/max: signed zeros, quiet and signaling NaNs. */
  const float pz = F(0), nz = F(0x80000000u), qnan = F(0x7FC00000u), snan = F(0x7F800001u);
  STRATA_CHECK(B(FOP2("fmin.s", pz, nz)) == 0x80000000u);
  STRATA_CHECK(B(FOP2("fmin.s", nz, pz)) == 0x80000000u);
  STRATA_CHECK(B(FOP2("fmax.s", nz, pz)) == 0x00000000u);
  STRATA_CHECK(B(FOP2("fmin.s", qnan, two)) == B(two));
  STRATA_CHECK(take_flags() == 0);
  STRATA_CHECK(B(FOP2("fmax.s", two, snan)) == B(two));
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(B(FOP2("fmin.s", qnan, F(0xFFC00001u))) == 0x7FC00000u);

  /* Comparisons: feq is quiet, flt and fle signal on any NaN. */
  STRATA_CHECK(FCMP("feq.s", qnan, qnan) == 0);
  STRATA_CHECK(take_flags() == 0);
  STRATA_CHECK(FCMP("flt.s", qnan, one) == 0);
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(FCMP("feq.s", snan, one) == 0);
  STRATA_CHECK(take_flags() == NV);
  STRATA_CHECK(FCMP("fle.s", nz, pz) == 1);
  STRATA_CHECK(FCMP("feq.s", nz, pz) == 1);
  STRATA_CHECK(FCMP("flt.s", nz, pz) == 0);

  /* fclass: one bit per category. */
  STRATA_CHECK(FCLASS(F(0xFF800000u)) == 1u << 0);
  STRATA_CHECK(FCLASS(-one) == 1u << 1);
  STRATA_CHECK(FCLASS(F(0x80000001u)) == 1u << 2);
  STRATA_CHECK(FCLASS(nz) == 1u << 3);
  STRATA_CHECK(FCLASS(pz) == 1u << 4);
  STRATA_CHECK(FCLASS(F(0x00000001u)) == 1u << 5);
  STRATA_CHECK(FCLASS(one) == 1u << 6);
  STRATA_CHECK(FCLASS(F(0x7F800000u)) == 1u << 7);
  STRATA_CHECK(FCLASS(snan) == 1u << 8);
  STRATA_CHECK(FCLASS(qnan) == 1u << 9);

  /* Sign injection: copysign, negation, absolute value. */
  STRATA_CHECK(B(__builtin_copysignf(two, -one)) == 0xC0000000u);
  STRATA_CHECK(B(-(float)three) == 0xC0400000u);
  STRATA_CHECK(B(__builtin_fabsf(-(float)three)) == 0x40400000u);

  /* A fused multiply-add rounds once: (1 + 2^-12)^2 - (1 + 2^-11) = 2^-24 exactly, while a
   * separately rounded product would give 0. */
  const float a = F(0x3F800800u), c = F(0xBF801000u);
  STRATA_CHECK(B(__builtin_fmaf(a, a, c)) == 0x33800000u);
  STRATA_CHECK(B(FOP2("fmul.s", a, a)) == 0x3F801000u);
  STRATA_CHECK(take_flags() == NX);

  STRATA_CHECK(B(series(1000)) == 0x3FD26C75u);
  STRATA_CHECK(B(newton_sqrt(2.0f)) == 0x3FB504F3u);
  return 0;
}
