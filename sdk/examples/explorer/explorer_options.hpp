#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace explorer {

// What the command line asks for. Each setting is one the panel also makes, so that a script (or a test)
// can start the explorer where a user would click to.
struct ExplorerOptions {
  std::filesystem::path pipeline;  // empty: the sample scene, built in code (sample_scene.hpp)
  int width = 1280;                // window size, pixels: 720p fits a laptop's screen with room to spare
  int height = 720;
  std::vector<std::string> hidden;                  // layers of the output's surface list to start unticked
  std::optional<std::string> date;                  // ISO 8601, the date slider's value
  std::optional<double> altitude;                   // m, the altitude slider's value
  std::optional<std::filesystem::path> screenshot;  // render, write the window to this PNG and quit
  int frames = 5;  // frames shown before the screenshot: the panel lays itself out in the first two
};

// Reads argv; throws std::invalid_argument with a line a user can act on.
ExplorerOptions parseOptions(int argc, char** argv);

// The usage text, for --help and for errors.
std::string usage();

}  // namespace explorer
