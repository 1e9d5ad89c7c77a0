#pragma once
#include <filesystem>
#include <fstream>
#include <string>

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
                         "  terrain: {type: " << type << ", height: relief, lowest: -12000, highest: 12000}\n"
                         "  frame: {type: output.image, geometry: terrain, surface: [colours]}\n";
  return file;
}

}  // namespace strata::bench
