#pragma once
#include <filesystem>
#include <fstream>
#include <string>

#include <strata/camera.hpp>

namespace strata::bench {

// The planet the benchmarks fly over: source.procedural's heights and colours on a Mars-sized body,
// unexaggerated (within +-12 km, the model's amplitude, which `lowest` and `highest` give the generator),
// drawn by the geometry generator `type`. Written to the temporary directory as `name`.yaml; returns its path.
inline std::filesystem::path writeProceduralMarsPipeline(const std::string& name, const std::string& type) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / (name + ".yaml");
  std::ofstream(file) << "strata: 1\n"
                         "body: {name: Mars, radius: 3396190}\n"
                         "nodes:\n"
                         "  colours: {type: source.procedural, kind: color}\n"
                         "  relief: {type: source.procedural, kind: height}\n"
                         "  terrain: {type: "
                      << type
                      << ", height: relief, lowest: -12000, highest: 12000}\n"
                         "  frame: {type: output.image, geometry: terrain, surface: [colours]}\n";
  return file;
}

// The two views it is seen from, after the test cases 1 and 2 of [Mahsman 2010, §6.1], so that every
// generator is timed on the same frames: the whole planet straight down from 8,000 km (it spans about 35 of
// the 45 degrees), and near it at a steep angle, 20 km up and tilted 70 degrees toward the horizon.
inline Camera wholeMarsView() { return {.lon = 30, .lat = 25, .altitude = 8.0e6, .heading = 0, .tilt = 0, .fov = 45}; }
inline Camera nearMarsView() { return {.lon = 30, .lat = 25, .altitude = 2.0e4, .heading = 0, .tilt = 70, .fov = 45}; }

}  // namespace strata::bench
