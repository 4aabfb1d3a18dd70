// Issue 39 F5, F10/F11, F13, F14: what an output's name may point at. The VCD is written under
// exactly the name given, complete or not at all (a full disk, simulated with RLIMIT_FSIZE, is
// an error and leaves neither a cut-off file nor a temporary); an output never replaces a
// device, a FIFO or a symbolic link with a regular file (a link is written through); and
// `trace --out` never overwrites the ray file it reads.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test/support/run_program.h"
#include "test/support/test_files.h"

namespace strata::sim::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSim = STRATA_SIM_EXE;
// The issue's frame: the pipelines design has the most signals (a VCD sampled every cycle is
// about 3 MB, its stats.json 43 KB).
const std::string kConfig = std::string(STRATA_SOURCE_DIR) + "/sim/configs/strata-pipelines.json";
const std::string kScene = "cornell:size=0.2";

std::vector<std::string> vcd_run(const fs::path& out, const fs::path& vcd, const std::string& window = "1000") {
  return {kSim, "run", "--config", kConfig, "--scene", kScene, "--res", "8x8", "--set", "tms=2", "--no-cache",
          "--quiet", "--out", out.string(), "--vcd", vcd.string(), "--vcd-window", window};
}

// Every name in `dir` that is a temporary (*.tmp.<pid>, and the VCD's FIFO *.tmp.<pid>.fifo.vcd).
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) found.push_back(e.path().string());
  return found;
}

// A complete VCD from SystemC: its header, then samples.
void expect_whole_vcd(const fs::path& file) {
  const std::string text = read_text(file);
  EXPECT_EQ(text.rfind("$date", 0), 0u) << file;
  EXPECT_NE(text.find("$enddefinitions"), std::string::npos) << file;
  EXPECT_NE(text.find("\n#"), std::string::npos) << file << ": no sample";
}

// A character device standing in for /dev/full (same numbers), made in the test's own folder so
// that no test could ever replace the system's. Only root may make one: false otherwise.
bool make_full_device(const fs::path& file) { return ::mknod(file.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0; }

// F10, F11: the VCD was written by SystemC straight to its final name and its write errors
// were never checked: exit 0, "wrote", and a file cut off at the limit.
TEST(OutputTargets, AVcdThatDoesNotFitIsAnErrorAndLeavesNoFile) {
  TempDir dir;
  const fs::path vcd = dir / "t.vcd";
  // 512 KB: the images and stats.json fit; a VCD sampled every cycle (megabytes) does not.
  const ProgramResult r = run_program(vcd_run(dir / "run", vcd, "1"), 512 * 1024);
  EXPECT_EQ(r.signal, 0) << r.output;
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(vcd.string() + ": cannot write VCD: File too large"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(vcd));
  EXPECT_EQ(temporaries(dir.path()), std::vector<std::string>{});
  // Written before the VCD, the frame's own outputs are whole and kept.
  EXPECT_TRUE(fs::exists(dir / "run" / "stats.json"));
}

// The control of the test above: the same trace with room is whole, and nothing else is left.
TEST(OutputTargets, AVcdWithRoomIsWholeUnderItsName) {
  TempDir dir;
  const fs::path vcd = dir / "t.vcd";
  const ProgramResult r = run_program(vcd_run(dir / "run", vcd, "1"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  expect_whole_vcd(vcd);
  EXPECT_GT(fs::file_size(vcd), 512u * 1024u);  // so the limit above really cuts it
  EXPECT_EQ(temporaries(dir.path()), std::vector<std::string>{});
}

// F5: `--vcd trace` wrote trace.vcd but reported trace.
TEST(OutputTargets, AVcdIsWrittenUnderExactlyTheNameGiven) {
  TempDir dir;
  const fs::path vcd = dir / "trace";
  const ProgramResult r = run_program(vcd_run(dir / "run", vcd));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  expect_whole_vcd(vcd);
  EXPECT_FALSE(fs::exists(dir / "trace.vcd"));
  EXPECT_NE(r.output.find("stats.json, " + vcd.string() + "\n"), std::string::npos) << r.output;
}

// F5: `--vcd /dev/full` made a regular file /dev/full.vcd; a FIFO got a regular file beside it.
TEST(OutputTargets, AVcdNameThatIsAFifoIsRefusedBeforeTheRun) {
  TempDir dir;
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const ProgramResult r = run_program(vcd_run(dir / "run", fifo), 0, 60);
  EXPECT_EQ(r.signal, 0) << "hung (killed by the test's alarm)";
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--vcd " + fifo.string() + ": not a regular file (a FIFO)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("frame "), std::string::npos) << r.output;  // refused before the run
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_FALSE(fs::exists(dir / "fifo.vcd"));
}

TEST(OutputTargets, AVcdNameThatIsADeviceIsRefused) {
  TempDir dir;
  const fs::path device = dir / "full.vcd";
  if (!make_full_device(device)) GTEST_SKIP() << "mknod needs root";
  const ProgramResult r = run_program(vcd_run(dir / "run", device));
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--vcd " + device.string() + ": not a regular file (a character device)"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_character_file(device));
}

// Not a bug of issue 39 but a guard on its fix: a VCD written to a temporary and renamed must
// go through a symbolic link, as SystemC's fopen did, and not replace the link.
TEST(OutputTargets, AVcdNameThatIsALinkIsWrittenThrough) {
  TempDir dir;
  const fs::path link = dir / "link.vcd";
  fs::create_symlink("real.vcd", link);
  const ProgramResult r = run_program(vcd_run(dir / "run", link));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(link));
  expect_whole_vcd(dir / "real.vcd");
}

// `trace --generate N --out <file>`: the ray file a trace test writes.
ProgramResult generate(const fs::path& out) {
  return run_program({kSim, "trace", "--scene", kScene, "--generate", "100", "--out", out.string()}, 0, 60);
}

// F13: trace replaced a FIFO (and, as root, /dev/full) at --out with a regular file.
TEST(OutputTargets, TraceRefusesAnOutThatIsAFifo) {
  TempDir dir;
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const ProgramResult r = generate(fifo);
  EXPECT_EQ(r.signal, 0) << "hung (killed by the test's alarm)";
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--out " + fifo.string() + ": not a regular file (a FIFO)"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_fifo(fifo));
  // The same for a hit file.
  ASSERT_EQ(generate(dir / "rays.bin").exit_status, 0);
  const ProgramResult t = run_program(
      {kSim, "trace", "--scene", kScene, "--no-cache", "--rays", (dir / "rays.bin").string(), "--out", fifo.string()},
      0, 60);
  EXPECT_NE(t.exit_status, 0) << t.output;
  EXPECT_NE(t.output.find("--out " + fifo.string() + ": not a regular file (a FIFO)"), std::string::npos) << t.output;
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(temporaries(dir.path()), std::vector<std::string>{});
}

TEST(OutputTargets, TraceRefusesAnOutThatIsADevice) {
  TempDir dir;
  const fs::path device = dir / "full";
  if (!make_full_device(device)) GTEST_SKIP() << "mknod needs root";
  const ProgramResult r = generate(device);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--out " + device.string() + ": not a regular file (a character device)"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_character_file(device));
}

// F13: a symbolic link at --out was replaced by a regular file; it is written through instead,
// the link's target replaced atomically and the link kept.
TEST(OutputTargets, TraceWritesThroughAnOutThatIsALink) {
  TempDir dir;
  fs::create_directories(dir / "data");
  const fs::path link = dir / "rays.bin";
  fs::create_symlink("data/real.bin", link);  // relative, and its target does not exist yet
  ASSERT_EQ(generate(link).exit_status, 0);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fs::file_size(dir / "data" / "real.bin"), 16u + 32u * 100u);
  ASSERT_EQ(generate(link).exit_status, 0);  // once more, now over an existing target
  EXPECT_TRUE(fs::is_symlink(link));
  // A link to a FIFO is refused as the FIFO is.
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0);
  fs::create_symlink("fifo", dir / "to-fifo");
  const ProgramResult r = generate(dir / "to-fifo");
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("not a regular file (a FIFO)"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
  EXPECT_EQ(temporaries(dir.path()), std::vector<std::string>{});
}

