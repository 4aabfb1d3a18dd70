#include "model/memory/data_traffic.h"

#include <string>

namespace strata::memory {

using stats::Unit;

namespace {
const char* class_description(transport::DataClass c) {
  switch (c) {
    case transport::DataClass::kNodes: return "BVH nodes (node treelets).";
    case transport::DataClass::kTriangles: return "Triangle records (triangle treelets).";
    case transport::DataClass::kScene: return "The rest of the scene image: header, materials, treelet table.";
    case transport::DataClass::kPathState: return "The streaming kernels' path records.";
    case transport::DataClass::kFramebuffer: return "The framebuffer.";
    case transport::DataClass::kThreadData:
      return "Per-thread stacks and locals, ray counters, frame parameters and the kernel's own data.";
    case transport::DataClass::kInstructions: return "Instruction fetches and instruction-line fills.";
    case transport::DataClass::kRays: return "Ray records of the stream memory.";
    case transport::DataClass::kOther: return "Accesses no initiator classified (plain TLM payloads).";
    case transport::DataClass::kCount: break;
  }
  return "";
}
}  // namespace

DataTrafficStats::DataTrafficStats(const DataTraffic& t, bool misses, const char* accesses_are,
                                   const char* bytes_are)
    : group_("by_data", "This level's traffic split by what the addressed bytes hold; the classes sum to the "
                        "level's totals.") {
  for (unsigned i = 0; i < transport::kDataClassCount; ++i) {
    const auto c = static_cast<transport::DataClass>(i);
    auto g = std::make_unique<stats::Group>(transport::data_class_name(c), class_description(c));
    g->count("accesses", &t[i].accesses, Unit::kCount, accesses_are);
    if (misses) g->count("misses", &t[i].misses, Unit::kCount, "Of those, misses that went to the level below.");
    g->count("bytes", &t[i].bytes, Unit::kBytes, bytes_are);
    group_.child(g.get());
    classes_[i] = std::move(g);
  }
}

}  // namespace strata::memory
