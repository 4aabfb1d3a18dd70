/* Machine-mode traps: a handler installed in mtvec sees mcause, mepc and mtval of each
 * faulting instruction, skips it and returns with mret. Also CSR basics. */
#include "strata_runtime.h"
#include "firmware/abi/strata_isa.h"

static volatile uint32_t seen_cause, seen_epc, seen_tval, seen_mstatus, trap_count;

__attribute__((interrupt("machine"), aligned(4))) static void handler(void) {
  seen_cause = STRATA_CSR_READ(mcause);
  seen_epc = STRATA_CSR_READ(mepc);
  seen_tval = STRATA_CSR_READ(mtval);
  seen_mstatus = STRATA_CSR_READ(mstatus);
  trap_count = trap_count + 1;
  STRATA_CSR_WRITE(mepc, seen_epc + 4);
}

/* Each macro runs one faulting instruction at a known address; epc receives that address. */
#define FAULT_LOAD(insn, addr, epc) \
  __asm__ volatile("la %0, 1f\n1: " insn " t0, 0(%1)" : "=&r"(epc) : "r"(addr) : "t0", "memory")
#define FAULT_STORE(insn, addr, epc) \
  __asm__ volatile("la %0, 1f\n1: " insn " zero, 0(%1)" : "=&r"(epc) : "r"(addr) : "memory")
#define FAULT_WORD(word, epc) __asm__ volatile("la %0, 1f\n1: .word " #word : "=&r"(epc) : : "memory")
#define FAULT_INSN(text, epc) __asm__ volatile("la %0, 1f\n1: " text : "=&r"(epc) : : "memory")

static uint32_t buffer[4];

static int expect(uint32_t cause, uint32_t epc, uint32_t tval, uint32_t count) {
  return seen_cause == cause && seen_epc == epc && seen_tval == tval && trap_count == count;
}

int main(void) {
  uint32_t epc;
  uint32_t n = 0;
  STRATA_CSR_WRITE(mtvec, (uint32_t)(uintptr_t)&handler);
  STRATA_CHECK(STRATA_CSR_READ(mtvec) == (uint32_t)(uintptr_t)&handler);

  const uintptr_t base = (uintptr_t)buffer;
  FAULT_LOAD("lw", base + 1, epc);
  STRATA_CHECK(expect(4, epc, base + 1, ++n));
  FAULT_LOAD("lh", base + 3, epc);
  STRATA_CHECK(expect(4, epc, base + 3, ++n));
  FAULT_STORE("sw", base + 2, epc);
  STRATA_CHECK(expect(6, epc, base + 2, ++n));
  FAULT_STORE("sh", base + 1, epc);
  STRATA_CHECK(expect(6, epc, base + 1, ++n));
  FAULT_LOAD("lw", (uintptr_t)0, epc); /* below the image: access fault */
  STRATA_CHECK(expect(5, epc, 0, ++n));
  FAULT_STORE("sb", (uintptr_t)0xFFFFFFF0u, epc);
  STRATA_CHECK(expect(7, epc, 0xFFFFFFF0u, ++n));
  FAULT_WORD(0xFFFFFFFF, epc);
  STRATA_CHECK(expect(2, epc, 0xFFFFFFFFu, ++n));
  FAULT_WORD(0x00000000, epc);
  STRATA_CHECK(expect(2, epc, 0, ++n));
  FAULT_INSN(".insn r 0x0B, 3, 0, x0, x0, x0", epc); /* custom-0 funct3 3 is not an operation */
  STRATA_CHECK(expect(2, epc, 0x0000300Bu, ++n));
  FAULT_INSN(".insn r 0x0B, 0, 0, x0, x1, x0", epc); /* strata.threadid with a nonzero rs1 */
  STRATA_CHECK(expect(2, epc, 0x0000800Bu, ++n));
  FAULT_INSN("ecall", epc);
  STRATA_CHECK(expect(11, epc, 0, ++n));
  FAULT_INSN("ebreak", epc);
  STRATA_CHECK(expect(3, epc, epc, ++n));
  FAULT_INSN("csrw mhartid, zero", epc); /* read-only CSR */
  STRATA_CHECK(expect(2, epc, 0xF1401073u, ++n));
  FAULT_INSN("csrr t0, 0x7C0", epc); /* unimplemented CSR */
  STRATA_CHECK(seen_cause == 2 && seen_epc == epc && trap_count == ++n);

  /* mstatus: MIE goes to MPIE on a trap and comes back on mret; MPP stays M. */
  STRATA_CSR_WRITE(mstatus, STRATA_CSR_READ(mstatus) | 8u);
  FAULT_INSN("ecall", epc);
  STRATA_CHECK(trap_count == ++n);
  STRATA_CHECK((seen_mstatus & 8u) == 0 && (seen_mstatus & 0x80u) != 0 && (seen_mstatus & 0x1800u) == 0x1800u);
  STRATA_CHECK((STRATA_CSR_READ(mstatus) & 8u) != 0);

  /* Identity and counters. */
  STRATA_CHECK(STRATA_CSR_READ(mhartid) == 0);
  const uint32_t misa = STRATA_CSR_READ(misa);
  STRATA_CHECK((misa >> 30) == 1 && (misa & (1u << 8)) && (misa & (1u << 12)) && (misa & (1u << 5)));
  STRATA_CSR_WRITE(mscratch, 0x12345678u);
  STRATA_CHECK(STRATA_CSR_READ(mscratch) == 0x12345678u);
  const uint32_t i0 = STRATA_CSR_READ(minstret);
  const uint32_t i1 = STRATA_CSR_READ(minstret);
  STRATA_CHECK(i1 - i0 == 1);
  STRATA_CHECK(STRATA_CSR_READ(cycle) >= i1);
  return 0;
}
