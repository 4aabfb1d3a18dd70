// Typed configuration of every memory module (in the spirit of DRAMSys: one struct per
// module, defaults from the STRaTA paper, validated once at construction with errors that
// name the field). Sizes are bytes, times are cycles of the 1 GHz clock, energies are nJ per
// access. Every struct has a validate() that throws std::invalid_argument.
#pragma once

#include "model/memory/dram_timing.h"

#include <cstdint>
#include <optional>
#include <string>

namespace strata::memory {

// The documented ranges of the fields every module shares (docs/memory-system.md): a latency
// beyond this would run for ever in simulated time, a horizon beyond it would not fit memory.
constexpr uint32_t kMaxLatencyCycles = 65536;
constexpr uint32_t kMaxCalendarHorizonCycles = 1u << 20;

// Write-around: stores go through to the next level and never allocate; a present line stays
// valid (the data lives in the backing store). TRaX's policy; see docs/memory-system.md.
struct L1DataCacheConfig {
  uint32_t size_bytes = 32 * 1024;
  uint32_t banks = 8;
  uint32_t line_bytes = 64;
  uint32_t hit_latency_cycles = 1;
  // Must exceed the LT quantum plus the longest wait a request can see, queueing included:
  // 16384 keeps every booking of a 128-TM Sibenik frame inside (fidelity.calendar_overflow_bookings).
  uint32_t calendar_horizon_cycles = 16384;
  // Per access (a lookup, or a line fill), nJ. STRaTA's table (../shared/ARCHITECTURE.md,
  // CACTI 6.5, 65 nm) leaves the L1 data cache out. This default is derived from that same
  // table rather than taken from a separate publication: a log-log fit through its 4 KB
  // I-cache (0.014 nJ) and 512 KB SRAM (0.524 nJ) points, evaluated at 32 KB:
  // 0.014 * 8^0.7466 = 0.066 nJ. Replace it with a CACTI run of the exact geometry when one
  // is available (docs/memory-system.md, "Energy").
  double access_energy_nj = 0.066;
  void validate() const;
};

struct L1InstructionCacheConfig {
  uint32_t size_bytes = 4 * 1024;
  uint32_t banks = 4;
  uint32_t line_bytes = 64;
  uint32_t hit_latency_cycles = 1;
  // false: every fetch hits (the firmware is a few KB, as TRaX assumed); true: misses go to
  // the L2 through the downstream socket.
  bool model_misses = true;
  uint32_t calendar_horizon_cycles = 16384;  // as the L1 data cache's
  double access_energy_nj = 0.014;  // STRaTA table: I-cache 4 KB, CACTI 6.5, 65 nm
  void validate() const;
};

struct L2Config {
  uint32_t size_bytes = 512 * 1024;  // STRaTA 512 KB; the TRaX baseline sweeps 512 KB..16 MB
  uint32_t banks = 16;
  uint32_t line_bytes = 64;
  uint32_t ways = 1;  // 1: direct-mapped; more: set-associative with LRU replacement
  // true: the bank index is XOR-folded from the whole line address (bank_interleave.h), as a
  // banked L2 in hardware is built; false: the line's low bits, so 32 KB-aligned treelet roots
  // all land in bank 0 (kept to measure that, docs/paper-reproduction.md).
  bool hash_banks = true;
  uint32_t hit_latency_cycles = 3;
  uint32_t calendar_horizon_cycles = 16384;  // as the L1 data cache's
  // Unset: the STRaTA CACTI table entry for size_bytes (sram_access_energy_nj).
  std::optional<double> access_energy_nj;
  void validate() const;
  double energy_per_access_nj() const;
};

enum class SchedulingPolicy : uint8_t {
  kFullestFirst,  // a TM that needs a buffer gets the one holding the most rays
  kRoundRobin,    // buffers are handed out in turn, in the order they became non-empty
};
const char* to_string(SchedulingPolicy p);

struct StreamMemoryConfig {
  uint32_t size_bytes = 512 * 1024;  // S: same sizes as the baseline L2 sweep
  uint32_t treelets = 1024;          // head pointers carved out of the SRAM
  uint32_t threads = 4096;           // one "holds a ray" bit per thread, also in the SRAM
  uint32_t tms = 128;
  // The SRAM's banks, each with its own ports and its own link from the crossbar. Ray entries
  // are interleaved over the banks, path-state rows (64 B) too; a push takes the entry the
  // allocator hands out, a pop the one it finds. ARCHITECTURE.md: the stream memory is carved
  // from the L2's SRAM, so the STRaTA designs give it the L2's banking (sim/configs).
  uint32_t banks = 1;
  uint32_t ports = 4;                // ray and path-state reads/writes per cycle, per bank
  // Width of each bank's link from the crossbar (0: the stream memory books no link; the
  // interconnect does, as one link). The chip sets it from the interconnect's link width.
  uint32_t link_bytes_per_cycle = 0;
  uint32_t access_latency_cycles = 3;
  uint32_t query_latency_cycles = 1;  // size, assign, capacity: head/count region only
  SchedulingPolicy policy = SchedulingPolicy::kFullestFirst;
  bool sticky = true;  // a TM keeps its treelet while that buffer has rays
  uint32_t calendar_horizon_cycles = 16384;  // as the L1 data cache's
  // Bytes of one entry's ray: 48 (the paper's ray; its path's state elsewhere) or 64 (a ray
  // that carries its path's state: design.path_state = compact). The chip sets it.
  uint32_t ray_bytes = 48;
  // Bytes of path state kept beside each ray slot (0: none; the chip sets it when path state
  // lives on chip). They come out of size_bytes, so the ray capacity shrinks.
  uint32_t path_record_bytes = 0;
  // Unset: the L2 of the same size (STRaTA: a stream access costs about an L2 access).
  std::optional<double> access_energy_nj;
  void validate() const;
  double energy_per_access_nj() const;
};

enum class DramModel : uint8_t {
  kChannel,  // each channel a data bus behind a fixed latency (Dram; the default)
  kBanked,   // each channel ranks, bank groups and banks with row buffers and command timing
};
const char* to_string(DramModel m);

struct DramConfig {
  DramModel model = DramModel::kChannel;
  uint32_t channels = 8;
  uint32_t bytes_per_cycle = 256;  // total peak: 256 GB/s at 1 GHz, split evenly over channels
  uint32_t latency_cycles = 100;   // from request to first data, unloaded
  uint32_t interleave_bytes = 256;  // consecutive blocks of this size go to consecutive channels
  // true: the block index is XOR-folded before it picks the channel (Dram::channel_of), as
  // memory controllers do; false: plain block % channels (treelet-aligned data then camps on
  // channel 0; kept to measure that).
  bool hash_channels = true;
  uint32_t burst_bytes = 64;        // one access moves up to this much; energy is per access
  uint32_t calendar_horizon_cycles = 16384;
  double access_energy_nj = 16.3;  // STRaTA table: off-chip DRAM, per access
  // model = banked only (latency_cycles is then unused: the commands' timing gives it).
  DramTimingConfig banked;
  void validate() const;
  uint32_t channel_bytes_per_cycle() const { return bytes_per_cycle / channels; }
};

struct InterconnectConfig {
  uint32_t tm_ports = 128;
  uint32_t l2_banks = 16;       // must match the L2: requests are routed to bank ports
  uint32_t l2_line_bytes = 64;  // bank interleaving granule, as in the L2
  bool l2_hash_banks = true;    // as the L2's hash_banks: the same line goes to the same bank
  uint32_t link_bytes_per_cycle = 64;
  uint32_t hop_latency_cycles = 1;  // each way
  // Book a link for stream-memory traffic here (one for all of it). The chip turns it off:
  // the stream memory books its own banks' links (StreamMemoryConfig::link_bytes_per_cycle).
  bool stream_link = true;
  uint32_t calendar_horizon_cycles = 16384;  // as the L1 data cache's
  // STRaTA's CACTI figures include the arrays' own routing; the crossbar wires are not in
  // its table, so they cost nothing unless a figure is given.
  double transfer_energy_nj = 0.0;
  void validate() const;
};

}  // namespace strata::memory
