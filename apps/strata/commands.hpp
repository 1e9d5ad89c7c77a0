#pragma once
#include <CLI/CLI.hpp>

namespace strata::cli {

// Each command adds its subcommand to the application; the callback it installs runs the command and
// returns through the exit code it stores.
void addRenderCommand(CLI::App& app, int& exitCode);
void addViewCommand(CLI::App& app, int& exitCode);
void addPluginsCommand(CLI::App& app, int& exitCode);
void addInfoCommand(CLI::App& app, int& exitCode);
void addProjectCommand(CLI::App& app, int& exitCode);
void addTileCommand(CLI::App& app, int& exitCode);
void addBuildBdamCommand(CLI::App& app, int& exitCode);
void addBenchCommand(CLI::App& app, int& exitCode);

}  // namespace strata::cli
