#include "scenes/procedural/params.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace strata::scenes::procedural {

void check_params(const char* scene, const ProceduralParams& params) {
  // Written so that NaN fails too.
  if (!(params.size > 0.0 && params.size <= 1.0)) {
    std::ostringstream msg;
    msg << scene << ": ProceduralParams.size must be in (0, 1], got " << params.size;
    throw SceneError(msg.str());
  }
}

std::string spec_name(const char* scene, const ProceduralParams& params) {
  std::ostringstream name;
  name << scene << ":size=" << params.size << ",seed=" << params.seed;
  return name.str();
}

uint64_t scaled_count(double full, double size, uint64_t minimum) {
  return std::max(minimum, static_cast<uint64_t>(std::llround(full * size)));
}

}  // namespace strata::scenes::procedural
