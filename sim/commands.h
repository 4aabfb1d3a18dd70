// Registration of strata-sim's subcommands. Each lives in its own file; a command reports
// failure by throwing, and main turns that into a message and a non-zero exit.
#pragma once

#include <CLI/CLI.hpp>

namespace strata::sim {

void add_scene_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_trace_command(CLI::App& app);

}  // namespace strata::sim
