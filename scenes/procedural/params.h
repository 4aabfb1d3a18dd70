// Parameter checking and naming shared by the procedural generators.
#pragma once

#include "scenes/procedural/procedural.h"

#include <cstdint>
#include <string>

namespace strata::scenes::procedural {

// Throws SceneError("<scene>: ...") unless params.size is in (0, 1].
void check_params(const char* scene, const ProceduralParams& params);

// The Scene::name of a generated scene, e.g. "hairball:size=0.5,seed=1".
std::string spec_name(const char* scene, const ProceduralParams& params);

// round(full * size), but never below `minimum`.
uint64_t scaled_count(double full, double size, uint64_t minimum);

}  // namespace strata::scenes::procedural
