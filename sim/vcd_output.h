// The chip's VCD (`run --vcd FILE`), written as every other output (sim/output_file.h): under
// exactly the name given, complete or not at all, a failed write an error.
//
// SystemC's VCD writer opens "<base>.vcd" itself through stdio and never reports a failed write
// (a full disk left a cut-off file and exit 0). So it is given a FIFO to write to, and a thread
// copies what comes out into a temporary beside the final file with every write checked;
// commit() renames the temporary once everything arrived and was written.
#pragma once

#include <filesystem>
#include <memory>
#include <thread>

#include <systemc>

#include "sim/output_file.h"

namespace strata::sim {

class VcdOutput {
 public:
  // Creates the trace file (before the simulation starts, as SystemC requires).
  explicit VcdOutput(const std::filesystem::path& file);
  // If never committed: closes the trace file and removes every temporary.
  ~VcdOutput();
  VcdOutput(const VcdOutput&) = delete;
  VcdOutput& operator=(const VcdOutput&) = delete;

  sc_core::sc_trace_file* trace_file() const { return trace_; }
  // Closes SystemC's trace file and waits until the copy has all of it. Idempotent.
  void close();
  // close(), then the checked rename; throws "<file>: cannot write VCD: <reason>".
  void commit();

 private:
  void copy();  // the copying thread

  PendingFile out_;
  CheckedFile data_;
  std::filesystem::path fifo_;
  int read_end_ = -1;
  int keep_open_ = -1;  // a writer of our own, so the copy sees no end before SystemC opens it
  std::thread copier_;
  sc_core::sc_trace_file* trace_ = nullptr;
};

}  // namespace strata::sim
