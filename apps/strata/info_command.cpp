#include <cstdio>

#include <GLFW/glfw3.h>

#include <strata/gl/context.hpp>
#include <strata/host/library_versions.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

void info() {
  for (const auto& [name, version] : libraryVersions()) std::printf("%-12s %s\n", name.c_str(), version.c_str());
  std::printf("%-12s %s\n", "GLFW", glfwGetVersionString());
  auto context = createHeadlessContext();
  const GlInfo gl = currentGlInfo();
  std::printf("\nheadless OpenGL through %s\n", context->description().c_str());
  std::printf("%-12s %s\n%-12s %s\n%-12s %s\n%-12s %s\n", "renderer", gl.renderer.c_str(), "vendor", gl.vendor.c_str(),
              "GL version", gl.version.c_str(), "GLSL", gl.shadingLanguage.c_str());
  std::printf("\nplugin directories:\n");
  for (const auto& directory : defaultPluginDirectories()) std::printf("  %s\n", directory.c_str());
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  CLI::App* command = app.add_subcommand("info", "print the GPU, OpenGL version and library versions");
  command->callback([&exitCode] { exitCode = reportingErrors(info); });
}

}  // namespace strata::cli
