// Output files that are either complete or absent. Each is written to a temporary name in its
// own folder, every write and the final close checked, flushed to the device, and only then
// renamed onto its final name; any failure (a full disk, a read-only folder) removes the
// temporary and throws an error naming the file. A run never reports success for output it
// did not write, and never leaves a cut-off file under a final name. SIGINT and SIGTERM are held
// while write_file_atomically's temporary exists, so a Ctrl-C during the write takes effect
// after it, leaving no temporary either.
//
// The final name is never replaced by something of another kind: a symbolic link is written
// through (the file it leads to is replaced, atomically, and the link stays), and a target that
// exists and is not a regular file (a device such as /dev/full, a FIFO, a socket, a folder) is
// refused, since renaming a regular file onto it would replace it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace strata::sim {

// `kind` names what the file holds in the error ("<file>: cannot write <kind>: <reason>").
void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t bytes,
                           const std::string& kind = "");
inline void write_file_atomically(const std::filesystem::path& file, const std::string& text,
                                  const std::string& kind = "") {
  write_file_atomically(file, text.data(), text.size(), kind);
}
inline void write_file_atomically(const std::filesystem::path& file, const std::vector<uint8_t>& bytes,
                                  const std::string& kind = "") {
  write_file_atomically(file, bytes.data(), bytes.size(), kind);
}

// Where a write to `file` lands: `file` itself or, if it is a symbolic link, what the chain
// of links leads to (which need not exist yet). Throws on a loop of links.
std::filesystem::path output_target(const std::filesystem::path& file);

// A file descriptor whose every write is checked: the first error (an errno) is kept and later
// writes are dropped, so a writer can go on and ask once at the end.
class CheckedFile {
 public:
  CheckedFile() = default;
  ~CheckedFile();
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  // Creates or truncates `file`; false (and error() set) if it cannot.
  bool open(const std::filesystem::path& file);
  void write(const void* data, std::size_t bytes);
  void fail(int err) { if (err_ == 0) err_ = err; }
  // Flushes to the device (a full disk may show only here) and closes; returns error().
  int close();
  int error() const { return err_; }

 private:
  int fd_ = -1;
  int err_ = 0;
};

// An output whose bytes are written by someone else (a library that opens the file itself, such
// as a VCD writer): they go to temporary(), in the final file's folder; commit() renames it onto
// the final name if no write failed, and otherwise, or if never committed, it is removed.
class PendingFile {
 public:
  // Throws if the target exists and is not a regular file (see above).
  PendingFile(std::filesystem::path file, std::string kind);
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  const std::filesystem::path& file() const { return file_; }
  const std::filesystem::path& temporary() const { return tmp_; }
  // `error`: the errno of the first failed write or close, 0 if none. Throws
  // "<file>: cannot write <kind>: <reason>" after removing the temporary.
  void commit(int error);

 private:
  std::filesystem::path file_, target_, tmp_;
  std::string kind_;
  bool committed_ = false;
};

// Creates `dir` if needed and proves a file can be written in it, so that a long simulation
// does not end in an unwritable folder. `what` names the option (e.g. "--out").
void require_writable_dir(const std::filesystem::path& dir, const std::string& what);

// The folder a file will be written to (a link's target's folder) must be writable (see
// above); a file path that names a folder, a device, a FIFO or a socket is an error.
void require_writable_file(const std::filesystem::path& file, const std::string& what);

// An output that is also one of the command's inputs would be overwritten with the input still
// wanted: refused, naming both options. Compared by identity (device and inode, links followed),
// so another spelling of the path, a hard link or a symbolic link to the input is caught too.
void require_not_input(const std::filesystem::path& output, const std::string& output_option,
                       const std::filesystem::path& input, const std::string& input_option);

}  // namespace strata::sim
