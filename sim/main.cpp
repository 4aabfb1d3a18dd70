// strata-sim: entry point. Each subcommand lives in its own file and registers here.
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <systemc>

#include "sim/commands.h"

// libsystemc owns main() and calls sc_main(), so the chip can be elaborated here.
int sc_main(int argc, char** argv) {
  CLI::App app{"strata-sim: SystemC/TLM-2.0 model of the STRaTA ray-tracing architecture"};
  app.require_subcommand(1);
  strata::sim::add_scene_command(app);
  strata::sim::add_render_command(app);
  strata::sim::add_trace_command(app);
  strata::sim::add_run_command(app);
  strata::sim::add_stats_reference_command(app);
  strata::sim::add_arithmetic_error_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const strata::sim::Interrupted& e) {
    std::cerr << "strata-sim: " << e.what() << "\n";
    return e.exit_status();
  } catch (const std::exception& e) {
    std::cerr << "strata-sim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
