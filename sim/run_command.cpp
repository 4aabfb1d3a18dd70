// `strata-sim run`: one frame on a simulated chip. Loads a design config (plus --set
// overrides), the scene and its image (treelets sized to the L1), runs the design's firmware
// kernel on every TP of the chip, and writes the image, the statistics and optionally a VCD.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <unistd.h>

#include "model/chip/chip.h"
#include "model/chip/chip_report.h"
#include "sim/commands.h"
#include "sim/frame_setup.h"
#include "sim/image_output.h"
#include "sim/iss_render.h"
#include "sim/native_render.h"
#include "sim/output_file.h"
#include "sim/pipeline_backend.h"
#include "sim/progress_monitor.h"
#include "sim/resolution.h"
#include "sim/sanitizer_stack.h"
#include "sim/scene_source.h"
#include "sim/vcd_output.h"

namespace strata::sim {
namespace {

struct RunOptions {
  std::string config_file;
  std::vector<std::string> overrides;
  SceneSourceOptions source;
  std::string resolution = "256x256";
  RenderSettings settings;
  std::string out_dir = "out/run";
  std::string firmware;  // default: the design's kernel
  std::string vcd;
  uint64_t progress_cycles = 200000;
  uint64_t max_cycles = 0;  // 0: no limit
  bool quiet = false;
  uint64_t vcd_window_cycles = 1000;
  uint64_t vcd_start = 0, vcd_end = ~uint64_t{0};
  bool check = false;
  bool progress = false;  // progress lines even when stderr is not a terminal
  std::vector<std::string> stats_detail;
};

// --stats-detail tm,l2-bank,channel | all | none: which instance arrays stats.json lists one by one.
std::set<std::string> detail_axes(const std::vector<std::string>& asked) {
  if (asked.empty()) return chip::FrameReport::default_detail();
  std::set<std::string> axes;
  for (const std::string& a : asked) {
    if (a == "all") return chip::FrameReport::detail_axes();
    if (a == "none") continue;
    if (chip::FrameReport::detail_axes().count(a) == 0)
      throw std::runtime_error("--stats-detail: unknown '" + a + "' (tm, l2-bank, channel, all or none)");
    axes.insert(a);
  }
  return axes;
}

void run_frame(RunOptions o) {
  const std::set<std::string> detail = detail_axes(o.stats_detail);
  parse_resolution(o.resolution, &o.settings.width, &o.settings.height);
  check_render_settings(o.settings);
  chip::ChipConfig config = chip::load_chip_config(o.config_file, o.overrides);
  if (config.timing.mode != transport::TimingMode::kSampled) {
    std::string fields;
    for (const std::string& f : chip::sampled_only_fields_changed(config.timing)) fields += (fields.empty() ? "" : ", ") + f;
    if (!fields.empty())
      std::fprintf(stderr, "warning: %s set, but timing.mode is %s: sampled timing's options do nothing in this mode\n",
                   fields.c_str(), to_string(config.timing.mode));
  }
  o.source.params = scene_image_params_for(config, o.source.params);
  const LoadedScene loaded = load_scene_and_image(o.source);
  PreparedFrame prepared = prepare_frame(config, loaded.image, o.settings, o.firmware);
  config = prepared.config;
  chip::FrameInputs& inputs = prepared.inputs;
  // Before the simulation, not after it: an unwritable --out or --vcd fails in a second.
  require_writable_dir(o.out_dir, "--out");
  if (!o.vcd.empty()) require_writable_file(o.vcd, "--vcd");
  // 0 would wake the progress monitor every cycle, and a 0-cycle VCD window traces nothing.
  if (o.progress_cycles == 0)
    throw std::runtime_error("--progress-cycles 0: must be at least 1 (for no progress lines, use --quiet)");
  if (o.vcd_window_cycles == 0)
    throw std::runtime_error("--vcd-window 0: must be at least 1 cycle (a 0-cycle window traces no signal)");
  if (o.vcd_start > o.vcd_end)
    throw std::runtime_error("--vcd-start " + std::to_string(o.vcd_start) + " is after --vcd-end " +
                             std::to_string(o.vcd_end));
  // The RTL's VCDs are named after the chip's without its .vcd: t.vcd gives t.rtl_tm0.vcd.
  std::string vcd_base = o.vcd;
  if (vcd_base.size() > 4 && vcd_base.substr(vcd_base.size() - 4) == ".vcd") vcd_base.resize(vcd_base.size() - 4);
  // Declared before the chip, whose RTL backends write these files: they outlive it.
  const auto rtl_vcds = std::make_shared<RtlVcdSet>();
  if (config.pipeline_impl == chip::PipelineImpl::kRtl)
    inputs.pipeline_backend =
        rtl_pipeline_backend(config, {o.vcd.empty() ? "" : vcd_base, o.vcd_start, o.vcd_end, rtl_vcds});
  chip::Chip chip("chip", config, inputs);

  std::unique_ptr<VcdOutput> vcd;  // written under exactly the name given (vcd_output.h)
  if (!o.vcd.empty()) {
    vcd = std::make_unique<VcdOutput>(o.vcd);
    vcd->trace_file()->set_time_unit(1, sc_core::SC_NS);
    chip.trace(vcd->trace_file(), memory::TraceWindow(o.vcd_window_cycles, o.vcd_start, o.vcd_end));
  }
  ProgressMonitor progress("progress", chip, o.progress_cycles, !o.quiet && (o.progress || isatty(STDERR_FILENO) != 0),
                           isatty(STDERR_FILENO) != 0);
  progress.set_cycle_limit(o.max_cycles);
  progress.arm();
  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  restore_main_stack_for_asan();  // ASan builds only: the outputs below may throw (a full disk, a signal)
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.disarm();
  if (vcd) vcd->close();
  const bool interrupted = progress.interrupted() || progress.cycle_limit_reached();
  if (!chip.finished() && !interrupted) throw std::runtime_error("simulation failed: " + chip.error());

  const chip::FrameReport report(chip, wall, interrupted);
  const std::filesystem::path dir(o.out_dir);
  const std::vector<kernels::Pixel> image = chip.framebuffer();
  write_exr(dir / "image.exr", o.settings.width, o.settings.height, image);
  write_png_preview(dir / "image.png", o.settings.width, o.settings.height, image);
  write_file_atomically(dir / "stats.json", report.to_json(detail).dump(2) + "\n");
  // The VCDs last: a full disk there still leaves the image and the statistics, and the error.
  if (vcd) vcd->commit();
  rtl_vcds->commit();
  std::printf("%s", report.summary().c_str());
  std::printf("wrote          %s/image.exr, image.png, stats.json%s%s\n", dir.c_str(),
              o.vcd.empty() ? "" : ", ", o.vcd.c_str());
  if (!o.vcd.empty() && o.vcd_start >= chip.cycles())
    std::printf("warning        --vcd-start %llu is at or after the frame's last cycle (%llu): the VCD holds the "
                "signals but no sample\n",
                static_cast<unsigned long long>(o.vcd_start), static_cast<unsigned long long>(chip.cycles()));
  if (!rtl_vcds->empty())
    std::printf("wrote          the RTL pipelines' VCD: %s (one per TM using the RTL)\n",
                (vcd_base + ".rtl_tm<k>.vcd").c_str());

  if (progress.cycle_limit_reached())
    throw std::runtime_error("--max-cycles " + std::to_string(o.max_cycles) +
                             ": the frame did not finish within the limit (firmware in a loop?); partial image "
                             "and statistics written to " + dir.string());
  if (interrupted)
    throw Interrupted("interrupted: partial image and statistics written to " + dir.string(), progress.signal());
  if (o.check) {
    // The twin computes with the design's path arithmetic: packed where the rays carry it.
    RenderSettings twin_settings = o.settings;
    if (config.design.streams && config.design.path_state == chip::PathStatePlacement::kCompact)
      twin_settings.path_arithmetic = PathArithmetic::kPacked;
    const RenderResult twin = render_native(loaded.image, twin_settings);
    const kernels::RayCounters chip_rays = chip.ray_counters();
    const bool same_image =
        std::memcmp(twin.image.data(), image.data(), image.size() * sizeof(kernels::Pixel)) == 0;
    bool same_rays = chip_rays.paths == twin.counters.paths;
    for (uint32_t t = 0; t < kernels::kRayTypes; ++t)
      same_rays = same_rays && chip_rays.rays[t] == twin.counters.rays[t] && chip_rays.hits[t] == twin.counters.hits[t];
    std::printf("check          image %s the native twin's; rays and hits by type %s\n",
                same_image ? "bit-identical to" : "DIFFERS from", same_rays ? "equal" : "DIFFER");
    if (!same_image || !same_rays) throw std::runtime_error("the chip's frame does not match the native twin");
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Simulate one frame on a chip design");
  auto opts = std::make_shared<RunOptions>();
  cmd->add_option("--config", opts->config_file, "design config (sim/configs/*.json)")->required();
  cmd->add_option("--set", opts->overrides, "override a config field: path=value (repeatable)");
  cmd->add_option("--scene", opts->source.scene, "scene spec, as for `scene info`")->required();
  cmd->add_option("--res", opts->resolution, "image size WxH")->capture_default_str();
  cmd->add_option("--spp", opts->settings.samples_per_pixel, "samples per pixel")->capture_default_str();
  cmd->add_option("--max-path-vertices", opts->settings.max_path_vertices, "closest-hit segments per path")
      ->capture_default_str();
  cmd->add_option("--seed", opts->settings.seed, "random seed of the frame")->capture_default_str();
  cmd->add_option("--out", opts->out_dir, "output folder")->capture_default_str();
  cmd->add_option("--firmware", opts->firmware, "kernel ELF (default: the design's kernel)");
  cmd->add_option("--vcd", opts->vcd,
                  "write a VCD waveform to exactly this file (with tm.pipeline_impl=rtl also <FILE without "
                  ".vcd>.rtl_tm<k>.vcd)");
  cmd->add_option("--vcd-window", opts->vcd_window_cycles, "VCD sampling window in cycles")->capture_default_str();
  cmd->add_option("--vcd-start", opts->vcd_start, "first cycle the VCD records");
  cmd->add_option("--vcd-end", opts->vcd_end, "cycle after which the VCD records nothing");
  cmd->add_option("--progress-cycles", opts->progress_cycles, "simulated cycles between progress lines")
      ->capture_default_str();
  cmd->add_option("--max-cycles", opts->max_cycles,
                  "stop with an error once this many cycles are simulated (0: no limit); partial outputs are written")
      ->capture_default_str();
  cmd->add_flag("--quiet", opts->quiet, "no progress lines");
  cmd->add_flag("--progress", opts->progress, "progress lines even when stderr is not a terminal (one per line)");
  cmd->add_option("--stats-detail", opts->stats_detail,
                  "list instance arrays one by one in stats.json: tm, l2-bank, channel, all, none (default: channel)")
      ->delimiter(',');
  cmd->add_flag("--check", opts->check, "also render with the native twin and require identical results");
  cmd->add_option("--cache-dir", opts->source.cache_dir, "scene image cache");
  cmd->add_flag("--no-cache", opts->source.no_cache, "always build the scene image");
  cmd->callback([opts] { run_frame(*opts); });
}

}  // namespace strata::sim
