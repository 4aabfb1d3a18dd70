#include "sim/output_file.h"

#include <cerrno>
#include <csignal>
#include <pthread.h>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace strata::sim {
namespace {

namespace fs = std::filesystem;

std::runtime_error write_error(const fs::path& file, const std::string& kind, const std::string& reason) {
  return std::runtime_error(file.string() + ": cannot write" + (kind.empty() ? "" : " " + kind) + ": " + reason);
}

// What a non-regular file is, for the errors that refuse one.
std::string describe(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory: return "a folder";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

// The type of what `target` names now (links followed); not_found if nothing.
fs::file_type type_of(const fs::path& target) {
  std::error_code ec;
  return fs::status(target, ec).type();
}

bool replaceable(fs::file_type t) { return t == fs::file_type::not_found || t == fs::file_type::regular; }

// SIGINT and SIGTERM held back while write_file_atomically's temporary exists: the run's
// handlers are gone once the simulation has stopped, so a second Ctrl-C while the outputs were
// written killed the process between open and rename and left "<file>.tmp.<pid>" behind
// (issue 39). A signal that arrives meanwhile is delivered when the guard ends, with the file
// complete under its final name or the temporary removed. (strata-sim writes its outputs from
// its one thread; the VCD's copier thread blocks every signal.)
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

fs::path output_target(const fs::path& file) {
  fs::path p = file;
  // 40, as the kernel's own limit on links followed in one lookup.
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(p, ec)) return p;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) return p;
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  throw std::runtime_error(file.string() + ": too many levels of symbolic links");
}

CheckedFile::~CheckedFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool CheckedFile::open(const fs::path& file) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(errno);
  return fd_ >= 0;
}

void CheckedFile::write(const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0 && err_ == 0 && fd_ >= 0) {
    const ssize_t n = ::write(fd_, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      fail(n < 0 ? errno : EIO);
      break;
    }
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
}

int CheckedFile::close() {
  if (fd_ < 0) return err_;
  // A full disk may show only here, when the data reaches the device.
  if (err_ == 0 && ::fsync(fd_) != 0 && errno != EINVAL) fail(errno);
  if (::close(fd_) != 0) fail(errno);
  fd_ = -1;
  return err_;
}

// The temporary sits next to the file that will be replaced (rename is atomic only within one
// file system) and carries the process id, so two processes writing the same file never share one.
PendingFile::PendingFile(fs::path file, std::string kind)
    : file_(std::move(file)), target_(output_target(file_)), kind_(std::move(kind)) {
  const fs::file_type t = type_of(target_);
  if (!replaceable(t)) throw write_error(file_, kind_, "not a regular file (" + describe(t) + ")");
  tmp_ = target_;
  tmp_ += ".tmp." + std::to_string(::getpid());
}

PendingFile::~PendingFile() {
  if (!committed_) ::unlink(tmp_.c_str());
}

void PendingFile::commit(int error) {
  // Checked again: the target may have become something else while the file was written.
  if (error == 0 && !replaceable(type_of(target_))) {
    ::unlink(tmp_.c_str());
    throw write_error(file_, kind_, "not a regular file (" + describe(type_of(target_)) + ")");
  }
  if (error == 0 && ::rename(tmp_.c_str(), target_.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(tmp_.c_str());
    throw write_error(file_, kind_, std::strerror(error));
  }
  committed_ = true;
}

void write_file_atomically(const fs::path& file, const void* data, std::size_t bytes, const std::string& kind) {
  const SignalsHeld held;  // first: released after the temporary is renamed or removed
  PendingFile out(file, kind);
  CheckedFile f;
  if (f.open(out.temporary())) f.write(data, bytes);
  out.commit(f.close());
}

void require_writable_dir(const fs::path& dir, const std::string& what) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(what + " " + dir.string() + ": cannot create the folder: " + ec.message());
  if (!fs::is_directory(dir))
    throw std::runtime_error(what + " " + dir.string() + ": not a folder");
  const fs::path probe = dir / (".strata-write-probe." + std::to_string(::getpid()));
  try {
    write_file_atomically(probe, "probe\n");
  } catch (const std::exception& e) {
    throw std::runtime_error(what + " " + dir.string() + ": cannot write in this folder (" + e.what() + ")");
  }
  fs::remove(probe, ec);
}

void require_writable_file(const fs::path& file, const std::string& what) {
  const fs::path target = output_target(file);
  const fs::file_type t = type_of(target);
  if (t == fs::file_type::directory)
    throw std::runtime_error(what + " " + file.string() + ": is a folder, not a file");
  if (!replaceable(t))
    throw std::runtime_error(what + " " + file.string() + ": not a regular file (" + describe(t) +
                             "); outputs are written to a new file and renamed onto their name, which would "
                             "replace it: give the name of a regular file or a new one");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  require_writable_dir(dir, what);
}

void require_not_input(const fs::path& output, const std::string& output_option, const fs::path& input,
                       const std::string& input_option) {
  struct stat out {}, in {};
  if (::stat(output.c_str(), &out) != 0 || ::stat(input.c_str(), &in) != 0) return;  // no file: not the same
  if (out.st_dev == in.st_dev && out.st_ino == in.st_ino)
    throw std::runtime_error(output_option + " " + output.string() + " is the same file as " + input_option + " " +
                             input.string() + ": writing it would overwrite the input; give another " +
                             output_option);
}

}  // namespace strata::sim
