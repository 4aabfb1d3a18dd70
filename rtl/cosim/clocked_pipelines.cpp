// The verilated pipelines clocked by hand: see clocked_pipelines.h.
#include "rtl/cosim/clocked_pipelines.h"

#include <cerrno>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

#include "Vbox_pipeline_cc.h"
#include "Vtriangle_pipeline_cc.h"
#include "verilated.h"
#include "verilated_vcd_c.h"

#include "firmware/common/float_bits.h"

namespace strata::rtl {
namespace {

float lane_float(uint64_t v, int lane) { return bits_float(static_cast<uint32_t>(v >> (32 * lane))); }
bool lane_bit(uint32_t v, int lane) { return (v >> lane & 1u) != 0; }
uint64_t on_lane(float f, int lane) { return static_cast<uint64_t>(float_bits(f)) << (32 * lane); }

// The longest latency is 33 cycles; a pipeline silent for this long never answers.
constexpr uint64_t kMaxCyclesPerOperation = 1000;

// Verilator's VCD file with every write checked: the first error is kept and reported by
// close_vcd(), and writes are then dropped but reported done, since Verilator would abort the
// whole process on a failed one. fsync at the close: a full disk may show only there.
class CheckedVcdFile : public VerilatedVcdFile {
 public:
  bool open(const std::string& name) override {
    fd_ = ::open(name.c_str(), O_CREAT | O_WRONLY | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) error_ = errno;
    return fd_ >= 0;
  }
  ssize_t write(const char* data, ssize_t bytes) override {
    for (ssize_t done = 0; done < bytes && error_ == 0;) {
      const ssize_t n = ::write(fd_, data + done, static_cast<size_t>(bytes - done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) error_ = n < 0 ? errno : EIO;
      else done += n;
    }
    return bytes;
  }
  void close() override {
    if (fd_ < 0) return;
    if (error_ == 0 && ::fsync(fd_) != 0 && errno != EINVAL) error_ = errno;
    if (::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
  }
  int error() const { return error_; }

 private:
  int fd_ = -1;
  int error_ = 0;
};

}  // namespace

struct ClockedPipelines::Models {
  // One context per instance: no state shared with any other model in the process.
  VerilatedContext context;
  std::unique_ptr<Vbox_pipeline_cc> box;
  std::unique_ptr<Vtriangle_pipeline_cc> triangle;
  // The file outlives the VerilatedVcdC that writes to it (declared before it).
  std::unique_ptr<CheckedVcdFile> vcd_file;
  std::unique_ptr<VerilatedVcdC> vcd;
};

ClockedPipelines::ClockedPipelines() : m_(std::make_unique<Models>()) {
  // Whether a run traces is decided later, but the models must be built able to (it keeps
  // signals Verilator would otherwise optimise away); it costs nothing until a VCD is open.
  m_->context.traceEverOn(true);
  m_->context.timeprecision(-12);  // the VCD's time unit, 1 ps
  m_->box = std::make_unique<Vbox_pipeline_cc>(&m_->context, "box_pipeline");
  m_->triangle = std::make_unique<Vtriangle_pipeline_cc>(&m_->context, "triangle_pipeline");
  Vbox_pipeline_cc& b = *m_->box;
  Vtriangle_pipeline_cc& t = *m_->triangle;
  // Synchronous reset, as PipelineTransactor applies it: high for the first two edges.
  b.rst = 1;
  t.rst = 1;
  b.out_ready = 1;
  t.out_ready = (1u << kTriangleLanes) - 1;
  for (uint64_t i = 0; i < kResetCycles; ++i) {
    clock(b, box_cycle_);
    clock(t, triangle_cycle_);
  }
  b.rst = 0;
  t.rst = 0;
  b.eval();
  t.eval();
}

ClockedPipelines::~ClockedPipelines() {
  if (m_->vcd) m_->vcd->close();
  m_->box->final();
  m_->triangle->final();
}

void ClockedPipelines::open_vcd(const std::string& path) {
  m_->vcd_file = std::make_unique<CheckedVcdFile>();
  m_->vcd = std::make_unique<VerilatedVcdC>(m_->vcd_file.get());
  m_->box->trace(m_->vcd.get(), 99);
  m_->triangle->trace(m_->vcd.get(), 99);
  m_->vcd->open(path.c_str());
  if (!m_->vcd->isOpen()) throw std::runtime_error(path + ": cannot write the RTL pipelines' VCD");
}

int ClockedPipelines::close_vcd() {
  if (m_->vcd) m_->vcd->close();
  m_->vcd.reset();  // no dump after this (trace_from sees no VCD)
  tracing_ = false;
  return m_->vcd_file ? m_->vcd_file->error() : 0;
}

void ClockedPipelines::trace_from(uint64_t time_ps) {
  tracing_ = m_->vcd != nullptr;
  if (time_ps > trace_time_) trace_time_ = time_ps;
}

void ClockedPipelines::dump() {
  if (!tracing_) return;
  m_->vcd->dump(trace_time_);
  ++trace_time_;
}

template <class Model>
uint64_t ClockedPipelines::clock(Model& model, uint64_t& cycle) {
  model.clk = 1;
  model.eval();
  ++cycle;
  dump();
  model.clk = 0;
  model.eval();
  dump();
  return cycle;
}

BoxResult ClockedPipelines::box(const BoxOperands& in, OpTiming* timing) {
  Vbox_pipeline_cc& m = *m_->box;
  m.bmin_x = float_bits(in.bmin[0]);
  m.bmin_y = float_bits(in.bmin[1]);
  m.bmin_z = float_bits(in.bmin[2]);
  m.bmax_x = float_bits(in.bmax[0]);
  m.bmax_y = float_bits(in.bmax[1]);
  m.bmax_z = float_bits(in.bmax[2]);
  m.origin_x = float_bits(in.ray.origin.x);
  m.origin_y = float_bits(in.ray.origin.y);
  m.origin_z = float_bits(in.ray.origin.z);
  m.inv_dir_x = float_bits(in.ray.inv_dir.x);
  m.inv_dir_y = float_bits(in.ray.inv_dir.y);
  m.inv_dir_z = float_bits(in.ray.inv_dir.z);
  m.tmin = float_bits(in.ray.tmin);
  m.tmax = float_bits(in.ray.tmax);
  m.in_valid = 1;
  m.eval();  // in_ready follows the pins combinationally
  BoxResult result;
  bool accepted = false;
  for (uint64_t n = 0; n < kMaxCyclesPerOperation; ++n) {
    // What the coming edge sees: the pins as they are now.
    const bool accept = !accepted && m.in_valid && m.in_ready;
    const bool leave = accepted && m.out_valid && m.out_ready;
    if (leave) result = {m.out_hit != 0, m.out_overlap != 0, bits_float(m.out_t_entry)};
    const uint64_t edge = clock(m, box_cycle_);
    if (leave) {
      timing->done_cycle = edge;
      timing->latency_cycles = static_cast<uint32_t>(edge - timing->accept_cycle);
      timing->lane = 0;
      return result;
    }
    if (accept) {
      accepted = true;
      timing->accept_cycle = edge;
      m.in_valid = 0;
      m.eval();
    }
  }
  throw std::runtime_error("the RTL box pipeline gave no result within " + std::to_string(kMaxCyclesPerOperation) +
                           " cycles");
}

TriangleResult ClockedPipelines::triangle(const TriangleOperands& in, OpTiming* timing) {
  Vtriangle_pipeline_cc& m = *m_->triangle;
  const int lane = next_lane_;
  next_lane_ = (next_lane_ + 1) % kTriangleLanes;
  // The other lane's operand words are zero: its in_valid is low.
  m.v0_x = on_lane(in.v0.x, lane);
  m.v0_y = on_lane(in.v0.y, lane);
  m.v0_z = on_lane(in.v0.z, lane);
  m.v1_x = on_lane(in.v1.x, lane);
  m.v1_y = on_lane(in.v1.y, lane);
  m.v1_z = on_lane(in.v1.z, lane);
  m.v2_x = on_lane(in.v2.x, lane);
  m.v2_y = on_lane(in.v2.y, lane);
  m.v2_z = on_lane(in.v2.z, lane);
  m.origin_x = on_lane(in.origin.x, lane);
  m.origin_y = on_lane(in.origin.y, lane);
  m.origin_z = on_lane(in.origin.z, lane);
  m.dir_x = on_lane(in.dir.x, lane);
  m.dir_y = on_lane(in.dir.y, lane);
  m.dir_z = on_lane(in.dir.z, lane);
  m.in_valid = static_cast<uint8_t>(1u << lane);
  m.eval();
  TriangleResult result;
  bool accepted = false;
  for (uint64_t n = 0; n < kMaxCyclesPerOperation; ++n) {
    const bool accept = !accepted && lane_bit(m.in_valid, lane) && lane_bit(m.in_ready, lane);
    const bool leave = accepted && lane_bit(m.out_valid, lane) && lane_bit(m.out_ready, lane);
    if (leave) {
      result.hit = lane_bit(m.out_hit, lane);
      result.exact = lane_bit(m.out_exact, lane);
      result.partial = {lane_float(m.out_e0, lane), lane_float(m.out_e1, lane), lane_float(m.out_e2, lane),
                        lane_float(m.out_t_num, lane), lane_float(m.out_t_den, lane)};
    }
    const uint64_t edge = clock(m, triangle_cycle_);
    if (leave) {
      timing->done_cycle = edge;
      timing->latency_cycles = static_cast<uint32_t>(edge - timing->accept_cycle);
      timing->lane = static_cast<uint32_t>(lane);
      return result;
    }
    if (accept) {
      accepted = true;
      timing->accept_cycle = edge;
      m.in_valid = 0;
      m.eval();
    }
  }
  throw std::runtime_error("the RTL triangle pipeline gave no result within " +
                           std::to_string(kMaxCyclesPerOperation) + " cycles");
}

}  // namespace strata::rtl
