#include "scenes/scene_cache.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace strata::scenes {

std::filesystem::path default_cache_dir() {
  if (const char* d = std::getenv("STRATA_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return std::filesystem::path(x) / "strata-tlm";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "strata-tlm";
  return std::filesystem::temp_directory_path() / "strata-tlm-cache";
}

std::filesystem::path cache_file_for(const std::filesystem::path& dir, uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof name, "%016llx.strs", static_cast<unsigned long long>(key));
  return dir / name;
}

SceneImage read_scene_image(const std::filesystem::path& file) {
  // Checked before opening: opening a FIFO would block for ever, a directory reads as garbage.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw SceneError(file.string() + ": cannot open scene image: " +
                     (std::filesystem::exists(file, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw SceneError(file.string() + ": cannot open scene image");
  const auto size = static_cast<uint64_t>(in.tellg());
  if (size % 8 != 0)
    throw SceneError(file.string() + ": invalid scene image: size " + std::to_string(size) +
                     " is not a multiple of 8 (truncated?)");
  std::vector<uint64_t> words(size / 8);
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(words.data()), std::streamsize(size)))
    throw SceneError(file.string() + ": read error");
  return SceneImage(std::move(words), file.string());
}

void write_scene_image(const SceneImage& image, const std::filesystem::path& file) {
  // Write beside the target and rename, so a crash never leaves a half-written cache file
  // under the final name (and a concurrent reader sees the old file or the new one).
  // Host and process in the name: Slurm tasks on several nodes may share the cache folder.
  char host[256] = "host";
  ::gethostname(host, sizeof host - 1);
  const auto tmp = file.string() + ".tmp." + host + "." + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(image.bytes()), std::streamsize(image.size_bytes()));
    out.close();
    if (!out) {
      std::filesystem::remove(tmp, ec);
      throw SceneError(tmp + ": cannot write scene image");
    }
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw SceneError(file.string() + ": cannot write scene image: " + ec.message());
  }
}

SceneImage load_or_build_scene_image(const Scene& scene, const SceneImageParams& params,
                                     const std::filesystem::path& cache_dir,
                                     SceneBuildReport* report) {
  SceneBuildReport local;
  SceneBuildReport& rep = report ? *report : local;
  if (cache_dir.empty()) {
    rep.cache_note = "cache disabled";
    return build_scene_image(scene, params, &rep);
  }
  check_image_params(params);
  const uint64_t key = scene_content_key(scene, params);
  const auto file = cache_file_for(cache_dir, key);
  std::string why_rebuild = "not cached yet";
  std::error_code exists_ec;
  if (std::filesystem::exists(file, exists_ec) && !std::filesystem::is_regular_file(file, exists_ec))
    throw SceneError(file.string() + ": the scene cache entry is not a regular file (a FIFO or a folder?); "
                     "remove it, or pass --no-cache or another --cache-dir");
  if (std::filesystem::exists(file)) {
    try {
      SceneImage cached = read_scene_image(file);
      if (cached.header().content_key == key) {
        rep.from_cache = true;
        rep.cache_note = "loaded from " + file.string();
        return cached;
      }
      why_rebuild = "stale cache file " + file.string() + " (key mismatch)";
    } catch (const SceneError& e) {
      why_rebuild = std::string("rejected cache file: ") + e.what();
    }
  }
  SceneImage image = build_scene_image(scene, params, &rep);
  std::error_code ec;
  std::filesystem::create_directories(cache_dir, ec);
  try {
    write_scene_image(image, file);
    rep.cache_note = why_rebuild + "; built and stored in " + file.string();
  } catch (const std::exception& e) {
    // Failing to cache costs the next run a rebuild, nothing more.
    rep.cache_note = why_rebuild + "; built, but could not store it: " + e.what();
  }
  return image;
}

}  // namespace strata::scenes
