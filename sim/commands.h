// Registration of strata-sim's subcommands. Each lives in its own file; a command reports
// failure by throwing, and main turns that into a message and a non-zero exit.
#pragma once

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace strata::sim {

// A run stopped by Ctrl-C after writing what it had; strata-sim exits with status 130.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void add_scene_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_trace_command(CLI::App& app);
void add_stats_reference_command(CLI::App& app);

}  // namespace strata::sim
