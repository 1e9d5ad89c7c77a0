// strata: render pipelines headless, view them in a window, time them, list plugins, project points,
// describe the machine.
#include <CLI/CLI.hpp>

#include <strata/version.hpp>

#include "commands.hpp"
#include "interrupt_cleanup.hpp"

int main(int argc, char** argv) {
  strata::cli::removeUnfinishedOutputsOnSignal();
  CLI::App app{"Strata composes planetary height and surface maps of any projection into one view of a planet.",
               "strata"};
  app.set_version_flag("--version", strata::kVersionString);
  app.require_subcommand(1);
  int exitCode = 0;
  strata::cli::addRenderCommand(app, exitCode);
  strata::cli::addViewCommand(app, exitCode);
  strata::cli::addPluginsCommand(app, exitCode);
  strata::cli::addTileCommand(app, exitCode);
  strata::cli::addBuildBdamCommand(app, exitCode);
  strata::cli::addBenchCommand(app, exitCode);
  strata::cli::addProjectCommand(app, exitCode);
  strata::cli::addInfoCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive here with exit code 0. A mistake on the command line exits 1 like every
    // other error of strata, not with CLI11's own codes (105, 106, ...), which scripts would not expect.
    return app.exit(error) == 0 ? 0 : 1;
  }
  return exitCode;
}
