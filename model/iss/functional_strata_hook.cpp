#include "model/iss/functional_strata_hook.h"

#include <cstring>

#include "firmware/common/float_bits.h"

namespace strata::iss {
namespace {

HookResult ok(uint32_t d0 = 0, uint32_t d1 = 0, uint32_t d2 = 0) {
  HookResult r;
  r.dest[0] = d0;
  r.dest[1] = d1;
  r.dest[2] = d2;
  return r;
}

HookResult illegal(const char* why) {
  HookResult r;
  r.status = HookStatus::kIllegal;
  r.message = why;
  return r;
}

}  // namespace

FunctionalStrataHook::FunctionalStrataHook(const Config& config) : config_(config) {}

HookResult FunctionalStrataHook::execute(const HookCall& call) {
  switch (call.op) {
    case Op::kStThreadId: return ok(config_.tm_id * config_.tps_per_tm + config_.tp_id);
    case Op::kStTpId: return ok(config_.tp_id);
    case Op::kStTmId: return ok(config_.tm_id);
    case Op::kStThreadCount: return ok(config_.tps_per_tm * config_.tm_count);
    case Op::kStTpsPerTm: return ok(config_.tps_per_tm);
    case Op::kStTmCount: return ok(config_.tm_count);
    case Op::kStAtomicInc:
    case Op::kStAtomicAdd:
    case Op::kStGlobalRead:
    case Op::kStGlobalWrite: {
      if (call.rs1 >= globals_.size()) return illegal("global register index out of range");
      uint32_t& g = globals_[call.rs1];
      const uint32_t old = g;
      if (call.op == Op::kStAtomicInc) g += 1;
      if (call.op == Op::kStAtomicAdd) g += call.rs2;
      if (call.op == Op::kStGlobalWrite) g = call.rs2;
      return ok(old);
    }
    case Op::kStStreamCapacity:
    case Op::kStStreamPush:
    case Op::kStStreamPop:
    case Op::kStStreamPush64:
    case Op::kStStreamPop64:
    case Op::kStStreamAssign: return stream(call);
    default: return pipeline(call);
  }
}

HookResult FunctionalStrataHook::pipeline(const HookCall& call) {
  switch (call.op) {
    case Op::kStPipeGeneral: mode_ = Mode::kGeneral; return ok();
    case Op::kStPipeBox: mode_ = Mode::kBox; return ok();
    case Op::kStPipeTriangle: mode_ = Mode::kTriangle; return ok();
    case Op::kStLoadRay: std::memcpy(&ray_, call.in, STRATA_PIPE_RAY_WORDS * 4); return ok();
    case Op::kStLoadBox: std::memcpy(&box_, call.in, sizeof box_); return ok();
    case Op::kStLoadTriangle: std::memcpy(&triangle_, call.in, sizeof triangle_); return ok();
    case Op::kStSetTmax: std::memcpy(&ray_.tmax, &call.rs1, 4); return ok();
    case Op::kStBoxTest: {
      if (mode_ != Mode::kBox) return illegal("strata.boxtest needs the box pipeline configured");
      const BoxTestResult r = backend_ ? backend_->box_test(ray_, box_) : box_test(ray_, box_);
      return ok(r.hit ? 1u : 0u, 0, float_bits(r.t_entry));
    }
    case Op::kStTriangleTest:
      if (mode_ != Mode::kTriangle) return illegal("strata.tritest needs the triangle pipeline configured");
      last_triangle_ = backend_ ? backend_->triangle_test(ray_, triangle_, last_triangle_.partial)
                                : triangle_test(ray_, triangle_, last_triangle_.partial);
      return ok(last_triangle_.hit ? 1u : 0u);
    case Op::kStTriangleDivide: {
      if (mode_ != Mode::kTriangle) return illegal("strata.tridiv needs the triangle pipeline configured");
      const TriangleHit h = triangle_divide(last_triangle_.partial);
      return ok(float_bits(h.t), float_bits(h.b1), float_bits(h.b2));
    }
    default: break;
  }
  HookResult r;
  r.status = HookStatus::kFatal;
  r.message = "operation not implemented by the functional STRaTA hook";
  return r;
}

HookResult FunctionalStrataHook::stream(const HookCall& call) {
  switch (call.op) {
    case Op::kStStreamCapacity: return ok(config_.stream_capacity);
    case Op::kStStreamPush:
    case Op::kStStreamPush64: {
      if (rays_queued_ >= config_.stream_capacity) return ok(0);
      StreamRay ray{};
      ray.bytes = stream_ray_bytes(call.op);
      std::memcpy(ray.words.data(), call.in, ray.bytes);
      buffers_[call.rs2].push_back(ray);
      ++rays_queued_;
      return ok(1);
    }
    case Op::kStStreamPop:
    case Op::kStStreamPop64: {
      auto it = buffers_.find(current_treelet_);
      if (it == buffers_.end() || it->second.empty()) return ok(0);
      const StreamRay& ray = it->second.back();
      if (ray.bytes != stream_ray_bytes(call.op)) {
        HookResult r;
        r.status = HookStatus::kIllegal;
        r.message = ray.bytes == STRATA_STREAM_RAY_BYTES ? "a 64-byte stream pop of a 48-byte ray"
                                                          : "a 48-byte stream pop of a 64-byte ray";
        return r;
      }
      std::memcpy(call.out, ray.words.data(), ray.bytes);
      it->second.pop_back();
      --rays_queued_;
      HookResult r = ok(1);
      r.status = HookStatus::kStore;
      return r;
    }
    default: {  // kStStreamAssign: keep a non-empty buffer, else take the fullest one
      auto current = buffers_.find(current_treelet_);
      if (current != buffers_.end() && !current->second.empty()) return ok(current_treelet_);
      current_treelet_ = STRATA_NO_TREELET;
      size_t best = 0;
      for (const auto& [treelet, rays] : buffers_) {
        if (rays.size() > best) {
          best = rays.size();
          current_treelet_ = treelet;
        }
      }
      return ok(current_treelet_);
    }
  }
}

}  // namespace strata::iss
