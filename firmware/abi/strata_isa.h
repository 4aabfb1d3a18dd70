/* The STRaTA instruction-set extension: its encoding (shared by the ISS decoder and the
 * firmware) and, on RISC-V, the intrinsics that emit it.
 *
 * Every operation is an R-type instruction in a RISC-V custom major opcode. funct3 selects a
 * group and funct7 the operation inside it; unused register fields must be x0. The
 * instructions are emitted with the assembler's `.insn r` directive, so a stock toolchain
 * suffices. docs/isa-extension.md is the reference for the semantics; the pipelines
 * compute the functions of firmware/common/intersect.h.
 *
 * Freestanding C and C++: the only dependency is <stdint.h>. Assembly sources may include it
 * for the constants. */
#ifndef STRATA_FIRMWARE_COMMON_STRATA_ISA_H
#define STRATA_FIRMWARE_COMMON_STRATA_ISA_H

#ifndef __ASSEMBLER__
#include <stdint.h>
#endif

/* ---- Major opcodes ---- */
#define STRATA_OPCODE_THREAD 0x0B /* custom-0: ids, global registers, stream memory, halt */
#define STRATA_OPCODE_PIPE 0x2B   /* custom-1: fused box and triangle pipelines */

/* ---- custom-0 groups (funct3) and operations (funct7) ---- */
#define STRATA_F3_ID 0
#define STRATA_ID_THREAD 0       /* rd = global thread id (tm * tps_per_tm + tp) */
#define STRATA_ID_TP 1           /* rd = TP index inside its TM */
#define STRATA_ID_TM 2           /* rd = TM index */
#define STRATA_ID_THREAD_COUNT 3 /* rd = number of threads on the chip */
#define STRATA_ID_TPS_PER_TM 4   /* rd = TPs per TM */
#define STRATA_ID_TM_COUNT 5     /* rd = number of TMs */

#define STRATA_F3_GLOBAL 1
#define STRATA_GLOBAL_ATOMIC_INC 0 /* rd = G[x[rs1]]; G[x[rs1]] += 1 */
#define STRATA_GLOBAL_ATOMIC_ADD 1 /* rd = G[x[rs1]]; G[x[rs1]] += x[rs2] */
#define STRATA_GLOBAL_READ 2       /* rd = G[x[rs1]] */
#define STRATA_GLOBAL_WRITE 3      /* G[x[rs1]] = x[rs2] */

#define STRATA_F3_STREAM 2
#define STRATA_STREAM_CAPACITY 0 /* rd = rays the stream memory holds */
#define STRATA_STREAM_PUSH 1     /* push ray at x[rs1] to treelet x[rs2]; rd = 1, or 0 if full */
#define STRATA_STREAM_POP 2      /* pop from the TM's buffer to x[rs1]; rd = 1, or 0 if empty */
#define STRATA_STREAM_ASSIGN 3   /* rd = the TM's treelet, or STRATA_NO_TREELET */
/* The same for a stream memory with 64-byte entries (the compact path state): a ray that
   carries its path's state. An entry width the stream memory was not built with traps. */
#define STRATA_STREAM_PUSH64 4
#define STRATA_STREAM_POP64 5

#define STRATA_F3_CONTROL 7
#define STRATA_CONTROL_HALT 0 /* the thread stops */

/* ---- custom-1 groups (funct3) and operations (funct7) ---- */
#define STRATA_F3_PIPE_CONFIG 0
#define STRATA_PIPE_GENERAL 0 /* XUs back to general use */
#define STRATA_PIPE_BOX 1     /* chain XUs into the ray-box pipeline */
#define STRATA_PIPE_TRIANGLE 2

#define STRATA_F3_PIPE_LOAD 1
#define STRATA_LOAD_RAY 0      /* input registers <- strata_pipe_ray at x[rs1] */
#define STRATA_LOAD_BOX 1      /* input registers <- strata_pipe_box at x[rs1] */
#define STRATA_LOAD_TRIANGLE 2 /* input registers <- strata_pipe_triangle at x[rs1] */
#define STRATA_SET_TMAX 3      /* ray tmax <- f[rs1] */

#define STRATA_F3_PIPE_TEST 2
#define STRATA_BOX_TEST 0        /* x[rd] = hit; f[rs2] = entry distance (+inf on a miss) */
#define STRATA_TRIANGLE_TEST 1   /* x[rd] = hit, decided without a divide (t range unchecked) */
#define STRATA_TRIANGLE_DIVIDE 2 /* f[rd] = t, f[rs1] = u, f[rs2] = v of the last hit */