// F14: `trace --rays same.bin --out same.bin` overwrote the rays with the hits. Compared by
// identity: the same name, another spelling of it, a hard link and a symbolic link.
TEST(OutputTargets, TraceRefusesAnOutThatIsItsRayFile) {
  TempDir dir;
  const fs::path rays = dir / "same.bin";
  ASSERT_EQ(generate(rays).exit_status, 0);
  const std::vector<uint8_t> before = read_bytes(rays);
  fs::create_hard_link(rays, dir / "hard.bin");
  fs::create_symlink("same.bin", dir / "soft.bin");
  for (const fs::path& out : {rays, dir / "." / "same.bin", dir / "hard.bin", dir / "soft.bin"}) {
    const ProgramResult r = run_program(
        {kSim, "trace", "--scene", kScene, "--no-cache", "--rays", rays.string(), "--out", out.string()}, 0, 60);
    EXPECT_NE(r.exit_status, 0) << out << "\n" << r.output;
    EXPECT_NE(r.output.find("--out " + out.string() + " is the same file as --rays " + rays.string()),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("hits "), std::string::npos) << r.output;  // refused before tracing
  }
  EXPECT_EQ(read_bytes(rays), before);
  EXPECT_TRUE(fs::is_symlink(dir / "soft.bin"));
}

// The same for the scene file: `--generate` must not write its rays over the mesh.
TEST(OutputTargets, TraceRefusesAnOutThatIsItsSceneFile) {
  TempDir dir;
  const fs::path mesh = dir / "tri.obj";
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  write_bytes(mesh, std::vector<uint8_t>(obj.begin(), obj.end()));
  const ProgramResult r = run_program(
      {kSim, "trace", "--scene", mesh.string(), "--generate", "10", "--out", mesh.string()}, 0, 60);
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("--out " + mesh.string() + " is the same file as --scene " + mesh.string()),
            std::string::npos)
      << r.output;
  EXPECT_EQ(read_text(mesh), obj);
}

}  // namespace
}  // namespace strata::sim::testing
