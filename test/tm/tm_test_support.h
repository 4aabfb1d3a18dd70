// Helpers for the TM timing tests: instructions built with the ISS test encoder and
// decoded by the real decoder, plus encoders for the STRaTA ops the tests use.
#pragma once

#include "firmware/abi/strata_isa.h"
#include "model/iss/decoder.h"
#include "model/tm/tm_config.h"
#include "test/iss/iss_test_support.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace strata::tm::testing {

namespace enc = strata::iss::testing::enc;

inline iss::Decoded decoded(uint32_t word) {
  const iss::Decoded d = iss::decode(word);
  EXPECT_NE(d.op, iss::Op::kIllegal) << "word 0x" << std::hex << word;
  return d;
}

// A switch that costs nothing, for tests about the pipelines themselves.
inline TmConfig instant_switch() {
  TmConfig c;
  c.pipelines.reconfigure_cycles = 0;
  return c;
}

namespace st {
inline uint32_t pipe(uint32_t f3, uint32_t f7, uint32_t rd, uint32_t rs1, uint32_t rs2) {
  return enc::strata(STRATA_OPCODE_PIPE, f3, f7, rd, rs1, rs2);
}
inline uint32_t thread(uint32_t f3, uint32_t f7, uint32_t rd, uint32_t rs1, uint32_t rs2) {
  return enc::strata(STRATA_OPCODE_THREAD, f3, f7, rd, rs1, rs2);
}
inline uint32_t pipe_general() { return pipe(STRATA_F3_PIPE_CONFIG, STRATA_PIPE_GENERAL, 0, 0, 0); }
inline uint32_t pipe_box() { return pipe(STRATA_F3_PIPE_CONFIG, STRATA_PIPE_BOX, 0, 0, 0); }
inline uint32_t pipe_triangle() { return pipe(STRATA_F3_PIPE_CONFIG, STRATA_PIPE_TRIANGLE, 0, 0, 0); }
inline uint32_t ldray(uint32_t rs1) { return pipe(STRATA_F3_PIPE_LOAD, STRATA_LOAD_RAY, 0, rs1, 0); }
inline uint32_t ldbox(uint32_t rs1) { return pipe(STRATA_F3_PIPE_LOAD, STRATA_LOAD_BOX, 0, rs1, 0); }
inline uint32_t ldtri(uint32_t rs1) { return pipe(STRATA_F3_PIPE_LOAD, STRATA_LOAD_TRIANGLE, 0, rs1, 0); }
inline uint32_t settmax(uint32_t fs1) { return pipe(STRATA_F3_PIPE_LOAD, STRATA_SET_TMAX, 0, fs1, 0); }
inline uint32_t boxtest(uint32_t rd, uint32_t fd) { return pipe(STRATA_F3_PIPE_TEST, STRATA_BOX_TEST, rd, 0, fd); }
inline uint32_t tritest(uint32_t rd) { return pipe(STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_TEST, rd, 0, 0); }
inline uint32_t tridiv(uint32_t ft, uint32_t fu, uint32_t fv) {
  return pipe(STRATA_F3_PIPE_TEST, STRATA_TRIANGLE_DIVIDE, ft, fu, fv);
}
inline uint32_t threadid(uint32_t rd) { return thread(STRATA_F3_ID, STRATA_ID_THREAD, rd, 0, 0); }
inline uint32_t atominc(uint32_t rd, uint32_t rs1) { return thread(STRATA_F3_GLOBAL, STRATA_GLOBAL_ATOMIC_INC, rd, rs1, 0); }
inline uint32_t streampop(uint32_t rd, uint32_t rs1) { return thread(STRATA_F3_STREAM, STRATA_STREAM_POP, rd, rs1, 0); }
}  // namespace st

}  // namespace strata::tm::testing
