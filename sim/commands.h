// Registration of strata-sim's subcommands. Each lives in its own file; a command reports
// failure by throwing, and main turns that into a message and a non-zero exit.
#pragma once

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace strata::sim {

// A run stopped by a signal (Ctrl-C, SIGTERM) after writing what it had; strata-sim exits
// with the shell's status for that signal, 128 + its number (130 for SIGINT, 143 for SIGTERM).
class Interrupted : public std::runtime_error {
 public:
  Interrupted(const std::string& what, int signal) : std::runtime_error(what), signal_(signal) {}
  int exit_status() const { return 128 + signal_; }

 private:
  int signal_;
};

void add_scene_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_trace_command(CLI::App& app);
void add_stats_reference_command(CLI::App& app);
void add_arithmetic_error_command(CLI::App& app);

}  // namespace strata::sim
