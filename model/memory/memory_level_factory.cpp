#include "model/memory/memory_level_factory.h"

#include <stdexcept>
#include <string>

#include "model/memory/dram.h"
#include "model/memory/l2_cache.h"
#include "model/memory/stream_memory.h"

namespace strata::memory {
namespace {

template <class Level>
std::unique_ptr<Level> checked(std::unique_ptr<Level> level, const std::string& model) {
  stats::require_stats(level->stats(), model, Level::contract());
  return level;
}

}  // namespace

std::unique_ptr<DramLevel> make_dram_level(const char* name, const DramConfig& config, SparseMemory& backing) {
  switch (config.model) {
    case DramModel::kChannel:
      return checked<DramLevel>(std::make_unique<Dram>(name, config, backing), "memory.dram.model=channel");
    case DramModel::kBanked:
      return checked<DramLevel>(std::make_unique<Dram>(name, config, backing), "memory.dram.model=banked");
  }
  throw std::logic_error("memory.dram.model: no model for this value");
}

std::unique_ptr<L2Level> make_l2_level(const char* name, const L2Config& config, SparseMemory& backing) {
  return checked<L2Level>(std::make_unique<L2Cache>(name, config, backing), "the L2 cache");
}

std::unique_ptr<StreamLevel> make_stream_level(const char* name, const StreamMemoryConfig& config) {
  return checked<StreamLevel>(std::make_unique<StreamMemory>(name, config), "the ray stream memory");
}

}  // namespace strata::memory
