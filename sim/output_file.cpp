#include "sim/output_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace strata::sim {
namespace {

std::runtime_error write_error(const std::filesystem::path& file, const std::string& kind, int err) {
  return std::runtime_error(file.string() + ": cannot write" + (kind.empty() ? "" : " " + kind) + ": " +
                            std::strerror(err));
}

// The temporary sits next to the file (rename is atomic only within one file system) and
// carries the process id, so two processes writing the same file never share one.
std::filesystem::path temporary_for(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp." + std::to_string(::getpid());
  return tmp;
}

// SIGINT and SIGTERM held back while a temporary exists: the run's handlers are gone once the
// simulation has stopped, so a second Ctrl-C while the outputs were written killed the process
// between open and rename and left "<file>.tmp.<pid>" behind (issue 39). A signal that arrives
// meanwhile is delivered when the guard ends, with the file complete under its final name or
// the temporary removed. (strata-sim writes its outputs from its one thread.)
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &held, &previous_);
  }
  ~SignalsHeld() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t previous_;
};

}  // namespace

void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t bytes,
                           const std::string& kind) {
  const std::filesystem::path tmp = temporary_for(file);
  const SignalsHeld held;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw write_error(file, kind, errno);
  const char* p = static_cast<const char*>(data);
  std::size_t left = bytes;
  int err = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  // A full disk may show only here, when the data reaches the device.
  if (err == 0 && ::fsync(fd) != 0 && errno != EINVAL) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(tmp.c_str(), file.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(tmp.c_str());
    throw write_error(file, kind, err);
  }
}

void require_writable_dir(const std::filesystem::path& dir, const std::string& what) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(what + " " + dir.string() + ": cannot create the folder: " + ec.message());
  if (!std::filesystem::is_directory(dir))
    throw std::runtime_error(what + " " + dir.string() + ": not a folder");
  const std::filesystem::path probe = dir / (".strata-write-probe." + std::to_string(::getpid()));
  try {
    write_file_atomically(probe, "probe\n");
  } catch (const std::exception& e) {
    throw std::runtime_error(what + " " + dir.string() + ": cannot write in this folder (" + e.what() + ")");
  }
  std::filesystem::remove(probe, ec);
}

void require_writable_file(const std::filesystem::path& file, const std::string& what) {
  if (std::filesystem::is_directory(file))
    throw std::runtime_error(what + " " + file.string() + ": is a folder, not a file");
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  require_writable_dir(dir, what);
}

}  // namespace strata::sim
