/* Ends with strata.halt instead of returning, as a thread on the chip does. */
#include "strata_runtime.h"
#include "firmware/abi/strata_isa.h"

volatile uint32_t result;

int main(void) {
  result = 42;
  strata_halt();
}
