// The hart's memory interface: another policy type (as the TLM thread processor will use),
// and FlatMemory's out-of-region fallback.
#include "iss_test_support.h"

#include "model/iss/hart_impl.h"

#include <gtest/gtest.h>

#include <map>

namespace strata::iss::testing {
namespace {

using namespace enc;

// Records every access and forwards it to a flat memory.
class RecordingMemory {
 public:
  explicit RecordingMemory(FlatMemory& backing) : backing_(backing) {}

  template <unsigned N>
  bool load(uint32_t addr, uint32_t& value) {
    log.push_back({'L', addr, N});
    return backing_.load<N>(addr, value);
  }
  template <unsigned N>
  bool store(uint32_t addr, uint32_t value) {
    log.push_back({'S', addr, N});
    return backing_.store<N>(addr, value);
  }

  struct Access {
    char kind;
    uint32_t addr;
    unsigned size;
  };
  std::vector<Access> log;

 private:
  FlatMemory& backing_;
};

TEST(IssMemory, HartRunsOnAnotherMemoryPolicy) {
  FlatMemory flat(0x1000, 0x2000);
  std::vector<uint32_t> code = {lw(2, 1, 0), sh(2, 1, 6), lbu(3, 1, 7), halt()};
  flat.write(0x1000, code.data(), code.size() * 4);
  flat.write32(0x2000, 0xCAFEBABEu);
  CodeImage image(0x1000, code);
  RecordingMemory memory(flat);
  Hart<RecordingMemory> hart(image, memory);
  hart.set_x(1, 0x2000);
  ASSERT_EQ(hart.run(10).reason, StopReason::kHalt);
  EXPECT_EQ(hart.x(3), 0xBAu);  // the high byte of the stored halfword 0xBABE
  ASSERT_EQ(memory.log.size(), 3u);  // fetches come from the code image, not the policy
  EXPECT_EQ(memory.log[0].kind, 'L');
  EXPECT_EQ(memory.log[1].kind, 'S');
  EXPECT_EQ(memory.log[1].addr, 0x2006u);
  EXPECT_EQ(memory.log[1].size, 2u);
  EXPECT_EQ(memory.log[2].size, 1u);
}

// A device register file outside guest memory, reached through the fallback pointers.
struct Device {
  std::map<uint32_t, uint32_t> registers;
  static bool load(void* self, uint32_t addr, unsigned size, uint32_t& value) {
    auto& regs = static_cast<Device*>(self)->registers;
    if (addr < 0xF0000000u || size != 4) return false;
    value = regs[addr];
    return true;
  }
  static bool store(void* self, uint32_t addr, unsigned size, uint32_t value) {
    if (addr < 0xF0000000u || size != 4) return false;
    static_cast<Device*>(self)->registers[addr] = value;
    return true;
  }
};

TEST(IssMemory, OutOfRegionAccessesUseTheFallback) {
  Device device;
  device.registers[0xF0000000u] = 1234;
  Machine m({lw(2, 1, 0), addi(2, 2, 1), sw(2, 1, 4), lb(3, 1, 0)});
  m.memory.set_fallback({&device, &Device::load, &Device::store});
  m.hart.set_x(1, 0xF0000000u);
  const RunResult r = m.run();
  EXPECT_EQ(m.hart.x(2), 1235u);
  EXPECT_EQ(device.registers[0xF0000004u], 1235u);
  EXPECT_EQ(r.reason, StopReason::kTrap);  // the device refuses byte accesses
  EXPECT_EQ(r.cause, cause::kLoadAccessFault);
  EXPECT_EQ(r.tval, 0xF0000000u);
}

TEST(IssMemory, FlatMemoryBounds) {
  FlatMemory mem(0x1000, 16);
  uint32_t v = 0;
  EXPECT_TRUE(mem.load<4>(0x100C, v));
  EXPECT_FALSE(mem.load<4>(0x1010, v));
  EXPECT_FALSE(mem.load<1>(0x0FFF, v));
  EXPECT_FALSE(mem.store<2>(0xFFFFFFFEu, 0));
  EXPECT_TRUE(mem.store<1>(0x100F, 0xAB));
  EXPECT_THROW(mem.write32(0x100E, 0), std::out_of_range);
  EXPECT_THROW(FlatMemory(0xFFFFFFF0u, 32), std::invalid_argument);
}

}  // namespace
}  // namespace strata::iss::testing
