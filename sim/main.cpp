// strata-sim: entry point. Each subcommand lives in its own file and registers here.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "sim/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"strata-sim: SystemC/TLM-2.0 model of the STRaTA ray-tracing architecture"};
  app.require_subcommand(1);
  strata::sim::add_scene_command(app);
  strata::sim::add_render_command(app);
  strata::sim::add_trace_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "strata-sim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
