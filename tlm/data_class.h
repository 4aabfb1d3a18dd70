// What the bytes of an access hold. The chip lays out guest memory, so it knows the regions
// (DataClassMap); its TMs tag each request with the class of its address, and every level
// below (L1s, interconnect, L2, stream memory, DRAM) counts its accesses, misses and bytes by
// that tag. A cache line keeps the class it was filled with, so a write-back is counted as
// what it holds. docs/statistics.md lists the split; its classes sum to each level's totals.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace strata::transport {

enum class DataClass : uint8_t {
  kNodes,         // BVH nodes (node treelets)
  kTriangles,     // triangle records (triangle treelets)
  kScene,         // the rest of the scene image: header, materials, treelet table
  kPathState,     // the streaming kernels' per-path records
  kFramebuffer,
  kThreadData,    // per-thread stacks and locals, ray counters, frame parameters, kernel data
  kInstructions,  // instruction fetches and their line fills
  kRays,          // ray records in the stream memory
  kOther,         // an access no initiator classified (plain TLM payloads, unit tests)
  kCount
};
constexpr unsigned kDataClassCount = static_cast<unsigned>(DataClass::kCount);

constexpr const char* data_class_name(DataClass c) {
  constexpr const char* kNames[kDataClassCount] = {"nodes",       "triangles",    "scene", "path_state", "framebuffer",
                                                   "thread_data", "instructions", "rays",  "other"};
  return c < DataClass::kCount ? kNames[static_cast<unsigned>(c)] : "invalid";
}
// For people: "path state", "thread data", ...
constexpr const char* data_class_label(DataClass c) {
  constexpr const char* kLabels[kDataClassCount] = {"nodes",       "triangles",    "scene data", "path state",
                                                    "framebuffer", "thread data",  "instructions", "rays",
                                                    "unclassified"};
  return c < DataClass::kCount ? kLabels[static_cast<unsigned>(c)] : "invalid";
}

// Guest address ranges and what they hold; addresses outside every range are kOther.
// A lookup is one load from a table of 4 KB pages; only a page shared by two ranges falls
// back to a binary search over the ranges. No allocation after add().
class DataClassMap {
 public:
  // [begin, end); ranges must not overlap. Empty ranges are ignored.
  void add(uint64_t begin, uint64_t end, DataClass c);
  DataClass of(uint64_t addr) const {
    const uint64_t page = addr >> kPageShift;
    if (page < pages_.size() && pages_[page] != kMixed) return static_cast<DataClass>(pages_[page]);
    return search(addr);
  }
  std::size_t ranges() const { return begins_.size(); }

 private:
  static constexpr unsigned kPageShift = 12;
  static constexpr uint8_t kMixed = 0xFF;
  void rebuild_pages();
  DataClass search(uint64_t addr) const {
    std::size_t lo = 0, hi = begins_.size();
    while (lo < hi) {  // first range whose begin is > addr
      const std::size_t mid = (lo + hi) / 2;
      if (begins_[mid] <= addr) lo = mid + 1;
      else hi = mid;
    }
    if (lo == 0) return DataClass::kOther;
    const std::size_t r = lo - 1;
    return addr < ends_[r] ? classes_[r] : DataClass::kOther;
  }

  std::vector<uint64_t> begins_, ends_;  // sorted by begin
  std::vector<DataClass> classes_;
  std::vector<uint8_t> pages_;  // the class of each page below the last range's end, or kMixed
};

}  // namespace strata::transport
