#pragma once
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace strata::cli {

// A frame size given as WIDTHxHEIGHT.
struct FrameSize {
  int width = 1280;  // 720p: the default the issue asks for, and quick on a CPU renderer
  int height = 720;
};

// Reads "1280x720" into `size`; returns the problem, for CLI11's error, or empty.
std::string parseSize(const std::string& text, FrameSize& size);

// What render and view both take: the pipeline, overrides and a size.
struct PipelineOptions {
  std::string pipeline;
  std::vector<std::string> overrides;
  FrameSize size;
  bool glDebug = false;
};

void addPipelineOptions(CLI::App& command, PipelineOptions& options);

// Runs `command`, turning any error into a message on stderr and exit code 1, so no failure a user can
// cause ends in a crash or an uncaught exception.
int reportingErrors(const std::function<void()>& command);

}  // namespace strata::cli
