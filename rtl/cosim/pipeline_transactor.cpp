// TLM-2.0 transactor for the verilated fused pipelines: see pipeline_transactor.h.
#include "rtl/cosim/pipeline_transactor.h"

#include <string>

#include "firmware/common/float_bits.h"

namespace strata::rtl {
namespace {

uint32_t lane_word(uint64_t v, int lane) { return static_cast<uint32_t>(v >> (32 * lane)); }
bool lane_bit(uint32_t v, int lane) { return (v >> lane & 1u) != 0; }

}  // namespace

PipelineTransactor::PipelineTransactor(sc_core::sc_module_name name, sc_core::sc_time clock_period)
    : sc_core::sc_module(name),
      socket("socket"),
      clk_("clk", clock_period),
      box_("box_pipeline"),
      triangle_("triangle_pipeline") {
  socket.register_b_transport(this, &PipelineTransactor::b_transport);

  box_.clk(clk_);
  box_.rst(rst_);
  box_.in_valid(box_in_valid_);
  box_.in_ready(box_in_ready_);
  sc_core::sc_in<uint32_t>* box_ports[kBoxOperands] = {
      &box_.bmin_x,   &box_.bmin_y,   &box_.bmin_z,    &box_.bmax_x,    &box_.bmax_y,    &box_.bmax_z, &box_.origin_x,
      &box_.origin_y, &box_.origin_z, &box_.inv_dir_x, &box_.inv_dir_y, &box_.inv_dir_z, &box_.tmin,   &box_.tmax};
  for (int i = 0; i < kBoxOperands; ++i) (*box_ports[i])(box_operand_[i]);
  box_.out_valid(box_out_valid_);
  box_.out_ready(box_out_ready_);
  box_.out_hit(box_out_hit_);
  box_.out_overlap(box_out_overlap_);
  box_.out_t_entry(box_out_t_entry_);

  triangle_.clk(clk_);
  triangle_.rst(rst_);
  triangle_.in_valid(tri_in_valid_);
  triangle_.in_ready(tri_in_ready_);
  sc_core::sc_in<uint64_t>* tri_ports[kTriangleOperands] = {
      &triangle_.v0_x,     &triangle_.v0_y,     &triangle_.v0_z,     &triangle_.v1_x,  &triangle_.v1_y,
      &triangle_.v1_z,     &triangle_.v2_x,     &triangle_.v2_y,     &triangle_.v2_z,  &triangle_.origin_x,
      &triangle_.origin_y, &triangle_.origin_z, &triangle_.dir_x,    &triangle_.dir_y, &triangle_.dir_z};
  for (int i = 0; i < kTriangleOperands; ++i) (*tri_ports[i])(tri_operand_[i]);
  triangle_.out_valid(tri_out_valid_);
  triangle_.out_ready(tri_out_ready_);
  triangle_.out_hit(tri_out_hit_);
  triangle_.out_exact(tri_out_exact_);
  triangle_.out_e0(tri_out_e0_);
  triangle_.out_e1(tri_out_e1_);
  triangle_.out_e2(tri_out_e2_);
  triangle_.out_t_num(tri_out_t_num_);
  triangle_.out_t_den(tri_out_t_den_);

  SC_METHOD(on_edge);
  sensitive << clk_.posedge_event();
  dont_initialize();
}

void PipelineTransactor::b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay) {
  FusedOpExtension* op = nullptr;
  payload.get_extension(op);
  if (op == nullptr || payload.get_command() != tlm::TLM_IGNORE_COMMAND) {
    payload.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  sc_core::wait(delay);
  delay = sc_core::SC_ZERO_TIME;
  Request request;
  request.op = op;
  request.arrived = sc_core::sc_time_stamp();
  (op->kind == FusedOpKind::kBox ? box_queue_ : triangle_queue_).push_back(&request);
  sc_core::wait(request.done);
  payload.set_response_status(tlm::TLM_OK_RESPONSE);
}

void PipelineTransactor::on_edge() {
  ++cycle_;
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  // Requests that arrived before this edge see it as their first; one arriving at the time
  // of the edge itself waits for the next edge (deterministic whatever the process order).
  for (std::deque<Request*>* q : {&box_queue_, &triangle_queue_})
    for (Request* r : *q)
      if (r->first_edge == 0 && r->arrived < now) r->first_edge = cycle_;
  if (!rst_.read()) {
    drive_box();
    drive_triangle();
  }
  rst_.write(cycle_ < kResetCycles);
}

// Samples the box pipeline's handshakes of the edge, then drives its inputs for the next one.
void PipelineTransactor::drive_box() {
  if (box_out_valid_.read() && box_out_ready_.read()) {
    if (box_in_flight_.empty()) SC_REPORT_FATAL("strata/rtl/transactor", "box pipeline produced an unrequested result");
    Request* r = box_in_flight_.front();
    box_in_flight_.pop_front();
    r->op->box_result = {box_out_hit_.read(), box_out_overlap_.read(), bits_float(box_out_t_entry_.read())};
    r->op->done_cycle = cycle_;
    r->op->latency_cycles = static_cast<uint32_t>(cycle_ - r->op->accept_cycle);
    ++box_done_;
    r->done.notify();
  }
  if (box_presented_ != nullptr && box_in_valid_.read() && box_in_ready_.read()) {
    box_presented_->op->accept_cycle = cycle_;
    box_presented_->op->queued_cycles = static_cast<uint32_t>(cycle_ - box_presented_->first_edge - 1);
    box_presented_->op->lane = 0;
    box_in_flight_.push_back(box_presented_);
    box_presented_ = nullptr;
  }
  if (box_presented_ == nullptr && !box_queue_.empty() && box_queue_.front()->first_edge != 0) {
    box_presented_ = box_queue_.front();
    box_queue_.pop_front();
    const BoxOperands& b = box_presented_->op->box;
    const float v[kBoxOperands] = {b.bmin[0],        b.bmin[1],        b.bmin[2],        b.bmax[0],       b.bmax[1],
                                   b.bmax[2],        b.ray.origin.x,   b.ray.origin.y,   b.ray.origin.z,  b.ray.inv_dir.x,
                                   b.ray.inv_dir.y,  b.ray.inv_dir.z,  b.ray.tmin,       b.ray.tmax};
    for (int i = 0; i < kBoxOperands; ++i) box_operand_[i].write(float_bits(v[i]));
  }
  box_in_valid_.write(box_presented_ != nullptr);
  box_out_ready_.write(true);
}

void PipelineTransactor::drive_triangle() {
  const uint32_t out_valid = tri_out_valid_.read(), out_ready = tri_out_ready_.read();
  const uint32_t in_valid = tri_in_valid_.read(), in_ready = tri_in_ready_.read();
  bool accepted_now[kTriangleLanes] = {false, false};
  for (int l = 0; l < kTriangleLanes; ++l) {
    if (lane_bit(out_valid, l) && lane_bit(out_ready, l)) {
      if (tri_in_flight_[l].empty())
        SC_REPORT_FATAL("strata/rtl/transactor", "triangle pipeline produced an unrequested result");
      Request* r = tri_in_flight_[l].front();
      tri_in_flight_[l].pop_front();
      TriangleResult& res = r->op->triangle_result;
      res.hit = lane_bit(tri_out_hit_.read(), l);
      res.exact = lane_bit(tri_out_exact_.read(), l);
      res.partial = {bits_float(lane_word(tri_out_e0_.read(), l)), bits_float(lane_word(tri_out_e1_.read(), l)),
                     bits_float(lane_word(tri_out_e2_.read(), l)), bits_float(lane_word(tri_out_t_num_.read(), l)),
                     bits_float(lane_word(tri_out_t_den_.read(), l))};
      r->op->done_cycle = cycle_;
      r->op->latency_cycles = static_cast<uint32_t>(cycle_ - r->op->accept_cycle);
      ++triangle_done_;
      r->done.notify();
    }
    Request*& presented = tri_presented_[l];
    if (presented != nullptr && lane_bit(in_valid, l) && lane_bit(in_ready, l)) {
      presented->op->accept_cycle = cycle_;
      presented->op->queued_cycles = static_cast<uint32_t>(cycle_ - presented->first_edge - 1);
      presented->op->lane = static_cast<uint32_t>(l);
      tri_in_flight_[l].push_back(presented);
      presented = nullptr;
      accepted_now[l] = true;
      tri_last_accept_[l] = cycle_;
    }
  }
  // The oldest waiting request goes to a lane with nothing on its pins: a free lane (ready
  // before this edge and not just taken) if there is one, else the lane that accepted its last
  // operation earliest (the lanes are identical, so it is the first to be ready again). It
  // stays on that lane's pins until the lane accepts it.
  uint64_t words[kTriangleOperands];
  for (int i = 0; i < kTriangleOperands; ++i) words[i] = tri_operand_[i].read();
  while (!triangle_queue_.empty() && triangle_queue_.front()->first_edge != 0) {
    int pick = -1;
    for (int l = 0; l < kTriangleLanes && pick < 0; ++l)
      if (tri_presented_[l] == nullptr && lane_bit(in_ready, l) && !accepted_now[l]) pick = l;
    for (int l = 0; l < kTriangleLanes && pick < 0; ++l)
      if (tri_presented_[l] == nullptr) pick = l;
    if (pick < 0) break;
    for (int l = pick + 1; l < kTriangleLanes; ++l)
      if (tri_presented_[l] == nullptr && !(lane_bit(in_ready, pick) && !accepted_now[pick]) &&
          tri_last_accept_[l] < tri_last_accept_[pick])
        pick = l;
    Request* r = triangle_queue_.front();
    triangle_queue_.pop_front();
    tri_presented_[pick] = r;
    const TriangleOperands& t = r->op->triangle;
    const float v[kTriangleOperands] = {t.v0.x,     t.v0.y,     t.v0.z,     t.v1.x,  t.v1.y,
                                        t.v1.z,     t.v2.x,     t.v2.y,     t.v2.z,  t.origin.x,
                                        t.origin.y, t.origin.z, t.dir.x,    t.dir.y, t.dir.z};
    const uint64_t mask = 0xFFFFFFFFull << (32 * pick);
    for (int i = 0; i < kTriangleOperands; ++i)
      words[i] = (words[i] & ~mask) | static_cast<uint64_t>(float_bits(v[i])) << (32 * pick);
  }
  uint32_t valid = 0;
  for (int l = 0; l < kTriangleLanes; ++l)
    if (tri_presented_[l] != nullptr) valid |= 1u << l;
  for (int i = 0; i < kTriangleOperands; ++i) tri_operand_[i].write(words[i]);
  tri_in_valid_.write(valid);
  tri_out_ready_.write((1u << kTriangleLanes) - 1);
}

}  // namespace strata::rtl
