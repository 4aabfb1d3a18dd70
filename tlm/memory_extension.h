// What a memory request is, beyond address and command: who sent it and which kind of access
// it is. Stream-memory operations also carry their treelet and come back with a status and a
// result word. One extension is attached to every pooled payload for its whole life, so the
// hot path never allocates one.
#pragma once

#include <tlm>

#include <cstdint>

#include "firmware/abi/strata_isa.h"
#include "tlm/data_class.h"

namespace strata::transport {

enum class AccessClass : uint8_t {
  kDataLoad,
  kDataStore,
  kInstructionFetch,
  kStreamPush,      // write 48 B ray to `treelet`'s buffer
  kStreamPop,       // read 48 B ray from `treelet` (kNoTreelet: the TM's assigned buffer)
  kStreamSize,      // result = rays in `treelet`'s buffer
  kStreamAssign,    // result = the TM's treelet (kNoTreelet when every buffer is empty)
  kStreamCapacity,  // result = rays the stream memory holds
  kStreamPathRead,  // on-chip path state: a load from the path records beside the rays
  kStreamPathWrite, // ... and a store
};

constexpr bool is_stream_access(AccessClass a) { return a >= AccessClass::kStreamPush; }

enum class StreamStatus : uint8_t { kOk, kFull, kEmpty, kBadRequest };

// The level that answered a load: lets tests and statistics see where a latency came from.
enum class ServedBy : uint8_t { kNone, kL1, kL1Merged, kL2, kL2Merged, kDram, kStream, kSink };

constexpr uint32_t kNoTreelet = STRATA_NO_TREELET;  // the firmware ABI's sentinel

struct MemoryExtension : tlm::tlm_extension<MemoryExtension> {
  // Request.
  uint32_t initiator_id = 0;  // global thread id (tm * tps_per_tm + tp)
  uint32_t tm_id = 0;
  AccessClass access = AccessClass::kDataLoad;
  // The level above already moved the data through the backing store; only book time.
  bool timing_only = false;
  // Sampled timing, fast-forward: do the access's function (a stream push or pop) but book no
  // time and count nothing, so the statistics hold the detailed windows only.
  bool functional = false;
  // Sampled timing, warm-up part of a detailed window: book time as usual (refilling queues
  // and caches) but count nothing, so the statistics hold the measured parts only.
  bool uncounted = false;
  // Sampled timing, functional warming: a fast-forward load or store that only keeps the
  // caches' tags current (lookup, allocate, evict, dirty bits, down to the L2). It moves no
  // data, books no time and counts nothing; `functional` is set too, so every module that does
  // not keep tags passes it by. Detailed windows then start from warm caches.
  bool warm = false;
  uint32_t treelet = kNoTreelet;
  // What the addressed bytes hold, for the traffic-by-data statistics (data_class.h).
  DataClass data = DataClass::kOther;
  // Response.
  StreamStatus stream_status = StreamStatus::kOk;
  uint32_t result = 0;
  ServedBy served_by = ServedBy::kNone;

  void reset_response() {
    stream_status = StreamStatus::kOk;
    result = 0;
    served_by = ServedBy::kNone;
  }
  tlm::tlm_extension_base* clone() const override { return new MemoryExtension(*this); }
  void copy_from(const tlm::tlm_extension_base& other) override {
    *this = static_cast<const MemoryExtension&>(other);
  }
};

// Whether a target counts this access in its statistics (plain TLM payloads: always).
inline bool counts(const MemoryExtension* ext) {
  return ext == nullptr || !(ext->functional || ext->uncounted || ext->warm);
}
inline bool is_warming(const MemoryExtension* ext) { return ext != nullptr && ext->warm; }

// A module's counters come in two copies: those the statistics report, and those of the
// accesses sampled timing leaves out (warm-up and fast-forward), which are still counted so
// the code path is the same. `of(ext)` picks the copy for one access.
template <class Counters>
struct CountedPair {
  Counters counted;
  Counters uncounted;
  Counters& of(const MemoryExtension* ext) { return counts(ext) ? counted : uncounted; }
};

// The data class of an access an initiator did not classify: fetches hold instructions and
// stream pushes and pops move rays; anything else is unknown.
constexpr DataClass default_data_class(AccessClass a) {
  return a == AccessClass::kInstructionFetch                                       ? DataClass::kInstructions
         : a == AccessClass::kStreamPathRead || a == AccessClass::kStreamPathWrite ? DataClass::kPathState
         : is_stream_access(a)                                                    ? DataClass::kRays
                                                                                   : DataClass::kOther;
}
inline DataClass data_class_of(const MemoryExtension* ext) { return ext ? ext->data : DataClass::kOther; }

// The access class of a payload; plain TLM initiators without the extension are data accesses.
inline AccessClass access_class_of(const tlm::tlm_generic_payload& gp, const MemoryExtension* ext) {
  if (ext != nullptr) return ext->access;
  return gp.is_write() ? AccessClass::kDataStore : AccessClass::kDataLoad;
}

}  // namespace strata::transport
