// Off-chip DRAM: channels interleaved by address, each with a share of the total peak
// bandwidth, an access latency and queueing under load. The data bus of each channel is a
// reservation calendar in bytes per cycle: an access asks for its bytes at or after
// request + latency, so an idle channel answers in latency + bytes/bandwidth and a busy one
// queues it behind the bytes already booked. Functional data lives in the SparseMemory.
// With memory.dram.model = banked, the time from request to data comes from BankedDram
// instead (banks, row buffers, command timing); the channels, their hash, their buses and
// every statistic here stay, and BankedDram's statistics join them under "banked".
#pragma once

#include "model/memory/bank_interleave.h"
#include "model/memory/config.h"
#include "model/memory/data_traffic.h"
#include "model/memory/memory_levels.h"
#include "model/memory/dram_banked.h"
#include "model/memory/sparse_memory.h"
#include "model/stats/stat_group.h"
#include "model/memory/window_trace.h"
#include "tlm/clock.h"
#include "tlm/memory_extension.h"
#include "tlm/reservation_calendar.h"

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include <memory>
#include <vector>

namespace strata::memory {

class Dram : public sc_core::sc_module, public DramLevel {
 public:
  tlm_utils::simple_target_socket<Dram> target{"target"};
  tlm::tlm_target_socket<>& target_socket() override { return target; }

  struct ChannelCounters {
    uint64_t accesses = 0;  // bursts of up to burst_bytes
    uint64_t requests = 0;
    uint64_t bytes_read = 0, bytes_written = 0;
    uint64_t queued_cycles = 0;  // waiting for the bus beyond the unloaded latency
    double energy_nj = 0.0;
  };
  struct Counters {
    uint64_t accesses = 0, requests = 0, bytes_read = 0, bytes_written = 0;
    double energy_nj = 0.0;
    DataTraffic by_data{};  // requests and bytes by what they hold
  };

  Dram(sc_core::sc_module_name name, const DramConfig& config, SparseMemory& backing);

  // Blocks of interleave_bytes go to channels in turn; hashed (the default), the block index is
  // XOR-folded first, as memory controllers do, so that the 32 KB-aligned treelets' first
  // blocks do not all land in channel 0 (docs/memory-system.md, "Bank selection").
  uint32_t channel_of(uint64_t addr) const {
    return channels_of_.bank(addr >> interleave_shift_);
  }
  // The chip's clock (default 1 GHz). Before sc_start: every module of a chip must count in
  // the same cycles as the TMs, or each latency in cycles stretches by the ratio of the clocks.
  void set_clock(const transport::Clock& clock) override;
  const Counters& counters() const { return counters_; }
  const ChannelCounters& channel(uint32_t c) const { return channels_[c]; }
  const stats::Group& stats() const override { return stats_; }
  const DramConfig& config() const { return config_; }
  SparseMemory& backing() { return backing_; }
  const BankedDram* banked() const { return banked_.get(); }  // null unless model = banked
  uint64_t overflow_bookings() const;
  // VCD: per channel, bytes per cycle over each window and queue depth (booked cycles ahead);
  // banked, over the whole DRAM: row hits, misses and conflicts per cycle, the latest read latency.
  using sc_core::sc_object::trace;  // ours adds a window; the base's stays visible
  void trace(sc_core::sc_trace_file* file, const TraceWindow& window) override;

 private:
  void b_transport(tlm::tlm_generic_payload& gp, sc_core::sc_time& delay);

  DramConfig config_;
  SparseMemory& backing_;
  transport::Clock clock_;
  uint32_t interleave_shift_ = 0;
  BankInterleave channels_of_{1, false};  // set from the config in the constructor
  std::vector<transport::ReservationCalendar> buses_;
  std::unique_ptr<BankedDram> banked_;
  std::vector<ChannelCounters> channels_;
  Counters counters_;
  stats::Group stats_;
  std::vector<std::unique_ptr<stats::Group>> channel_stats_;
  std::unique_ptr<DataTrafficStats> by_data_stats_;
  WindowTrace trace_;
  std::vector<std::size_t> tr_bandwidth_, tr_depth_;
  std::vector<std::size_t> tr_rows_;  // banked: hits, misses, conflicts (RowOutcome order)
  std::size_t tr_latency_ = 0;
};

}  // namespace strata::memory
