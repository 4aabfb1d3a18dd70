#include "model/iss/strata_hook.h"

#include "firmware/abi/strata_isa.h"

namespace strata::iss {

unsigned strata_mem_in_words(Op op) {
  switch (op) {
    case Op::kStLoadRay: return STRATA_PIPE_RAY_WORDS;
    case Op::kStLoadBox: return STRATA_PIPE_BOX_WORDS;
    case Op::kStLoadTriangle: return STRATA_PIPE_TRIANGLE_WORDS;
    case Op::kStStreamPush: return STRATA_STREAM_RAY_WORDS;
    case Op::kStStreamPush64: return STRATA_STREAM_RAY64_WORDS;
    default: return 0;
  }
}

unsigned strata_mem_out_words(Op op) {
  switch (op) {
    case Op::kStStreamPop: return STRATA_STREAM_RAY_WORDS;
    case Op::kStStreamPop64: return STRATA_STREAM_RAY64_WORDS;
    default: return 0;
  }
}

unsigned stream_ray_bytes(Op op) {
  switch (op) {
    case Op::kStStreamPush:
    case Op::kStStreamPop: return STRATA_STREAM_RAY_BYTES;
    case Op::kStStreamPush64:
    case Op::kStStreamPop64: return STRATA_STREAM_RAY64_BYTES;
    default: return 0;
  }
}

}  // namespace strata::iss
