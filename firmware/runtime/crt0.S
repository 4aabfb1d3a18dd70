/* Start-up code for RV32IMF firmware: stack, bss, FPU, main, and the exit report.
 *
 * The platform may preset sp (the ISS runner sets it to the top of guest memory, a TP model
 * to its local memory); only a zero sp falls back to the linker script's stack.
 * main's return value is written to tohost as (value << 1) | 1, the HTIF exit convention;
 * a platform that ignores tohost sees strata.halt right after. */
#include "firmware/abi/strata_isa.h"

  .section .text.init, "ax", @progbits
  .globl _start
  .type _start, @function
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  bnez sp, 1f
  la sp, __stack_top
1:
  andi sp, sp, -16

#ifndef STRATA_CRT0_KEEP_BSS
  /* Many threads sharing one image must not all clear it: such kernels define
   * STRATA_CRT0_KEEP_BSS and rely on the loader's zeroed image. */
  la t0, __bss_start
  la t1, __bss_end
2:
  bgeu t0, t1, 3f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 2b
3:
#endif

  /* mstatus.FS resets to Off, which makes every F instruction illegal: set it to Initial. */
  li t0, (1 << 13)
  csrs mstatus, t0
  csrwi fcsr, 0

  li a0, 0
  li a1, 0
  call main

  slli a0, a0, 1
  ori a0, a0, 1
  la t0, tohost
  sw a0, 0(t0)
  .insn r STRATA_OPCODE_THREAD, STRATA_F3_CONTROL, STRATA_CONTROL_HALT, x0, x0, x0
4:
  j 4b
  .size _start, . - _start

  /* Host-target interface words, in their own section so the linker script can place them. */
  .section .tohost, "aw", @progbits
  .balign 64
  .globl tohost
tohost:
  .word 0, 0
  .globl fromhost
fromhost:
  .word 0, 0
