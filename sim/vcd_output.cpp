#include "sim/vcd_output.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include <sysc/tracing/sc_tracing_ids.h>  // not included by <systemc>

namespace strata::sim {
namespace {

namespace fs = std::filesystem;

// SystemC appends ".vcd" to the name it is given; the FIFO is named so that it ends so.
const char* const kSystemcSuffix = ".vcd";

// The FIFO beside the temporary (its name ends in .tmp.<pid>..., as every temporary's does);
// where FIFOs cannot be made (a FAT stick), in the system's temp folder: only bytes pass
// through it, so its folder does not matter.
fs::path make_fifo(const fs::path& temporary) {
  fs::path beside = temporary;
  beside += std::string(".fifo") + kSystemcSuffix;
  if (::mkfifo(beside.c_str(), 0600) == 0) return beside;
  const int err = errno;
  const fs::path elsewhere =
      fs::temp_directory_path() / ("strata-vcd.tmp." + std::to_string(::getpid()) + ".fifo" + kSystemcSuffix);
  ::unlink(elsewhere.c_str());  // a left-over of an earlier process with our id
  if (::mkfifo(elsewhere.c_str(), 0600) == 0) return elsewhere;
  throw std::runtime_error(beside.string() + ": cannot make the VCD's FIFO: " + std::strerror(err));
}

}  // namespace

VcdOutput::VcdOutput(const fs::path& file) : out_(file, "VCD") {
  if (!data_.open(out_.temporary())) out_.commit(data_.error());  // throws, naming the file
  fifo_ = make_fifo(out_.temporary());
  // Non-blocking, so opening the read end does not wait for a writer; then one writer of our
  // own, so reads see no end of file before SystemC opens the FIFO (at the first time step).
  read_end_ = ::open(fifo_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (read_end_ >= 0) keep_open_ = ::open(fifo_.c_str(), O_WRONLY | O_CLOEXEC);
  if (read_end_ < 0 || keep_open_ < 0 || ::fcntl(read_end_, F_SETFL, 0) != 0) {
    const int err = errno;
    if (read_end_ >= 0) ::close(read_end_);
    if (keep_open_ >= 0) ::close(keep_open_);
    ::unlink(fifo_.c_str());
    throw std::runtime_error(fifo_.string() + ": cannot open the VCD's FIFO: " + std::strerror(err));
  }
  // SystemC's note on the time unit would name the FIFO, not the file: the run sets the unit.
  sc_core::sc_report_handler::set_actions(sc_core::SC_ID_TRACING_TIMESCALE_UNIT_, sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  // SystemC opens the FIFO only at the simulation's first time step.
  std::string base = fifo_.string();
  base.resize(base.size() - std::strlen(kSystemcSuffix));
  trace_ = sc_core::sc_create_vcd_trace_file(base.c_str());
  // Signals (Ctrl-C) go to the simulation's thread, which handles them, not to the copier.
  sigset_t all, old;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &old);
  copier_ = std::thread([this] { copy(); });
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

void VcdOutput::copy() {
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(read_end_, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) data_.fail(errno);
    if (n <= 0) break;
    // After a failed write the data is dropped but still read, so SystemC never blocks.
    data_.write(buffer.data(), static_cast<size_t>(n));
  }
}

void VcdOutput::close() {
  if (trace_) {
    sc_core::sc_close_vcd_trace_file(trace_);  // SystemC's fclose: its last bytes, then its end
    trace_ = nullptr;
  }
  if (keep_open_ >= 0) {
    ::close(keep_open_);
    keep_open_ = -1;
  }
  if (copier_.joinable()) copier_.join();
  if (read_end_ >= 0) {
    ::close(read_end_);
    read_end_ = -1;
    ::unlink(fifo_.c_str());
  }
  data_.close();
}

void VcdOutput::commit() {
  close();
  out_.commit(data_.error());
}

VcdOutput::~VcdOutput() { close(); }  // out_ removes the temporary unless committed

}  // namespace strata::sim
