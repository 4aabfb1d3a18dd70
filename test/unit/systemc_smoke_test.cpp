// Proves SystemC, TLM-2.0 and GoogleTest link and run together in one process.
#include <gtest/gtest.h>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include <array>
#include <cstdint>
#include <cstring>

namespace {

struct EchoMemory : sc_core::sc_module {
  tlm_utils::simple_target_socket<EchoMemory> socket{"socket"};
  std::array<uint8_t, 64> bytes{};

  explicit EchoMemory(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    socket.register_b_transport(this, &EchoMemory::b_transport);
  }

  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
    const uint64_t addr = trans.get_address();
    if (addr + trans.get_data_length() > bytes.size()) {
      trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
      return;
    }
    if (trans.is_write())
      std::memcpy(&bytes[addr], trans.get_data_ptr(), trans.get_data_length());
    else
      std::memcpy(trans.get_data_ptr(), &bytes[addr], trans.get_data_length());
    delay += sc_core::sc_time(3, sc_core::SC_NS);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
  }
};

struct Initiator : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Initiator> socket{"socket"};
  uint32_t read_back = 0;
  sc_core::sc_time finished_at;
  bool address_error_seen = false;

  SC_HAS_PROCESS(Initiator);
  explicit Initiator(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_THREAD(run);
  }

  void transfer(tlm::tlm_command cmd, uint64_t addr, uint32_t& value) {
    tlm::tlm_generic_payload trans;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    trans.set_command(cmd);
    trans.set_address(addr);
    trans.set_data_ptr(reinterpret_cast<unsigned char*>(&value));
    trans.set_data_length(sizeof value);
    trans.set_streaming_width(sizeof value);
    trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    socket->b_transport(trans, delay);
    if (trans.get_response_status() == tlm::TLM_ADDRESS_ERROR_RESPONSE) address_error_seen = true;
    wait(delay);
  }

  void run() {
    uint32_t value = 0xC0FFEEu;
    transfer(tlm::TLM_WRITE_COMMAND, 8, value);
    transfer(tlm::TLM_READ_COMMAND, 8, read_back);
    uint32_t scratch = 0;
    transfer(tlm::TLM_READ_COMMAND, 1000, scratch);
    finished_at = sc_core::sc_time_stamp();
  }
};

}  // namespace

TEST(SystemCSmoke, TargetAnswersBTransportWithAnnotatedDelay) {
  Initiator initiator("initiator");
  EchoMemory memory("memory");
  initiator.socket.bind(memory.socket);
  sc_core::sc_start();
  EXPECT_EQ(initiator.read_back, 0xC0FFEEu);
  EXPECT_TRUE(initiator.address_error_seen);
  // Two good transactions of 3 ns each, waited for one after another; the rejected one
  // returns at once.
  EXPECT_EQ(initiator.finished_at, sc_core::sc_time(6, sc_core::SC_NS));
}
