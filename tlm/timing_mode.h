// The fidelity levels one model runs at (docs/chip-model.md, "Timing modes"). Every number the
// simulator reports names the mode it came from. Shared by the chip, its TMs and the memory
// system's test initiators, so it lives with the timing plumbing rather than in any of them.
#pragma once

#include <cstdint>

namespace strata::transport {

enum class TimingMode : uint8_t {
  kLooselyTimed,  // decoupled within a quantum; shared resources book reservation calendars
  kPrecise,       // every access synchronised: the accuracy reference
  kSampled,       // short loosely-timed windows and functional fast-forward (chip only)
};

constexpr const char* to_string(TimingMode mode) {
  switch (mode) {
    case TimingMode::kPrecise: return "precise";
    case TimingMode::kSampled: return "sampled";
    case TimingMode::kLooselyTimed: break;
  }
  return "loosely-timed";
}

}  // namespace strata::transport
