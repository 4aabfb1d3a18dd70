#include "model/iss/hart_impl.h"

namespace strata::iss {

template class Hart<FlatMemory>;

}  // namespace strata::iss
