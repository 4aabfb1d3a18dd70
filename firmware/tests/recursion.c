/* Deep and branching recursion: calls, returns, stack frames and spills. */
#include "strata_runtime.h"

__attribute__((noinline)) static uint32_t fib(uint32_t n) { return n < 2 ? n : fib(n - 1) + fib(n - 2); }

__attribute__((noinline)) static uint32_t ackermann(uint32_t m, uint32_t n) {
  if (m == 0) return n + 1;
  if (n == 0) return ackermann(m - 1, 1);
  return ackermann(m - 1, ackermann(m, n - 1));
}

static int is_odd(uint32_t n);
__attribute__((noinline)) static int is_even(uint32_t n) { return n == 0 ? 1 : is_odd(n - 1); }
__attribute__((noinline)) static int is_odd(uint32_t n) { return n == 0 ? 0 : is_even(n - 1); }

/* Keeps a local array live across the recursive calls, so each frame holds real data. */
__attribute__((noinline)) static uint32_t tree_sum(uint32_t depth, uint32_t seed) {
  uint32_t local[8];
  for (uint32_t i = 0; i < 8; ++i) local[i] = seed * 31u + i;
  if (depth == 0) return local[seed & 7];
  const uint32_t left = tree_sum(depth - 1, seed * 2 + 1);
  const uint32_t right = tree_sum(depth - 1, seed * 2 + 2);
  return left + right + local[depth & 7];
}

static void hanoi(uint32_t n, uint32_t from, uint32_t to, uint32_t via, uint32_t* moves) {
  if (n == 0) return;
  hanoi(n - 1, from, via, to, moves);
  ++*moves;
  hanoi(n - 1, via, to, from, moves);
}

int main(void) {
  volatile uint32_t twenty = 20, three = 3, deep = 5000;
  STRATA_CHECK(fib(twenty) == 6765);
  STRATA_CHECK(ackermann(2, three) == 9);
  STRATA_CHECK(ackermann(three, three) == 61);
  STRATA_CHECK(ackermann(three, 5) == 253);
  STRATA_CHECK(is_even(deep) == 1);
  STRATA_CHECK(is_odd(deep + 1) == 1);
  uint32_t moves = 0;
  hanoi(12, 0, 2, 1, &moves);
  STRATA_CHECK(moves == 4095);
  /* Reference value from the same code compiled natively. */
  STRATA_CHECK(tree_sum(10, 1) == 0x0673F726u);
  return 0;
}
