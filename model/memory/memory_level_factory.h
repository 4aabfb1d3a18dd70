// Makes each shared memory level from its config: the model the config names, checked against
// its level's statistics contract (memory_levels.h) before the chip wires it in. A new model of
// a level is a case here, under a new value of its config's model field.
#pragma once

#include <memory>

#include "model/memory/config.h"
#include "model/memory/memory_levels.h"
#include "model/memory/sparse_memory.h"

namespace strata::memory {

// memory.dram.model: `channel` (latency plus a byte calendar per channel) and `banked` (banks,
// row buffers and command timing, dram_banked.h) are one module, Dram, whose channels keep the
// buses, the hash and the statistics either way and ask BankedDram for the time when banked.
std::unique_ptr<DramLevel> make_dram_level(const char* name, const DramConfig& config, SparseMemory& backing);
std::unique_ptr<L2Level> make_l2_level(const char* name, const L2Config& config, SparseMemory& backing);
std::unique_ptr<StreamLevel> make_stream_level(const char* name, const StreamMemoryConfig& config);

}  // namespace strata::memory
