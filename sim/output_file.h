// Output files that are either complete or absent. Each is written to a temporary name in its
// own folder, every write and the final close checked, flushed to the device, and only then
// renamed onto its final name; any failure (a full disk, a read-only folder) removes the
// temporary and throws an error naming the file. A run never reports success for output it
// did not write, and never leaves a cut-off file under a final name. SIGINT and SIGTERM are held
// while a temporary exists, so a Ctrl-C during the write takes effect after it, leaving no
// temporary either.
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

// Creates `dir` if needed and proves a file can be written in it, so that a long simulation
// does not end in an unwritable folder. `what` names the option (e.g. "--out").
void require_writable_dir(const std::filesystem::path& dir, const std::string& what);

// The folder a file will be written to must be writable (see above); a file path that names a
// folder is an error.
void require_writable_file(const std::filesystem::path& file, const std::string& what);

}  // namespace strata::sim