/* ---- Data the extension reads and writes ---- */
#define STRATA_GLOBAL_REGISTERS 32
#define STRATA_NO_TREELET 0xFFFFFFFFu
#define STRATA_STREAM_RAY_BYTES 48 /* one queued ray, opaque to the stream memory */
#define STRATA_STREAM_RAY_WORDS 12
#define STRATA_STREAM_RAY64_BYTES 64 /* one queued ray with its path's state (compact) */
#define STRATA_STREAM_RAY64_WORDS 16
#define STRATA_PIPE_RAY_WORDS 11 /* origin, tmin, direction, tmax, inverse direction */
#define STRATA_PIPE_BOX_WORDS 6
#define STRATA_PIPE_TRIANGLE_WORDS 9

#ifndef __ASSEMBLER__

typedef struct strata_pipe_ray {
  float origin[3];
  float tmin;
  float direction[3];
  float tmax;
  float inv_direction[3];
  float pad; /* not read; keeps the record 16-byte sized */
} strata_pipe_ray;

typedef struct strata_pipe_box {
  float min[3];
  float max[3];
} strata_pipe_box;

typedef struct strata_pipe_triangle {
  float v0[3];
  float v1[3];
  float v2[3];
} strata_pipe_triangle;

typedef struct strata_stream_ray {
  uint32_t words[STRATA_STREAM_RAY_WORDS];
} strata_stream_ray;

typedef struct strata_stream_ray64 {
  uint32_t words[STRATA_STREAM_RAY64_WORDS];
} strata_stream_ray64;

/* ---- Intrinsics (RISC-V only; a host build supplies same-named functional versions) ---- */
#if defined(__riscv)

#define STRATA_INSN_RD_(op, f3, f7, name)                                                     \
  static inline uint32_t name(void) {                                                        \
    uint32_t rd;                                                                             \
    __asm__ volatile(".insn r %1, %2, %3, %0, x0, x0" : "=r"(rd) : "i"(op), "i"(f3), "i"(f7)); \
    return rd;                                                                               \
  }

STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_THREAD, strata_thread_id)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_TP, strata_tp_id)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_TM, strata_tm_id)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_THREAD_COUNT, strata_thread_count)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_TPS_PER_TM, strata_tps_per_tm)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_ID, STRATA_ID_TM_COUNT, strata_tm_count)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_STREAM, STRATA_STREAM_CAPACITY,
                strata_stream_capacity)
STRATA_INSN_RD_(STRATA_OPCODE_THREAD, STRATA_F3_STREAM, STRATA_STREAM_ASSIGN,
                strata_stream_assign)
STRATA_INSN_RD_(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_TEST,
                strata_triangle_test)
#undef STRATA_INSN_RD_

#define STRATA_INSN_NONE_(op, f3, f7, name)                                                \
  static inline void name(void) {                                                         \
    __asm__ volatile(".insn r %0, %1, %2, x0, x0, x0" : : "i"(op), "i"(f3), "i"(f7));       \
  }

STRATA_INSN_NONE_(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_GENERAL,
                  strata_pipe_general)
STRATA_INSN_NONE_(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_BOX, strata_pipe_box_mode)
STRATA_INSN_NONE_(STRATA_OPCODE_PIPE, STRATA_F3_PIPE_CONFIG, STRATA_PIPE_TRIANGLE,
                  strata_pipe_triangle_mode)
#undef STRATA_INSN_NONE_

/* Global registers: volatile plus a memory clobber, because they order shared work. */
static inline uint32_t strata_atomic_inc(uint32_t reg) {
  uint32_t rd;
  __asm__ volatile(".insn r %1, %2, %3, %0, %4, x0"
                   : "=r"(rd)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_GLOBAL), "i"(STRATA_GLOBAL_ATOMIC_INC),
                     "r"(reg)
                   : "memory");
  return rd;
}

static inline uint32_t strata_atomic_add(uint32_t reg, uint32_t value) {
  uint32_t rd;
  __asm__ volatile(".insn r %1, %2, %3, %0, %4, %5"
                   : "=r"(rd)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_GLOBAL), "i"(STRATA_GLOBAL_ATOMIC_ADD),
                     "r"(reg), "r"(value)
                   : "memory");
  return rd;
}

static inline uint32_t strata_global_read(uint32_t reg) {
  uint32_t rd;
  __asm__ volatile(".insn r %1, %2, %3, %0, %4, x0"
                   : "=r"(rd)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_GLOBAL), "i"(STRATA_GLOBAL_READ),
                     "r"(reg)
                   : "memory");
  return rd;
}

