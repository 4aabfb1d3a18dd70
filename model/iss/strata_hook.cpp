#include "model/iss/strata_hook.h"

#include "firmware/abi/strata_isa.h"

namespace strata::iss {

unsigned strata_mem_in_words(Op op) {
  switch (op) {
    case Op::kStLoadRay: return STRATA_PIPE_RAY_WORDS;
    case Op::kStLoadBox: return STRATA_PIPE_BOX_WORDS;
    case Op::kStLoadTriangle: return STRATA_PIPE_TRIANGLE_WORDS;
    case Op::kStStreamPush: return STRATA_STREAM_RAY_WORDS;
    default: return 0;
  }
}

unsigned strata_mem_out_words(Op op) { return op == Op::kStStreamPop ? STRATA_STREAM_RAY_WORDS : 0; }

}  // namespace strata::iss
