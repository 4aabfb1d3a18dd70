// The stream memory's storage under random push and pop sequences, against a plain model:
// no ray lost or duplicated, each treelet's count right, stored + credits <= capacity, and a
// push refused only when the memory is full for that thread.
#include "model/memory/stream_sram.h"

#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <vector>

using strata::memory::StreamLayout;
using strata::memory::StreamMemoryConfig;
using strata::memory::StreamSram;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  StreamMemoryConfig c;
  c.size_bytes = 4096u << (data[0] % 4);
  c.ray_bytes = (data[0] & 4) ? 64u : 48u;  // the record kernels' ray, or the compact one
  c.treelets = 1 + data[1] % 16;
  c.threads = 8;
  c.tms = 1;
  StreamLayout layout;
  try {
    layout = strata::memory::make_stream_layout(c);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  StreamSram sram(layout);
  std::vector<std::multiset<uint64_t>> model(c.treelets);  // ray ids per treelet
  std::set<uint64_t> live;
  uint64_t next_id = 1;
  for (size_t i = 2; i + 1 < size; i += 2) {
    const uint32_t thread = data[i] % c.threads, treelet = data[i + 1] % c.treelets;
    uint8_t ray[64] = {};  // the widest entry
    if (data[i] & 0x80) {
      const uint64_t id = next_id++;
      std::memcpy(ray, &id, sizeof id);
      const bool had_credit = sram.holds_credit(thread);
      const bool room = sram.stored() + sram.credits() < sram.capacity();
      const auto status = sram.push(thread, treelet, ray);
      if (status == StreamSram::Status::kOk) {
        model[treelet].insert(id);
        live.insert(id);
      } else if (status == StreamSram::Status::kFull) {
        if (had_credit || room) std::abort();  // refused although a slot was free for it
      } else {
        std::abort();
      }
    } else {
      const auto status = sram.pop(thread, treelet, ray);
      if (status == StreamSram::Status::kOk) {
        uint64_t id = 0;
        std::memcpy(&id, ray, sizeof id);
        const auto it = model[treelet].find(id);
        if (it == model[treelet].end() || live.count(id) == 0) std::abort();  // invented or duplicated
        model[treelet].erase(it);
        live.erase(id);
      } else if (!model[treelet].empty() && status == StreamSram::Status::kEmpty) {
        std::abort();  // lost: the model still holds rays there
      }
    }
    if (sram.size(treelet) != model[treelet].size()) std::abort();
    if (sram.stored() != live.size()) std::abort();
    if (uint64_t{sram.stored()} + sram.credits() > sram.capacity()) std::abort();
  }
  return 0;
}

// libsystemc, which strata_memory links, calls sc_main; libFuzzer owns main, so this never runs.
extern "C" int sc_main(int, char**) { return 0; }