static inline void strata_global_write(uint32_t reg, uint32_t value) {
  __asm__ volatile(".insn r %0, %1, %2, x0, %3, %4"
                   :
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_GLOBAL), "i"(STRATA_GLOBAL_WRITE),
                     "r"(reg), "r"(value)
                   : "memory");
}

static inline uint32_t strata_stream_push(const strata_stream_ray* ray, uint32_t treelet) {
  uint32_t rd;
  __asm__ volatile(".insn r %1, %2, %3, %0, %4, %5"
                   : "=r"(rd)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_STREAM), "i"(STRATA_STREAM_PUSH),
                     "r"(ray), "r"(treelet), "m"(*ray)
                   : "memory");
  return rd;
}

static inline uint32_t strata_stream_pop(strata_stream_ray* ray) {
  uint32_t rd;
  __asm__ volatile(".insn r %2, %3, %4, %0, %5, x0"
                   : "=r"(rd), "=m"(*ray)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_STREAM), "i"(STRATA_STREAM_POP),
                     "r"(ray)
                   : "memory");
  return rd;
}

static inline uint32_t strata_stream_push64(const strata_stream_ray64* ray, uint32_t treelet) {
  uint32_t rd;
  __asm__ volatile(".insn r %1, %2, %3, %0, %4, %5"
                   : "=r"(rd)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_STREAM), "i"(STRATA_STREAM_PUSH64),
                     "r"(ray), "r"(treelet), "m"(*ray)
                   : "memory");
  return rd;
}

static inline uint32_t strata_stream_pop64(strata_stream_ray64* ray) {
  uint32_t rd;
  __asm__ volatile(".insn r %2, %3, %4, %0, %5, x0"
                   : "=r"(rd), "=m"(*ray)
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_STREAM), "i"(STRATA_STREAM_POP64),
                     "r"(ray)
                   : "memory");
  return rd;
}

static inline __attribute__((noreturn)) void strata_halt(void) {
  __asm__ volatile(".insn r %0, %1, %2, x0, x0, x0"
                   :
                   : "i"(STRATA_OPCODE_THREAD), "i"(STRATA_F3_CONTROL), "i"(STRATA_CONTROL_HALT)
                   : "memory");
  __builtin_unreachable();
}

/* Pipeline loads read their record through an "m" operand, so the compiler stores it first
 * without a full memory clobber; volatile keeps them ordered before the tests. */
static inline void strata_load_ray(const strata_pipe_ray* ray) {
  __asm__ volatile(".insn r %0, %1, %2, x0, %3, x0"
                   :
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_LOAD), "i"(STRATA_LOAD_RAY),
                     "r"(ray), "m"(*ray));
}

static inline void strata_load_box(const strata_pipe_box* box) {
  __asm__ volatile(".insn r %0, %1, %2, x0, %3, x0"
                   :
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_LOAD), "i"(STRATA_LOAD_BOX),
                     "r"(box), "m"(*box));
}

static inline void strata_load_triangle(const strata_pipe_triangle* tri) {
  __asm__ volatile(".insn r %0, %1, %2, x0, %3, x0"
                   :
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_LOAD), "i"(STRATA_LOAD_TRIANGLE),
                     "r"(tri), "m"(*tri));
}

static inline void strata_set_tmax(float tmax) {
  __asm__ volatile(".insn r %0, %1, %2, x0, %3, x0"
                   :
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_LOAD), "i"(STRATA_SET_TMAX),
                     "f"(tmax));
}

/* Returns the hit flag; *t_entry gets the entry distance (+inf on a miss). */
static inline uint32_t strata_box_test(float* t_entry) {
  uint32_t hit;
  float t;
  __asm__ volatile(".insn r %2, %3, %4, %0, x0, %1"
                   : "=r"(hit), "=f"(t)
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_TEST), "i"(STRATA_BOX_TEST));
  *t_entry = t;
  return hit;
}

static inline void strata_triangle_divide(float* t, float* u, float* v) {
  float rt, ru, rv;
  __asm__ volatile(".insn r %3, %4, %5, %0, %1, %2"
                   : "=f"(rt), "=f"(ru), "=f"(rv)
                   : "i"(STRATA_OPCODE_PIPE), "i"(STRATA_F3_PIPE_TEST), "i"(STRATA_TRIANGLE_DIVIDE));
  *t = rt;
  *u = ru;
  *v = rv;
}

#endif /* __riscv */

#endif /* __ASSEMBLER__ */

#endif /* STRATA_FIRMWARE_COMMON_STRATA_ISA_H */
